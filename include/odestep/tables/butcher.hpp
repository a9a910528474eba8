// odestep: the Butcher table type and the checks every table must pass at compile time.
#ifndef ODESTEP_TABLES_BUTCHER_HPP
#define ODESTEP_TABLES_BUTCHER_HPP

#include <array>
#include <cstddef>
#include <limits>

#include "../detail/ops.hpp"

namespace odestep {

/// An explicit Runge-Kutta method with S stages and E embedded weight vectors:
///
///     k_i     = f(t + c_i h, y + h * sum_{j<i} a_ij k_j)
///     y_{n+1} = y_n + h * sum_i b_i k_i                   (order `order`)
///     yhat_e  = y_n + h * sum_i bhat_e,i k_i              (order `embedded_order[e]`)
///
/// Only the strictly lower triangle of `a` is read. The stepper's error estimate for vector e is
/// y_{n+1} - yhat_e = h * sum_i (b_i - bhat_e,i) k_i.
template <class T, std::size_t S, std::size_t E = 0>
struct butcher_tableau {
    using value_type = T;
    static constexpr std::size_t stages = S;
    static constexpr std::size_t embedded = E;

    std::array<std::array<T, S>, S> a{};
    std::array<T, S> b{};
    std::array<T, S> c{};
    std::array<std::array<T, S>, E> bhat{};
    int order = 0;
    std::array<int, E> embedded_order{};
};

namespace detail {

// |sum - target| within a few rounding errors of the terms that made the sum: the coefficients are
// rounded to T, so exact equality is too strict and a fixed 1e-12 is wrong for float.
template <class T, std::size_t S>
constexpr bool sums_to(const std::array<T, S>& v, std::size_t count, T target) noexcept {
    T sum = T(0);
    T magnitude = abs_value(target);
    for (std::size_t j = 0; j < count; ++j) {
        sum += v[j];
        magnitude += abs_value(v[j]);
    }
    // The floor covers tables published only as decimals (DOP853 gives about 28 digits), which a 128-bit
    // long double resolves; it is far below the epsilon of float, double and x87 long double.
    const T unit = std::numeric_limits<T>::epsilon() > T(1e-26L) ? std::numeric_limits<T>::epsilon() : T(1e-26L);
    const T tolerance = T(4) * T(S + 1) * unit * magnitude;
    return abs_value(sum - target) <= tolerance;
}

}  // namespace detail

/// Row sums c_i = sum_j a_ij, the first node c_1 = 0 (explicit), and sum b = sum bhat_e = 1.
/// The full order conditions (rooted trees) are checked by the test suite.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_consistent(const butcher_tableau<T, S, E>& tab) noexcept {
    if (tab.c[0] != T(0)) return false;
    for (std::size_t i = 0; i < S; ++i) {
        for (std::size_t j = i; j < S; ++j)
            if (tab.a[i][j] != T(0)) return false;  // explicit: strictly lower triangular
        if (!detail::sums_to(tab.a[i], i, tab.c[i])) return false;
    }
    if (!detail::sums_to(tab.b, S, T(1))) return false;
    for (std::size_t e = 0; e < E; ++e)
        if (!detail::sums_to(tab.bhat[e], S, T(1))) return false;
    return tab.order >= 1;
}

}  // namespace odestep

#endif
