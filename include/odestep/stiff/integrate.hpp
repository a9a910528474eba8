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

namespace detail {
// The stiff engines' dense output for integrate_times, and its completion with the counted f: Radau's
// collocation polynomial and the SDIRK pairs' Hermite interpolant need nothing more; the Rosenbrock pairs'
// Hermite interpolant needs f at the step's ends. A stiff engine is one with this trait.
template <class Engine>
struct stiff_dense;
template <class Dense>
struct complete_dense {  // a dense output that needs no evaluation
    using type = Dense;
    template <class System>
    static status complete(type&, System&) noexcept {
        return status::ok;
    }
};
template <class State>
struct stiff_dense<radau5<State>> : complete_dense<radau5_dense<State>> {};
template <class Method, class State>
struct stiff_dense<sdirk_adaptive<Method, State>> : complete_dense<sdirk_dense<State>> {};
template <class Method, class State>
struct stiff_dense<rosenbrock_adaptive<Method, State>> {
    using type = rosenbrock_dense<State>;
    template <class System>
    static status complete(type& dense, System& f) {
        return dense.complete(f);
    }
};

template <class Engine, class = void>
struct is_stiff_engine : std::false_type {};
template <class Engine>
struct is_stiff_engine<Engine, std::void_t<typename stiff_dense<Engine>::type>> : std::true_type {};
// A stiff engine (odestep::radau5, odestep::rosenbrock_adaptive, odestep::sdirk_adaptive).
template <class Engine>
inline constexpr bool is_stiff_engine_v = is_stiff_engine<Engine>::value;
}  // namespace detail

/// Integrates y' = f(t, y) from t0 to exactly t1 with the error-controlled steps of a stiff `engine`
/// (odestep::radau5, odestep::rosenbrock_adaptive, odestep::sdirk_adaptive: its tolerances, controller, and
/// what it carries), and calls observe(t, y) with the initial state and after every accepted step. The
/// result's `steps` counts the accepted steps.
///
/// Work is bounded: at most `max_attempts` attempts, hence at most 1 + Engine::rhs_evals_to_start +
/// max_attempts * Engine::rhs_evals_per_attempt evaluations of f. Statuses, with y always the last accepted
/// state at the returned t: invalid_tolerance / invalid_setting (settings, or max_attempts = 0) and
/// invalid_time (t0 or t1 not finite), nothing evaluated or observed; non_finite, singular_matrix,
/// step_too_small (see the engine); substep_limit (max_attempts reached before t1).
template <class Engine, class System, class Observer,
          std::enable_if_t<detail::is_stiff_engine_v<Engine> && !std::is_arithmetic_v<std::decay_t<Observer>> &&
                               !detail::is_event_set_v<Observer>,
                           int> = 0>
[[nodiscard]] integrate_result<typename Engine::value_type> integrate_adaptive(
    Engine& engine, System&& f, typename Engine::state_type& y, detail::time_t_of<typename Engine::state_type> t0,
    detail::time_t_of<typename Engine::state_type> t1, Observer&& observe,
    step_count max_attempts = default_max_attempts) {
    return detail::free_running(engine, f, y, t0, t1, observe, max_attempts);
}

/// integrate_adaptive with a stiff engine, without an observer.
template <class Engine, class System, std::enable_if_t<detail::is_stiff_engine_v<Engine>, int> = 0>
[[nodiscard]] integrate_result<typename Engine::value_type> integrate_adaptive(
    Engine& engine, System&& f, typename Engine::state_type& y, detail::time_t_of<typename Engine::state_type> t0,
    detail::time_t_of<typename Engine::state_type> t1, step_count max_attempts = default_max_attempts) {
    detail::no_observer none;
    return integrate_adaptive(engine, f, y, t0, t1, none, max_attempts);
}

/// Integrates from t0 to the last of `times` (a container of T with size() and operator[], in the direction
/// of the run and never going back) with the stiff engine's free-running steps, and calls observe(times[i], u)
/// with the state at every times[i]: inside a step from the step's dense output, the step's own state at its
/// end. The output times do not shorten the steps. At the end y is the state at the last time; `steps` counts
/// the accepted steps. The dense output:
///   - odestep::radau5: the step's collocation polynomial (odestep::radau5_dense), no extra evaluation of f;
///   - odestep::sdirk_adaptive: the cubic Hermite interpolant of the step's ends and slopes
///     (odestep::sdirk_dense, order 3), no extra evaluation of f;
///   - odestep::rosenbrock_adaptive: the cubic Hermite interpolant of the step's ends
///     (odestep::rosenbrock_dense, order 3), which costs up to rosenbrock_dense::rhs_evals_to_complete (2)
///     evaluations of f for each step with an output time inside it: at most rhs_evals_to_start +
///     max_attempts * (rhs_evals_per_attempt + 2) in all.
///
/// Work otherwise as integrate_adaptive. Statuses as integrate_adaptive (non_finite also when the interpolant
/// overflows at an output time; y is then the state at the end of the step that holds it, at the returned t);
/// invalid_time also when a time is not finite, lies before t0 or before the time before it (nothing
/// evaluated or observed). With no times the call does nothing and returns ok.
template <class Engine, class System, class Times, class Observer,
          std::enable_if_t<detail::is_stiff_engine_v<Engine>, int> = 0>
[[nodiscard]] integrate_result<typename Engine::value_type> integrate_times(
    Engine& engine, System&& f, typename Engine::state_type& y, detail::time_t_of<typename Engine::state_type> t0,
    const Times& times, Observer&& observe, step_count max_attempts = default_max_attempts) {
    using dense_of = detail::stiff_dense<Engine>;
    typename dense_of::type dense;
    return detail::sampled_run(engine, f, y, t0, times, observe, max_attempts, dense,
                               [&](auto& counted) { return dense_of::complete(dense, counted); });
}

}  // namespace odestep

#endif
