// SPDX-License-Identifier: BSL-1.0
// odestep: integrate with events: the driving loop of a run over [t0, t1] (detail::run_grid, the grid clock) with
// the event engine stepping it, first-order and Newtonian.
#ifndef ODESTEP_EVENTS_INTEGRATE_HPP
#define ODESTEP_EVENTS_INTEGRATE_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../counts.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/preflight.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "bounds.hpp"
#include "engine.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {

template <class T, class Stepper, class System, class Set, class Observer, class State, class... More>
event_integrate_result<T, Set::size> drive_events_on(Stepper& stepper, System& f, Set& set, Observer& observe,
                                                     status planned, const grid_plan<T>& plan, State& y0, More&... ys) {
    require_self_starting<Stepper>();
    constexpr std::size_t K = 1 + sizeof...(More);
    using engine_type = event_engine<State, K, Set>;
    engine_type engine;
    using S = std::remove_cv_t<std::remove_reference_t<Stepper>>;
    evaluation_tally tally;
    // Calls of advance: the completed steps and the one that ended the run early (none for an empty run).
    step_count advances = 0;
    const auto finish = [&](status s, T t, step_count steps, std::size_t event) {
        event_integrate_result<T, Set::size> r{s, t, steps, event, 0, {}, {}};
        for (std::size_t i = 0; i < Set::size; ++i) {
            r.firings[i] = engine.memory[i].fired;
            r.fired += engine.memory[i].fired;
        }
        // The quiet part of each advance is derived: one step call, and E evaluations of g unless that call
        // failed; the engine counted the rest where it did it.
        const step_count calls = advances + engine.work.steps;
        counts& c = r.counts;
        add_implicit_work<S>(c, calls, tally, has_jacobian_v<std::remove_cv_t<System>, State>);
        c.rhs_evals =
            exact_rhs_evals_v<S> ? calls * static_cast<step_count>(S::rhs_evals_per_step) + engine.work.rhs : tally.rhs;
        c.event_evals = (advances - engine.work.failed_steps) * Set::size + engine.work.g;
        c.accepted_steps = steps;
        c.firings = r.fired;
        return r;
    };
    planned = preflight(stepper, planned, plan);
    if (planned == status::ok)
        planned = limits_status<Stepper, typename Set::finder, value_type_t<State>>(Set::size, set.limits);
    if (planned != status::ok) return finish(planned, plan.clock.t0, 0, no_event);
    const std::array<State*, K> y{&y0, &ys...};
    const status started = engine.begin(set, plan.clock.t0, y);
    if (started != status::ok) return finish(started, plan.clock.t0, 0, no_event);
    no_sink sink;
    run_outcome<T> r;
    if constexpr (exact_rhs_evals_v<S>) {  // f uncounted: derived from the step calls
        r = run_grid(
            plan, [&](T t, T h, T next) { return engine.advance(stepper, f, set, y, t, h, next, sink); }, observe, y0,
            ys...);
    } else {
        auto counted = counting(f, tally);
        r = run_grid(
            plan, [&](T t, T h, T next) { return engine.advance(stepper, counted, set, y, t, h, next, sink); }, observe,
            y0, ys...);
    }
    advances = r.steps + (r.code != status::ok && plan.steps != 0 ? 1 : 0);
    return finish(r.code, r.t, r.steps, r.event);
}

// A const set (integrate(..., const event_set&, ...)) runs on a copy: its g and actions are called as
// non-const, as the engine calls them; the caller's set is left as it was.
template <class T, class Stepper, class System, class Set, class Observer, class State, class... More>
event_integrate_result<T, Set::size> drive_events(Stepper& stepper, System& f, Set& set, Observer& observe,
                                                  status planned, const grid_plan<T>& plan, State& y0, More&... ys) {
    if constexpr (std::is_const_v<Set>) {
        std::remove_const_t<Set> copy = set;
        return drive_events_on(stepper, f, copy, observe, planned, plan, y0, ys...);
    } else {
        return drive_events_on(stepper, f, set, observe, planned, plan, y0, ys...);
    }
}

}  // namespace detail

/// Integrates y' = f(t, y) from t0 to t1 on the grid t0 + i dt, as `integrate` does, and watches the events
/// of `events` (odestep::watch(...)): each crossing inside a step is located by re-stepping from the step's
/// start, its action runs on the integrator's own state at that time, and the rest of the step is taken
/// from there, so the observer still sees the grid. A terminal event (or an action that returns
/// event_result::stop) ends the run: status::stopped_by_event, `event` says which, `t` when, and y is the
/// state then (the observer sees it too). The result also counts the firings, per event and in all.
///
/// After a callable action (which may change the state, or only a parameter the right-hand side reads) the
/// rest of the step is recomputed from the event, and the stepper is reset (its history, or a kept
/// acceleration, belongs to the old state). A `record` event leaves the trajectory exactly as it would be
/// without it. A terminal event at the start of a step (a root within the tolerance after a grid time) is
/// not observed a second time, unless the state there is another one: an action changed it, or the root lies
/// under half an ULP of the time after the step's start.
template <class Stepper, class System, class State, class Set, class Observer,
          std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, System&& f, State& y, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events,
                             Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive_events(stepper, f, events, observe, planned, plan, y);
}

/// integrate with events, without an observer.
template <class Stepper, class System, class State, class Set, std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, System&& f, State& y, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events) {
    detail::no_observer none;
    return integrate(stepper, f, y, t0, t1, dt, events, none);
}

/// Newton's equations with events: g(t, x, v), action(t, x, v), observe(t, x, v).
template <class Stepper, class Accel, class State, class Set, class Observer,
          std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, Accel&& a, State& x, State& v, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events,
                             Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive_events(stepper, a, events, observe, planned, plan, x, v);
}

template <class Stepper, class Accel, class State, class Set, std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, Accel&& a, State& x, State& v, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events) {
    detail::no_observer none;
    return integrate(stepper, a, x, v, t0, t1, dt, events, none);
}

}  // namespace odestep

#endif
