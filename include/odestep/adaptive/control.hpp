// SPDX-License-Identifier: BSL-1.0
// odestep: error control for the embedded Runge-Kutta pairs: tolerances, the scaled error norm, the PI
// step-size controller and the first-step estimate. Everything here is a pure function of its arguments or
// a small value type; the steppers in adaptive/ hold the controller's memory.
#ifndef ODESTEP_ADAPTIVE_CONTROL_HPP
#define ODESTEP_ADAPTIVE_CONTROL_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"

namespace odestep {

/// \brief Relative and absolute tolerances, one pair per component.
///
/// Component i of a step's error estimate is measured against
///     sc_i = atol_i + rtol_i max(|y_i(t)|, |y_i(t + h)|)
/// (Hairer, Norsett & Wanner, Solving ODE I, 2nd ed., Sec. II.4, eq. (4.10)). Built from two scalars (every
/// component the same) or from two arrays.
template <class State>
struct tolerances {
    using value_type = value_type_t<State>;  ///< the scalar T
    State rtol{};                            ///< relative tolerance per component, >= 0
    State atol{};                            ///< absolute tolerance per component, >= 0

    /// Every component: rtol = r, atol = a.
    static constexpr tolerances uniform(value_type r, value_type a) noexcept {
        tolerances t{};
        for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
            t.rtol[i] = r;
            t.atol[i] = a;
        }
        return t;
    }
    /// Per component.
    static constexpr tolerances per_component(const State& r, const State& a) noexcept { return tolerances{r, a}; }

    /// status::ok, or status::invalid_tolerance when a tolerance is negative, NaN or infinite, or a
    /// component has both zero (its error could never be measured).
    constexpr status check() const noexcept {
        for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
            const value_type r = rtol[i];
            const value_type a = atol[i];
            if (!detail::is_finite(r) || !detail::is_finite(a)) return status::invalid_tolerance;
            if (r < value_type(0) || a < value_type(0)) return status::invalid_tolerance;
            if (!(r > value_type(0) || a > value_type(0))) return status::invalid_tolerance;
        }
        return status::ok;
    }
};

/// The scaled RMS norm of an error estimate, sqrt((1/N) sum_i (err_i / sc_i)^2) with sc_i as in
/// odestep::tolerances (HNW I, Sec. II.4, eq. (4.11)). A step is acceptable when it is at most 1. NaN when
/// any term is not finite. Each term is divided before it is squared, so an error far below the tolerance
/// underflows harmlessly and one far above it overflows to Inf (rejected), never to NaN.
template <class State>
ODESTEP_INLINE value_type_t<State> scaled_error_norm(const State& err, const State& y_old, const State& y_new,
                                                     const tolerances<State>& tol) noexcept {
    using T = value_type_t<State>;
    constexpr std::size_t N = state_traits<State>::size;
    T sum = T(0);
    for (std::size_t i = 0; i < N; ++i) {
        const T sc =
            tol.atol[i] + tol.rtol[i] * detail::max_value(detail::abs_value(y_old[i]), detail::abs_value(y_new[i]));
        const T q = err[i] == T(0) ? T(0) : err[i] / sc;  // 0 / 0 where atol = 0 and y = 0: no error there
        sum += q * q;
    }
    return std::sqrt(sum / static_cast<T>(N));
}

/// The norm of HNW I's starting-step algorithm: sqrt((1/N) sum_i (v_i / sc_i)^2) with
/// sc_i = atol_i + rtol_i |y_i| (one state only).
template <class State>
value_type_t<State> scaled_norm(const State& v, const State& y, const tolerances<State>& tol) noexcept {
    return scaled_error_norm(v, y, y, tol);
}

/// \brief The step-size controller's settings.
///
/// After a step with error norm err (at most 1: accepted), the next step is
///     h_new = h * clamp(safety * err^(-alpha) * err_prev^(beta), min_factor, max_factor)
/// the PI controller of Gustafsson (1991, "Control-theoretic techniques for stepsize selection in explicit
/// Runge-Kutta methods", ACM TOMS 17(4), 533-554), in the form Hairer's DOPRI5 and DOP853 use ("stabilized
/// step size control", HNW I, Sec. II.4; HNW II, Sec. IV.2), err_prev the norm of the previous accepted
/// step. With k the order of the error estimate (the embedded order + 1), alpha = 0.7 / k and beta = 0.4 / k
/// are the gains HNW quote from Gustafsson; beta = 0 is the classical (integral only) controller
/// h err^(-1/k). After a rejection the step shrinks by safety * err^(-1/k) (at least min_factor) and the
/// next accepted step may not grow (Hairer's codes do the same), so a controller cannot oscillate between
/// rejections and large steps.
///
/// A zero alpha or beta means "the default for this method's k". Everything else is checked by check().
template <class T>
struct step_control {
    T safety = T(9) / T(10);     ///< in (0, 1]: aim this far below the tolerance
    T min_factor = T(1) / T(5);  ///< in (0, 1]: the most a step shrinks at once
    T max_factor = T(5);         ///< >= 1: the most a step grows at once
    T alpha = T(0);              ///< >= 0: the integral gain; 0 means 0.7 / k
    T beta = T(-1);              ///< the proportional gain, >= 0; negative means 0.4 / k
    T max_step = T(0);           ///< > 0: the largest |h|; 0 means no limit but the interval

    /// status::ok or status::invalid_setting.
    constexpr status check() const noexcept {
        const bool finite = detail::is_finite(safety) && detail::is_finite(min_factor) &&
                            detail::is_finite(max_factor) && detail::is_finite(alpha) && detail::is_finite(beta) &&
                            detail::is_finite(max_step);
        if (!finite) return status::invalid_setting;
        if (!(safety > T(0) && safety <= T(1))) return status::invalid_setting;
        if (!(min_factor > T(0) && min_factor <= T(1))) return status::invalid_setting;
        if (!(max_factor >= T(1))) return status::invalid_setting;
        if (alpha < T(0) || max_step < T(0)) return status::invalid_setting;
        return status::ok;
    }
};

/// The gains in use for a method whose error estimate has order k: (alpha, beta) from the settings, or the
/// defaults 0.7 / k and 0.4 / k.
template <class T>
struct pi_gains {
    T alpha;  ///< integral gain
    T beta;   ///< proportional gain
};

/// The gains of step_control s for an error estimate of order k.
template <class T>
constexpr pi_gains<T> gains_for(const step_control<T>& s, int k) noexcept {
    const T kk = static_cast<T>(k);
    return {s.alpha > T(0) ? s.alpha : T(7) / (T(10) * kk), s.beta >= T(0) ? s.beta : T(4) / (T(10) * kk)};
}

namespace detail {
/// The accepted step's PI factor from the natural logarithms of the two norms (err > 0):
///     safety exp(beta ln err_prev - alpha ln err) = safety err^(-alpha) err_prev^(beta)
/// within [min_factor, max_factor] and at most 1 after a rejection. One exp where the closed form takes two
/// pow (the engines keep ln err_prev from the step before, so a step takes one log and one exp). With the
/// default gains and k >= 2, wherever the factor is not clamped its two terms are at most 4 in magnitude
/// (|beta ln err_prev| <= 0.2 |ln 1e-4|, and alpha |ln err| is what keeps safety exp(...) within
/// [min_factor, max_factor]), so the exponent carries an absolute error of a few epsilon and the factor a
/// relative one of at most 16 epsilon against the closed form (tests/adaptive/adaptive_test.cpp checks it
/// over a sweep of both norms).
template <class T>
ODESTEP_INLINE T pi_factor(const step_control<T>& s, pi_gains<T> g, T log_err, T log_err_prev,
                           bool after_rejection) noexcept {
    using std::exp;
    // beta = 0 is the integral controller: err_prev plays no part (not even a zero one: 0 * -Inf is NaN).
    const T memory = g.beta != T(0) ? g.beta * log_err_prev : T(0);
    T f = s.safety * exp(memory - g.alpha * log_err);
    if (f > s.max_factor) f = s.max_factor;
    if (after_rejection && f > T(1)) f = T(1);
    return max_value(s.min_factor, f);
}

/// ln 1e-4, the floor of the previous accepted norm's logarithm (pi_memory::log_err_prev).
template <class T>
constexpr T log_err_floor() noexcept {
    return -T(9.21034037197618273607196581873745730L);
}
}  // namespace detail

/// The factor h_new / h after a step with error norm err (HNW's stabilized control, see step_control):
///   accepted (err <= 1): safety err^(-alpha) err_prev^(beta), within [min_factor, max_factor], and at most
///                        1 when the step before was rejected (computed as detail::pi_factor does, from
///                        logarithms: the closed form to within 16 epsilon, relative);
///   rejected (err > 1):  safety err^(-1/k), within [min_factor, 1).
/// err_prev is the previous accepted step's norm (at least 1e-4, as Hairer's codes keep it).
template <class T>
T step_factor(const step_control<T>& s, pi_gains<T> g, int k, T err, T err_prev, bool after_rejection) noexcept {
    using std::log;
    using std::pow;
    if (err > T(1)) {
        const T f = s.safety * pow(err, -T(1) / static_cast<T>(k));
        return detail::max_value(s.min_factor, f < T(1) ? f : T(9) / T(10));
    }
    // err = 0 (a polynomial the pair integrates exactly): the largest growth.
    if (!(err > T(0))) return after_rejection ? T(1) : s.max_factor;
    return detail::pi_factor(s, g, log(err), log(err_prev), after_rejection);
}

namespace detail {
/// The step-size quotient |h| / |h_new| of Hairer's stiff codes (radau5.f; odestep::radau5 and
/// odestep::sdirk_adaptive) after an attempt with error norm err and an estimate of order k:
/// err^(1/k) / fac, fac the safety lowered by the attempt's Newton iterations,
/// fac = min(safety, safety (1 + 2 cap) / (iterations + 2 cap)), within [1 / max_factor, 1 / min_factor].
template <class T>
T hairer_quotient(const step_control<T>& c, T err, int k, std::size_t iterations, std::size_t cap) noexcept {
    const T cfac = c.safety * static_cast<T>(1 + 2 * cap);
    const T lowered = cfac / static_cast<T>(iterations + 2 * cap);
    const T fac = lowered < c.safety ? lowered : c.safety;
    const T q = std::pow(err, T(1) / static_cast<T>(k)) / fac;
    const T lo = T(1) / c.max_factor;
    const T hi = T(1) / c.min_factor;
    return q < lo ? lo : (q > hi ? hi : q);
}

/// Gustafsson's predictive controller (Gustafsson 1994, BIT 34, 173-187; radau5.f's PRED) as a quotient
/// |h| / |h_new| after an accepted step of size h with error err, the previous accepted step having had
/// size h_prev and error err_prev: (h_prev / h) (err^2 / err_prev)^(1/k) / safety, within the same bounds
/// as hairer_quotient. The engines take the larger of the two quotients (the smaller step).
template <class T>
T gustafsson_quotient(const step_control<T>& c, T h, T err, T h_prev, T err_prev, int k) noexcept {
    const T q = (h_prev / h) * std::pow(err * err / err_prev, T(1) / static_cast<T>(k)) / c.safety;
    const T lo = T(1) / c.max_factor;
    const T hi = T(1) / c.min_factor;
    return q < lo ? lo : (q > hi ? hi : q);
}
}  // namespace detail

/// The first step's size by Hairer's algorithm (HNW I, Sec. II.4, "Starting step size"; the routine HINIT
/// of DOPRI5), for a method of order p from (t0, y0) with f0 = f(t0, y0) given; one more evaluation of f.
///   d0 = ||y0||, d1 = ||f0||;  h0 = 0.01 d0 / d1 (1e-6 when either is below 1e-5)
///   f1 = f(t0 + h0, y0 + h0 f0);  d2 = ||f1 - f0|| / h0
///   h1 = (0.01 / max(d1, d2))^(1 / (p + 1))  (max(1e-6, 1e-3 h0) when max(d1, d2) <= 1e-15)
///   h  = min(100 h0, h1, limit)
/// with ||.|| the scaled norm (scaled_norm). `limit` > 0 bounds it (the interval, a maximum step); the
/// result has the sign of `direction`. Returns 0 when f1 is not finite (the caller's non_finite).
template <class State, class System>
value_type_t<State> initial_step(System& f, value_type_t<State> t0, const State& y0, const State& f0, int p,
                                 const tolerances<State>& tol, value_type_t<State> limit,
                                 value_type_t<State> direction) {
    using T = value_type_t<State>;
    using std::pow;
    const T d0 = scaled_norm(y0, y0, tol);
    const T d1 = scaled_norm(f0, y0, tol);
    T h0 = (d0 < T(1e-5f) || d1 < T(1e-5f)) ? T(1e-6f) : T(1) / T(100) * (d0 / d1);
    if (limit > T(0) && h0 > limit) h0 = limit;
    const T s0 = direction < T(0) ? -h0 : h0;
    State y1 = detail::plus_scaled(y0, s0, f0);
    State f1;
    detail::evaluate(f, t0 + s0, static_cast<const State&>(y1), f1);
    if (!detail::all_finite(f1)) return T(0);
    State diff;
    for (std::size_t i = 0; i < state_traits<State>::size; ++i) diff[i] = f1[i] - f0[i];
    const T d2 = scaled_norm(diff, y0, tol) / h0;
    const T dmax = detail::max_value(d1, d2);
    const T h1 = dmax <= T(1e-15f) ? detail::max_value(T(1e-6f), h0 * T(1e-3f))
                                   : pow(T(1) / (T(100) * dmax), T(1) / static_cast<T>(p + 1));
    T h = h1 < T(100) * h0 ? h1 : T(100) * h0;
    if (limit > T(0) && h > limit) h = limit;
    return direction < T(0) ? -h : h;
}

namespace detail {
/// The time an engine stopped at, as a caller's grid gives it back: equal within a few rounding errors (the
/// grid's t0 + (i + 1) dt against the engine's t + dt differ by about an ULP), so a call on the next interval
/// continues with what the engine carries (f there is the kept value to that time perturbation, as any
/// stage's t + c h is).
template <class T>
bool same_point_time(T a, T b) noexcept {
    const T d = abs_value(a - b);
    return d <= T(4) * std::numeric_limits<T>::epsilon() * (abs_value(a) + abs_value(b));
}

// The memory of the Newton-based stiff engines (stiff/step_control.hpp).
template <class T>
struct stiff_step_control;

/// What every error-controlled engine carries from one attempt to the next for its step size: the |h| to try
/// next, whether the last attempt was rejected, the failed attempts in a row, and the rejections counted.
template <class T>
struct step_memory {
    T h = T(0);                  ///< |h| of the next attempt; 0: estimate it
    bool rejected_last = false;  ///< the last attempt was rejected
    std::size_t failures = 0;    ///< failed attempts (singular matrix, NaN or Inf) in a row
    step_count rejected = 0;     ///< rejected attempts since construction
    step_count accepted = 0;     ///< accepted steps since construction

    /// A rejected attempt of size step: the next one is |step| factor; step_too_small when that is 0.
    status shrink(T step, T factor) noexcept {
        ++rejected;
        rejected_last = true;
        h = abs_value(step) * factor;
        return h > T(0) ? status::ok : status::step_too_small;
    }
    /// A failed attempt: h halved. `failure` (singular_matrix, non_finite) is returned once it has happened
    /// max_failures times in a row; ok (an iteration that diverged or reached its cap) never ends the
    /// attempts by itself (the caller's attempt cap bounds them).
    status retry_smaller(T step, status failure, std::size_t max_failures) noexcept {
        if (failure != status::ok && ++failures >= max_failures) {
            failures = 0;
            (void)shrink(step, T(1) / T(2));
            return failure;
        }
        return shrink(step, T(1) / T(2));
    }
};

/// The PI controller's memory (step_control; adaptive_rk and rosenbrock_adaptive): step_memory and the
/// previous accepted error norm.
template <class T>
struct pi_memory : step_memory<T> {
    /// ln of the previous accepted step's norm, at least ln 1e-4 (the norm kept as its logarithm: the next
    /// step's factor then costs one log and one exp, detail::pi_factor)
    T log_err_prev = log_err_floor<T>();

    /// Forgets the step size and the controller's memory.
    void restart() noexcept {
        this->h = T(0);
        log_err_prev = log_err_floor<T>();
        this->rejected_last = false;
        this->failures = 0;
    }
    /// |h| step_factor after an accepted step (e <= 1) of size habs with error norm e (k the estimate's
    /// order); log_e receives what accept() keeps of e (ln e, or the floor for e = 0).
    ODESTEP_INLINE T next_step(const step_control<T>& c, int k, T habs, T e, T& log_e) const noexcept {
        using std::log;
        // e = 0 (a polynomial the pair integrates exactly): the largest growth, as step_factor.
        if (!(e > T(0))) {
            log_e = log_err_floor<T>();
            return habs * (this->rejected_last ? T(1) : c.max_factor);
        }
        log_e = log(e);
        return habs * pi_factor(c, gains_for(c, k), log_e, log_err_prev, this->rejected_last);
    }
    /// Rejected by the error test (e > 1): the next |h| shrunk by step_factor.
    ODESTEP_INLINE status reject_error(const step_control<T>& c, int k, T habs, T e) noexcept {
        // err_prev plays no part in a rejection's factor.
        return this->shrink(habs, step_factor(c, gains_for(c, k), k, e, T(1), this->rejected_last));
    }
    /// Accepted with error norm e (log_e from next_step), the next |h| `next` (this step's size when next
    /// underflowed to zero: a zero would send the next attempt back to the first-step estimate, one
    /// evaluation over the published bound).
    void accept(T next, T habs, T log_e) noexcept {
        this->h = next > T(0) ? next : habs;
        log_err_prev = max_value(log_e, log_err_floor<T>());
        this->rejected_last = false;
        this->failures = 0;
    }
};

/// The first step's |h| for an attempt from (t, y) with f0 = f(t, y) over the rest `rem` of the interval in
/// direction `dir` (initial_step for an estimate of order k, within rem and max_step); 0 when f at the
/// estimate's probe was not finite.
template <class State, class System, class T>
T first_step_size(System& f, T t, const State& y, const State& f0, int k, const tolerances<State>& tol,
                  const step_control<T>& c, T rem, T dir) {
    T limit = rem;
    if (c.max_step > T(0) && c.max_step < limit) limit = c.max_step;
    return abs_value(initial_step(f, t, y, f0, k - 1, tol, limit, dir));
}

/// The size of one attempt as every error-controlled engine plans it: `mag` the controller's |h| within
/// max_step; within 1% of the rest `rem` of the interval the step lands on its end (`last`, no sliver is
/// left) unless that would stretch it past max_step (`split`: the rest, at most 1.01 max_step, is more than
/// one step).
template <class T>
struct step_plan {
    T mag;       ///< |h| the controller asks for, within max_step
    bool last;   ///< the step lands on the interval's end
    bool split;  ///< near the end, but landing would exceed max_step
};

/// The plan for the controller's |h| `mag` and the rest `rem`.
template <class T>
step_plan<T> plan_step(const step_control<T>& c, T mag, T rem) noexcept {
    if (c.max_step > T(0) && mag > c.max_step) mag = c.max_step;
    const bool near_end = mag + mag / T(100) >= rem;
    const bool split = near_end && c.max_step > T(0) && rem > c.max_step;
    return {mag, near_end && !split, split};
}

/// The controller's step h below ten ULPs of t: the run cannot resolve it. (A step to the interval's end is
/// the caller's own, however short: an event's location re-steps to within ULPs of it.)
template <class T>
bool unresolved_step(T h, T t) noexcept {
    return !(abs_value(h) > T(10) * std::numeric_limits<T>::epsilon() * abs_value(t));
}
}  // namespace detail

/// \brief The settings every error-controlled engine has (odestep::adaptive_rk, odestep::rosenbrock_adaptive,
/// odestep::sdirk_adaptive, odestep::radau5): the tolerances, the controller's settings and the step size to
/// try next, with what the engine carries between attempts for its step size (the PI controller's memory,
/// or with `Newton` that of Hairer's stiff codes, radau5.f's).
///
/// `Engine` is the engine deriving from it; an engine that derives something from the tolerances (Radau's
/// transformed tolerances, Newton's) has it recomputed through its `tolerance_changed()` on set_tolerance.
template <class Engine, class State, bool Newton = false>
class engine_settings {
public:
    using value_type = value_type_t<State>;  ///< the scalar T

private:
    using T = value_type;
    using memory_type = std::conditional_t<Newton, detail::stiff_step_control<T>, detail::pi_memory<T>>;

public:
    /// status::invalid_tolerance, status::invalid_setting, or ok.
    status settings_status() const noexcept {
        const status s = tol_.check();
        return s != status::ok ? s : control_.check();
    }
    /// The tolerances, as given.
    const tolerances<State>& tolerance() const noexcept { return tol_; }
    /// The controller's settings.
    const step_control<T>& control() const noexcept { return control_; }
    /// Replaces the tolerances (checked by the next call).
    void set_tolerance(const tolerances<State>& tol) noexcept {
        tol_ = tol;
        static_cast<Engine&>(*this).tolerance_changed();
    }
    /// Replaces the controller's settings (checked by the next call).
    void set_control(const step_control<T>& control) noexcept { control_ = control; }
    /// |h| of the next attempt; 0 before the first (then odestep::initial_step chooses it).
    T step_size() const noexcept { return ctl_.h; }
    /// Sets |h| of the next attempt (0: estimate it); a negative or non-finite value is ignored.
    void set_step_size(T h) noexcept {
        if (detail::is_finite(h) && h >= T(0)) ctl_.h = h;
    }
    /// Accepted steps since construction.
    step_count accepted_steps() const noexcept { return ctl_.accepted; }
    /// Rejected attempts since construction.
    step_count rejected_steps() const noexcept { return ctl_.rejected; }

protected:
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    engine_settings(const tolerances<State>& tol, const step_control<T>& control) noexcept
        : tol_(tol), control_(control) {}
    /// Nothing derived from the tolerances.
    void tolerance_changed() noexcept {}

    tolerances<State> tol_;    ///< the tolerances
    step_control<T> control_;  ///< the controller's settings
    memory_type ctl_{};        ///< the step size and what the controller carries between attempts
};

}  // namespace odestep

#endif
