// SPDX-License-Identifier: BSL-1.0
// odestep: the state type, std::array<T, N> with T float, double or long double.
#ifndef ODESTEP_STATE_HPP
#define ODESTEP_STATE_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "config.hpp"

namespace odestep {

/// The scalar types the library is written for.
template <class T>
inline constexpr bool is_scalar_v =
    std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>;

/// True for the types odestep integrates: std::array<T, N> with T float, double or long double and N > 0.
template <class State>
inline constexpr bool is_state_v = false;
template <class T, std::size_t N>
inline constexpr bool is_state_v<std::array<T, N>> = is_scalar_v<T>&& N > 0;

namespace detail {
template <class State>
struct state_shape {
    using value_type = float;  // (anything: only reached after the static_assert below has failed)
    static constexpr std::size_t size = 1;
};
template <class T, std::size_t N>
struct state_shape<std::array<T, N>> {
    using value_type = T;
    static constexpr std::size_t size = N;
};
}  // namespace detail

/// The scalar type and the size of a state. Anything but std::array<T, N> (a std::vector, a C array, an
/// Eigen vector) fails here with one line: the state must be a fixed-size std::array, so that no step
/// allocates and the compiler sees the size.
template <class State>
struct state_traits : detail::state_shape<State> {
    static_assert(is_state_v<State>,
                  "odestep: a state is std::array<T, N> with T float, double or long double and N > 0");
};

/// The scalar type T of a state std::array<T, N>.
template <class State>
using value_type_t = typename state_traits<State>::value_type;

}  // namespace odestep

#endif
