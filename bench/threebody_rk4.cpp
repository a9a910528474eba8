// SPDX-License-Identifier: BSL-1.0
// Planar three-body problem (12 states, double), classic RK4, fixed step.
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include "gsl.hpp"
#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 12>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::three_body<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::three_body<double>(y, d); };
int gsl_rhs(double, const double y[], double d[], void*) {
    bench::three_body<double>(y, d);
    return GSL_SUCCESS;
}
boost::numeric::odeint::runge_kutta4<State> odeint_rk4;
bench::gsl_stepper gsl_rk4(gsl_odeiv2_step_rk4, gsl_rhs, 12);
}  // namespace

BENCH_STEP int bench_step_threebody_rk4_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::rk4<State>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_threebody_rk4_odestep_unchecked(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<State>>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_threebody_rk4_hand(State& y, State&, double t, double dt) {
    bench::hand::rk4(rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_threebody_rk4_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::rk4_checked(rhs, y, t, dt);
}
BENCH_STEP int bench_step_threebody_rk4_odeint(State& y, State&, double t, double dt) {
    odeint_rk4.do_step(odeint_rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_threebody_rk4_gsl(State& y, State& err, double t, double dt) {
    return gsl_rk4.apply(y.data(), err.data(), t, dt);
}

int main(int argc, char** argv) {
    const State y0 = bench::figure_eight<double>();
    const double dt = 0.01;
    const int steps = 100;
    bench::problem<State> p{
        "threebody_rk4", y0, 0.0, dt, steps,
        bench::reference_solution<12>([](long double, const auto& y, auto& d) { bench::three_body<long double>(y, d); },
                                      y0, 0.0L, steps * 0.01L, 16 * steps),
        // Round-off: 100 steps of a few ulps each on a smooth, stable orbit.
        1e-12,
        // RK4 with h = 0.01 over a sixth of the figure-eight's period: 1.3e-8 relative.
        1e-7, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::rk4", bench_step_threebody_rk4_odestep, true},
         {"odestep_unchecked", "odestep::unchecked_t<odestep::rk4<State>>: no NaN/Inf test (the same arithmetic)",
          bench_step_threebody_rk4_odestep_unchecked, true},
         {"hand", "hand-written RK4 loop", bench_step_threebody_rk4_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new y fails the step, which is rolled back "
          "(hand.hpp rk4_checked)",
          bench_step_threebody_rk4_hand_checked, true},
         {"odeint", "Odeint runge_kutta4<std::array> do_step", bench_step_threebody_rk4_odeint, true},
         {"gsl", "GSL rk4 (step doubling: 11 f evaluations, error estimate)", bench_step_threebody_rk4_gsl, false}});
}
