// odestep: how a user's right-hand side is called. Both common signatures are accepted and the choice is
// made at compile time, so neither costs anything at run time.
#ifndef ODESTEP_SYSTEM_HPP
#define ODESTEP_SYSTEM_HPP

#include <type_traits>
#include <utility>

namespace odestep {

/// True when `f(t, y, dydt)` writes the derivative into its third argument.
template <class System, class State, class T = typename State::value_type>
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
template <class System, class State, class T = typename State::value_type>
inline constexpr bool is_returning_system_v = detail::returns_state<System, State, T>::value;

/// A first-order system y' = f(t, y) in either accepted form.
template <class System, class State>
inline constexpr bool is_system_v = is_inplace_system_v<System, State> || is_returning_system_v<System, State>;

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

}  // namespace detail
}  // namespace odestep

#endif
