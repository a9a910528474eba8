// SPDX-License-Identifier: BSL-1.0
// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, Forest-Ruth (fourth order: four drifts and three kicks, three evaluations of the
// force per step, nothing kept between steps), fixed step. Odeint has no Forest-Ruth: its nearest
// fourth-order symplectic method, symplectic_rkn_sb3a_m4_mclachlan (McLachlan's, five drift-kick stages whose
// last kick has coefficient 0 but is evaluated all the same: five evaluations), stands in, checked
// against the reference only. GSL odeiv2 has no symplectic method: no GSL variant. The reference is the
// closed-form solution (Kepler's equation by Newton's method).
// The McLachlan header uses symplectic_nystroem_stepper_base without including it (Boost 1.74, still in
// 1.86): its base first.
#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>

#include <utility>

#include "hand.hpp"
#include "harness.hpp"
#include "kepler.hpp"
#include "problems.hpp"

namespace {
using bench::kepler_case::vec;
using State = bench::kepler_case::phase;
using bench::kepler_case::force;
using bench::kepler_case::hand_force;
// Odeint's symplectic steppers take a force of position alone as a(q, dpdt), without t.
constexpr auto odeint_force = [](const vec& x, vec& a) { bench::kepler<double>(x, a); };

boost::numeric::odeint::symplectic_rkn_sb3a_m4_mclachlan<vec> odeint_mclachlan;
}  // namespace

BENCH_STEP int bench_step_kepler_forest_ruth_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::forest_ruth<vec>{}.step(force, y.first, y.second, t, dt));
}
BENCH_STEP int bench_step_kepler_forest_ruth_hand(State& y, State&, double t, double dt) {
    bench::hand::forest_ruth(hand_force, y.first, y.second, t, dt);
    return 0;
}
BENCH_STEP int bench_step_kepler_forest_ruth_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::forest_ruth_checked(hand_force, y.first, y.second, t, dt);
}
BENCH_STEP int bench_step_kepler_forest_ruth_odeint(State& y, State&, double t, double dt) {
    std::pair<vec, vec>& xv = y;  // Odeint's state for its symplectic steppers: the pair (positions, momenta)
    odeint_mclachlan.do_step(odeint_force, xv, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const bench::problem<State> p =
        bench::kepler_case::problem("kepler_forest_ruth",
                                    // Round-off: 500 steps of the same seven updates, with the same coefficients
                                    // rounded the same way, in the same order; measured 0 (bit for bit) at -O2 and -Os.
                                    1e-12,
                                    // Forest-Ruth (order 4) with 1000 steps per orbit: 6.09e-8 relative at aphelion
                                    // (3.81e-9 with 2000 steps, 2.38e-10 with 4000: h^4); Odeint's McLachlan method
                                    // 2.56e-9 (1.60e-10, 1.00e-11: h^4). Position Verlet (order 2) with the same
                                    // step is 1.2e-4 off.
                                    2e-7);
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::forest_ruth<std::array<double, 2>> step(a, x, v, t, dt) (3 evaluations)",
          bench_step_kepler_forest_ruth_odestep, true},
         {"hand", "hand-written Forest-Ruth, the 7 updates written out (3 evaluations)",
          bench_step_kepler_forest_ruth_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new x or v fails the step, which is rolled back (hand.hpp "
          "forest_ruth_checked)",
          bench_step_kepler_forest_ruth_hand_checked, true},
         {"odeint",
          "Odeint symplectic_rkn_sb3a_m4_mclachlan on std::pair (x, v) (no Forest-Ruth in Odeint; 5 evaluations)",
          bench_step_kepler_forest_ruth_odeint, false}});
}
