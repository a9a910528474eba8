// SPDX-License-Identifier: BSL-1.0
// odestep: the one error channel.
#ifndef ODESTEP_STATUS_HPP
#define ODESTEP_STATUS_HPP

namespace odestep {

/// Every fallible call returns one of these. Whatever the value, the caller's state is the last good
/// one: a failed call either touched nothing (bad arguments) or rolled its step back (non-finite result).
// clang-format off
enum class [[nodiscard]] status : unsigned char {
    ok = 0,
    invalid_time,       ///< t0 or t1 is NaN or infinite, or a time of the run is not finite; nothing was touched
    invalid_step,       ///< dt is zero, NaN or infinite; nothing was touched
    wrong_direction,    ///< dt points away from t1; nothing was touched
    too_many_steps,     ///< (t1 - t0) / dt does not fit the step counter; nothing was touched
    non_finite,         ///< a step produced NaN or Inf (from the right-hand side or by overflow); it was rolled back
    no_convergence,     ///< an iteration did not meet its tolerance within its cap; rolled back
    step_mismatch,      ///< a step that does not continue the stepper's grid (a multistep history: another dt or
                        ///< t; a shortened step a uniform-step method cannot take); nothing was touched
    invalid_tolerance,  ///< a tolerance is zero, negative or NaN (for events: negative or not finite); nothing was touched
    stopped_by_event,   ///< a terminal event fired: the state is the integrator's own state at the event's time
    event_limit,        ///< more events fired in one step than the limit allows (a Zeno storm or chattering); the
                        ///< state is the one after the last event that did fire, at its time
    non_finite_event,   ///< an event function returned NaN or Inf; the state is the last one where all were finite
    singular_matrix,    ///< an implicit method's iteration matrix is singular or not finite; rolled back
    substep_limit,      ///< an adaptive step needed more internal steps than its cap; the state is back at the
                        ///< interval's start (integrate_adaptive, integrate_times: the attempt cap was reached
                        ///< first; the state is the last accepted one, at the returned time)
    step_too_small,     ///< an adaptive step size fell below what the time's precision resolves; rolled back
    invalid_setting,    ///< a setting other than a tolerance (a limit, a cap, a controller parameter) is out of
                        ///< its range; nothing was touched
    storage_full,       ///< caller-provided storage (an adaptive run's solution) is full; the state is the last
                        ///< accepted one, at the returned time, and the storage holds the run up to there
};
// clang-format on

/// A short English name for logs and test output; constant storage, no allocation.
constexpr const char* to_string(status s) noexcept {
    switch (s) {
        case status::ok: return "ok";
        case status::invalid_time: return "invalid_time";
        case status::invalid_step: return "invalid_step";
        case status::wrong_direction: return "wrong_direction";
        case status::too_many_steps: return "too_many_steps";
        case status::non_finite: return "non_finite";
        case status::no_convergence: return "no_convergence";
        case status::step_mismatch: return "step_mismatch";
        case status::invalid_tolerance: return "invalid_tolerance";
        case status::stopped_by_event: return "stopped_by_event";
        case status::event_limit: return "event_limit";
        case status::non_finite_event: return "non_finite_event";
        case status::singular_matrix: return "singular_matrix";
        case status::substep_limit: return "substep_limit";
        case status::step_too_small: return "step_too_small";
        case status::invalid_setting: return "invalid_setting";
        case status::storage_full: return "storage_full";
    }
    return "unknown";
}

}  // namespace odestep

#endif
