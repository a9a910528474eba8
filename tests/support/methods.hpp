// SPDX-License-Identifier: BSL-1.0
// The library's method families as type lists, for tests that run over every method of a family (with
// for_each_type, type_list.hpp): a method added to the library is added here once, and every test that
// iterates the family covers it.
#ifndef ODESTEP_TESTS_METHODS_HPP
#define ODESTEP_TESTS_METHODS_HPP

#include <odestep/multistep/adams.hpp>
#include <odestep/newtonian/classic.hpp>
#include <odestep/newtonian/splitting.hpp>
#include <odestep/roots/bracket.hpp>
#include <odestep/tables/runge_kutta.hpp>
#include <tuple>

#include "type_list.hpp"

namespace odestep_test {

/// Every explicit Runge-Kutta table of the library, in the order of tableaux.hpp.
using all_methods =
    std::tuple<odestep::tables::euler, odestep::tables::midpoint, odestep::tables::heun, odestep::tables::ralston2,
               odestep::tables::kutta3, odestep::tables::ssprk3, odestep::tables::rk4, odestep::tables::rk38,
               odestep::tables::bogacki_shampine32, odestep::tables::fehlberg45, odestep::tables::cash_karp54,
               odestep::tables::dormand_prince54, odestep::tables::fehlberg78, odestep::tables::dop853>;

/// Calls f(Method{}) for every method of all_methods, in the order above.
template <class F>
void for_each_method(F&& f) {
    for_each_type<all_methods>(f);
}

/// Every Adams table (odestep::adams<Table, State>).
using adams_methods = std::tuple<odestep::tables::bashforth2, odestep::tables::bashforth3, odestep::tables::bashforth4,
                                 odestep::tables::bashforth5, odestep::tables::bashforth_moulton4>;

/// Every splitting table (odestep::splitting<Table, State>).
using splitting_methods =
    std::tuple<odestep::tables::euler_cromer, odestep::tables::euler_cromer_drift_first,
               odestep::tables::velocity_verlet, odestep::tables::position_verlet, odestep::tables::forest_ruth,
               odestep::tables::yoshida6, odestep::tables::blanes_moan4>;

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
