// odestep: the forms of system a stepper takes, and how each is called. Every accepted signature is
// detected at compile time, so the choice costs nothing at run time.
#ifndef ODESTEP_SYSTEM_HPP
#define ODESTEP_SYSTEM_HPP

#include <type_traits>
#include <utility>

#include "state.hpp"

namespace odestep {

/// The form of system a stepper integrates (its trait `system`).
enum class system_form : unsigned char {
    first_order,       ///< y' = f(t, y): `State f(T t, const State& y)` or `void f(T t, const State& y, State& dydt)`
    newtonian,         ///< x'' = a: `State a(T t, const State& x)`, or `State a(T t, const State& x, const State& v)`
                       ///< where the stepper accepts it
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

// ---- Newton's equations: x'' = a(t, x) or a(t, x, v)

namespace detail {
template <class Accel, class State, class T, class = void>
struct position_force : std::false_type {};
template <class Accel, class State, class T>
struct position_force<Accel, State, T,
                      std::enable_if_t<std::is_convertible_v<std::invoke_result_t<Accel&, T, const State&>, State>>>
    : std::true_type {};
template <class Accel, class State, class T, class = void>
struct velocity_force : std::false_type {};
template <class Accel, class State, class T>
struct velocity_force<
    Accel, State, T,
    std::enable_if_t<std::is_convertible_v<std::invoke_result_t<Accel&, T, const State&, const State&>, State>>>
    : std::true_type {};
}  // namespace detail

/// True when the acceleration is written `State a(T t, const State& x)`: a force of position alone, the
/// case in which splitting methods are symplectic.
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_position_force_v = detail::position_force<Accel, State, T>::value;

/// True when the acceleration is written `State a(T t, const State& x, const State& v)`.
template <class Accel, class State, class T = value_type_t<State>>
inline constexpr bool is_velocity_force_v = detail::velocity_force<Accel, State, T>::value;

/// A Newtonian system x'' = a(...) in either accepted form.
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

// a(t, x, v), whichever form the user wrote (a position-only force ignores v).
template <class Accel, class State, class T>
constexpr State acceleration(Accel& a, T t, const State& x, const State& v) {
    if constexpr (is_velocity_force_v<Accel, State, T>) {
        return a(t, x, v);
    } else if constexpr (is_position_force_v<Accel, State, T>) {
        (void)v;
        return a(t, x);
    } else {
        static_assert(is_newtonian_system_v<Accel, State>,
                      "odestep: the acceleration must be callable as `State a(T t, const State& x, const State& v)` "
                      "or `State a(T t, const State& x)`, with State = std::array<T, N>");
        return x;
    }
}

// a(t, x) for the methods that need a force of position alone.
template <class Accel, class State, class T>
constexpr State acceleration(Accel& a, T t, const State& x) {
    if constexpr (is_position_force_v<Accel, State, T>) {
        return a(t, x);
    } else {
        static_assert(is_position_force_v<Accel, State, T>,
                      "odestep: this method needs a force of position alone, written `State a(T t, const State& x)`");
        return x;
    }
}

}  // namespace detail
}  // namespace odestep

#endif
