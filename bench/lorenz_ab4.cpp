// SPDX-License-Identifier: BSL-1.0
// Lorenz (3 states, double), the four-step Adams-Bashforth method, fixed step, started by three RK4 steps.
// Every variant keeps the derivatives of the last three steps between steps (one evaluation of f per step
// once started): odestep in its stepper (with its checks that a step continues the history: the same dt
// and the expected time), the hand loops in an array of three next to the state (shifted down as a block each step), Odeint in its stepper, its
// initializing stepper set to runge_kutta4 (its default is an extrapolation stepper: another start). GSL
// odeiv2's Adams method (msadams) varies its order and step: no GSL variant. The reference is a DOP853 run
// in long double.
#include <boost/numeric/odeint/stepper/adams_bashforth.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 3>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::lorenz<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::lorenz<double>(y, d); };

namespace odeint = boost::numeric::odeint;
using odeint_ab4_type =
    odeint::adams_bashforth<4, State, double, State, double, odeint::algebra_dispatcher<State>::algebra_type,
                            odeint::operations_dispatcher<State>::operations_type, odeint::initially_resizer,
                            odeint::runge_kutta4<State>>;

odestep::adams_bashforth4<State> odestep_ab4;
odestep::unchecked_t<odestep::adams_bashforth4<State, odestep::unchecked_t<odestep::rk4<State>>>> unchecked_ab4;
bench::hand::ab4_history<double, 3> hand_hist;
bench::hand::ab4_history<double, 3> checked_hist;
odeint_ab4_type odeint_ab4;

void start_odestep(const State&, double) { odestep_ab4.reset(); }
void start_odestep_unchecked(const State&, double) { unchecked_ab4.reset(); }
void start_hand(const State&, double) { hand_hist = {}; }
void start_hand_checked(const State&, double) { checked_hist = {}; }
void start_odeint(const State&, double) { odeint_ab4.reset(); }
}  // namespace

BENCH_STEP int bench_step_lorenz_ab4_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep_ab4.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_lorenz_ab4_odestep_unchecked(State& y, State&, double t, double dt) {
    return static_cast<int>(unchecked_ab4.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_lorenz_ab4_hand(State& y, State&, double t, double dt) {
    bench::hand::adams_bashforth4(rhs, y, hand_hist, t, dt);
    return 0;
}
BENCH_STEP int bench_step_lorenz_ab4_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::adams_bashforth4_checked(rhs, y, checked_hist, t, dt);
}
BENCH_STEP int bench_step_lorenz_ab4_odeint(State& y, State&, double t, double dt) {
    odeint_ab4.do_step(odeint_rhs, y, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const State y0{-8.0, 8.0, 27.0};
    const double dt = 0.005;
    const int steps = 100;
    bench::problem<State> p{
        "lorenz_ab4", y0, 0.0, dt, steps,
        bench::reference_solution<3>([](long double, const auto& y, auto& d) { bench::lorenz<long double>(y, d); }, y0,
                                     0.0L, steps * 0.005L, 16 * steps),
        // Round-off: 100 steps of a few ulps each, amplified a few times over t = 0.5.
        1e-12,
        // AB4 with h = 0.005 on Lorenz: 2.22e-5 relative at t = 0.5 (1.40e-6 with h =
        // 0.0025: h^4); three-step Adams-Bashforth (order 3) misses by 2.5e-4.
        5e-5, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::adams_bashforth4 (rk4 start), history kept and checked by the stepper",
          bench_step_lorenz_ab4_odestep, true, start_odestep},
         {"odestep_unchecked",
          "odestep::adams_bashforth4<State, rk4<State, unchecked>, unchecked>: no NaN/Inf test (the same "
          "arithmetic), the history's grid still checked",
          bench_step_lorenz_ab4_odestep_unchecked, true, start_odestep_unchecked},
         {"hand", "hand-written Adams-Bashforth 4 loop, the last three f shifted as a block, rk4 start out of line",
          bench_step_lorenz_ab4_hand, true, start_hand},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new y (or in f at the start) fails the step; y and the history are "
          "left as they were (hand.hpp adams_bashforth4_checked)",
          bench_step_lorenz_ab4_hand_checked, true, start_hand_checked},
         {"odeint", "Odeint adams_bashforth<4, std::array> do_step, runge_kutta4 as its initializing stepper",
          bench_step_lorenz_ab4_odeint, true, start_odeint}});
}
