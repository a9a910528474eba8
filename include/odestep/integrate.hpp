// SPDX-License-Identifier: BSL-1.0
// odestep: the fixed-step driving loops, all on one grid clock (detail/grid_clock.hpp).
#ifndef ODESTEP_INTEGRATE_HPP
#define ODESTEP_INTEGRATE_HPP

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "counts.hpp"
#include "detail/grid_clock.hpp"
#include "detail/ops.hpp"
#include "detail/preflight.hpp"
#include "state.hpp"
#include "status.hpp"
#include "stepper.hpp"

namespace odestep {

/// What a driving loop reports. On failure `t` is the time of the caller's state (the last good one)
/// and `steps` the number of steps that completed; `counts` what the call did (odestep::counts).
template <class T>
struct integrate_result {
    odestep::status status;    ///< ok, or why the run stopped
    T t;                       ///< the time of the state
    step_count steps;          ///< steps completed
    odestep::counts counts{};  ///< evaluations, steps and the rest of the call's work
};

/// "No event", in results that name one.
inline constexpr std::size_t no_event = static_cast<std::size_t>(-1);

namespace detail {

// A set of events (events/) is not an observer: it is recognised by its tag, so this header needs to know
// nothing of the event loop, which builds on it.
template <class T, class = void>
struct has_event_set_tag : std::false_type {};
template <class T>
struct has_event_set_tag<T, std::void_t<typename T::event_set_tag>> : std::true_type {};
template <class T>
inline constexpr bool is_event_set_v = has_event_set_tag<std::remove_cv_t<std::remove_reference_t<T>>>::value;
template <class T>
inline constexpr bool is_observer_v = !is_event_set_v<T>;

template <class T>
struct identity {
    using type = T;
};
template <class T>
using identity_t = typename identity<T>::type;  // keeps t0, t1, dt out of template argument deduction

template <class State>
using time_t_of = identity_t<value_type_t<State>>;

struct no_observer {
    template <class T, class... States>
    constexpr void operator()(T, const States&...) const noexcept {}
};

/// What one step of a driving loop ends in: the status, the time of the state (the step's end, or where
/// it stopped), and for the event loop the firings inside the step and the event that stopped it.
template <class T>
struct step_outcome {
    status code;
    T t;
    std::size_t fired;
    std::size_t event;
    /// an event's action ran inside the step, or it stopped at its start's time with another state (an offset
    /// under half an ULP of t): the state at t may differ from the one observed
    bool acted = false;
};

/// What the loop ends in: as integrate_result, and the event that stopped it (or no_event).
template <class T>
struct run_outcome {
    status code;
    T t;
    step_count steps;
    std::size_t event;
};

/// THE fixed-step loop. `advance(t, h, t_next)` takes one step of h from the state at t to the grid time
/// t_next and returns its step_outcome; the observer sees the initial state, every completed step, and
/// the state where a terminal event stopped the run. An empty run (no step) ends as a run's first step
/// would on its state: ok at t_end if it is finite, non_finite at t0 (the state untouched) if not.
template <class T, class Advance, class Observer, class... States>
run_outcome<T> run_grid(const grid_plan<T>& plan, Advance&& advance, Observer& observe, States&... ys) {
    observe(plan.clock.t0, static_cast<const States&>(ys)...);
    if (plan.steps == 0 && !(all_finite(static_cast<const States&>(ys)) && ...))
        return {status::non_finite, plan.clock.t0, 0, no_event};
    T t = plan.clock.t0;
    for (step_count i = 0; i < plan.steps; ++i) {
        const T next = plan.end_of(i);
        const step_outcome<T> a = advance(t, plan.step_size(i), next);
        if (a.code != status::ok) {
            // The state where a terminal event stopped the run, unless that is the step's start, already
            // observed, with no action run since (a root within the tolerance after a grid time).
            if (a.code == status::stopped_by_event && (!(a.t == t) || a.acted))
                observe(a.t, static_cast<const States&>(ys)...);
            return {a.code, a.t, i, a.event};
        }
        observe(next, static_cast<const States&>(ys)...);
        t = next;
    }
    return {status::ok, plan.t_end, plan.steps, no_event};
}

// integrate and integrate_n_steps for a first-order state (y) or a Newtonian pair (x, v): the stepper is
// called as step(f, states..., t, h) and the observer as observe(t, states...).
template <system_form Form, class T, class Stepper, class System, class Observer, class... States>
integrate_result<T> drive(Stepper& stepper, System& f, Observer& observe, status planned, const grid_plan<T>& plan,
                          States&... ys) {
    if constexpr (!stepper_fits<Stepper, Form>()) {
        return {status::invalid_step, plan.clock.t0, 0, {}};  // not reached: stepper_fits stopped the compilation
    } else {
        planned = preflight(stepper, planned, plan);
        if (planned != status::ok) return {planned, plan.clock.t0, 0, {}};
        using S = std::remove_cv_t<std::remove_reference_t<Stepper>>;
        using First = std::tuple_element_t<0, std::tuple<States...>>;
        evaluation_tally tally;
        counts before;
        if constexpr (has_engine<S>::value) before = engine_counts(stepper.engine());
        run_outcome<T> r;
        if constexpr (exact_rhs_evals_v<S>) {
            // f uncounted: every step call makes rhs_evals_per_step evaluations
            r = run_grid(
                plan,
                [&](T t, T h, T) {
                    return step_outcome<T>{stepper.step(f, ys..., t, h), t, 0, no_event};
                },
                observe, ys...);
        } else {
            auto counted = counting(f, tally);
            r = run_grid(
                plan,
                [&](T t, T h, T) {
                    return step_outcome<T>{stepper.step(counted, ys..., t, h), t, 0, no_event};
                },
                observe, ys...);
        }
        // Step calls: the completed steps and the one that failed (run_grid stops at the first failure; an
        // empty run fails without a call).
        const step_count calls = r.steps + (r.code != status::ok && plan.steps != 0 ? 1 : 0);
        counts c;
        if constexpr (has_engine<S>::value) {
            c = engine_work(stepper.engine(), before, tally);
        } else {
            add_implicit_work<S>(c, calls, tally, has_jacobian_v<std::remove_cv_t<System>, First>);
            c.accepted_steps = r.steps;
            c.rhs_evals = exact_rhs_evals_v<S> ? calls * static_cast<step_count>(S::rhs_evals_per_step) : tally.rhs;
        }
        return {r.code, r.t, r.steps, c};
    }
}

}  // namespace detail

/// Integrates y' = f(t, y) from t0 to exactly t1 with steps of dt (negative dt integrates backwards). The
/// step times are t0 + i dt from an integer counter; the last step ends on t1, shortened when t1 - t0 is
/// not a whole number of steps (to the grid's rounding). A stepper that needs equal steps (uniform_steps:
/// Adams) refuses a run whose last step would be shortened, with status::step_mismatch. The observer
/// is called as observe(t, y) with the initial state and after every step.
///
/// Bad arguments return a status before anything is touched. A step that produces NaN or Inf is rolled
/// back: y is the state at the returned time and the status says why the run stopped.
template <class Stepper, class System, class State, class Observer,
          std::enable_if_t<detail::is_observer_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, System&& f, State& y,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt, Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive<system_form::first_order>(stepper, f, observe, planned, plan, y);
}

/// integrate without an observer.
template <class Stepper, class System, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, System&& f, State& y,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt) {
    detail::no_observer none;
    return integrate(stepper, f, y, t0, t1, dt, none);
}

/// Takes exactly `steps` steps of dt from t0 (so it ends at t0 + steps * dt), observing as `integrate`. A
/// run whose last time t0 + steps * dt is not finite is refused with status::invalid_time.
template <class Stepper, class System, class State, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, System&& f, State& y,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, step_count steps,
                                                                      Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_steps(t0, dt, steps, plan);
    return detail::drive<system_form::first_order>(stepper, f, observe, planned, plan, y);
}

/// integrate_n_steps without an observer.
template <class Stepper, class System, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, System&& f, State& y,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, step_count steps) {
    detail::no_observer none;
    return integrate_n_steps(stepper, f, y, t0, dt, steps, none);
}

/// Newton's equations x'' = a (and the charged particle's fields): the same loops for steppers that take
/// position and velocity separately. The observer is called as observe(t, x, v).
template <class Stepper, class Accel, class State, class Observer,
          std::enable_if_t<detail::is_observer_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt, Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive<system_form::newtonian>(stepper, a, observe, planned, plan, x, v);
}

/// integrate for Newton's equations, without an observer.
template <class Stepper, class Accel, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt) {
    detail::no_observer none;
    return integrate(stepper, a, x, v, t0, t1, dt, none);
}

/// integrate_n_steps for Newton's equations.
template <class Stepper, class Accel, class State, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, step_count steps,
                                                                      Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_steps(t0, dt, steps, plan);
    return detail::drive<system_form::newtonian>(stepper, a, observe, planned, plan, x, v);
}

/// integrate_n_steps for Newton's equations, without an observer.
template <class Stepper, class Accel, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, step_count steps) {
    detail::no_observer none;
    return integrate_n_steps(stepper, a, x, v, t0, dt, steps, none);
}

}  // namespace odestep

#endif
