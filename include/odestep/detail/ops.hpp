// SPDX-License-Identifier: BSL-1.0
// odestep: the whole-state operations every stepper is made of (finiteness, absolute value, assignment,
// scaled sums), written once.
#ifndef ODESTEP_DETAIL_OPS_HPP
#define ODESTEP_DETAIL_OPS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../config.hpp"

namespace odestep::detail {

template <class T>
constexpr bool is_finite(T x) noexcept {
    // x * 0 is +-0 for every finite x and NaN for NaN or +-Inf (IEEE 754); works in constexpr, unlike
    // std::isfinite before C++23. Breaks under -ffinite-math-only (-ffast-math), which the README forbids.
    return x * T(0) == T(0);
}

/// |x|. With the compiler's builtin it is one instruction (a sign-bit mask) and a constant expression;
/// the fallback x < 0 ? -x : x keeps the sign of -0, which no sum of magnitudes or comparison can see.
template <class T>
constexpr T abs_value(T x) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    if constexpr (std::is_same_v<T, float>) {
        return __builtin_fabsf(x);
    } else if constexpr (std::is_same_v<T, double>) {
        return __builtin_fabs(x);
    } else if constexpr (std::is_same_v<T, long double>) {
        return __builtin_fabsl(x);
    } else {
        return x < T(0) ? -x : x;
    }
#else
    return x < T(0) ? -x : x;
#endif
}

template <class T>
constexpr T max_value(T a, T b) noexcept {
    return a < b ? b : a;
}

/// The fast half of the finiteness test, for a plain sum of values: sum - sum is +0 when the sum is finite
/// and NaN when it is NaN or +-Inf (Inf - Inf is NaN), and only NaN compares unequal to itself. A sum of
/// finite values is finite unless it overflows, so `true` proves every term finite, and `false` means
/// that a term is not finite or that the sum overflowed (then ask each_finite).
template <class T>
constexpr bool finite_sum(T sum) noexcept {
    const T d = sum - sum;
    return d == d;  // one compare and one branch on unordered; no zero constant
}

/// total += every component of v, for the finiteness test's sum of a step (finite_sum): in lanes, component
/// n into lane n % lanes and the lanes added into total at the end, so that the additions of one pass are
/// independent and vectorize (one serial sum is a chain of dependent additions, which the compiler must
/// keep in order). 32 bytes of lanes, one AVX register: for float always, for double where AVX is enabled
/// (x86-64 without it, GCC 12 -O2: the serial double sum is cheaper at N >= 64; docs/performance.md,
/// "Large states"). Only for states of at least four passes of lanes (double with AVX at N = 8 took an
/// instruction or three more); a smaller state, or another T, sums serially, component 0 first. The one
/// lane sum of the library: explicit_rk and the splitting methods use it.
template <class T, std::size_t N>
ODESTEP_INLINE void add_in_lanes(T& total, const std::array<T, N>& v) noexcept {
#if defined(__AVX__)
    constexpr bool wide_vectors = true;
#else
    constexpr bool wide_vectors = false;
#endif
    constexpr std::size_t lanes = sizeof(T) == 4 || (sizeof(T) == 8 && wide_vectors) ? 32 / sizeof(T) : 1;
    if constexpr (N >= 4 * lanes && lanes > 1) {
        std::array<T, lanes> lane;
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t l = 0; l < lanes; ++l) lane[l] = v[l];
        constexpr std::size_t whole = N / lanes * lanes;
        for (std::size_t n = lanes; n < whole; n += lanes) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t l = 0; l < lanes; ++l) lane[l] += v[n + l];
        }
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = whole; n < N; ++n) total += v[n];
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t l = 0; l < lanes; ++l) total += lane[l];
    } else {
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) total += v[n];
    }
}

/// The exact test, component by component. Always inlined: it is the slow path after a failed
/// finite_sum, and as a call (at -Os) it made every value live across it spill to the stack on the hot
/// path too.
///   - Otherwise -largest <= y_i <= largest, false for +-Inf and NaN: comparisons, which overwrite no
///     register, so the values the step is about to store need no copies kept for this path.
///   - Optimizing for size, the sum of y_i * 0 (+-0 exactly when y_i is finite, NaN otherwise) in a loop
///     without a branch, the smallest form.
template <class T, std::size_t N>
ODESTEP_INLINE constexpr bool each_finite(const std::array<T, N>& y) noexcept {
    if constexpr (optimizing_for_size) {
        T zeros = T(0);
        for (std::size_t n = 0; n < N; ++n) zeros += y[n] * T(0);
        return zeros == T(0);
    } else {
        constexpr T largest = std::numeric_limits<T>::max();
        for (std::size_t n = 0; n < N; ++n)
            if (!(y[n] >= -largest && y[n] <= largest)) return false;
        return true;
    }
}

/// sum += every component of y (or y itself, a scalar that belongs to the test).
template <class T, std::size_t N>
ODESTEP_INLINE constexpr void add_components(T& sum, const std::array<T, N>& y) noexcept {
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t n = 0; n < N; ++n) sum += y[n];
}
template <class T>
ODESTEP_INLINE constexpr void add_components(T& sum, T y) noexcept {
    sum += y;
}
template <class T>
ODESTEP_INLINE constexpr bool each_finite(T y) noexcept {
    return is_finite(y);
}

/// True when every component of every array given (and every scalar given after the first array) is finite.
/// The hot path is one plain sum of all the components (finite_sum): one compare and one branch however many
/// values; only when that fails, because a component is not finite or because the sum overflowed, is the
/// exact test run. Always inlined, like each_finite: GCC at -Os keeps a function called from two places out
/// of line, and then every value live across the call spills.
template <class T, std::size_t N, class... More>
ODESTEP_INLINE constexpr bool all_finite(const std::array<T, N>& y, const More&... more) noexcept {
    T sum = y[0];
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t n = 1; n < N; ++n) sum += y[n];
    (add_components(sum, more), ...);
    return finite_sum(sum) || (each_finite(y) && (each_finite(more) && ...));
}

/// The fast finiteness test of a step under its check policy (odestep::checked, odestep::unchecked), the one
/// place where the policy acts: finite_sum(total) for a policy that checks (total: the plain sum of every
/// value the step tests; the step runs the exact test, each_finite, only when this fails), the constant
/// true for one that does not, which makes the step's `!finite_sum_under(total) && !exact` false at compile
/// time: no sum, no exact test, and the results written where they go, with no copy kept for a roll-back
/// (the same arithmetic otherwise: a finite run gives the same state, bit for bit unless the compiler fuses
/// different products into multiply-adds in the two forms).
template <class Check, class T>
ODESTEP_INLINE constexpr bool finite_sum_under([[maybe_unused]] T total) noexcept {
    if constexpr (Check::checks_finiteness) {
        return finite_sum(total);
    } else {
        return true;
    }
}

/// all_finite under a check policy: all_finite for a policy that checks, true for one that does not.
template <class Check, class T, std::size_t N, class... More>
ODESTEP_INLINE constexpr bool all_finite_under([[maybe_unused]] const std::array<T, N>& y,
                                               [[maybe_unused]] const More&... more) noexcept {
    if constexpr (Check::checks_finiteness) {
        return all_finite(y, more...);
    } else {
        return true;
    }
}

/// Where a step computes a result: the caller's object itself (InPlace: an unchecked step, nothing to roll
/// back), or the step's local, copied to the caller's after the finiteness test.
template <bool InPlace, class State>
ODESTEP_INLINE constexpr State& result_target(State& local, State& caller) noexcept {
    if constexpr (InPlace) {
        return caller;
    } else {
        return local;
    }
}

/// How assign copies a state: component by component, so that values still in registers go straight to
/// memory (the default); or, where the build optimizes for size and the state has more than two components,
/// as one block, the fewest and shortest instructions for a state built in memory (explicit_rk's new
/// state). Which is smaller depends on where the values are, so each caller says which it has (measured:
/// explicit_rk's RK4 on Cortex-M4F is smallest with the block, Adams' history with the components).
enum class copy_form { components, block_at_size };

/// to = from, in the form given.
template <copy_form Form = copy_form::components, class T, std::size_t N>
ODESTEP_INLINE constexpr void assign(std::array<T, N>& to, const std::array<T, N>& from) noexcept {
    if constexpr (Form == copy_form::block_at_size && optimizing_for_size && N > 2) {
        to = from;
    } else {
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t n = 0; n < N; ++n) to[n] = from[n];
    }
}

/// x + c v, component by component (c a scalar): a drift, a kick, an Euler step.
template <class T, std::size_t N>
constexpr std::array<T, N> plus_scaled(const std::array<T, N>& x, T c, const std::array<T, N>& v) noexcept {
    std::array<T, N> out;
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t n = 0; n < N; ++n) out[n] = x[n] + c * v[n];
    return out;
}

/// The same state bit for bit as == and the sign tell (+0 and -0 differ; NaN equals nothing): a state the
/// observer has already seen, or another one.
template <class T, std::size_t N>
constexpr bool same_bits(const std::array<T, N>& a, const std::array<T, N>& b) noexcept {
    for (std::size_t n = 0; n < N; ++n)
        if (!(a[n] == b[n]) || std::signbit(a[n]) != std::signbit(b[n])) return false;
    return true;
}

/// The same values, bit for bit where they are numbers (NaN equals nothing).
template <class T, std::size_t N>
ODESTEP_INLINE constexpr bool same_values(const std::array<T, N>& a, const std::array<T, N>& b) noexcept {
    for (std::size_t n = 0; n < N; ++n)
        if (!(a[n] == b[n])) return false;
    return true;
}

}  // namespace odestep::detail

#endif
