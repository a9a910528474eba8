// SPDX-License-Identifier: BSL-1.0
// odestep: the one check before a run. Every driving loop (integrate, the event loops, the adaptive loops), the
// per-tick loop's start, the substep forms' step and the C API ask it before anything is evaluated or observed,
// so that a bad argument or a bad setting is refused the same way, with nothing touched, whichever loop runs.
#ifndef ODESTEP_DETAIL_PREFLIGHT_HPP
#define ODESTEP_DETAIL_PREFLIGHT_HPP

#include <type_traits>
#include <utility>

#include "../status.hpp"
#include "grid_clock.hpp"
#include "ops.hpp"

namespace odestep::detail {

/// A stepper with settings of its own (predictor_corrector's tolerance, the substep forms' tolerances and
/// cap) publishes `status settings_status() const`; a stepper without one has nothing to check.
template <class S, class = void>
struct has_settings_status : std::false_type {};
template <class S>
struct has_settings_status<S, std::void_t<decltype(std::declval<const S&>().settings_status())>> : std::true_type {};
template <class Stepper>
constexpr status check_settings(const Stepper& stepper) noexcept {
    if constexpr (has_settings_status<Stepper>::value) {
        return stepper.settings_status();
    } else {
        (void)stepper;
        return status::ok;
    }
}

/// A stepper with a history or a kept value (Adams, the staggered and first-same-as-last Newtonian methods)
/// has `reset()`: a loop calls it where a history must start afresh.
template <class S, class = void>
struct has_reset : std::false_type {};
template <class S>
struct has_reset<S, std::void_t<decltype(std::declval<S&>().reset())>> : std::true_type {};

template <class S>
constexpr void reset_if_any(S& s) noexcept {
    if constexpr (has_reset<S>::value) s.reset();
}

/// Before a run on a grid plan (integrate, integrate_n_steps, the event loops, the C API's loops), in this
/// order: the plan's own status (plan_run, plan_steps), a stepper that needs every step to be dt
/// (`uniform`: the stepper's uniform_steps, or the C method's, known at run time) against a shortened last
/// step (status::step_mismatch), then the stepper's settings.
template <class Stepper, class T>
constexpr status preflight(const Stepper& stepper, status planned, const grid_plan<T>& plan,
                           bool uniform = std::remove_reference_t<Stepper>::uniform_steps) noexcept {
    if (planned != status::ok) return planned;
    if (uniform && plan.uneven_last()) return status::step_mismatch;
    return check_settings(stepper);
}

/// Before a run on a clock of steps of dt from t (event_stepper::start) or before one interval [t, t + dt]
/// (the substep forms' step): t and dt as the grid clock checks them (check_step), then the settings.
template <class Stepper, class T>
ODESTEP_INLINE status preflight(const Stepper& stepper, T t, T dt) noexcept {
    const status s = check_step(t, dt);
    return s != status::ok ? s : check_settings(stepper);
}

/// Before a free-running run over [t0, t1] (integrate_adaptive, integrate_times, the stiff engines' loops):
/// the settings, a cap of at least one attempt (status::invalid_setting), then t0, t1 and t1 - t0 finite
/// (status::invalid_time).
template <class Engine, class T>
constexpr status preflight(const Engine& engine, T t0, T t1, step_count max_attempts) noexcept {
    const status s = check_settings(engine);
    if (s != status::ok) return s;
    if (max_attempts == 0) return status::invalid_setting;
    if (!is_finite(t0) || !is_finite(t1) || !is_finite(t1 - t0)) return status::invalid_time;
    return status::ok;
}

}  // namespace odestep::detail

#endif
