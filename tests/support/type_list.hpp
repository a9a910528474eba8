// Iteration over a list of types (a std::tuple of them), for tests that run over every method of a family.
#ifndef ODESTEP_TESTS_SUPPORT_TYPE_LIST_HPP
#define ODESTEP_TESTS_SUPPORT_TYPE_LIST_HPP

#include <tuple>

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

}  // namespace odestep_test

#endif
