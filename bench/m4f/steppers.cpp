// SPDX-License-Identifier: BSL-1.0
// The rows of the emulated Cortex-M4F table (bench/m4f/main.cpp runs them; scripts/bench-m4f.sh builds them),
// one per block `#if M4F_UNIT == k`: the script compiles this file once per block, k = the row's place in the
// table, so that each row is a translation unit of its own, as a firmware with that one stepper would be.
//
// Each row: odestep's step and, where written, the scalar hand loops of a careful engineer, plain (`hand`)
// and with odestep's guarantee (`hand_checked`: a NaN/Inf test of the new state and the caller's state left
// as it was on failure): bench/hand.hpp's (rk4, the Newtonian loops, AB4, ABM4) and bench/m4f/hand_more.hpp's
// (euler, midpoint, heun, Dormand-Prince 5(4) in float).
//
// The problems (bench/m4f/common.hpp), float, dt = 0.01: the first-order, Adams, implicit and Rosenbrock
// steppers integrate two coupled oscillators as y = (x1, x2, v1, v2), 4 states; the Newtonian steppers the
// same springs as x'' = a(x), x and v of 2; the Boris pusher a Penning trap, x and v of 3. For the implicit
// steppers the system is not stiff: their figure is the cost of a step whose Newton iteration converges at
// once (a linear system), the Jacobian by differences, the default Newton policy.
#include "m4f/units.hpp"  // first: scripts/bench-m4f.sh precompiles it

#ifndef M4F_UNIT
#error "compile with -DM4F_UNIT=k: scripts/bench-m4f.sh builds one translation unit per row"
#endif

namespace {
using namespace m4f;
namespace o = odestep;

#if M4F_UNIT == 0  // euler
first_order context[3];
M4F_STEP int step_euler_hand(void* p, float t, float dt) {
    bench::m4f_hand::euler(rhs, as<first_order>(p).y, t, dt);
    return 0;
}
M4F_STEP int step_euler_hand_checked(void* p, float t, float dt) {
    return bench::m4f_hand::euler_checked(rhs, as<first_order>(p).y, t, dt);
}
const registration row(M4F_UNIT, "euler", make(step_first_order<o::euler<State>>, context[0]),
                       make(step_euler_hand, context[1]), make(step_euler_hand_checked, context[2]));
#endif

#if M4F_UNIT == 1  // midpoint
first_order context[3];
M4F_STEP int step_midpoint_hand(void* p, float t, float dt) {
    bench::m4f_hand::midpoint(rhs, as<first_order>(p).y, t, dt);
    return 0;
}
M4F_STEP int step_midpoint_hand_checked(void* p, float t, float dt) {
    return bench::m4f_hand::midpoint_checked(rhs, as<first_order>(p).y, t, dt);
}
const registration row(M4F_UNIT, "midpoint", make(step_first_order<o::midpoint<State>>, context[0]),
                       make(step_midpoint_hand, context[1]), make(step_midpoint_hand_checked, context[2]));
#endif

#if M4F_UNIT == 2  // heun
first_order context[3];
M4F_STEP int step_heun_hand(void* p, float t, float dt) {
    bench::m4f_hand::heun(rhs, as<first_order>(p).y, t, dt);
    return 0;
}
M4F_STEP int step_heun_hand_checked(void* p, float t, float dt) {
    return bench::m4f_hand::heun_checked(rhs, as<first_order>(p).y, t, dt);
}
const registration row(M4F_UNIT, "heun", make(step_first_order<o::heun<State>>, context[0]),
                       make(step_heun_hand, context[1]), make(step_heun_hand_checked, context[2]));
#endif

#if M4F_UNIT == 3  // ralston2
first_order context;
const registration row(M4F_UNIT, "ralston2", make(step_first_order<o::ralston2<State>>, context));
#endif

#if M4F_UNIT == 4  // kutta3
first_order context;
const registration row(M4F_UNIT, "kutta3", make(step_first_order<o::kutta3<State>>, context));
#endif

#if M4F_UNIT == 5  // ssprk3
first_order context;
const registration row(M4F_UNIT, "ssprk3", make(step_first_order<o::ssprk3<State>>, context));
#endif

#if M4F_UNIT == 6  // rk4
first_order context[3];
M4F_STEP int step_rk4_hand(void* p, float t, float dt) {
    bench::hand::rk4(rhs, as<first_order>(p).y, t, dt);
    return 0;
}
M4F_STEP int step_rk4_hand_checked(void* p, float t, float dt) {
    return bench::hand::rk4_checked(rhs, as<first_order>(p).y, t, dt);
}
const registration row(M4F_UNIT, "rk4", make(step_first_order<o::rk4<State>>, context[0]),
                       make(step_rk4_hand, context[1]), make(step_rk4_hand_checked, context[2]));
#endif

#if M4F_UNIT == 7  // rk38
first_order context;
const registration row(M4F_UNIT, "rk38", make(step_first_order<o::rk38<State>>, context));
#endif

#if M4F_UNIT == 8  // bogacki_shampine32
first_order context;
const registration row(M4F_UNIT, "bogacki_shampine32", make(step_first_order<o::bogacki_shampine32<State>>, context));
#endif

#if M4F_UNIT == 9  // fehlberg45
first_order context;
const registration row(M4F_UNIT, "fehlberg45", make(step_first_order<o::fehlberg45<State>>, context));
#endif

#if M4F_UNIT == 10  // cash_karp54
first_order context;
const registration row(M4F_UNIT, "cash_karp54", make(step_first_order<o::cash_karp54<State>>, context));
#endif

#if M4F_UNIT == 11  // dormand_prince54
first_order context;
const registration row(M4F_UNIT, "dormand_prince54", make(step_first_order<o::dormand_prince54<State>>, context));
#endif

#if M4F_UNIT == 12  // dormand_prince54 with its error estimate
first_order context[3];
M4F_STEP int step_dormand_prince54_error(void* p, float t, float dt) {
    first_order& c = as<first_order>(p);
    return static_cast<int>(o::dormand_prince54<State>{}.step(rhs, c.y, t, dt, c.err));
}
M4F_STEP int step_dopri5_hand(void* p, float t, float dt) {
    first_order& c = as<first_order>(p);
    return bench::m4f_hand::dopri5<false>(rhs, c.y, t, dt, c.err);
}
M4F_STEP int step_dopri5_hand_checked(void* p, float t, float dt) {
    first_order& c = as<first_order>(p);
    return bench::m4f_hand::dopri5<true>(rhs, c.y, t, dt, c.err);
}
const registration row(M4F_UNIT, "dormand_prince54 with its error estimate",
                       make(step_dormand_prince54_error, context[0]), make(step_dopri5_hand, context[1]),
                       make(step_dopri5_hand_checked, context[2]));
#endif

#if M4F_UNIT == 13  // fehlberg78
first_order context;
const registration row(M4F_UNIT, "fehlberg78", make(step_first_order<o::fehlberg78<State>>, context));
#endif

#if M4F_UNIT == 14  // dop853
first_order context;
const registration row(M4F_UNIT, "dop853", make(step_first_order<o::dop853<State>>, context));
#endif

#if M4F_UNIT == 15  // euler_cromer
kept<o::euler_cromer<vec2>> context;
newtonian hand_context[2];
M4F_STEP int step_euler_cromer_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::hand::euler_cromer(hand_springs, c.x, c.v, t, dt);
    return 0;
}
M4F_STEP int step_euler_cromer_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::hand::euler_cromer_checked(hand_springs, c.x, c.v, t, dt);
}
const registration row(M4F_UNIT, "euler_cromer", make(step_newtonian<o::euler_cromer<vec2>>, context),
                       make(step_euler_cromer_hand, hand_context[0]),
                       make(step_euler_cromer_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 16  // euler_cromer_drift_first
kept<o::euler_cromer_drift_first<vec2>> context;
const registration row(M4F_UNIT, "euler_cromer_drift_first",
                       make(step_newtonian<o::euler_cromer_drift_first<vec2>>, context));
#endif

#if M4F_UNIT == 17  // velocity_verlet, acc kept by the caller
newtonian context;
M4F_STEP int step_velocity_verlet_caller_kept(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return static_cast<int>(o::velocity_verlet<vec2>{}.step(springs, c.x, c.v, c.acc, t, dt));
}
newtonian hand_context[2];
M4F_STEP int step_velocity_verlet_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::m4f_hand::velocity_verlet_kdk(hand_springs, c.x, c.v, c.acc, t, dt);
    return 0;
}
M4F_STEP int step_velocity_verlet_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::m4f_hand::velocity_verlet_kdk_checked(hand_springs, c.x, c.v, c.acc, t, dt);
}
const registration row(M4F_UNIT, "velocity_verlet, acc kept by the caller",
                       make(step_velocity_verlet_caller_kept, context),
                       make(step_velocity_verlet_hand, hand_context[0]),
                       make(step_velocity_verlet_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 18  // velocity_verlet, acc kept by the stepper
kept<o::velocity_verlet<vec2>> context;
newtonian hand_context[2];
M4F_STEP int step_velocity_verlet_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::m4f_hand::velocity_verlet_kdk(hand_springs, c.x, c.v, c.acc, t, dt);
    return 0;
}
M4F_STEP int step_velocity_verlet_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::m4f_hand::velocity_verlet_kdk_checked(hand_springs, c.x, c.v, c.acc, t, dt);
}
const registration row(M4F_UNIT, "velocity_verlet, acc kept by the stepper",
                       make(step_newtonian<o::velocity_verlet<vec2>>, context),
                       make(step_velocity_verlet_hand, hand_context[0]),
                       make(step_velocity_verlet_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 19  // position_verlet
kept<o::position_verlet<vec2>> context;
newtonian hand_context[2];
M4F_STEP int step_position_verlet_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::hand::position_verlet(hand_springs, c.x, c.v, t, dt);
    return 0;
}
M4F_STEP int step_position_verlet_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::hand::position_verlet_checked(hand_springs, c.x, c.v, t, dt);
}
const registration row(M4F_UNIT, "position_verlet", make(step_newtonian<o::position_verlet<vec2>>, context),
                       make(step_position_verlet_hand, hand_context[0]),
                       make(step_position_verlet_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 20  // forest_ruth
kept<o::forest_ruth<vec2>> context;
newtonian hand_context[2];
M4F_STEP int step_forest_ruth_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::hand::forest_ruth(hand_springs, c.x, c.v, t, dt);
    return 0;
}
M4F_STEP int step_forest_ruth_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::hand::forest_ruth_checked(hand_springs, c.x, c.v, t, dt);
}
const registration row(M4F_UNIT, "forest_ruth", make(step_newtonian<o::forest_ruth<vec2>>, context),
                       make(step_forest_ruth_hand, hand_context[0]),
                       make(step_forest_ruth_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 21  // yoshida6
kept<o::yoshida6<vec2>> context;
const registration row(M4F_UNIT, "yoshida6", make(step_newtonian<o::yoshida6<vec2>>, context));
#endif

#if M4F_UNIT == 22  // blanes_moan4
kept<o::blanes_moan4<vec2>> context;
const registration row(M4F_UNIT, "blanes_moan4", make(step_newtonian<o::blanes_moan4<vec2>>, context));
#endif

#if M4F_UNIT == 23  // newtonian_euler
kept<o::newtonian_euler<vec2>> context;
const registration row(M4F_UNIT, "newtonian_euler", make(step_newtonian<o::newtonian_euler<vec2>>, context));
#endif

#if M4F_UNIT == 24  // newtonian_midpoint
kept<o::newtonian_midpoint<vec2>> context;
const registration row(M4F_UNIT, "newtonian_midpoint", make(step_newtonian<o::newtonian_midpoint<vec2>>, context));
#endif

#if M4F_UNIT == 25  // newtonian_euler_richardson
kept<o::newtonian_euler_richardson<vec2>> context;
const registration row(M4F_UNIT, "newtonian_euler_richardson",
                       make(step_newtonian<o::newtonian_euler_richardson<vec2>>, context));
#endif

#if M4F_UNIT == 26  // half_step
kept<o::half_step<vec2>> context;
const registration row(M4F_UNIT, "half_step", make(step_newtonian<o::half_step<vec2>>, context));
#endif

#if M4F_UNIT == 27  // leapfrog_position_form
kept<o::leapfrog_position_form<vec2>> context;
const registration row(M4F_UNIT, "leapfrog_position_form",
                       make(step_newtonian<o::leapfrog_position_form<vec2>>, context));
#endif

#if M4F_UNIT == 28  // beeman, history kept by the caller
struct beeman_caller {
    vec2 x, v;
    o::beeman<vec2>::history hist;
};
void start(beeman_caller& c) { c = {x0, v0, {}}; }
result_t result(const beeman_caller& c) { return {c.x[0], c.x[1], c.v[0], c.v[1]}; }
beeman_caller context;
M4F_STEP int step_beeman_caller_kept(void* p, float t, float dt) {
    beeman_caller& c = as<beeman_caller>(p);
    return static_cast<int>(o::beeman<vec2>{}.step(springs, c.x, c.v, c.hist, t, dt));
}
newtonian hand_context[2];
M4F_STEP int step_beeman_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::hand::beeman(hand_springs, c.x, c.v, c.acc, c.acc_prev, c.started, t, dt);
    return 0;
}
M4F_STEP int step_beeman_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::hand::beeman_checked(hand_springs, c.x, c.v, c.acc, c.acc_prev, c.started, t, dt);
}
const registration row(M4F_UNIT, "beeman, history kept by the caller", make(step_beeman_caller_kept, context),
                       make(step_beeman_hand, hand_context[0]), make(step_beeman_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 29  // beeman, history kept by the stepper
kept<o::beeman<vec2>> context;
newtonian hand_context[2];
M4F_STEP int step_beeman_hand(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    bench::hand::beeman(hand_springs, c.x, c.v, c.acc, c.acc_prev, c.started, t, dt);
    return 0;
}
M4F_STEP int step_beeman_hand_checked(void* p, float t, float dt) {
    newtonian& c = as<newtonian>(p);
    return bench::hand::beeman_checked(hand_springs, c.x, c.v, c.acc, c.acc_prev, c.started, t, dt);
}
const registration row(M4F_UNIT, "beeman, history kept by the stepper", make(step_newtonian<o::beeman<vec2>>, context),
                       make(step_beeman_hand, hand_context[0]), make(step_beeman_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 30  // predictor_corrector
kept<o::predictor_corrector<vec2>> context;
const registration row(M4F_UNIT, "predictor_corrector", make(step_newtonian<o::predictor_corrector<vec2>>, context));
#endif

#if M4F_UNIT == 31  // boris (x, v of 3)
particle context;
M4F_STEP int step_boris(void* p, float t, float dt) {
    particle& c = as<particle>(p);
    return static_cast<int>(o::boris<vec3>{}.step(penning{}, c.x, c.v, t, dt));
}
const registration row(M4F_UNIT, "boris (x, v of 3)", make(step_boris, context));
#endif

#if M4F_UNIT == 32  // adams_bashforth2
multistep<o::adams_bashforth2<State>> context;
const registration row(M4F_UNIT, "adams_bashforth2", make(step_multistep<o::adams_bashforth2<State>>, context));
#endif

#if M4F_UNIT == 33  // adams_bashforth3
multistep<o::adams_bashforth3<State>> context;
const registration row(M4F_UNIT, "adams_bashforth3", make(step_multistep<o::adams_bashforth3<State>>, context));
#endif

#if M4F_UNIT == 34  // adams_bashforth4
multistep<o::adams_bashforth4<State>> context;
struct adams_hand {
    State y;
    bench::hand::ab4_history<float, 4> hist;
};
void start(adams_hand& c) { c = {y0, {}}; }
result_t result(const adams_hand& c) { return {c.y[0], c.y[1], c.y[2], c.y[3]}; }
adams_hand hand_context[2];
M4F_STEP int step_adams_bashforth4_hand(void* p, float t, float dt) {
    adams_hand& c = as<adams_hand>(p);
    bench::hand::adams_bashforth4(rhs, c.y, c.hist, t, dt);
    return 0;
}
M4F_STEP int step_adams_bashforth4_hand_checked(void* p, float t, float dt) {
    adams_hand& c = as<adams_hand>(p);
    return bench::hand::adams_bashforth4_checked(rhs, c.y, c.hist, t, dt);
}
const registration row(M4F_UNIT, "adams_bashforth4", make(step_multistep<o::adams_bashforth4<State>>, context),
                       make(step_adams_bashforth4_hand, hand_context[0]),
                       make(step_adams_bashforth4_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 35  // adams_bashforth5
multistep<o::adams_bashforth5<State>> context;
const registration row(M4F_UNIT, "adams_bashforth5", make(step_multistep<o::adams_bashforth5<State>>, context));
#endif

#if M4F_UNIT == 36  // adams_bashforth_moulton4
multistep<o::adams_bashforth_moulton4<State>> context;
struct adams_hand {
    State y;
    bench::hand::ab4_history<float, 4> hist;
};
void start(adams_hand& c) { c = {y0, {}}; }
result_t result(const adams_hand& c) { return {c.y[0], c.y[1], c.y[2], c.y[3]}; }
adams_hand hand_context[2];
M4F_STEP int step_adams_bashforth_moulton4_hand(void* p, float t, float dt) {
    adams_hand& c = as<adams_hand>(p);
    bench::hand::adams_bashforth_moulton4(rhs, c.y, c.hist, t, dt);
    return 0;
}
M4F_STEP int step_adams_bashforth_moulton4_hand_checked(void* p, float t, float dt) {
    adams_hand& c = as<adams_hand>(p);
    return bench::hand::adams_bashforth_moulton4_checked(rhs, c.y, c.hist, t, dt);
}
const registration row(M4F_UNIT, "adams_bashforth_moulton4",
                       make(step_multistep<o::adams_bashforth_moulton4<State>>, context),
                       make(step_adams_bashforth_moulton4_hand, hand_context[0]),
                       make(step_adams_bashforth_moulton4_hand_checked, hand_context[1]));
#endif

#if M4F_UNIT == 37  // backward_euler
first_order context;
const registration row(M4F_UNIT, "backward_euler", make(step_first_order<o::backward_euler<State>>, context));
#endif

#if M4F_UNIT == 38  // trapezoid
first_order context;
const registration row(M4F_UNIT, "trapezoid", make(step_first_order<o::trapezoid<State>>, context));
#endif

#if M4F_UNIT == 39  // sdirk3
first_order context;
const registration row(M4F_UNIT, "sdirk3", make(step_first_order<o::sdirk3<State>>, context));
#endif

#if M4F_UNIT == 40  // radau_iia5
first_order context;
const registration row(M4F_UNIT, "radau_iia5", make(step_first_order<o::radau_iia5<State>>, context));
#endif

#if M4F_UNIT == 41  // rodas3
first_order context;
const registration row(M4F_UNIT, "rodas3", make(step_first_order<o::rodas3<State>>, context));
#endif

}  // namespace
