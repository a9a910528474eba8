// SPDX-License-Identifier: BSL-1.0
// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, velocity Verlet, fixed step. Every variant keeps the last acceleration between
// steps (one evaluation of the force per step): odestep in its stepper (checked by its continuation test),
// the hand loop in a variable next to the state, Odeint in its stepper. GSL odeiv2 has no velocity Verlet:
// no GSL variant. The reference is the closed-form solution (Kepler's equation by Newton's method).
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

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
constexpr auto odeint_force = [](const vec& x, const vec&, vec& a, double) { bench::kepler<double>(x, a); };

odestep::velocity_verlet<vec> odestep_vv;
vec odestep_acc;       // odestep's explicit form: the caller keeps a(t, x), as the hand loop does
vec unchecked_acc;     // the same for the unchecked form
vec hand_acc;          // the hand loop's kept acceleration, a(x) of the current x
vec hand_checked_acc;  // the checked hand loop's, likewise
boost::numeric::odeint::velocity_verlet<vec> odeint_vv;

void start_odestep(const State& y0, double t0) { odestep_acc = force(t0, y0.first); }
void start_odestep_kept(const State&, double) { odestep_vv.reset(); }
void start_odestep_unchecked(const State& y0, double t0) { unchecked_acc = force(t0, y0.first); }
void start_hand(const State& y0, double t0) { hand_force(t0, y0.first, hand_acc); }
void start_hand_checked(const State& y0, double t0) { hand_force(t0, y0.first, hand_checked_acc); }
void start_odeint(const State&, double) { odeint_vv.reset(); }
}  // namespace

BENCH_STEP int bench_step_kepler_verlet_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_vv.step(force, y.first, y.second, odestep_acc, t, dt));
}
BENCH_STEP int bench_step_kepler_verlet_odestep_unchecked(State& y, State&, double t, double dt) {
    return static_cast<int>(
        odestep::unchecked_t<odestep::velocity_verlet<vec>>{}.step(force, y.first, y.second, unchecked_acc, t, dt));
}
BENCH_STEP int bench_step_kepler_verlet_odestep_kept(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_vv.step(force, y.first, y.second, t, dt));
}
BENCH_STEP int bench_step_kepler_verlet_hand(State& y, State&, double t, double dt) {
    bench::hand::velocity_verlet(hand_force, y.first, y.second, hand_acc, t, dt);
    return 0;
}
BENCH_STEP int bench_step_kepler_verlet_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::velocity_verlet_checked(hand_force, y.first, y.second, hand_checked_acc, t, dt);
}
BENCH_STEP int bench_step_kepler_verlet_odeint(State& y, State&, double t, double dt) {
    std::pair<vec, vec>& xv = y;  // Odeint's state for its velocity_verlet: the pair (positions, velocities)
    odeint_vv.do_step(odeint_force, xv, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const bench::problem<State> p =
        bench::kepler_case::problem("kepler_verlet",
                                    // Round-off: 500 steps, a few ulps each, through perihelion (|v| = sqrt 3)
                                    // to aphelion; measured 1e-15 to 3e-15 between the arithmetic forms.
                                    1e-12,
                                    // Velocity Verlet (order 2) with 1000 steps per orbit: 2.66e-4 relative at
                                    // aphelion (6.65e-5 with 2000 steps, 1.66e-5 with 4000: h^2). Euler-Cromer
                                    // (order 1) with the same step is 1.9e-2 off.
                                    5e-4);
    return bench::main<State>(
        argc, argv, p,
        {{"odestep",
          "odestep::velocity_verlet<std::array<double, 2>> step(a, x, v, acc, t, dt), acc kept by the caller",
          bench_step_kepler_verlet_odestep, true, start_odestep},
         {"odestep_kept", "the same stepper's step(a, x, v, t, dt), acc kept and checked by the stepper",
          bench_step_kepler_verlet_odestep_kept, true, start_odestep_kept},
         {"odestep_unchecked",
          "odestep::unchecked_t<odestep::velocity_verlet<..>> step(a, x, v, acc, t, dt): no NaN/Inf test (the same "
          "arithmetic)",
          bench_step_kepler_verlet_odestep_unchecked, true, start_odestep_unchecked},
         {"hand", "hand-written velocity Verlet loop, acceleration kept", bench_step_kepler_verlet_hand, true,
          start_hand},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new x or v fails the step; x, v and the kept acceleration are "
          "left as they were (hand.hpp velocity_verlet_checked)",
          bench_step_kepler_verlet_hand_checked, true, start_hand_checked},
         {"odeint", "Odeint velocity_verlet<std::array<double, 2>> do_step on std::pair (x, v)",
          bench_step_kepler_verlet_odeint, true, start_odeint}});
}
