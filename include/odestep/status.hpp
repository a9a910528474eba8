// odestep: the one error channel.
#ifndef ODESTEP_STATUS_HPP
#define ODESTEP_STATUS_HPP

namespace odestep {

/// Every fallible call returns one of these. Whatever the value, the caller's state is the last good
/// one: a failed call either touched nothing (bad arguments) or rolled its step back (non-finite result).
enum class [[nodiscard]] status : unsigned char{
    ok = 0,
    invalid_time,     ///< t0 or t1 is NaN or infinite; nothing was touched
    invalid_step,     ///< dt is zero, NaN or infinite; nothing was touched
    wrong_direction,  ///< dt points away from t1; nothing was touched
    too_many_steps,   ///< (t1 - t0) / dt does not fit the step counter (std::size_t); nothing was touched
    non_finite,       ///< a step produced NaN or Inf (from the right-hand side or by overflow); it was rolled back
    no_convergence,   ///< an iterated corrector did not meet its tolerance within its iteration cap; rolled back
    step_mismatch,  ///< a multistep method was asked for a dt, or a t, other than where its history ends; nothing touched
    invalid_tolerance,  ///< a tolerance is zero, negative or NaN (for events: negative or not finite); nothing was touched
    stopped_by_event,  ///< a terminal event fired: the state is the integrator's own state at the event's time
    event_limit,       ///< more events fired in one step than the limit allows (a Zeno storm or chattering); the
                       ///< state is the one after the last event that did fire, at its time
    non_finite_event,  ///< an event function returned NaN or Inf; the state is the last one where all were finite
};

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
    }
    return "unknown";
}

}  // namespace odestep

#endif
