// SPDX-License-Identifier: BSL-1.0
// Lorenz (3 states, double), classic RK4, fixed step.
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include "gsl.hpp"
#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"
#include "sundials.hpp"

namespace {
using State = std::array<double, 3>;
constexpr auto rhs = [](double, const State& y, State& d) { bench::lorenz<double>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, double) { bench::lorenz<double>(y, d); };
int gsl_rhs(double, const double y[], double d[], void*) {
    bench::lorenz<double>(y, d);
    return GSL_SUCCESS;
}
boost::numeric::odeint::runge_kutta4<State> odeint_rk4;
bench::gsl_stepper gsl_rk4(gsl_odeiv2_step_rk4, gsl_rhs, 3);
#ifdef BENCH_HAVE_SUNDIALS
// ARKODE (optional, bench/sundials.hpp): ARKStep in explicit mode, fixed step, the classic RK4 table as a
// user table (SUNDIALS 6.4.1 has no built-in classic RK4).
int arkode_rhs(double, N_Vector y, N_Vector d, void*) {
    double* out = N_VGetArrayPointer(d);
    bench::lorenz<double>(N_VGetArrayPointer(y), out);
    return 0;
}
const double rk4_a[16] = {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0};
const double rk4_b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
const double rk4_c[4] = {0, 0.5, 0.5, 1};
bench::arkode_erk arkode_rk4(arkode_rhs, 3, 0.005, bench::arkode_user_table{4, 4, rk4_a, rk4_b, rk4_c});
#endif
}  // namespace

BENCH_STEP int bench_step_lorenz_rk4_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::rk4<State>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_lorenz_rk4_odestep_unchecked(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<State>>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_lorenz_rk4_hand(State& y, State&, double t, double dt) {
    bench::hand::rk4(rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_lorenz_rk4_hand_checked(State& y, State&, double t, double dt) {
    return bench::hand::rk4_checked(rhs, y, t, dt);
}
BENCH_STEP int bench_step_lorenz_rk4_odeint(State& y, State&, double t, double dt) {
    odeint_rk4.do_step(odeint_rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_lorenz_rk4_gsl(State& y, State& err, double t, double dt) {
    return gsl_rk4.apply(y.data(), err.data(), t, dt);
}
#ifdef BENCH_HAVE_SUNDIALS
BENCH_STEP int bench_step_lorenz_rk4_arkode(State& y, State&, double t, double dt) {
    return arkode_rk4.step(y.data(), t, dt);
}
#endif

int main(int argc, char** argv) {
    const State y0{-8.0, 8.0, 27.0};
    const double dt = 0.005;
    const int steps = 100;
    bench::problem<State> p{
        "lorenz_rk4", y0, 0.0, dt, steps,
        bench::reference_solution<3>([](long double, const auto& y, auto& d) { bench::lorenz<long double>(y, d); }, y0,
                                     0.0L, steps * 0.005L, 16 * steps),
        // Round-off: 100 steps of a few ulps each, amplified a few times over t = 0.5.
        1e-12,
        // RK4 with h = 0.005 on Lorenz: global error 3.5e-8 relative (GSL, which steps
        // by h/2: 2e-9); a step of lower order misses this by orders of magnitude.
        1e-7, false};
    std::vector<bench::variant<State>> variants{
        {"odestep", "odestep::rk4", bench_step_lorenz_rk4_odestep, true},
        {"odestep_unchecked", "odestep::unchecked_t<odestep::rk4<State>>: no NaN/Inf test (the same arithmetic)",
         bench_step_lorenz_rk4_odestep_unchecked, true},
        {"hand", "hand-written RK4 loop", bench_step_lorenz_rk4_hand, true},
        {"hand_checked",
         "the hand loop, checked: NaN/Inf in the new y fails the step, which is rolled back "
         "(hand.hpp rk4_checked)",
         bench_step_lorenz_rk4_hand_checked, true},
        {"odeint", "Odeint runge_kutta4<std::array> do_step", bench_step_lorenz_rk4_odeint, true},
        {"gsl", "GSL rk4 (step doubling: 11 f evaluations, error estimate)", bench_step_lorenz_rk4_gsl, false}};
#ifdef BENCH_HAVE_SUNDIALS
    // ARKODE keeps its state between steps: each run starts with ARKStepReset (the start hook).
    variants.push_back({"arkode", "SUNDIALS ARKODE ARKStep explicit, fixed step, classic RK4 as a user table",
                        bench_step_lorenz_rk4_arkode, true,
                        [](const State& y, double t) { arkode_rk4.start(y.data(), t); }});
#endif
    return bench::main<State>(argc, argv, p, variants);
}
