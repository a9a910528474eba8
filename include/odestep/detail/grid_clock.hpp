// SPDX-License-Identifier: BSL-1.0
// odestep: the grid clock, the one place where the times of a fixed-step run come from.
#ifndef ODESTEP_DETAIL_GRID_CLOCK_HPP
#define ODESTEP_DETAIL_GRID_CLOCK_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../status.hpp"
#include "ops.hpp"

namespace odestep {

/// The step counter of every driving loop: 64 bits on every target (a 32-bit count of 1 kHz ticks wraps
/// after 49.7 days).
using step_count = std::uint64_t;

namespace detail {

/// A step count as T, converted as two 32-bit halves: while the high half is zero (the first 2^32 steps)
/// the result is the low half's conversion, one instruction on a 32-bit core; after, hi 2^32 + lo, within
/// one rounding of the exact value.
template <class T>
ODESTEP_INLINE constexpr T count_halves(step_count n) noexcept {
    const auto lo = static_cast<std::uint32_t>(n);
    const auto hi = static_cast<std::uint32_t>(n >> 32);
    if (ODESTEP_UNLIKELY(hi != 0)) return static_cast<T>(hi) * T(4294967296.0L) + static_cast<T>(lo);  // 2^32
    return static_cast<T>(lo);
}

/// A step count as T, for t0 + n dt. Where std::size_t has 64 bits this is the one conversion; on a 32-bit
/// target a 64-bit integer to floating-point conversion is a library call, so there it is count_halves.
template <class T>
ODESTEP_INLINE constexpr T count_value(step_count n) noexcept {
    if constexpr (sizeof(std::size_t) >= sizeof(step_count)) {
        return static_cast<T>(n);
    } else {
        return count_halves<T>(n);
    }
}

/// The whole part of a T in [0, 2^62) as a step count, converted as two 32-bit halves: the high half is
/// trunc(x / 2^32), and x - hi 2^32 is exact (both are multiples of x's ULP once x >= 2^32) and below 2^32.
template <class T>
ODESTEP_INLINE constexpr step_count count_of_halves(T x) noexcept {
    constexpr T two32 = T(4294967296.0L);  // 2^32
    if (ODESTEP_UNLIKELY(!(x < two32))) {
        const auto hi = static_cast<std::uint32_t>(x / two32);
        const auto lo = static_cast<std::uint32_t>(x - static_cast<T>(hi) * two32);
        return (static_cast<step_count>(hi) << 32) + lo;
    }
    return static_cast<std::uint32_t>(x);
}

/// The whole part of a T in [0, 2^62) as a step count. Where std::size_t has fewer than 64 bits a T to 64-bit
/// integer conversion is a library call, and libgcc's for float (__fixunssfdi) converts to double first,
/// which would put double arithmetic in a float program: there it is count_of_halves.
template <class T>
ODESTEP_INLINE constexpr step_count count_of(T x) noexcept {
    if constexpr (sizeof(std::size_t) >= sizeof(step_count)) {
        return static_cast<step_count>(x);
    } else {
        return count_of_halves(x);
    }
}

/// THE check of a step's time and size, for every loop and the C API: t finite (else status::invalid_time), dt
/// finite and not zero (else status::invalid_step). The common case is two tests: (t - t) + (dt - dt) is +0
/// when both are finite and NaN otherwise (IEEE 754: Inf - Inf is NaN), and only NaN compares unequal to
/// itself; then dt is not +-0, for IEEE float and double one integer test of dt's bits without the sign.
template <class T>
ODESTEP_INLINE status check_step(T t, T dt) noexcept {
    const T d = (t - t) + (dt - dt);
    bool zero = false;
    if constexpr (std::numeric_limits<T>::is_iec559 && (sizeof(T) == 4 || sizeof(T) == 8)) {
        using bits_t = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
        bits_t dt_bits;
        std::memcpy(&dt_bits, &dt, sizeof dt_bits);
        zero = static_cast<bits_t>(dt_bits << 1) == 0;
    } else {
        zero = dt == T(0);
    }
    if (ODESTEP_UNLIKELY(!(d == d)) || ODESTEP_UNLIKELY(zero)) {
        if (!is_finite(t)) return status::invalid_time;
        return status::invalid_step;
    }
    return status::ok;
}

/// The times of a fixed-step run: t_n = t0 + n dt, computed from the integer n every time and never as a
/// running sum (in float, t += 1e-3 reaches 991.14 instead of 1000 after 10^6 steps).
template <class T>
struct grid_clock {
    T t0 = T(0);
    T dt = T(0);

    /// t0 + n dt.
    ODESTEP_INLINE constexpr T time(step_count n) const noexcept { return t0 + count_value<T>(n) * dt; }

    /// t0 finite, dt finite and not zero (check_step).
    status check() const noexcept { return check_step(t0, dt); }
};

/// How far the computed grid times may be from the exact t0 + n dt near [t0, t1]: each is rounded in the
/// product n dt and in the sum, about one ULP of the larger of |t0| and |t1| in all, so 2 eps (|t0| + |t1|)
/// covers them. Two times of the run closer than this are the same time to the grid. Computed as
/// 2 eps |t0| + 2 eps |t1|, each term finite, so that it is finite for every finite t0 and t1 (as
/// 2 eps (|t0| + |t1|) it overflowed to Inf near the top of the range, and the plan then counted grid
/// times past t1, out to Inf).
template <class T>
constexpr T grid_rounding(T t0, T t1) noexcept {
    constexpr T c = T(2) * std::numeric_limits<T>::epsilon();
    return c * abs_value(t0) + c * abs_value(t1);
}

/// A fixed-step run: its clock, how many steps, and the last step, which ends exactly on t_end.
template <class T>
struct grid_plan {
    grid_clock<T> clock{};
    step_count steps = 0;
    T t_end = T(0);   ///< where the last step ends: t1 for a run over [t0, t1], t0 + n dt for n steps
    T h_last = T(0);  ///< the last step's size: t_end - t_{n-1}, or dt where they differ only by rounding

    /// The size of step i (from 0), and the time it ends at.
    ODESTEP_INLINE constexpr T step_size(step_count i) const noexcept { return i + 1 == steps ? h_last : clock.dt; }
    ODESTEP_INLINE constexpr T end_of(step_count i) const noexcept {
        return i + 1 == steps ? t_end : clock.time(i + 1);
    }
    /// The last step is genuinely shorter (or longer) than dt, not dt to rounding.
    constexpr bool uneven_last() const noexcept { return steps > 0 && !(h_last == clock.dt); }
};

/// Plans a run over [t0, t1] with steps of dt. The steps are t0 + n dt for n = 0 .. steps - 1 and the last
/// one ends exactly on t1. Their number is the n for which t0 + n dt reaches t1 to within the grid's
/// rounding (then the last step is dt, to rounding), or else one more than the whole steps that fit
/// (then the last step is shortened to end on t1): no step is longer than dt by more than the grid's
/// rounding, and none is a sliver. Bad arguments give their status and an empty plan.
template <class T>
status plan_run(T t0, T t1, T dt, grid_plan<T>& plan) noexcept {
    plan = grid_plan<T>{grid_clock<T>{t0, dt}, 0, t0, dt};
    if (!is_finite(t1) || !is_finite(t1 - t0)) return status::invalid_time;  // a NaN or Inf t0 too
    const status checked = check_step(t0, dt);
    if (checked != status::ok) return checked;
    const T span = t1 - t0;
    if (span == T(0)) {  // no step; the run still ends on t1 itself (from -0.0 to +0.0: +0.0)
        plan.t_end = t1;
        return status::ok;
    }
    // The signs, not the quotient: span / dt can underflow to -0 or +0.
    if ((span > T(0)) != (dt > T(0))) return status::wrong_direction;
    const T ratio = span / dt;  // > 0, or +0 after an underflow
    // Past 2^62 steps the counter's conversion and the grid itself lose whole steps; no run gets there.
    constexpr T most = T(4611686018427387904.0L);  // 2^62
    if (!(ratio < most)) return status::too_many_steps;
    const grid_clock<T> clock{t0, dt};
    const T rounding = grid_rounding(t0, t1);
    // How far t_n lies beyond t1, in the direction of the run (negative: not there yet).
    const auto beyond = [&](step_count n) {
        const T tn = clock.time(n);
        return dt > T(0) ? tn - t1 : t1 - tn;
    };
    // The quotient is rounded, and so is each t_n: move n to the last grid time that is not past t1 by
    // more than the rounding. Each correction is at most a step or two where the grid resolves dt; the
    // caps keep the loops bounded where it does not (there any n is right to the grid's rounding).
    step_count n = count_of(ratio);
    for (int k = 0; k < 4 && n > 0 && beyond(n) > rounding; ++k) --n;
    for (int k = 0; k < 4 && !(beyond(n + 1) > rounding); ++k) ++n;
    // t_n reaches t1 to the grid's rounding: n steps, the last one dt; otherwise one more, shortened.
    const bool reaches = n > 0 && !(-beyond(n) > rounding);
    step_count steps = reaches ? n : n + 1;
    // Where dt is below the grid's rounding (a few ULPs of t), grid times before t_n can lie on or past t1
    // too, and the last step would go back to t1 (or stay there). The last step then starts at the last grid
    // time before t1: t_m with beyond(m) < 0 (t_0 is one), found by bisection (the grid times are monotone
    // in m), so that the times of the run are monotone and the last step, t1 - t_m, is no longer than dt.
    // Where the grid resolves dt, t_{steps-1} is before t1 by about dt and this costs one comparison.
    if (!(beyond(steps - 1) < T(0))) {
        step_count lo = 0;          // beyond(lo) < 0
        step_count hi = steps - 1;  // beyond(hi) >= 0
        while (hi - lo > 1) {
            const step_count mid = lo + (hi - lo) / 2;
            (beyond(mid) < T(0) ? lo : hi) = mid;
        }
        steps = lo + 1;
    }
    plan.steps = steps;
    plan.t_end = t1;
    const T h = t1 - clock.time(plan.steps - 1);
    plan.h_last = abs_value(h - dt) <= rounding ? dt : h;
    return status::ok;
}

/// Plans exactly n steps of dt from t0, ending on t0 + n dt. Every time of the run must be finite
/// (status::invalid_time otherwise: t0 + n dt overflows).
template <class T>
status plan_steps(T t0, T dt, step_count n, grid_plan<T>& plan) noexcept {
    plan = grid_plan<T>{grid_clock<T>{t0, dt}, 0, t0, dt};
    const status s = plan.clock.check();
    if (s != status::ok) return s;
    // t_n is the time farthest from t0 (the times are monotone in n, and the product n dt is the largest
    // term), so a finite t_n makes every time of the run finite.
    const T end = plan.clock.time(n);
    if (!is_finite(end)) return status::invalid_time;
    plan.steps = n;
    plan.t_end = end;
    return status::ok;
}

}  // namespace detail
}  // namespace odestep

#endif
