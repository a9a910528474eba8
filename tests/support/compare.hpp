// SPDX-License-Identifier: BSL-1.0
// Comparisons the tests make of whole states: bit for bit, and the largest component difference.
#ifndef ODESTEP_TESTS_SUPPORT_COMPARE_HPP
#define ODESTEP_TESTS_SUPPORT_COMPARE_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace odestep_test {

/// True when a and b hold the same bytes: the same values bit for bit, the sign of zero and the payload of
/// a NaN included (stricter than odestep::detail::same_values, where NaN equals nothing and -0 == +0). The
/// check that a failing call left the caller's state exactly as it was, and that two routes to a result
/// took the same arithmetic.
template <class State>
bool same_bits(const State& a, const State& b) {
    static_assert(sizeof(a) == sizeof(b), "same_bits compares two objects of one size");
    return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

/// The largest |a_i - b_i| over the components; NaN when any difference is NaN, so that a state gone
/// non-finite never passes for a small error.
template <class T, std::size_t N>
T max_abs_difference(const std::array<T, N>& a, const std::array<T, N>& b) {
    T largest = T(0);
    for (std::size_t i = 0; i < N; ++i) {
        const T d = std::fabs(a[i] - b[i]);
        if (d != d) return d;
        if (d > largest) largest = d;
    }
    return largest;
}

/// The largest |x_i - xe_i| and |v_i - ve_i| together (a position and a velocity against their expected
/// values); NaN when any difference is NaN.
template <class T, std::size_t N>
T max_abs_difference(const std::array<T, N>& x, const std::array<T, N>& xe, const std::array<T, N>& v,
                     const std::array<T, N>& ve) {
    const T dx = max_abs_difference(x, xe);
    const T dv = max_abs_difference(v, ve);
    return (dx != dx || dx > dv) ? dx : dv;
}

}  // namespace odestep_test

#endif
