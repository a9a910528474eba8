// SPDX-License-Identifier: BSL-1.0
// Lorenz (3 states, double), Adams-Bashforth-Moulton 4 in PECE mode (the AB4 predictor, the three-step Adams-
// Moulton corrector applied once), fixed step, started by three RK4 steps.
// Every variant keeps the derivatives of the last three steps between steps (two evaluations of f per step
// once started): odestep in its stepper (with its checks that a step continues the history: the same dt
// and the expected time), the hand loops in an array of three next to the state (shifted down as a block each step), Odeint in its stepper, its
// initializing stepper runge_kutta4 (its default here; written out as in lorenz_ab4). Odeint's corrector
// coefficients for 4 steps are 3/8, 19/24, -5/24, 1/24 (Boost 1.74, adams_moulton_coefficients.hpp), the same. GSL
// odeiv2's Adams method (msadams) varies its order and step: no GSL variant. The reference is a DOP853 run
// in long double.
#include <boost/numeric/odeint/stepper/adams_bashforth_moulton.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 3>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::lorenz<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::lorenz<double>(y, d); };

namespace odeint = boost::numeric::odeint;
using odeint_abm4_type =
    odeint::adams_bashforth_moulton<4, State, double, State, double, odeint::algebra_dispatcher<State>::algebra_type,
                                    odeint::operations_dispatcher<State>::operations_type, odeint::initially_resizer,
                                    odeint::runge_kutta4<State>>;

odestep::adams_bashforth_moulton4<State> odestep_abm4;
bench::hand::ab4_history<double, 3> hand_hist;
bench::hand::ab4_history<double, 3> checked_hist;
odeint_abm4_type odeint_abm4;

void start_odestep(const State&, double) { odestep_abm4.reset(); }
void start_hand(const State&, double) { hand_hist = {}; }
void start_hand_checked(const State&, double) { checked_hist = {}; }
void start_odeint(const State&, double) { odeint_abm4.reset(); }
}  // namespace

BENCH_STEP int bench_step_lorenz_abm4_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_abm4.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_lorenz_abm4_hand(State& y, State&, double t, double dt) {
    bench::hand::adams_bashforth_moulton4(rhs, y, hand_hist, t, dt);
    return 0;
}
BENCH_STEP int bench_step_lorenz_abm4_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::adams_bashforth_moulton4_checked(rhs, y, checked_hist, t, dt);
}
BENCH_STEP int bench_step_lorenz_abm4_odeint(State& y, State&, double t, double dt) {
    odeint_abm4.do_step(odeint_rhs, y, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const State y0{-8.0, 8.0, 27.0};
    const double dt = 0.005;
    const int steps = 100;
    bench::problem<State> p{
        "lorenz_abm4", y0, 0.0, dt, steps,
        bench::reference_solution<3>([](long double, const auto& y, auto& d) { bench::lorenz<long double>(y, d); }, y0,
                                     0.0L, steps * 0.005L, 16 * steps),
        // Round-off: 100 steps of a few ulps each, amplified a few times over t = 0.5.
        1e-12,
        // ABM4 with h = 0.005 on Lorenz: 1.69e-6 relative at t = 0.5 (1.06e-7 with h =
        // 0.0025: h^4); Adams-Bashforth 4 alone misses by 2.2e-5.
        4e-6, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::adams_bashforth_moulton4 (PECE, rk4 start), history kept and checked by the stepper",
          bench_step_lorenz_abm4_odestep, true, start_odestep},
         {"hand",
          "hand-written Adams-Bashforth-Moulton 4 (PECE) loop, the last three f shifted as a block, rk4 start out of "
          "line",
          bench_step_lorenz_abm4_hand, true, start_hand},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new y (or in f at the start) fails the step; y and the history are "
          "left as they were (hand.hpp adams_bashforth_moulton4_checked)",
          bench_step_lorenz_abm4_hand_checked, true, start_hand_checked},
         {"odeint", "Odeint adams_bashforth_moulton<4, std::array> do_step, runge_kutta4 as its initializing stepper",
          bench_step_lorenz_abm4_odeint, true, start_odeint}});
}
