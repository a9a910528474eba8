// SPDX-License-Identifier: BSL-1.0
// odestep: the free-running loops for the error-controlled stiff engines (Radau 5(4), the Rosenbrock and SDIRK
// pairs): integrate_adaptive (every accepted step observed) and integrate_times (the state at the caller's times,
// from Radau's collocation polynomial or the pairs' cubic Hermite interpolant), the same names and contracts as
// the explicit pairs' loops (adaptive/integrate_adaptive.hpp).
#ifndef ODESTEP_STIFF_INTEGRATE_HPP
#define ODESTEP_STIFF_INTEGRATE_HPP

#include <cstddef>
#include <type_traits>

#include "../adaptive/integrate_adaptive.hpp"
#include "../detail/ops.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "radau5.hpp"
#include "rosenbrock_adaptive.hpp"
#include "sdirk_adaptive.hpp"

namespace odestep {

/// Integrates y' = f(t, y) from t0 to exactly t1 with the error-controlled Radau IIA 5 steps of `engine`
/// (odestep::radau5: its tolerances, controller, and what it carries), and calls observe(t, y) with the
/// initial state and after every accepted step. The result's `steps` counts the accepted steps.
///
/// Work is bounded: at most `max_attempts` attempts, hence at most 1 + radau5::rhs_evals_to_start +
/// max_attempts * radau5::rhs_evals_per_attempt evaluations of f. Statuses, with y always the last accepted
/// state at the returned t: invalid_tolerance / invalid_setting (settings, or max_attempts = 0) and
/// invalid_time (t0 or t1 not finite), nothing evaluated or observed; non_finite, singular_matrix,
/// step_too_small (see odestep::radau5); substep_limit (max_attempts reached before t1).
template <class State, class System, class Observer,
          std::enable_if_t<!std::is_arithmetic_v<std::decay_t<Observer>> && !detail::is_event_set_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(radau5<State>& engine, System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1, Observer&& observe,
                                                                       step_count max_attempts = default_max_attempts) {
    return detail::free_running(engine, f, y, t0, t1, observe, max_attempts);
}

/// integrate_adaptive with the Radau IIA 5 engine, without an observer.
template <class State, class System>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(radau5<State>& engine, System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1,
                                                                       step_count max_attempts = default_max_attempts) {
    detail::no_observer none;
    return integrate_adaptive(engine, f, y, t0, t1, none, max_attempts);
}

/// integrate_adaptive with a Rosenbrock pair (odestep::rosenbrock_adaptive): the same contract as with the
/// Radau IIA 5 engine, at most rhs_evals_to_start + max_attempts * rhs_evals_per_attempt evaluations of f.
template <class Method, class State, class System, class Observer,
          std::enable_if_t<!std::is_arithmetic_v<std::decay_t<Observer>> && !detail::is_event_set_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(rosenbrock_adaptive<Method, State>& engine,
                                                                       System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1, Observer&& observe,
                                                                       step_count max_attempts = default_max_attempts) {
    return detail::free_running(engine, f, y, t0, t1, observe, max_attempts);
}

/// integrate_adaptive with a Rosenbrock pair, without an observer.
template <class Method, class State, class System>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(rosenbrock_adaptive<Method, State>& engine,
                                                                       System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1,
                                                                       step_count max_attempts = default_max_attempts) {
    detail::no_observer none;
    return integrate_adaptive(engine, f, y, t0, t1, none, max_attempts);
}

/// integrate_adaptive with an SDIRK pair (odestep::sdirk_adaptive): the same contract as with the Radau IIA 5
/// engine, at most 1 + rhs_evals_to_start + max_attempts * rhs_evals_per_attempt evaluations of f.
template <class Method, class State, class System, class Observer,
          std::enable_if_t<!std::is_arithmetic_v<std::decay_t<Observer>> && !detail::is_event_set_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(sdirk_adaptive<Method, State>& engine,
                                                                       System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1, Observer&& observe,
                                                                       step_count max_attempts = default_max_attempts) {
    return detail::free_running(engine, f, y, t0, t1, observe, max_attempts);
}

/// integrate_adaptive with an SDIRK pair, without an observer.
template <class Method, class State, class System>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(sdirk_adaptive<Method, State>& engine,
                                                                       System&& f, State& y,
                                                                       detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1,
                                                                       step_count max_attempts = default_max_attempts) {
    detail::no_observer none;
    return integrate_adaptive(engine, f, y, t0, t1, none, max_attempts);
}

/// Integrates from t0 to the last of `times` (a container of T with size() and operator[], in the direction
/// of the run and never going back) with the engine's free-running steps, and calls observe(times[i], u) with
/// the state at every times[i]: from the step's collocation polynomial (odestep::radau5_dense, no extra
/// evaluation of f) inside a step, the step's own state at its end. The output times do not shorten the
/// steps. At the end y is the state at the last time; `steps` counts the accepted steps.
///
/// Work as integrate_adaptive. Statuses as integrate_adaptive (non_finite also when the polynomial overflows
/// at an output time; y is then the state at the end of the step that holds it, at the returned t);
/// invalid_time also when a time is not finite, lies before t0 or before the time before it (nothing
/// evaluated or observed). With no times the call does nothing and returns ok.
template <class State, class System, class Times, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_times(radau5<State>& engine, System&& f, State& y,
                                                                    detail::time_t_of<State> t0, const Times& times,
                                                                    Observer&& observe,
                                                                    step_count max_attempts = default_max_attempts) {
    radau5_dense<State> dense;
    return detail::sampled_run(engine, f, y, t0, times, observe, max_attempts, dense, [](auto&) { return status::ok; });
}

/// integrate_times with a Rosenbrock pair (odestep::rosenbrock_adaptive): the same contract as with the Radau IIA 5
/// engine; the state inside a step is the cubic Hermite interpolant of the step's ends (odestep::rosenbrock_dense,
/// order 3), which costs up to rosenbrock_dense::rhs_evals_to_complete (2) evaluations of f for each step with
/// an output time inside it: at most rhs_evals_to_start + max_attempts * (rhs_evals_per_attempt + 2) in all.
template <class Method, class State, class System, class Times, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_times(rosenbrock_adaptive<Method, State>& engine,
                                                                    System&& f, State& y, detail::time_t_of<State> t0,
                                                                    const Times& times, Observer&& observe,
                                                                    step_count max_attempts = default_max_attempts) {
    rosenbrock_dense<State> dense;
    return detail::sampled_run(engine, f, y, t0, times, observe, max_attempts, dense,
                               [&](auto& counted) { return dense.complete(counted); });
}

/// integrate_times with an SDIRK pair (odestep::sdirk_adaptive): the same contract as with the Radau IIA 5
/// engine; the state inside a step is the cubic Hermite interpolant of the step's ends and slopes
/// (odestep::sdirk_dense, order 3, no extra evaluation of f).
template <class Method, class State, class System, class Times, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_times(sdirk_adaptive<Method, State>& engine, System&& f,
                                                                    State& y, detail::time_t_of<State> t0,
                                                                    const Times& times, Observer&& observe,
                                                                    step_count max_attempts = default_max_attempts) {
    sdirk_dense<State> dense;
    return detail::sampled_run(engine, f, y, t0, times, observe, max_attempts, dense, [](auto&) { return status::ok; });
}

}  // namespace odestep

#endif
