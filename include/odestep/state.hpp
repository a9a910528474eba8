// odestep: the state type and the few whole-state operations every stepper needs.
#ifndef ODESTEP_STATE_HPP
#define ODESTEP_STATE_HPP

#include <array>
#include <limits>
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

// The stepper's per-component arithmetic is written as small functions over the table (one per weight row,
// class of terms, ...); they are expression fragments, meant to be inlined where they are used whatever
// the optimization level (at -Os a fragment used twice could otherwise stay a call inside the loop).
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_INLINE [[gnu::always_inline]] inline
#else
#define ODESTEP_INLINE inline
#endif

// A rare path (a multistep method's start, the event loop's crossings) kept out of line, so that the
// common step's frame and registers hold only what it needs.
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_NOINLINE [[gnu::noinline]]
#elif defined(_MSC_VER)
#define ODESTEP_NOINLINE __declspec(noinline)
#else
#define ODESTEP_NOINLINE
#endif

// The non-finite path of a step is the rare one: the compiler lays it out of line, so that the ordinary
// path runs straight through.
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_UNLIKELY(condition) __builtin_expect(static_cast<bool>(condition), 0)
#else
#define ODESTEP_UNLIKELY(condition) (condition)
#endif

namespace detail {
/// True where the build optimizes for size (-Os, -Oz): the loops over the components stay loops there,
/// and a few choices between two equivalent forms of a computation follow (the step's finiteness sum).
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool optimizing_for_size = true;
#else
inline constexpr bool optimizing_for_size = false;
#endif
}  // namespace detail

namespace detail {

template <class T>
constexpr bool is_finite(T x) noexcept {
    // x * 0 is +-0 for every finite x and NaN for NaN or +-Inf (IEEE 754); works in constexpr, unlike
    // std::isfinite before C++23. Breaks under -ffinite-math-only (-ffast-math), which the README forbids.
    return x * T(0) == T(0);
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

/// The exact test, component by component. Always inlined: it is the slow path after a failed
/// finite_sum, and as a call (at -Os) it made every value live across it spill to the stack on the hot
/// path too (velocity Verlet on x86-64 -Os: 111 instructions per step as a call, 95 inlined).
///   - Otherwise -largest <= y_i <= largest, false for +-Inf and NaN: comparisons, which overwrite no
///     register, so the values the step is about to store need no copies kept for this path (x86-64
///     -O2: 2 fewer instructions per step on the float oscillator's RK4).
///   - Optimizing for size, the sum of y_i * 0 (+-0 exactly when y_i is finite, NaN otherwise) in a loop
///     without a branch, the smallest form (M4F float RK4: 348 bytes of flash, 368 with the call).
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

template <class T, std::size_t N>
ODESTEP_INLINE constexpr void add_components(T& sum, const std::array<T, N>& y) noexcept {
    ODESTEP_UNROLL
    for (std::size_t n = 0; n < N; ++n) sum += y[n];
}

/// True when every component of every array given is finite. The hot path is one plain sum of all the
/// components (finite_sum): one compare and one branch however many arrays; only when that fails,
/// because a component is not finite or because the sum overflowed, is the exact test run. Always inlined,
/// like each_finite: GCC at -Os keeps a function called from two places out of line, and then every value
/// live across the call spills (Beeman's two forms on x86-64 -Os: 149 instructions per step as a call, 128
/// inlined).
template <class T, std::size_t N, class... More>
ODESTEP_INLINE constexpr bool all_finite(const std::array<T, N>& y, const More&... more) noexcept {
    T sum = y[0];
    ODESTEP_UNROLL
    for (std::size_t n = 1; n < N; ++n) sum += y[n];
    (add_components(sum, more), ...);
    return finite_sum(sum) || (each_finite(y) && (each_finite(more) && ...));
}


// |x| as one instruction (a sign-bit mask) where the compiler has the builtin; abs_value's x < 0 ? -x : x
// keeps the sign of -0 and so compiles to a compare and a blend or a branch. The two differ only in the
// sign of a zero, which no sum of magnitudes or comparison below can see.
template <class T>
constexpr T magnitude(T x) noexcept {
#if defined(__GNUC__) || defined(__clang__)
    if constexpr (std::is_same_v<T, float>) {
        return __builtin_fabsf(x);
    } else if constexpr (std::is_same_v<T, double>) {
        return __builtin_fabs(x);
    } else {
        return __builtin_fabsl(x);
    }
#else
    return abs_value(x);
#endif
}

// Where a history-keeping stepper expects its next step: the time (within a few ULPs of the run's times:
// integrate computes t0 + i dt from its counter, the stepper t + dt, and far from zero the two differ by
// more than an ULP of dt), the same dt, and the same position object. Anything else, a non-finite t
// included, means someone else's state or a new grid, and the stepper starts afresh.
//
// "Within a few ULPs" is |t_now - t| <= 8 eps (|t| + |dt| + |t_start|). The common case, a caller whose
// time is exactly the t + dt the stepper computed (t += dt, or the counter's time when it rounds the same
// way), is one comparison: expect() stores t only when it is finite (NaN otherwise, which equals nothing),
// so t_now == t proves t_now finite, and |t_now - t| = 0 is within any allowance. Only the other times
// compute the allowance; one that is not finite (the sum overflowing) is taken as NaN, which accepts
// nothing, and with a finite allowance and a finite t a non-finite t_now fails the comparison by itself.
template <class State, class T = value_type_t<State>>
struct continuation {
    T t = T(0);        // the time the next step is expected at; NaN when that was not finite
    T dt = T(0);
    T t_start = T(0);  // where this history began: the counter's times are t_start + i dt
    const State* x = nullptr;

    /// The same position object at the expected time, whatever the dt (what a kept acceleration a(t, x)
    /// needs: it does not depend on the next step's size).
    constexpr bool at(T t_now, const State& x_now) const noexcept {
        return x == &x_now && (t_now == t || near(t_now));
    }
    /// ... and the same dt (what a history on a grid needs).
    constexpr bool matches(T t_now, T dt_now, const State& x_now) const noexcept {
        return dt == dt_now && at(t_now, x_now);
    }
    /// The same dt at the expected time, whatever the state object (a history the caller vouches for: the
    /// Adams methods, which say step_mismatch rather than restart). After expect() only.
    constexpr bool on_grid(T t_now, T dt_now) const noexcept { return dt == dt_now && (t_now == t || near(t_now)); }
    /// After a step from t_now by dt_now on x_now: the next is expected at t_now + dt_now. `continued` is
    /// the caller's answer before the step (matches() for a history on a grid, at() for a value of x alone,
    /// a(t, x), which does not depend on dt), which nothing has changed since. A step that did not continue
    /// starts a fresh history here; one that did keeps its t_start, the time the allowance is measured from
    /// (for an at() caller whatever the dt: a new dt can only make the allowance smaller than the rounding
    /// of a counter restarted at the change, and a miss costs an evaluation, never a wrong value).
    constexpr void expect(T t_now, T dt_now, const State& x_now, bool continued) noexcept {
        if (!continued) {
            t_start = t_now;
            x = &x_now;
        }
        const T next = t_now + dt_now;
        t = next - next + next;  // next when finite (a zero's sign aside); Inf - Inf is NaN
        dt = dt_now;
    }
    constexpr void clear() noexcept { x = nullptr; }

private:
    // t_now within the allowance of t (which is finite or NaN).
    constexpr bool near(T t_now) const noexcept {
        const T s = T(8) * std::numeric_limits<T>::epsilon() * (magnitude(t) + magnitude(dt) + magnitude(t_start));
        return magnitude(t_now - t) <= s - s + s;  // s when finite; Inf - Inf is NaN
    }
};

}  // namespace detail
}  // namespace odestep

#endif
