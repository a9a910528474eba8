// The table library as one type list, for tests that run over every method.
#ifndef ODESTEP_TESTS_METHODS_HPP
#define ODESTEP_TESTS_METHODS_HPP

#include <odestep/tableaux.hpp>
#include <tuple>

namespace odestep_test {

using all_methods =
    std::tuple<odestep::tableaux::euler, odestep::tableaux::midpoint, odestep::tableaux::heun,
               odestep::tableaux::ralston2, odestep::tableaux::kutta3, odestep::tableaux::ssprk3,
               odestep::tableaux::rk4, odestep::tableaux::rk38, odestep::tableaux::bogacki_shampine32,
               odestep::tableaux::fehlberg45, odestep::tableaux::cash_karp54, odestep::tableaux::dormand_prince54,
               odestep::tableaux::fehlberg78, odestep::tableaux::dop853>;

// Calls f(Method{}) for every method, in the order above.
template <class F, class... M>
void for_each_method_in(F&& f, std::tuple<M...>*) {
    (f(M{}), ...);
}
template <class F>
void for_each_method(F&& f) {
    for_each_method_in(f, static_cast<all_methods*>(nullptr));
}

}  // namespace odestep_test

#endif
