// SPDX-License-Identifier: BSL-1.0
// The library's method families as type lists, for tests that run over every method of a family (with
// for_each_type, type_list.hpp): a method added to the library is added here once, and every test that
// iterates the family covers it.
#ifndef ODESTEP_TESTS_METHODS_HPP
#define ODESTEP_TESTS_METHODS_HPP

#include <odestep/bracket.hpp>
#include <odestep/multistep.hpp>
#include <odestep/newtonian.hpp>
#include <odestep/symplectic.hpp>
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

/// Every Adams table (odestep::adams<Table, State>).
using adams_methods =
    std::tuple<odestep::adams_tables::bashforth2, odestep::adams_tables::bashforth3, odestep::adams_tables::bashforth4,
               odestep::adams_tables::bashforth5, odestep::adams_tables::bashforth_moulton4>;

/// Every splitting table (odestep::splitting<Table, State>).
using splitting_methods =
    std::tuple<odestep::splittings::euler_cromer, odestep::splittings::euler_cromer_drift_first,
               odestep::splittings::velocity_verlet, odestep::splittings::position_verlet,
               odestep::splittings::forest_ruth, odestep::splittings::yoshida6, odestep::splittings::blanes_moan4>;

/// Every textbook Newtonian stepper that is not a splitting (newtonian/classic.hpp), on State.
template <class State>
using classic_newtonian_steppers =
    std::tuple<odestep::newtonian_euler<State>, odestep::newtonian_midpoint<State>,
               odestep::newtonian_euler_richardson<State>, odestep::half_step<State>,
               odestep::leapfrog_position_form<State>, odestep::beeman<State>, odestep::predictor_corrector<State>>;

/// The Adams steppers on State (default starter).
template <class State>
using adams_steppers = steppers_of<odestep::adams, adams_methods, State>;

/// The splitting steppers on State.
template <class State>
using splitting_steppers = steppers_of<odestep::splitting, splitting_methods, State>;

/// Every Newtonian stepper on State whose force is a(t, x): the classic ones, then the splittings (the Boris
/// pushers, which take fields, are not among them).
template <class State>
using newtonian_steppers = concat<classic_newtonian_steppers<State>, splitting_steppers<State>>;

/// Every bracketing root finder (roots/bracket.hpp).
using root_finders =
    std::tuple<odestep::bisection, odestep::illinois, odestep::anderson_bjorck, odestep::brent, odestep::itp>;

}  // namespace odestep_test

#endif
