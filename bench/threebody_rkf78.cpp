// SPDX-License-Identifier: BSL-1.0
// Planar three-body problem (12 states, double), Runge-Kutta-Fehlberg 7(8), eighth-order step, fixed step
// size: the eighth-order method Odeint and odestep both have. GSL has none (its rk8pd is in
// threebody_dop853).
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 12>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::three_body<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::three_body<double>(y, d); };
boost::numeric::odeint::runge_kutta_fehlberg78<State> odeint_rkf78;
}  // namespace

BENCH_STEP int bench_step_threebody_rkf78_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::fehlberg78<State>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_threebody_rkf78_hand(State& y, State&, double t, double dt) {
    bench::hand::rkf78(rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_threebody_rkf78_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::rkf78<true>(rhs, y, t, dt);
}
BENCH_STEP int bench_step_threebody_rkf78_odeint(State& y, State&, double t, double dt) {
    odeint_rkf78.do_step(odeint_rhs, y, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const State y0 = bench::figure_eight<double>();
    const double dt = 0.05;
    const int steps = 40;
    bench::problem<State> p{
        "threebody_rkf78", y0, 0.0, dt, steps,
        bench::reference_solution<12>([](long double, const auto& y, auto& d) { bench::three_body<long double>(y, d); },
                                      y0, 0.0L, steps * 0.05L, 16 * steps),
        // Round-off: 40 steps, coefficients up to 16 in magnitude.
        1e-12,
        // Eighth order with h = 0.05 over a third of the period: 2.6e-11 relative.
        1e-10, false};
    return bench::main<State>(argc, argv, p,
                              {{"odestep", "odestep::fehlberg78 (12 evaluations: stage 11 feeds only the estimate)",
                                bench_step_threebody_rkf78_odestep, true},
                               {"hand", "hand-written RKF78 eighth-order step, stage by stage (12 evaluations)",
                                bench_step_threebody_rkf78_hand, true},
                               {"hand_checked",
                                "the hand loop, checked: NaN/Inf in the new y or in a zero-weight stage (k1..k5) fails "
                                "the step, which is rolled back",
                                bench_step_threebody_rkf78_hand_checked, true},
                               {"odeint", "Odeint runge_kutta_fehlberg78 do_step (13 evaluations)",
                                bench_step_threebody_rkf78_odeint, true}});
}
