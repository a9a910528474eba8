// SPDX-License-Identifier: BSL-1.0
// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, position Verlet (leapfrog, drift-kick-drift: x += dt/2 v, v += dt a(t + dt/2, x),
// x += dt/2 v), fixed step, one evaluation of the force per step and nothing kept between steps. Odeint has
// no position Verlet (its velocity_verlet is the kick-drift-kick form, kepler_verlet; its other symplectic
// steppers are symplectic Euler and McLachlan's two fourth-order methods) and GSL odeiv2 no symplectic
// method: neither has a variant. The reference is the closed-form solution (Kepler's equation by Newton's
// method).
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
}  // namespace

BENCH_STEP int bench_step_kepler_position_verlet_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::position_verlet<vec>{}.step(force, y.first, y.second, t, dt));
}
BENCH_STEP int bench_step_kepler_position_verlet_hand(State& y, State&, double t, double dt) {
    bench::hand::position_verlet(hand_force, y.first, y.second, t, dt);
    return 0;
}
BENCH_STEP int bench_step_kepler_position_verlet_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::position_verlet_checked(hand_force, y.first, y.second, t, dt);
}

int main(int argc, char** argv) {
    const bench::problem<State> p =
        bench::kepler_case::problem("kepler_position_verlet",
                                    // Round-off: 500 steps of the same three updates in the same order; measured 0
                                    // (bit for bit) at -O2 and -Os.
                                    1e-12,
                                    // Position Verlet (order 2) with 1000 steps per orbit: 1.23e-4 relative at
                                    // aphelion (3.07e-5 with 2000 steps, 7.67e-6 with 4000: h^2). Euler-Cromer
                                    // (order 1) with the same step is 1.9e-2 off.
                                    3e-4);
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::position_verlet<std::array<double, 2>> step(a, x, v, t, dt)",
          bench_step_kepler_position_verlet_odestep, true},
         {"hand", "hand-written position Verlet loop (half drift, kick, half drift)",
          bench_step_kepler_position_verlet_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new x or v fails the step, which is rolled back (hand.hpp "
          "position_verlet_checked)",
          bench_step_kepler_position_verlet_hand_checked, true}});
}
