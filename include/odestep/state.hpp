// odestep: the state type and the few whole-state operations every stepper needs.
#ifndef ODESTEP_STATE_HPP
#define ODESTEP_STATE_HPP

#include <array>
#include <cstddef>
#include <type_traits>

namespace odestep {

/// The scalar types the library is written for.
template <class T>
inline constexpr bool is_scalar_v =
    std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>;

template <class State>
struct state_traits;  // only std::array<T, N> is a state

template <class T, std::size_t N>
struct state_traits<std::array<T, N>> {
    static_assert(is_scalar_v<T>, "odestep: a state is std::array<T, N> with T float, double or long double");
    static_assert(N > 0, "odestep: a state needs at least one component");
    using value_type = T;
    static constexpr std::size_t size = N;
};

template <class State>
using value_type_t = typename state_traits<State>::value_type;

// Loops over the components of a state are unrolled (fully, for up to 16 components) except where the
// build optimizes for size: there the loop is smaller, and flash is what counts.
#if defined(__OPTIMIZE_SIZE__) || !(defined(__GNUC__) || defined(__clang__))
#define ODESTEP_UNROLL
#else
#define ODESTEP_UNROLL _Pragma("GCC unroll 16")
#endif

namespace detail {

template <class T>
constexpr bool is_finite(T x) noexcept {
    // x * 0 is +-0 for every finite x and NaN for NaN or +-Inf (IEEE 754); works in constexpr, unlike
    // std::isfinite before C++23. Breaks under -ffinite-math-only (-ffast-math), which the README forbids.
    return x * T(0) == T(0);
}

/// True when every component is finite. The hot path is the plain sum of the components, finite
/// whenever they all are, unless it overflows; only then, or when a component is not finite, is the exact
/// per-component test run (x_i * 0 is zero exactly when x_i is finite).
template <class T, std::size_t N>
constexpr bool all_finite(const std::array<T, N>& y) noexcept {
    T sum = y[0];
    ODESTEP_UNROLL
    for (std::size_t n = 1; n < N; ++n) sum += y[n];
    if (sum - sum == T(0)) return true;  // NaN - NaN and Inf - Inf are NaN
    for (std::size_t n = 0; n < N; ++n)
        if (!is_finite(y[n])) return false;
    return true;  // finite components whose sum overflowed
}

}  // namespace detail
}  // namespace odestep

#endif
