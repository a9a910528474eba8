// odestep: the fixed-step driving loops.
#ifndef ODESTEP_INTEGRATE_HPP
#define ODESTEP_INTEGRATE_HPP

#include <cstddef>
#include <limits>
#include <type_traits>

#include "detail/ops.hpp"
#include "state.hpp"
#include "status.hpp"
#include "stepper.hpp"

namespace odestep {

/// What a driving loop reports. On failure `t` is the time of the caller's state (the last good one)
/// and `steps` the number of steps that completed.
template <class T>
struct integrate_result {
    odestep::status status;
    T t;
    std::size_t steps;
};

namespace detail {

// An event set (events.hpp) is not an observer: integrate's overloads with events are found instead.
template <class T>
struct is_event_set : std::false_type {};
template <class T>
inline constexpr bool is_observer_v = !is_event_set<std::remove_cv_t<std::remove_reference_t<T>>>::value;

template <class T>
struct identity {
    using type = T;
};
template <class T>
using identity_t = typename identity<T>::type;  // keeps t0, t1, dt out of template argument deduction

struct no_observer {
    template <class T, class... States>
    constexpr void operator()(T, const States&...) const noexcept {}
};

/// Checks the arguments of a fixed-step run over [t0, t1] and counts its steps: ceil((t1 - t0) / dt),
/// except that a quotient within a few rounding errors of a whole number n gives n steps, not n plus a
/// sliver of a few ULPs (0.3 / 0.1 is 2.9999999999999996 in double).
template <class T>
constexpr status plan_steps(T t0, T t1, T dt, std::size_t& steps) noexcept {
    if (!is_finite(t0) || !is_finite(t1) || !is_finite(t1 - t0)) return status::invalid_time;
    if (!is_finite(dt) || dt == T(0)) return status::invalid_step;
    const T span = t1 - t0;
    if (span == T(0)) {
        steps = 0;
        return status::ok;
    }
    const T ratio = span / dt;
    if (ratio < T(0)) return status::wrong_direction;
    constexpr std::size_t most = std::numeric_limits<std::size_t>::max() / 2;
    if (!(ratio < static_cast<T>(most))) return status::too_many_steps;
    const std::size_t whole = static_cast<std::size_t>(ratio);  // floor, as ratio > 0
    const T fraction = ratio - static_cast<T>(whole);
    const T tolerance = T(16) * std::numeric_limits<T>::epsilon() * ratio;
    // Just above a whole number: that many steps. Otherwise one more, the last one shortened to end on t1
    // (just below a whole number, that last step differs from dt by a few ULPs only).
    steps = (whole > 0 && fraction <= tolerance) ? whole : whole + 1;
    return status::ok;
}

}  // namespace detail

namespace detail {

// The last step of a run over [t0, t1]: t1 - t, except that a difference from dt within the rounding of the
// grid's times is rounding, not a shorter step, and the step is dt exactly (0.3 - 0.2 is not 0.1 in double;
// a multistep method would take it for a new step size).
template <class T>
constexpr T last_step(T t0, T t1, T t, T dt) noexcept {
    const T h = t1 - t;
    const T grid = T(4) * std::numeric_limits<T>::epsilon() * (abs_value(t0) + abs_value(t1));
    return abs_value(h - dt) <= grid ? dt : h;
}

// The one fixed-step loop, for a first-order state (y) or a Newtonian pair (x, v): the stepper is called
// as step(f, states..., t, h) and the observer as observe(t, states...).
template <class T, class Stepper, class System, class Observer, class... States>
integrate_result<T> drive(Stepper& stepper, System& f, Observer& observe, T t0, T t1, T dt, States&... ys) {
    std::size_t n = 0;
    const status valid = plan_steps(t0, t1, dt, n);
    if (valid != status::ok) return {valid, t0, 0};
    observe(t0, static_cast<const States&>(ys)...);
    T t = t0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool last = i + 1 == n;
        // t_i = t0 + i dt from the counter, never a running sum (in float, a running t += 1e-3 reaches
        // 991.14 instead of 1000 after 10^6 steps); the last step is shortened to end on t1.
        const T next = last ? t1 : t0 + static_cast<T>(i + 1) * dt;
        const status s = stepper.step(f, ys..., t, last ? last_step(t0, t1, t, dt) : dt);
        if (s != status::ok) return {s, t, i};
        observe(next, static_cast<const States&>(ys)...);
        t = next;
    }
    return {status::ok, t1, n};
}

template <class T, class Stepper, class System, class Observer, class... States>
integrate_result<T> drive_n(Stepper& stepper, System& f, Observer& observe, T t0, T dt, std::size_t steps,
                            States&... ys) {
    if (!is_finite(t0)) return {status::invalid_time, t0, 0};
    if (!is_finite(dt) || dt == T(0)) return {status::invalid_step, t0, 0};
    observe(t0, static_cast<const States&>(ys)...);
    T t = t0;
    for (std::size_t i = 0; i < steps; ++i) {
        const T next = t0 + static_cast<T>(i + 1) * dt;  // from the counter, as in drive
        const status s = stepper.step(f, ys..., t, dt);
        if (s != status::ok) return {s, t, i};
        observe(next, static_cast<const States&>(ys)...);
        t = next;
    }
    return {status::ok, t, steps};
}

template <class State>
using time_t_of = identity_t<value_type_t<State>>;

}  // namespace detail

/// Integrates y' = f(t, y) from t0 to exactly t1 with steps of dt (negative dt integrates backwards). The
/// step times are t0 + i dt from an integer counter; the last step is shortened to end on t1. The observer
/// is called as observe(t, y) with the initial state and after every step.
///
/// Bad arguments return a status before anything is touched. A step that produces NaN or Inf is rolled
/// back: y is the state at the returned time and the status says why the run stopped.
template <class Stepper, class System, class State, class Observer,
          std::enable_if_t<detail::is_observer_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, System&& f, State& y,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt, Observer&& observe) {
    return detail::drive(stepper, f, observe, t0, t1, dt, y);
}

/// integrate without an observer.
template <class Stepper, class System, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, System&& f, State& y,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt) {
    detail::no_observer none;
    return detail::drive(stepper, f, none, t0, t1, dt, y);
}

/// Takes exactly `steps` steps of dt from t0 (so it ends at t0 + steps * dt), observing as `integrate`.
template <class Stepper, class System, class State, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, System&& f, State& y,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, std::size_t steps,
                                                                      Observer&& observe) {
    return detail::drive_n(stepper, f, observe, t0, dt, steps, y);
}

/// integrate_n_steps without an observer.
template <class Stepper, class System, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, System&& f, State& y,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, std::size_t steps) {
    detail::no_observer none;
    return detail::drive_n(stepper, f, none, t0, dt, steps, y);
}

/// Newton's equations x'' = a: the same loops for steppers that take position and velocity separately.
/// The observer is called as observe(t, x, v).
template <class Stepper, class Accel, class State, class Observer,
          std::enable_if_t<detail::is_observer_v<Observer>, int> = 0>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt, Observer&& observe) {
    return detail::drive(stepper, a, observe, t0, t1, dt, x, v);
}

template <class Stepper, class Accel, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                              detail::time_t_of<State> t0, detail::time_t_of<State> t1,
                                                              detail::time_t_of<State> dt) {
    detail::no_observer none;
    return detail::drive(stepper, a, none, t0, t1, dt, x, v);
}

template <class Stepper, class Accel, class State, class Observer>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, std::size_t steps,
                                                                      Observer&& observe) {
    return detail::drive_n(stepper, a, observe, t0, dt, steps, x, v);
}

template <class Stepper, class Accel, class State>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_n_steps(Stepper&& stepper, Accel&& a, State& x, State& v,
                                                                      detail::time_t_of<State> t0,
                                                                      detail::time_t_of<State> dt, std::size_t steps) {
    detail::no_observer none;
    return detail::drive_n(stepper, a, none, t0, dt, steps, x, v);
}

}  // namespace odestep

#endif
