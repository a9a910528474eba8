// SPDX-License-Identifier: BSL-1.0
// Planar three-body problem (12 states, double), DOP853's eighth-order step at a fixed step size.
// Odeint has no DOP853: its nearest eighth-order method, runge_kutta_fehlberg78 (13 evaluations), stands in,
// as does GSL's rk8pd (Prince-Dormand 8(7), 13 stages, with error estimate). Both are other methods, so they
// are checked against the reference only; threebody_rkf78 compares Odeint with the same method.
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

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
boost::numeric::odeint::runge_kutta_fehlberg78<State> odeint_rkf78;
bench::gsl_stepper gsl_rk8pd(gsl_odeiv2_step_rk8pd, gsl_rhs, 12);
}  // namespace

BENCH_STEP int bench_step_threebody_dop853_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::dop853<State>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_threebody_dop853_hand(State& y, State&, double t, double dt) {
    bench::hand::dop853(rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_threebody_dop853_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::dop853<true>(rhs, y, t, dt);
}
BENCH_STEP int bench_step_threebody_dop853_odeint(State& y, State&, double t, double dt) {
    odeint_rkf78.do_step(odeint_rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_threebody_dop853_gsl(State& y, State& err, double t, double dt) {
    return gsl_rk8pd.apply(y.data(), err.data(), t, dt);
}

int main(int argc, char** argv) {
    const State y0 = bench::figure_eight<double>();
    const double dt = 0.05;
    const int steps = 40;
    bench::problem<State> p{
        "threebody_dop853", y0, 0.0, dt, steps,
        bench::reference_solution<12>([](long double, const auto& y, auto& d) { bench::three_body<long double>(y, d); },
                                      y0, 0.0L, steps * 0.05L, 16 * steps),
        // Round-off: DOP853's coefficients reach 43 in magnitude, so each stage input
        // carries a few hundred ulps of cancellation; 40 steps of that.
        1e-12,
        // Eighth order with h = 0.05 over a third of the period: 7e-12 relative
        // (RKF78 2.6e-11, rk8pd 5e-12); a seventh-order slip would be ~1e-9.
        1e-10, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::dop853 (12 evaluations)", bench_step_threebody_dop853_odestep, true},
         {"hand", "hand-written DOP853, dop853.f stage by stage", bench_step_threebody_dop853_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new y or in a zero-weight stage (k2..k5) fails the step, which is "
          "rolled back",
          bench_step_threebody_dop853_hand_checked, true},
         {"odeint", "Odeint runge_kutta_fehlberg78 (no DOP853 in Odeint; 13 evaluations)",
          bench_step_threebody_dop853_odeint, false},
         {"gsl", "GSL rk8pd (no DOP853 in GSL; 13 evaluations, error estimate)", bench_step_threebody_dop853_gsl,
          false}});
}
