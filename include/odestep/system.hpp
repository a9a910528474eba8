// SPDX-License-Identifier: BSL-1.0
// odestep: the forms of system a stepper takes, and how each is called. Every accepted signature is
// detected at compile time, so the choice costs nothing at run time.
#ifndef ODESTEP_SYSTEM_HPP
#define ODESTEP_SYSTEM_HPP

#include <array>
#include <type_traits>
#include <utility>

#include "state.hpp"

namespace odestep {

/// The form of system a stepper integrates (its trait `system`).
enum class system_form : unsigned char {
    first_order,       ///< y' = f(t, y): `State f(T t, const State& y)` or `void f(T t, const State& y, State& dydt)`
    newtonian,         ///< x'' = a: `State a(T t, const State& x)`, or `State a(T t, const State& x, const State& v)`
                       ///< where the stepper accepts it; or either in place, `void a(T t, const State& x,
                       ///< State& a_out)`, `void a(T t, const State& x, const State& v, State& a_out)`
    charged_particle,  ///< dv/dt = (q/m)(E + v x B): `void fields(T t, const State& x, State& E, State& B)`
};

// ---- first order: y' = f(t, y)

/// True when `f(t, y, dydt)` writes the derivative into its third argument.
template <class System, class State, class T = value_type_t<State>>
inline constexpr bool is_inplace_system_v = std::is_invocable_v<System&, T, const State&, State&>;

namespace detail {
template <class System, class State, class T, class = void>
struct returns_state : std::false_type {};
template <class System, class State, class T>
struct returns_state<System, State, T,
                     std::enable_if_t<std::is_convertible_v<std::invoke_result_t<System&, T, const State&>, State>>>
    : std::true_type {};
}  // namespace detail

/// True when `dydt = f(t, y)` returns the derivative.
template <class System, class State, class T = value_type_t<State>>
inline constexpr bool is_returning_system_v = detail::returns_state<System, State, T>::value;

/// A first-order system y' = f(t, y) in either accepted form.
template <class System, class State>
inline constexpr bool is_system_v = is_inplace_system_v<System, State> || is_returning_system_v<System, State>;

// ---- the Jacobian of a first-order system, for the implicit methods

/// The Jacobian of f at a state: dfdy[i][j] = d f_i / d y_j, an N x N std::array (std::array<State, N>).
template <class State>
using jacobian_t = std::array<State, state_traits<State>::size>;

namespace detail {
template <class System, class State, class T, class = void>
struct inplace_jacobian : std::false_type {};
template <class System, class State, class T>
struct inplace_jacobian<System, State, T,
                        std::void_t<decltype(std::declval<System&>().jacobian(
                            std::declval<T>(), std::declval<const State&>(), std::declval<jacobian_t<State>&>()))>>
    : std::true_type {};
template <class System, class State, class T, class = void>
struct returning_jacobian : std::false_type {};
template <class System, class State, class T>
struct returning_jacobian<System, State, T,
                          std::enable_if_t<std::is_convertible_v<decltype(std::declval<System&>().jacobian(
                                                                     std::declval<T>(), std::declval<const State&>())),
                                                                 jacobian_t<State>>>> : std::true_type {};
}  // namespace detail

/// True when the system carries its Jacobian: a member `jacobian(t, y, dfdy)` writing d f / d y into an
/// odestep::jacobian_t<State>, or `jacobian(t, y)` returning one. odestep::with_jacobian(f, J) makes such a
/// system from two callables. The implicit steppers then call it once per step instead of approximating
/// the Jacobian by differences (N evaluations of f); every other stepper and loop sees only f.
template <class System, class State, class T = value_type_t<State>>
inline constexpr bool has_jacobian_v =
    detail::inplace_jacobian<System, State, T>::value || detail::returning_jacobian<System, State, T>::value;

/// \brief A right-hand side f together with its Jacobian J, as one system object.
///
/// Made by odestep::with_jacobian. It is called as f (either form, whichever f has), so it goes wherever a
/// system goes: `integrate`, `integrate_n_steps`, the event loops, any stepper. Its `jacobian(t, y, dfdy)`
/// calls J as `J(t, y, dfdy)` (or `dfdy = J(t, y)`). A callable given as an lvalue is held by reference,
/// one given as an rvalue (a lambda written in the call) is moved in, so the object never dangles.
///
/// Why one object and not a second argument to step(): the driving loops and the event loop call
/// `stepper.step(f, y, t, dt)` for every stepper; a system that carries its Jacobian passes through all of
/// them unchanged, and the choice between the user's J and differences is made at compile time.
template <class F, class J>
struct system_with_jacobian {
    F f;    ///< the right-hand side, f(t, y) or f(t, y, dydt)
    J jac;  ///< the Jacobian, J(t, y, dfdy) or dfdy = J(t, y)

    /// dydt = f(t, y) (when f returns the derivative).
    template <class T, class State>
    constexpr auto operator()(T t, const State& y) -> decltype(std::declval<F&>()(t, y)) {
        return f(t, y);
    }
    /// f(t, y, dydt) (when f writes the derivative).
    template <class T, class State>
    constexpr auto operator()(T t, const State& y, State& dydt) -> decltype(std::declval<F&>()(t, y, dydt)) {
        return f(t, y, dydt);
    }
    /// The same through a const object (a callable held by reference is still called as it is).
    template <class T, class State>
    constexpr auto operator()(T t, const State& y) const -> decltype(std::declval<const F&>()(t, y)) {
        return f(t, y);
    }
    /// The same through a const object.
    template <class T, class State>
    constexpr auto operator()(T t, const State& y, State& dydt) const
        -> decltype(std::declval<const F&>()(t, y, dydt)) {
        return f(t, y, dydt);
    }
    /// J(t, y, dfdy) (when J writes the Jacobian).
    template <class T, class State, class M>
    constexpr auto jacobian(T t, const State& y, M& dfdy) -> decltype(std::declval<J&>()(t, y, dfdy)) {
        return jac(t, y, dfdy);
    }
    /// dfdy = J(t, y) (when J returns the Jacobian).
    template <class T, class State>
    constexpr auto jacobian(T t, const State& y) -> decltype(std::declval<J&>()(t, y)) {
        return jac(t, y);
    }
    /// The same through a const object.
    template <class T, class State, class M>
    constexpr auto jacobian(T t, const State& y, M& dfdy) const -> decltype(std::declval<const J&>()(t, y, dfdy)) {
        return jac(t, y, dfdy);
    }
    /// The same through a const object.
    template <class T, class State>
    constexpr auto jacobian(T t, const State& y) const -> decltype(std::declval<const J&>()(t, y)) {
        return jac(t, y);
    }
};

/// Pairs a right-hand side with its Jacobian, `J(T t, const State& y, odestep::jacobian_t<State>& dfdy)`
/// writing dfdy[i][j] = d f_i / d y_j (or returning the matrix from `J(t, y)`):
///
/// \code
/// auto sys = odestep::with_jacobian(f, [](double, const state& y, odestep::jacobian_t<state>& J) { ... });
/// auto r = odestep::integrate(odestep::radau_iia5<state>{}, sys, y, 0.0, 40.0, 0.1);
/// \endcode
template <class F, class J>
constexpr system_with_jacobian<F, J> with_jacobian(F&& f, J&& jacobian) {
    return {std::forward<F>(f), std::forward<J>(jacobian)};
}

// ---- Newton's equations: x'' = a(t, x) or a(t, x, v), returned or written in place

namespace detail {
// The in-place forms: callable with a State& to write into, and returning void (or anything but a State).
template <class Accel, class State, class T, class = void>
struct inplace_position_force : std::false_type {};
template <class Accel, class State, class T>
struct inplace_position_force<
    Accel, State, T,
    std::enable_if_t<!std::is_convertible_v<std::invoke_result_t<Accel&, T, const State&, State&>, State>>>
    : std::true_type {};
template <class Accel, class State, class T, class = void>
struct inplace_velocity_force : std::false_type {};
template <class Accel, class State, class T>
struct inplace_velocity_force<Accel, State, T,
                              std::enable_if_t<!std::is_convertible_v<
                                  std::invoke_result_t<Accel&, T, const State&, const State&, State&>, State>>>
    : std::true_type {};
template <class Accel, class State, class T, class = void>
struct returning_position_force : std::false_type {};
template <class Accel, class State, class T>
struct returning_position_force<
    Accel, State, T, std::enable_if_t<std::is_convertible_v<std::invoke_result_t<Accel&, T, const State&>, State>>>
    : std::true_type {};
template <class Accel, class State, class T, class = void>
struct returning_velocity_force_call : std::false_type {};
template <class Accel, class State, class T>
struct returning_velocity_force_call<
    Accel, State, T,
    std::enable_if_t<std::is_convertible_v<std::invoke_result_t<Accel&, T, const State&, const State&>, State>>>
    : std::true_type {};
// `State a(t, x, v)` has the arity of the in-place `a(t, x, a_out)`: the in-place form is asked first, and
// the returning one only where it is not (std::conjunction instantiates no further), so that a generic
// `a(auto t, const auto& x, auto& out)` is never called with a const out, which would not compile.
template <class Accel, class State, class T>
struct returning_velocity_force : std::conjunction<std::negation<inplace_position_force<Accel, State, T>>,
                                                   returning_velocity_force_call<Accel, State, T>> {};
}  // namespace detail

/// True when the acceleration is written `void a(T t, const State& x, State& a_out)`: a force of position
/// alone, written into its last argument (no State returned: what a large state wants).
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_inplace_position_force_v = detail::inplace_position_force<Accel, State, T>::value;

/// True when the acceleration is written `void a(T t, const State& x, const State& v, State& a_out)`.
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_inplace_velocity_force_v = detail::inplace_velocity_force<Accel, State, T>::value;

/// True when the acceleration is a force of position alone, `State a(T t, const State& x)` or
/// `void a(T t, const State& x, State& a_out)`: the case in which splitting methods are symplectic.
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_position_force_v =
    detail::returning_position_force<Accel, State, T>::value || is_inplace_position_force_v<Accel, State, T>;

/// True when the acceleration is written `State a(T t, const State& x, const State& v)` or
/// `void a(T t, const State& x, const State& v, State& a_out)`.
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_velocity_force_v =
    detail::returning_velocity_force<Accel, State, T>::value || is_inplace_velocity_force_v<Accel, State, T>;

/// A Newtonian system x'' = a(...) in any accepted form.
template <class Accel, class State>
inline constexpr bool is_newtonian_system_v = is_position_force_v<Accel, State> || is_velocity_force_v<Accel, State>;

// ---- a charged particle: the electric and magnetic fields

/// True when `fields(t, x, E, B)` writes the electric and magnetic fields at (t, x) into E and B.
template <class Fields, class State, class T = value_type_t<State>>
inline constexpr bool is_em_fields_v = std::is_invocable_v<Fields&, T, const State&, State&, State&>;

namespace detail {

// dydt = f(t, y), whichever form the user wrote. The in-place form wins if a callable offers both.
template <class System, class State, class T>
constexpr void evaluate(System& f, T t, const State& y, State& dydt) {
    if constexpr (is_inplace_system_v<System, State, T>) {
        f(t, y, dydt);
    } else if constexpr (is_returning_system_v<System, State, T>) {
        dydt = f(t, y);
    } else {
        static_assert(is_system_v<System, State>,
                      "odestep: the right-hand side must be callable as `State f(T t, const State& y)` "
                      "or `void f(T t, const State& y, State& dydt)`, with State = std::array<T, N>");
    }
}

// dfdy = the system's own Jacobian at (t, y), whichever form it has (only for has_jacobian_v systems).
template <class System, class State, class T>
constexpr void evaluate_jacobian(System& f, T t, const State& y, jacobian_t<State>& dfdy) {
    if constexpr (inplace_jacobian<System, State, T>::value) {
        f.jacobian(t, y, dfdy);
    } else {
        static_assert(returning_jacobian<System, State, T>::value,
                      "odestep: the system's Jacobian must be callable as `jacobian(T t, const State& y, "
                      "odestep::jacobian_t<State>& dfdy)` or `jacobian_t<State> jacobian(T t, const State& y)`");
        dfdy = f.jacobian(t, y);
    }
}

// a(t, x) for the methods that need a force of position alone.
template <class Accel, class State, class T>
constexpr State acceleration(Accel& a, T t, const State& x) {
    if constexpr (is_inplace_position_force_v<Accel, State, T>) {
        State out;  // written by a
        a(t, x, out);
        return out;
    } else if constexpr (is_position_force_v<Accel, State, T>) {
        return a(t, x);
    } else {
        static_assert(is_position_force_v<Accel, State, T>,
                      "odestep: this method needs a force of position alone, written `State a(T t, const State& x)` "
                      "or `void a(T t, const State& x, State& a_out)`");
        return x;
    }
}

// a(t, x, v), whichever form the user wrote (a position-only force ignores v). An in-place form writes into
// the returned object itself (named return value: no copy).
template <class Accel, class State, class T>
constexpr State acceleration(Accel& a, T t, const State& x, const State& v) {
    if constexpr (is_inplace_velocity_force_v<Accel, State, T>) {
        State out;  // written by a
        a(t, x, v, out);
        return out;
    } else if constexpr (is_velocity_force_v<Accel, State, T>) {
        return a(t, x, v);
    } else if constexpr (is_position_force_v<Accel, State, T>) {
        (void)v;
        return acceleration(a, t, x);
    } else {
        static_assert(is_newtonian_system_v<Accel, State>,
                      "odestep: the acceleration must be callable as `State a(T t, const State& x, const State& v)`, "
                      "`State a(T t, const State& x)`, or in place as `void a(T t, const State& x, const State& v, "
                      "State& a_out)` or `void a(T t, const State& x, State& a_out)`, with State = std::array<T, N>");
        return x;
    }
}

// out = a(t, x, v) (a position-only force ignores v), written straight into out by an in-place force, so
// that a large state is neither returned by value nor copied. out is not x or v.
template <class Accel, class State, class T>
ODESTEP_INLINE constexpr void accelerate(Accel& a, T t, const State& x, const State& v, State& out) {
    if constexpr (is_inplace_velocity_force_v<Accel, State, T>) {
        a(t, x, v, out);
    } else if constexpr (!is_velocity_force_v<Accel, State, T> && is_inplace_position_force_v<Accel, State, T>) {
        (void)v;
        a(t, x, out);
    } else {
        out = acceleration(a, t, x, v);
    }
}

}  // namespace detail
}  // namespace odestep

#endif
