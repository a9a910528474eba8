// SPDX-License-Identifier: BSL-1.0
// The planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion), positions and velocities as two
// std::array<double, 2>, Beeman's algorithm, fixed step. Every variant keeps a_n and a_{n-1} between steps
// (one evaluation of the force per step) and self-starts with one velocity Verlet step: odestep in the
// caller's beeman::history (row odestep) or in its stepper, checked by its continuation test (odestep_kept),
// the hand loops in variables next to the state. Neither Odeint
// nor GSL odeiv2 has Beeman's method: no variant of theirs. The reference is the closed-form solution
// (Kepler's equation by Newton's method).
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

odestep::beeman<vec> odestep_beeman;
odestep::beeman<vec>::history odestep_history;  // the caller-kept form's a_n, a_{n-1} and started flag
vec hand_acc;                                   // the hand loop's a_n, a(x) of the current x
vec hand_acc_prev;                              // and its a_{n-1}
bool hand_started;                              // false: the next step is the run's first, a velocity Verlet step
vec checked_acc;                                // the checked hand loop's, likewise
vec checked_acc_prev;
bool checked_started;

void start_odestep(const State&, double) { odestep_history = {}; }
void start_odestep_kept(const State&, double) { odestep_beeman.reset(); }
void start_hand(const State& y0, double t0) {
    hand_force(t0, y0.first, hand_acc);
    hand_started = false;
}
void start_hand_checked(const State& y0, double t0) {
    hand_force(t0, y0.first, checked_acc);
    checked_started = false;
}
}  // namespace

BENCH_STEP int bench_step_kepler_beeman_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_beeman.step(force, y.first, y.second, odestep_history, t, dt));
}
BENCH_STEP int bench_step_kepler_beeman_odestep_kept(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_beeman.step(force, y.first, y.second, t, dt));
}
BENCH_STEP int bench_step_kepler_beeman_hand(State& y, State&, double t, double dt) {
    bench::hand::beeman(hand_force, y.first, y.second, hand_acc, hand_acc_prev, hand_started, t, dt);
    return 0;
}
BENCH_STEP int bench_step_kepler_beeman_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::beeman_checked(hand_force, y.first, y.second, checked_acc, checked_acc_prev, checked_started, t,
                                       dt);
}

int main(int argc, char** argv) {
    const bench::problem<State> p =
        bench::kepler_case::problem("kepler_beeman",
                                    // Round-off: 500 steps, a few ulps each (the hand loop groups x + (h v + ...)
                                    // and multiplies by 1/6 where odestep divides by 6); measured 5.3e-15 at -O2 and
                                    // -Os.
                                    1e-12,
                                    // Beeman (order 2) with 1000 steps per orbit: 3.02e-4 relative at aphelion
                                    // (7.62e-5 with 2000 steps, 1.91e-5 with 4000: h^2). Euler-Cromer (order 1) with
                                    // the same step is 1.9e-2 off.
                                    6e-4);
    return bench::main<State>(
        argc, argv, p,
        {{"odestep",
          "odestep::beeman<std::array<double, 2>> step(a, x, v, hist, t, dt), a_n and a_{n-1} kept by the caller",
          bench_step_kepler_beeman_odestep, true, start_odestep},
         {"odestep_kept", "the same stepper's step(a, x, v, t, dt), a_n and a_{n-1} kept and checked by the stepper",
          bench_step_kepler_beeman_odestep_kept, true, start_odestep_kept},
         {"hand", "hand-written Beeman loop, a_n and a_{n-1} kept, velocity Verlet first step",
          bench_step_kepler_beeman_hand, true, start_hand},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new x or v fails the step; x, v and the kept accelerations are "
          "left as they were (hand.hpp beeman_checked)",
          bench_step_kepler_beeman_hand_checked, true, start_hand_checked}});
}
