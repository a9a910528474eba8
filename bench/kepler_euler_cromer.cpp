// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, Euler-Cromer (symplectic Euler, kick then drift: v += dt a(t, x), x += dt v), fixed
// step, one evaluation of the force per step and nothing kept between steps. Odeint's symplectic_euler is
// the other ordering, drift then kick (x += dt v, v += dt a(x); its symplectic_nystroem_stepper_base drifts
// first in every stage), the adjoint method: of the same order but another method, checked against the
// reference only. GSL odeiv2 has no symplectic method: no GSL variant. The reference is the closed-form
// solution (Kepler's equation by Newton's method).
#include <boost/numeric/odeint/stepper/symplectic_euler.hpp>

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

boost::numeric::odeint::symplectic_euler<vec> odeint_se;
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
BENCH_STEP int bench_step_kepler_euler_cromer_odeint(State& y, State&, double t, double dt) {
    std::pair<vec, vec>& xv = y;  // Odeint's state for its symplectic steppers: the pair (positions, momenta)
    odeint_se.do_step(odeint_force, xv, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const bench::problem<State> p = bench::kepler_case::problem("kepler_euler_cromer",
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
         {"odeint",
          "Odeint symplectic_euler<std::array<double, 2>> do_step on std::pair (x, v) (drift then kick: the adjoint)",
          bench_step_kepler_euler_cromer_odeint, false}});
}
