// SPDX-License-Identifier: BSL-1.0
// odestep: the free-running adaptive loops: integrate_adaptive (every accepted step observed) and
// integrate_times (the state at the caller's times, from the dense output, without changing the steps).
#ifndef ODESTEP_ADAPTIVE_INTEGRATE_ADAPTIVE_HPP
#define ODESTEP_ADAPTIVE_INTEGRATE_ADAPTIVE_HPP

#include <cstddef>
#include <type_traits>

#include "../counts.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "adaptive_rk.hpp"
#include "dense.hpp"

namespace odestep {

/// The default cap on attempted steps (accepted and rejected) of one free-running adaptive run.
inline constexpr step_count default_max_attempts = 100000;

namespace detail {
// A solution (adaptive/solution.hpp) is not an observer: recognised by its tag, it takes its own overload.
template <class T, class = void>
struct has_solution_tag : std::false_type {};
template <class T>
struct has_solution_tag<T, std::void_t<typename T::solution_tag>> : std::true_type {};
template <class T>
inline constexpr bool is_solution_v = has_solution_tag<std::remove_cv_t<std::remove_reference_t<T>>>::value;

// THE free-running loop, for every engine with settings_status() and attempt(f, t, y, t_end, accepted)
// (adaptive_rk, and the stiff engines of stiff/): observe (t0, y), then attempts until t1 or the cap. An empty
// run (t0 == t1) ends as integrate()'s does (integrate.hpp, run_grid): ok if y is finite, else non_finite at t0.
template <class Engine, class State, class System, class Observer>
integrate_result<value_type_t<State>> free_running(Engine& engine, System& f, State& y, value_type_t<State> t0,
                                                   value_type_t<State> t1, Observer& observe, step_count max_attempts) {
    using T = value_type_t<State>;
    status s = preflight(engine, t0, t1, max_attempts);
    if (s != status::ok) return {s, t0, 0, {}};
    observe(t0, static_cast<const State&>(y));
    if (t0 == t1 && !all_finite(y)) return {status::non_finite, t0, 0, {}};
    const counts before = engine_counts(engine);
    evaluation_tally tally;
    auto counted = counting(f, tally);
    const auto done = [&](status code, T t_end, step_count steps) {
        return integrate_result<T>{code, t_end, steps, engine_work(engine, before, tally)};
    };
    T t = t0;
    step_count accepted = 0;
    for (step_count n = 0; n < max_attempts && t != t1; ++n) {
        bool ok = false;
        s = engine.attempt(counted, t, y, t1, ok);
        if (s != status::ok) return done(s, t, accepted);
        if (ok) {
            ++accepted;
            observe(t, static_cast<const State&>(y));
        }
    }
    if (t != t1) return done(status::substep_limit, t, accepted);
    return done(status::ok, t1, accepted);  // t1 itself: a run from -0.0 to +0.0 ends on +0.0
}

// What integrate_times checks before anything is evaluated (the same for every engine): the run's preflight
// over [t0, the last time] (over [t0, t0] with no times), then the times (finite, in the run's direction,
// never going back). ok with t1 the last time (t0 with no times).
template <class Engine, class T, class Times>
status check_times(const Engine& engine, T t0, const Times& times, step_count max_attempts, T& t1) noexcept {
    const std::size_t count = times.size();
    t1 = count == 0 ? t0 : times[count - 1];
    const status s = preflight(engine, t0, t1, max_attempts);
    if (s != status::ok || count == 0) return s;
    const bool forward = !(t1 < t0);
    T previous = t0;
    for (std::size_t i = 0; i < count; ++i) {
        const T ti = times[i];
        if (!is_finite(ti) || (forward ? ti < previous : ti > previous)) return status::invalid_time;
        previous = ti;
    }
    return status::ok;
}

// THE loop of integrate_times, for every engine with attempt(f, t, y, t_end, accepted, dense): the steps are
// integrate_adaptive's, and each output time inside an accepted step comes from `dense` once complete(f) (the
// engine's extension: more evaluations for some pairs, none for Radau's polynomial) has returned ok.
template <class Engine, class System, class State, class Times, class Observer, class Dense, class Complete>
integrate_result<value_type_t<State>> sampled_run(Engine& engine, System& f, State& y, value_type_t<State> t0,
                                                  const Times& times, Observer& observe, step_count max_attempts,
                                                  Dense& dense, Complete&& complete) {
    using T = value_type_t<State>;
    const std::size_t count = times.size();
    T t1 = t0;
    status s = detail::check_times(engine, t0, times, max_attempts, t1);
    if (s != status::ok || count == 0) return {s, t0, 0, {}};
    const bool forward = !(t1 < t0);
    std::size_t next = 0;
    while (next < count && times[next] == t0) observe(times[next++], static_cast<const State&>(y));
    if (next == count && !detail::all_finite(y)) return {status::non_finite, t0, 0, {}};  // an empty run
    // Every evaluation counted: the attempts' and complete(counted)'s (the interpolant's extra stages).
    const counts before = engine_counts(engine);
    evaluation_tally tally;
    auto counted = counting(f, tally);
    const auto done = [&](status code, T t_end, step_count steps) {
        return integrate_result<T>{code, t_end, steps, engine_work(engine, before, tally)};
    };
    State u;
    T t = t0;
    step_count accepted = 0;
    for (step_count n = 0; n < max_attempts && next < count; ++n) {
        bool ok = false;
        s = engine.attempt(counted, t, y, t1, ok, dense);
        if (s != status::ok) return done(s, t, accepted);
        if (!ok) continue;
        ++accepted;
        // Every time inside the step: interpolated; a time on its end: the step's own state.
        const auto inside = [&](T ti) { return forward ? ti < t : ti > t; };
        if (next < count && inside(times[next])) {
            s = complete(counted);
            if (s != status::ok) return done(s, t, accepted);
            for (; next < count && inside(times[next]); ++next) {
                dense.at(times[next], u);
                // The interpolant of a finite step can still overflow between its ends (huge states).
                if (!detail::all_finite(u)) return done(status::non_finite, t, accepted);
                observe(times[next], static_cast<const State&>(u));
            }
        }
        while (next < count && times[next] == t) observe(times[next++], static_cast<const State&>(y));
    }
    if (next < count) return done(status::substep_limit, t, accepted);
    return done(status::ok, t1, accepted);  // the last time itself (-0.0 against +0.0)
}
}  // namespace detail

/// Integrates y' = f(t, y) from t0 to exactly t1 with the error-controlled steps of `engine`
/// (odestep::adaptive_rk: its tolerances, controller, and the step size it carries), and calls
/// observe(t, y) with the initial state and after every accepted step (Odeint's integrate_adaptive; SciPy's
/// solve_ivp without t_eval). The result's `steps` counts the accepted steps.
///
/// Work is bounded: at most `max_attempts` attempted steps, hence at most
/// adaptive_rk::rhs_evals_to_start + max_attempts * adaptive_rk::rhs_evals_per_attempt evaluations of f.
/// Statuses, with y always the last accepted state at the returned t: invalid_tolerance / invalid_setting
/// (settings, or max_attempts = 0) and invalid_time (t0 or t1 not finite), with nothing evaluated or observed;
/// non_finite (f gave NaN or Inf; that step was not taken), step_too_small, substep_limit (max_attempts
/// reached before t1).
template <class Method, class State, class System, class Observer,
          std::enable_if_t<!std::is_arithmetic_v<std::decay_t<Observer>> && !detail::is_solution_v<Observer> &&
                               !detail::is_event_set_v<Observer>,
                           int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(adaptive_rk<Method, State>& engine, System&& f,
                                                                       State& y, detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1, Observer&& observe,
                                                                       step_count max_attempts = default_max_attempts) {
    return detail::free_running(engine, f, y, t0, t1, observe, max_attempts);
}

/// integrate_adaptive without an observer.
template <class Method, class State, class System>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(adaptive_rk<Method, State>& engine, System&& f,
                                                                       State& y, detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1,
                                                                       step_count max_attempts = default_max_attempts) {
    detail::no_observer none;
    return integrate_adaptive(engine, f, y, t0, t1, none, max_attempts);
}

/// Integrates from t0 to the last of `times` (a container of T with size() and operator[], such as
/// std::array, in the direction of the run and never going back) with the engine's free-running steps, and
/// calls observe(times[i], u) with the state at every times[i] (SciPy's t_eval, Odeint's integrate_times).
/// The steps are those integrate_adaptive takes to the last time: the output times do not shorten them;
/// the state between a step's ends comes from odestep::dense_step (Dormand-Prince 5(4)'s continuous
/// extension of order 4, otherwise cubic Hermite), and a time at a step's end gets the step's own state.
/// At the end y is the state at the last time. The result's `steps` counts the accepted steps.
///
/// Work is bounded: at most `max_attempts` attempted steps, and each accepted step with an output time inside
/// it completes the interpolant once, hence at most adaptive_rk::rhs_evals_to_start + max_attempts *
/// (adaptive_rk::rhs_evals_per_attempt + dense_step::rhs_evals_to_complete) evaluations of f.
/// Statuses as integrate_adaptive (non_finite also when the interpolant overflows at an output time; y is then
/// the state at the end of the step that holds it, at the returned t); invalid_time also when a time is not finite, lies before t0 or before the
/// time before it (nothing evaluated or observed). With no times the call does nothing and returns ok.
template <class Method, class State, class System, class Times, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_times(adaptive_rk<Method, State>& engine, System&& f,
                                                                    State& y, detail::time_t_of<State> t0,
                                                                    const Times& times, Observer&& observe,
                                                                    step_count max_attempts = default_max_attempts) {
    dense_step<Method, State> dense;
    return detail::sampled_run(engine, f, y, t0, times, observe, max_attempts, dense,
                               [&](auto& counted) { return dense.complete(counted, engine); });
}

}  // namespace odestep

#endif
