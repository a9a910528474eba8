// SPDX-License-Identifier: BSL-1.0
// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, Euler-Cromer (symplectic Euler, kick then drift: v += dt a(t, x), x += dt v), fixed
// step, one evaluation of the force per step and nothing kept between steps. Odeint's symplectic_euler on
// (x, v) is the other ordering, drift then kick (x += dt v, v += dt a(x); its symplectic_nystroem_stepper_base
// drifts first in every stage), the adjoint method: row `odeint_adjoint`, of the same order but another
// method, checked against the reference only. Row `odeint` is the same stepper with the roles swapped, which
// is Euler-Cromer (below). GSL odeiv2 has no symplectic method: no GSL variant. The reference is the
// closed-form solution (Kepler's equation by Newton's method).
#include <boost/numeric/odeint/stepper/symplectic_euler.hpp>

#include <functional>
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

// The same stepper with the roles of q and p swapped (q = v, p = x) is Euler-Cromer itself: given a pair of
// functions it first updates q with coor_func(p) (v += dt a(x)), then p with momentum_func at the new q
// (x += dt v_new); symplectic_euler's two coefficients are both 1 (Boost 1.74,
// symplectic_rkn_stepper_base.hpp, do_step_impl for a pair system).
constexpr auto odeint_kick = [](const vec& x, vec& dvdt) { bench::kepler<double>(x, dvdt); };
constexpr auto odeint_drift = [](const vec& v, vec& dxdt) { dxdt = v; };

boost::numeric::odeint::symplectic_euler<vec> odeint_se;
boost::numeric::odeint::symplectic_euler<vec> odeint_se_swapped;
}  // namespace

BENCH_STEP int bench_step_kepler_euler_cromer_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::euler_cromer<vec>{}.step(force, y.first, y.second, t, dt));
}
BENCH_STEP int bench_step_kepler_euler_cromer_hand(State& y, State&, double t, double dt) {
    bench::hand::euler_cromer(hand_force, y.first, y.second, t, dt);
    return 0;
}
BENCH_STEP int bench_step_kepler_euler_cromer_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::euler_cromer_checked(hand_force, y.first, y.second, t, dt);
}
BENCH_STEP int bench_step_kepler_euler_cromer_odeint_adjoint(State& y, State&, double t, double dt) {
    std::pair<vec, vec>& xv = y;  // Odeint's state for its symplectic steppers: the pair (positions, momenta)
    odeint_se.do_step(odeint_force, xv, t, dt);
    return 0;
}

BENCH_STEP int bench_step_kepler_euler_cromer_odeint(State& y, State&, double t, double dt) {
    // (q, p) = (v, x), held by std::ref, which Odeint unwraps: the caller's own arrays are stepped.
    odeint_se_swapped.do_step(std::make_pair(odeint_kick, odeint_drift),
                              std::make_pair(std::ref(y.second), std::ref(y.first)), t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const bench::problem<State> p =
        bench::kepler_case::problem("kepler_euler_cromer",
                                    // Round-off: 500 steps of the same two updates in the same order; measured 0
                                    // (bit for bit) at -O2 and -Os.
                                    1e-12,
                                    // Euler-Cromer (order 1) with 1000 steps per orbit: 1.88e-2 relative at
                                    // aphelion (9.54e-3 with 2000 steps, 4.80e-3 with 4000: h). Odeint's drift-first
                                    // adjoint: 1.99e-2 (9.81e-3, 4.87e-3; bit for bit odestep's
                                    // euler_cromer_drift_first, 3.9e-2 from Euler-Cromer). Forward Euler with the same
                                    // step is 9.7e-2 off.
                                    4e-2);
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::euler_cromer<std::array<double, 2>> step(a, x, v, t, dt)",
          bench_step_kepler_euler_cromer_odestep, true},
         {"hand", "hand-written Euler-Cromer loop (kick, then drift with the new v)",
          bench_step_kepler_euler_cromer_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new x or v fails the step, which is rolled back (hand.hpp "
          "euler_cromer_checked)",
          bench_step_kepler_euler_cromer_hand_checked, true},
         {"odeint_adjoint",
          "Odeint symplectic_euler<std::array<double, 2>> do_step on std::pair (x, v) (drift then kick: the adjoint)",
          bench_step_kepler_euler_cromer_odeint_adjoint, false},
         {"odeint",
          "the same Odeint stepper on (q, p) = (v, x) with the functions (a(x), v): kick then drift, Euler-Cromer",
          bench_step_kepler_euler_cromer_odeint, true}});
}
