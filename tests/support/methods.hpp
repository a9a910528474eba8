// The table library as one type list, for tests that run over every method.
#ifndef ODESTEP_TESTS_METHODS_HPP
#define ODESTEP_TESTS_METHODS_HPP

#include <odestep/tableaux.hpp>
#include <tuple>

#include "type_list.hpp"

namespace odestep_test {

/// Every explicit Runge-Kutta table of the library, in the order of tableaux.hpp.
using all_methods =
    std::tuple<odestep::tableaux::euler, odestep::tableaux::midpoint, odestep::tableaux::heun,
               odestep::tableaux::ralston2, odestep::tableaux::kutta3, odestep::tableaux::ssprk3,
               odestep::tableaux::rk4, odestep::tableaux::rk38, odestep::tableaux::bogacki_shampine32,
               odestep::tableaux::fehlberg45, odestep::tableaux::cash_karp54, odestep::tableaux::dormand_prince54,
               odestep::tableaux::fehlberg78, odestep::tableaux::dop853>;

/// Calls f(Method{}) for every method of all_methods, in the order above.
template <class F>
void for_each_method(F&& f) {
    for_each_type<all_methods>(f);
}

}  // namespace odestep_test

#endif
