// SPDX-License-Identifier: BSL-1.0
// Iteration over a list of types (a std::tuple of them), for tests that run over every method of a family.
#ifndef ODESTEP_TESTS_SUPPORT_TYPE_LIST_HPP
#define ODESTEP_TESTS_SUPPORT_TYPE_LIST_HPP

#include <tuple>
#include <utility>

namespace odestep_test {

/// Calls f(Type{}) for every Type of the std::tuple `pointer` points to (only its type is used), in order.
template <class F, class... Types>
constexpr void for_each_type_in(F&& f, std::tuple<Types...>*) {
    (f(Types{}), ...);
}

/// Calls f(Type{}) for every Type of the std::tuple List, in order: f's parameter is `auto`, and
/// decltype(parameter) is the type.
template <class List, class F>
constexpr void for_each_type(F&& f) {
    for_each_type_in(f, static_cast<List*>(nullptr));
}

namespace detail {
/// The work of odestep_test::steppers_of: unpacks the std::tuple of methods.
template <template <class...> class Stepper, class Methods, class State>
struct steppers_of;
template <template <class...> class Stepper, class... Methods, class State>
struct steppers_of<Stepper, std::tuple<Methods...>, State> {
    using type = std::tuple<Stepper<Methods, State>...>;
};
}  // namespace detail

/// std::tuple<Stepper<Method, State>...> for the std::tuple<Method...> Methods: a family's steppers on one
/// state type, from its list of tables (steppers_of<odestep::adams, adams_methods, S>).
template <template <class...> class Stepper, class Methods, class State>
using steppers_of = typename detail::steppers_of<Stepper, Methods, State>::type;

/// One std::tuple of the types of the std::tuples Lists, in order.
template <class... Lists>
using concat = decltype(std::tuple_cat(std::declval<Lists>()...));

}  // namespace odestep_test

#endif
