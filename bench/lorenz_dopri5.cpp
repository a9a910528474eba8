// SPDX-License-Identifier: BSL-1.0
// Lorenz (3 states, double), Dormand-Prince 5(4) with its error estimate, fixed step: 7 evaluations
// (stateless: k1 is evaluated every step). The extra row odeint_fsal is Odeint's default use, which carries
// k7 over as the next step's k1 (6 evaluations); it is shown, not used as the reference. GSL has no
// Dormand-Prince 5(4): rkf45 (Fehlberg 4(5), 6 evaluations) is its nearest pair, another method.
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include "gsl.hpp"
#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 3>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::lorenz<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::lorenz<double>(y, d); };
int gsl_rhs(double, const double y[], double d[], void*) {
    bench::lorenz<double>(y, d);
    return GSL_SUCCESS;
}
boost::numeric::odeint::runge_kutta_dopri5<State> odeint_dopri5;
boost::numeric::odeint::runge_kutta_dopri5<State> odeint_dopri5_fsal;
bench::gsl_stepper gsl_rkf45(gsl_odeiv2_step_rkf45, gsl_rhs, 3);
}  // namespace

BENCH_STEP int bench_step_lorenz_dopri5_odestep(State& y, State& err, double t, double dt) {
    return static_cast<int>(odestep::dormand_prince54<State>{}.step(rhs, y, t, dt, err));
}
BENCH_STEP int bench_step_lorenz_dopri5_hand(State& y, State& err, double t, double dt) {
    bench::hand::dopri5(rhs, y, t, dt, err);
    return 0;
}
BENCH_STEP int bench_step_lorenz_dopri5_hand_checked(State& y, State& err, double t, double dt) {
    return bench::hand::dopri5<true>(rhs, y, t, dt, err);
}
BENCH_STEP int bench_step_lorenz_dopri5_odeint(State& y, State& err, double t, double dt) {
    odeint_dopri5.reset();  // forget the carried-over derivative: evaluate k1, as the others do
    odeint_dopri5.do_step(odeint_rhs, y, t, dt, err);
    return 0;
}
BENCH_STEP int bench_step_lorenz_dopri5_odeint_fsal(State& y, State& err, double t, double dt) {
    odeint_dopri5_fsal.do_step(odeint_rhs, y, t, dt, err);
    return 0;
}
BENCH_STEP int bench_step_lorenz_dopri5_gsl(State& y, State& err, double t, double dt) {
    return gsl_rkf45.apply(y.data(), err.data(), t, dt);
}

int main(int argc, char** argv) {
    const State y0{-8.0, 8.0, 27.0};
    const double dt = 0.005;
    const int steps = 100;
    odeint_dopri5_fsal.reset();  // each run starts from y0: the timing and check loops reset the state
    bench::problem<State> p{
        "lorenz_dopri5", y0, 0.0, dt, steps,
        bench::reference_solution<3>([](long double, const auto& y, auto& d) { bench::lorenz<long double>(y, d); }, y0,
                                     0.0L, steps * 0.005L, 16 * steps),
        // Round-off: 100 steps of a few ulps each, amplified a few times over t = 0.5.
        1e-12,
        // Fifth order with h = 0.005: 2.8e-10 relative; GSL rkf45 advances with
        // its fourth-order solution: 1.6e-9.
        1e-8, true};
    return bench::main<State>(argc, argv, p,
                              {{"odestep", "odestep::dormand_prince54, step with error (7 evaluations)",
                                bench_step_lorenz_dopri5_odestep, true},
                               {"hand", "hand-written DOPRI5 with error, dopri5.f stage by stage (7 evaluations)",
                                bench_step_lorenz_dopri5_hand, true},
                               {"hand_checked",
                                "the hand loop, checked: NaN/Inf in the new y, the estimate or k2 (weight 0) fails the "
                                "step, which is rolled back",
                                bench_step_lorenz_dopri5_hand_checked, true},
                               {"odeint", "Odeint runge_kutta_dopri5 reset() + do_step with error (7 evaluations)",
                                bench_step_lorenz_dopri5_odeint, true},
                               {"odeint_fsal", "Odeint runge_kutta_dopri5 do_step with error, FSAL (6 evaluations)",
                                bench_step_lorenz_dopri5_odeint_fsal, true},
                               {"gsl", "GSL rkf45 (no Dormand-Prince 5(4) in GSL; 6 evaluations, error estimate)",
                                bench_step_lorenz_dopri5_gsl, false}});
}
