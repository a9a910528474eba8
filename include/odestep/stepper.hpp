// SPDX-License-Identifier: BSL-1.0
// odestep: what a stepper is. Every stepper of the library, and any stepper a user writes, publishes one
// set of traits and one `step` form per kind of system; the driving loops accept exactly those.
#ifndef ODESTEP_STEPPER_HPP
#define ODESTEP_STEPPER_HPP

#include <cstddef>
#include <type_traits>
#include <utility>

#include "state.hpp"
#include "status.hpp"
#include "system.hpp"

namespace odestep {

/// \brief The check policy of a stepper that tests its results for NaN and Inf: the default of every stepper
/// that takes a policy. A step whose new state (or error estimate, or a stage no result reads) is not finite
/// returns `status::non_finite` and leaves the caller's state as it was.
struct checked {
    static constexpr bool checks_finiteness = true;  ///< the step tests its results (the trait of that name)
};

/// \brief The check policy for callers who validate elsewhere: the same arithmetic as `checked`, operation for
/// operation (the same results, bit for bit, on a finite run), without the NaN/Inf test and without the
/// roll-back it needs: a NaN or Inf from the right-hand side goes into the state and the step returns `ok`.
/// Other checks (a multistep history's grid, a tolerance) stay.
struct unchecked {
    static constexpr bool checks_finiteness = false;  ///< the step does not test its results
};

/// The stepper S under check policy Check, for the steppers that take one (explicit_rk and its named forms,
/// adams, splitting): `odestep::with_check_t<odestep::rk4<State>, odestep::unchecked>`.
template <class S, class Check>
using with_check_t = typename S::template with_check<Check>;

/// The unchecked form of stepper S: `odestep::unchecked_t<odestep::rk4<State>>` is RK4 without the NaN/Inf
/// test (odestep::unchecked).
template <class S>
using unchecked_t = with_check_t<S, unchecked>;

/// \brief The trait set every stepper publishes, with the values most steppers have.
///
/// A stepper is a class with `using state_type = State` (a `std::array<T, N>`), `using value_type = T`, the
/// `static constexpr` members below, and the `step` form of its system:
///
/// | system                       | step                                                   |
/// |------------------------------|--------------------------------------------------------|
/// | `system_form::first_order`   | `status step(System& f, State& y, T t, T dt)`          |
/// | `system_form::newtonian`     | `status step(Accel& a, State& x, State& v, T t, T dt)` |
/// | `system_form::charged_particle` | `status step(Fields& fields, State& x, State& v, T t, T dt)` |
///
/// `step` advances the state in place from t to t + dt; on any status but `ok` the state must be the one it
/// was given. A stepper with `error_estimate` also has `step(f, y, t, dt, error)` (first order) writing
/// y_{n+1} - yhat_{n+1}. Derive from stepper_defaults and override what differs:
///
/// \code
/// template <class State>
/// struct my_euler : odestep::stepper_defaults<State> {
///     static constexpr int order = 1;
///     static constexpr std::size_t rhs_evals_per_step = 1;
///     template <class F>
///     odestep::status step(F& f, State& y, typename State::value_type t, typename State::value_type dt) const;
/// };
/// \endcode
///
/// `odestep::check_stepper<S>()` (or using S with a driving loop) names the first trait that is missing.
template <class State>
struct stepper_defaults {
    using state_type = State;                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;  ///< its scalar T
    /// The order of the global error with a smooth system (for `newtonian` steppers: with a force of
    /// position alone). No default: every stepper states it.
    static constexpr int order = 0;
    /// Stages (evaluations in the formula of one step, kicks for a splitting method).
    static constexpr std::size_t stages = 1;
    /// The most right-hand-side (acceleration, field) evaluations one `step` call makes, whatever it is
    /// given: the first step of a history-keeping method, an iteration cap reached. No default.
    static constexpr std::size_t rhs_evals_per_step = 0;
    /// True when the stepper has a `step` form that also returns an error estimate.
    static constexpr bool error_estimate = false;
    /// The order of the embedded solution the estimate compares with (0 without an estimate).
    static constexpr int embedded_order = 0;
    /// The most evaluations of the estimating `step` (0 without an estimate).
    static constexpr std::size_t rhs_evals_per_error_step = 0;
    /// Symplectic for Newton's equations with a force of position alone.
    static constexpr bool symplectic = false;
    /// The step with -dt undoes the step with dt (a symmetric method).
    static constexpr bool time_reversible = false;
    /// The state at a step's end is the state at that time, and no step needs a state prepared by another
    /// call (Boris: v must be staggered first, so false).
    static constexpr bool self_starting = true;
    /// Every step must have the same dt: a history on a grid (Adams; Boris takes a shortened last step, at
    /// an O(dt^2) cost, see boris.hpp). `integrate` refuses, with status::step_mismatch and nothing
    /// touched, a run whose last step would be shortened.
    static constexpr bool uniform_steps = false;
    /// The form of system the stepper takes.
    static constexpr system_form system = system_form::first_order;
    /// Newtonian steppers: a force of position and velocity, a(t, x, v), is accepted (the method is then
    /// not symplectic). False for the other forms.
    static constexpr bool velocity_forces = false;
    /// Implicit (solves an equation in each step: Newton iterations, a factorization).
    static constexpr bool implicit = false;
    /// The step tests its results for NaN and Inf and returns `status::non_finite`, the state untouched, when
    /// one is not finite (the `checked` policy, every library stepper's default). False for a stepper in its
    /// `unchecked` form, which promises nothing about a non-finite value (the caller validates elsewhere).
    static constexpr bool checks_finiteness = true;
    /// Every `step` call makes exactly rhs_evals_per_step evaluations, whether it succeeds or not: the loops
    /// then derive the count of a run (odestep::counts) from the calls instead of counting each evaluation.
    static constexpr bool exact_rhs_evals = false;
};

namespace detail {

template <class...>
inline constexpr bool always_false = false;

#define ODESTEP_DETAIL_HAS_MEMBER(name)     \
    template <class S, class = void>        \
    struct has_##name : std::false_type {}; \
    template <class S>                      \
    struct has_##name<S, std::void_t<decltype(S::name)>> : std::true_type {};

ODESTEP_DETAIL_HAS_MEMBER(order)
ODESTEP_DETAIL_HAS_MEMBER(stages)
ODESTEP_DETAIL_HAS_MEMBER(rhs_evals_per_step)
ODESTEP_DETAIL_HAS_MEMBER(error_estimate)
ODESTEP_DETAIL_HAS_MEMBER(embedded_order)
ODESTEP_DETAIL_HAS_MEMBER(rhs_evals_per_error_step)
ODESTEP_DETAIL_HAS_MEMBER(symplectic)
ODESTEP_DETAIL_HAS_MEMBER(time_reversible)
ODESTEP_DETAIL_HAS_MEMBER(self_starting)
ODESTEP_DETAIL_HAS_MEMBER(uniform_steps)
ODESTEP_DETAIL_HAS_MEMBER(system)
ODESTEP_DETAIL_HAS_MEMBER(velocity_forces)
ODESTEP_DETAIL_HAS_MEMBER(implicit)
#undef ODESTEP_DETAIL_HAS_MEMBER

template <class S, class = void>
struct has_state_type : std::false_type {};
template <class S>
struct has_state_type<S, std::void_t<typename S::state_type, typename S::value_type>> : std::true_type {};

// Which requirement a stepper type misses first (0: none). The codes are diagnose()'s.
template <class S>
constexpr int first_missing_trait() noexcept {
    if constexpr (!has_state_type<S>::value)
        return 1;
    else if constexpr (!is_state_v<typename S::state_type>)
        return 18;
    else if constexpr (!std::is_same_v<typename S::value_type,
                                       typename state_traits<typename S::state_type>::value_type>)
        return 1;
    else if constexpr (!has_order<S>::value)
        return 2;
    else if constexpr (!has_stages<S>::value)
        return 3;
    else if constexpr (!has_rhs_evals_per_step<S>::value)
        return 4;
    else if constexpr (!has_error_estimate<S>::value)
        return 5;
    else if constexpr (!has_embedded_order<S>::value)
        return 6;
    else if constexpr (!has_rhs_evals_per_error_step<S>::value)
        return 7;
    else if constexpr (!has_symplectic<S>::value)
        return 8;
    else if constexpr (!has_time_reversible<S>::value)
        return 9;
    else if constexpr (!has_self_starting<S>::value)
        return 10;
    else if constexpr (!has_uniform_steps<S>::value)
        return 11;
    else if constexpr (!has_system<S>::value)
        return 12;
    else if constexpr (!has_velocity_forces<S>::value)
        return 13;
    else if constexpr (!has_implicit<S>::value)
        return 14;
    else if constexpr (!(S::order >= 1))
        return 15;
    else if constexpr (!(S::rhs_evals_per_step >= 1))
        return 16;
    else if constexpr (S::error_estimate && !(S::embedded_order >= 1 && S::rhs_evals_per_error_step >= 1))
        return 17;
    else
        return 0;
}

template <class S>
constexpr bool diagnose() noexcept {
    constexpr int code = first_missing_trait<S>();
    // 18: the state is not a std::array<T, N>; state_traits says so, in one line.
    if constexpr (code == 18) return sizeof(state_traits<typename S::state_type>) == 0;
    static_assert(code != 1,
                  "odestep: a stepper needs `using state_type = std::array<T, N>;` and `using value_type = T;`");
    static_assert(
        code != 2,
        "odestep: a stepper needs `static constexpr int order` (derive from odestep::stepper_defaults<State>)");
    static_assert(code != 3,
                  "odestep: a stepper needs `static constexpr std::size_t stages` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 4,
                  "odestep: a stepper needs `static constexpr std::size_t rhs_evals_per_step` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 5,
                  "odestep: a stepper needs `static constexpr bool error_estimate` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 6,
                  "odestep: a stepper needs `static constexpr int embedded_order` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 7,
                  "odestep: a stepper needs `static constexpr std::size_t rhs_evals_per_error_step` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(
        code != 8,
        "odestep: a stepper needs `static constexpr bool symplectic` (derive from odestep::stepper_defaults<State>)");
    static_assert(code != 9,
                  "odestep: a stepper needs `static constexpr bool time_reversible` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 10,
                  "odestep: a stepper needs `static constexpr bool self_starting` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 11,
                  "odestep: a stepper needs `static constexpr bool uniform_steps` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 12,
                  "odestep: a stepper needs `static constexpr odestep::system_form system` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(code != 13,
                  "odestep: a stepper needs `static constexpr bool velocity_forces` (derive from "
                  "odestep::stepper_defaults<State>)");
    static_assert(
        code != 14,
        "odestep: a stepper needs `static constexpr bool implicit` (derive from odestep::stepper_defaults<State>)");
    static_assert(code != 15, "odestep: a stepper's `order` must be at least 1");
    static_assert(code != 16, "odestep: a stepper's `rhs_evals_per_step` must be at least 1");
    static_assert(code != 17,
                  "odestep: a stepper with `error_estimate` states `embedded_order` and `rhs_evals_per_error_step`");
    return code == 0;
}

}  // namespace detail

/// True when S publishes the whole trait set with values that make sense (a type, never an error).
template <class S>
inline constexpr bool is_stepper_v = detail::first_missing_trait<std::remove_cv_t<std::remove_reference_t<S>>>() == 0;

/// Checks that S publishes the whole trait set; if not, compilation stops with one line naming the first
/// missing trait. `static_assert(odestep::check_stepper<my_stepper<state>>());`
template <class S>
constexpr bool check_stepper() noexcept {
    return detail::diagnose<std::remove_cv_t<std::remove_reference_t<S>>>();
}

/// True when stepper S, given the acceleration Accel, is symplectic: a symplectic method with a force of
/// position alone (with a(t, x, v) no splitting method is).
template <class S, class Accel>
inline constexpr bool is_symplectic_with_v = std::remove_reference_t<S>::symplectic&&
    is_position_force_v<Accel, typename std::remove_reference_t<S>::state_type>;

namespace detail {

// What a driving loop asks of its stepper: the trait set and the form of system the loop drives. One line
// on failure (the loop's body is not instantiated then, so nothing else is reported).
template <class S, system_form Form>
constexpr bool stepper_fits() noexcept {
    using B = std::remove_cv_t<std::remove_reference_t<S>>;
    if constexpr (first_missing_trait<B>() != 0) {
        return diagnose<B>();
    } else if constexpr (Form == system_form::first_order) {
        static_assert(B::system == system_form::first_order,
                      "odestep: this stepper integrates Newton's equations (x and v): call "
                      "integrate(stepper, a, x, v, t0, t1, dt)");
        return B::system == system_form::first_order;
    } else {
        static_assert(B::system != system_form::first_order,
                      "odestep: this stepper integrates y' = f(t, y): call integrate(stepper, f, y, t0, t1, dt)");
        return B::system != system_form::first_order;
    }
}

}  // namespace detail
}  // namespace odestep

#endif
