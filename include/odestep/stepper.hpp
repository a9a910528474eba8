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

/// THE trait list: every trait of stepper_defaults that a stepper must publish, with its type, in the order
/// odestep::check_stepper reports a missing one. The detectors, the diagnostics, the named traits
/// (odestep::trait, odestep::stepper_traits) are all generated from it.
#define ODESTEP_DETAIL_STEPPER_TRAITS(X)     \
    X(order, int)                            \
    X(stages, std::size_t)                   \
    X(rhs_evals_per_step, std::size_t)       \
    X(error_estimate, bool)                  \
    X(embedded_order, int)                   \
    X(rhs_evals_per_error_step, std::size_t) \
    X(symplectic, bool)                      \
    X(time_reversible, bool)                 \
    X(self_starting, bool)                   \
    X(uniform_steps, bool)                   \
    X(system, odestep::system_form)          \
    X(velocity_forces, bool)                 \
    X(implicit, bool)

/// \brief A trait's value by name, for odestep::stepper_traits: `trait::order<2>`, `trait::symplectic<true>`,
/// one template per trait of stepper_defaults (`order`, `stages`, `rhs_evals_per_step`, `error_estimate`,
/// `embedded_order`, `rhs_evals_per_error_step`, `symplectic`, `time_reversible`, `self_starting`,
/// `uniform_steps`, `system`, `velocity_forces`, `implicit`), each with a member `value`.
namespace trait {
#define ODESTEP_DETAIL_TRAIT_TAG(name, type) \
    template <type V>                        \
    struct name {                            \
        static constexpr type value = V;     \
    };
ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_TAG)
#undef ODESTEP_DETAIL_TRAIT_TAG
}  // namespace trait

namespace detail {

template <class...>
inline constexpr bool always_false = false;

// has_<trait>: S publishes the trait; names_<trait>: N is odestep::trait::<trait><V> (is), and V (v).
#define ODESTEP_DETAIL_TRAIT_DETECTORS(name, type)                            \
    template <class S, class = void>                                          \
    struct has_##name : std::false_type {};                                   \
    template <class S>                                                        \
    struct has_##name<S, std::void_t<decltype(S::name)>> : std::true_type {}; \
    template <class N>                                                        \
    struct names_##name {                                                     \
        static constexpr bool is = false;                                     \
        static constexpr type v{};                                            \
    };                                                                        \
    template <type V>                                                         \
    struct names_##name<::odestep::trait::name<V>> {                          \
        static constexpr bool is = true;                                      \
        static constexpr type v = V;                                          \
    };
ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_DETECTORS)
#undef ODESTEP_DETAIL_TRAIT_DETECTORS

template <class S, class = void>
struct has_state_type : std::false_type {};
template <class S>
struct has_state_type<S, std::void_t<typename S::state_type, typename S::value_type>> : std::true_type {};

// What diagnose() reports: the types, one code per trait of the list (trait_missing_<name>), the values.
enum trait_code : int {
    trait_ok = 0,
    trait_types,
    trait_state_not_array,
#define ODESTEP_DETAIL_TRAIT_CODE(name, type) trait_missing_##name,
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_CODE)
#undef ODESTEP_DETAIL_TRAIT_CODE
        trait_order_below_one,
    trait_evals_below_one,
    trait_estimate_incomplete
};

// The first trait of the list that S does not publish (trait_ok: none).
template <class S>
constexpr int first_absent_trait() noexcept {
    int code = trait_ok;
#define ODESTEP_DETAIL_TRAIT_ABSENT(name, type) \
    if (code == trait_ok && !has_##name<S>::value) code = trait_missing_##name;
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_ABSENT)
#undef ODESTEP_DETAIL_TRAIT_ABSENT
    return code;
}

// Which requirement a stepper type misses first (trait_ok: none).
template <class S>
constexpr int first_missing_trait() noexcept {
    if constexpr (!has_state_type<S>::value)
        return trait_types;
    else if constexpr (!is_state_v<typename S::state_type>)
        return trait_state_not_array;
    else if constexpr (!std::is_same_v<typename S::value_type,
                                       typename state_traits<typename S::state_type>::value_type>)
        return trait_types;
    else if constexpr (first_absent_trait<S>() != trait_ok)
        return first_absent_trait<S>();
    else if constexpr (!(S::order >= 1))
        return trait_order_below_one;
    else if constexpr (!(S::rhs_evals_per_step >= 1))
        return trait_evals_below_one;
    else if constexpr (S::error_estimate && !(S::embedded_order >= 1 && S::rhs_evals_per_error_step >= 1))
        return trait_estimate_incomplete;
    else
        return trait_ok;
}

template <class S>
constexpr bool diagnose() noexcept {
    constexpr int code = first_missing_trait<S>();
    // The state is not a std::array<T, N>: state_traits says so, in one line.
    if constexpr (code == trait_state_not_array) return sizeof(state_traits<typename S::state_type>) == 0;
    static_assert(code != trait_types,
                  "odestep: a stepper needs `using state_type = std::array<T, N>;` and `using value_type = T;`");
#define ODESTEP_DETAIL_TRAIT_MESSAGE(name, type)                                                              \
    static_assert(code != trait_missing_##name, "odestep: a stepper needs `static constexpr " #type " " #name \
                                                "` (derive from odestep::stepper_defaults<State>)");
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_MESSAGE)
#undef ODESTEP_DETAIL_TRAIT_MESSAGE
    static_assert(code != trait_order_below_one, "odestep: a stepper's `order` must be at least 1");
    static_assert(code != trait_evals_below_one, "odestep: a stepper's `rhs_evals_per_step` must be at least 1");
    static_assert(code != trait_estimate_incomplete,
                  "odestep: a stepper with `error_estimate` states `embedded_order` and `rhs_evals_per_error_step`");
    return code == trait_ok;
}

// The value Named... give a trait (Names: its names_<trait>), else `fallback`.
template <template <class> class Names, class Type, class... Named>
constexpr Type named_or(Type fallback) noexcept {
    Type r = fallback;
    ((r = Names<Named>::is ? Names<Named>::v : r), ...);
    return r;
}

// N names a trait of the list, and Named... name each trait at most once.
template <class N>
constexpr bool is_trait_name() noexcept {
    bool r = false;
#define ODESTEP_DETAIL_TRAIT_IS_NAME(name, type) r = r || names_##name<N>::is;
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_IS_NAME)
#undef ODESTEP_DETAIL_TRAIT_IS_NAME
    return r;
}
template <class... Named>
constexpr bool each_trait_once() noexcept {
    bool r = true;
#define ODESTEP_DETAIL_TRAIT_ONCE(name, type) r = r && (0 + ... + (names_##name<Named>::is ? 1 : 0)) <= 1;
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_TRAIT_ONCE)
#undef ODESTEP_DETAIL_TRAIT_ONCE
    return r;
}

}  // namespace detail

/// \brief stepper_defaults with the traits `Named...` (odestep::trait) set by name, each at most once:
/// `stepper_traits<State, trait::order<2>, trait::symplectic<true>>` is stepper_defaults<State> with
/// `order` 2 and `symplectic` true. A stepper derives from it instead of positional template arguments.
template <class State, class... Named>
struct stepper_traits : stepper_defaults<State> {
    static_assert((detail::is_trait_name<Named>() && ...),
                  "odestep: stepper_traits takes odestep::trait::<name><value> arguments only");
    static_assert(detail::each_trait_once<Named...>(), "odestep: stepper_traits names each trait at most once");
#define ODESTEP_DETAIL_NAMED_TRAIT(name, type) \
    static constexpr type name = detail::named_or<detail::names_##name, type, Named...>(stepper_defaults<State>::name);
    ODESTEP_DETAIL_STEPPER_TRAITS(ODESTEP_DETAIL_NAMED_TRAIT)
#undef ODESTEP_DETAIL_NAMED_TRAIT
};

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
