// SPDX-License-Identifier: BSL-1.0
// Robertson's kinetics (3 states, double), stiff, from t = 1 to 41 with dt = 0.1 (400 steps): odestep's implicit
// steppers and RODAS3 against Boost.Odeint's rosenbrock4 and implicit_euler (uBLAS) and, where SUNDIALS is
// installed, ARKODE's DIRK steppers (bench/sundials.hpp), every one with the exact Jacobian, at the same step
// size. The start at t = 1 skips the initial layer, where a Jacobian frozen at the step's start cannot see the
// stiffness yet (docs/stiff.md); y(1) and y(41) come from DOP853 in long double.
#include <boost/numeric/odeint/stepper/implicit_euler.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>

#include <cstring>
#include <utility>
#include <vector>

#include "cpu_time.hpp"
#include "harness.hpp"
#include "sundials.hpp"

namespace {
using State = std::array<double, 3>;
using Jac = odestep::jacobian_t<State>;
namespace ublas = boost::numeric::ublas;
constexpr double dt_case = 0.1;  // the step of every variant

template <class T, class Y, class D>
void robertson(const Y& y, D& d) {
    d[0] = T(-0.04) * y[0] + T(1e4) * y[1] * y[2];
    d[2] = T(3e7) * y[1] * y[1];
    d[1] = -d[0] - d[2];
}
template <class T, class Y, class M>
void robertson_jacobian(const Y& y, M& j) {
    j(0, 0) = T(-0.04), j(0, 1) = T(1e4) * y[2], j(0, 2) = T(1e4) * y[1];
    j(2, 0) = T(0), j(2, 1) = T(6e7) * y[1], j(2, 2) = T(0);
    j(1, 0) = -j(0, 0) - j(2, 0), j(1, 1) = -j(0, 1) - j(2, 1), j(1, 2) = -j(0, 2) - j(2, 2);
}
struct array_matrix {  // odestep's jacobian_t seen through (i, j)
    Jac& m;
    double& operator()(std::size_t i, std::size_t k) { return m[i][k]; }
};

constexpr auto rhs = [](double, const State& y, State& d) { robertson<double>(y, d); };
constexpr auto jac = [](double, const State& y, Jac& j) {
    array_matrix m{j};
    robertson_jacobian<double>(y, m);
};
const auto sys = odestep::with_jacobian(rhs, jac);

struct odeint_rhs {
    void operator()(const ublas::vector<double>& y, ublas::vector<double>& d, double) const { robertson<double>(y, d); }
};
struct odeint_jac {
    void operator()(const ublas::vector<double>& y, ublas::matrix<double>& j, double,
                    ublas::vector<double>& dfdt) const {
        robertson_jacobian<double>(y, j);
        dfdt[0] = dfdt[1] = dfdt[2] = 0;
    }
    void operator()(const ublas::vector<double>& y, ublas::matrix<double>& j, double) const {
        robertson_jacobian<double>(y, j);
    }
};
boost::numeric::odeint::rosenbrock4<double> odeint_ros4;
boost::numeric::odeint::implicit_euler<double> odeint_ie(1e-10);  // its stopping test: ||dx||_2 <= 1e-10
ublas::vector<double> ux(3);
void to_ublas(const State& y) {
    for (std::size_t i = 0; i < 3; ++i) ux[i] = y[i];
}
void from_ublas(State& y) {
    for (std::size_t i = 0; i < 3; ++i) y[i] = ux[i];
}

#ifdef BENCH_HAVE_SUNDIALS
// ARKODE's callbacks: f and the exact Jacobian through N_Vector and the dense SUNMatrix.
int arkode_rhs(double, N_Vector y, N_Vector d, void*) {
    double* out = N_VGetArrayPointer(d);
    robertson<double>(N_VGetArrayPointer(y), out);
    return 0;
}
int arkode_jac(double, N_Vector y, N_Vector, SUNMatrix j, void*, N_Vector, N_Vector, N_Vector) {
    bench::sun_dense m{j};
    robertson_jacobian<double>(N_VGetArrayPointer(y), m);
    return 0;
}
// The same tables as odestep's: backward Euler, and Alexander's SDIRK 3 (Alexander 1977, SIAM J. Numer.
// Anal. 14, 1006-1021) with its coefficients taken from odestep's own table (include/odestep/tables/).
constexpr auto& sdirk3_table = odestep::tables::sdirk3::table<double>;
const double be_a[1] = {1}, be_b[1] = {1}, be_c[1] = {1};
const double sd_a[9] = {sdirk3_table.a[0][0], sdirk3_table.a[0][1], sdirk3_table.a[0][2],
                        sdirk3_table.a[1][0], sdirk3_table.a[1][1], sdirk3_table.a[1][2],
                        sdirk3_table.a[2][0], sdirk3_table.a[2][1], sdirk3_table.a[2][2]};
const double sd_b[3] = {sdirk3_table.b[0], sdirk3_table.b[1], sdirk3_table.b[2]};
const double sd_c[3] = {sdirk3_table.c[0], sdirk3_table.c[1], sdirk3_table.c[2]};
bench::arkode_dirk arkode_be(arkode_rhs, arkode_jac, 3, dt_case, bench::arkode_user_table{1, 1, be_a, be_b, be_c});
bench::arkode_dirk arkode_sdirk3(arkode_rhs, arkode_jac, 3, dt_case, bench::arkode_user_table{3, 3, sd_a, sd_b, sd_c});
bench::arkode_dirk arkode_sdirk3_tight(arkode_rhs, arkode_jac, 3, dt_case,
                                       bench::arkode_user_table{3, 3, sd_a, sd_b, sd_c});
bench::arkode_dirk arkode_sdirk4(arkode_rhs, arkode_jac, 3, dt_case, ARKODE_SDIRK_5_3_4);
#endif
}  // namespace

BENCH_STEP int bench_step_stiff_robertson_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::backward_euler<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_robertson_odestep_fixed2(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::backward_euler<State, odestep::fixed_newton<2>>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_robertson_odestep_sdirk3(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::sdirk3<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_robertson_odestep_radau5(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::radau_iia5<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_robertson_odestep_rodas3(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::rodas3<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_robertson_odeint(State& y, State&, double t, double dt) {
    to_ublas(y);
    odeint_ros4.do_step(std::make_pair(odeint_rhs{}, odeint_jac{}), ux, t, dt);
    from_ublas(y);
    return 0;
}
BENCH_STEP int bench_step_stiff_robertson_odeint_implicit_euler(State& y, State&, double t, double dt) {
    to_ublas(y);
    odeint_ie.do_step(std::make_pair(odeint_rhs{}, odeint_jac{}), ux, t, dt);
    from_ublas(y);
    return 0;
}

#ifdef BENCH_HAVE_SUNDIALS
BENCH_STEP int bench_step_stiff_robertson_arkode_be(State& y, State&, double t, double dt) {
    return arkode_be.step(y.data(), t, dt);
}
BENCH_STEP int bench_step_stiff_robertson_arkode_sdirk3(State& y, State&, double t, double dt) {
    return arkode_sdirk3.step(y.data(), t, dt);
}
BENCH_STEP int bench_step_stiff_robertson_arkode_sdirk4(State& y, State&, double t, double dt) {
    return arkode_sdirk4.step(y.data(), t, dt);
}
#endif

int main(int argc, char** argv) {
    auto f = [](long double, const auto& y, auto& d) { robertson<long double>(y, d); };
    // DOP853 needs |h lambda| < 3 here (lambda down to about -3e3): 2e-5 over [0, 1] and 1e-4 over [1, 41].
    const State y0 = bench::reference_solution<3>(f, State{1, 0, 0}, 0.0L, 1.0L, 50000);
    const int steps = 400;
    const bench::problem<State> p{"stiff_robertson", y0, 1.0, dt_case, steps,
                                  bench::reference_solution<3>(f, y0, 1.0L, 41.0L, 400000),
                                  // backward Euler variants agree to their Newton tolerances (1.8e-12 relative)
                                  1e-9,
                                  // backward Euler at h = 0.1: 7e-4 relative error in y3 at t = 41 (y2 is tiny)
                                  5e-3, false};
    std::vector<bench::variant<State>> variants{
        {"odestep", "odestep::backward_euler, newton<10>, exact Jacobian", bench_step_stiff_robertson_odestep, true},
        {"odestep_fixed2", "odestep::backward_euler, fixed_newton<2> (constant cost)",
         bench_step_stiff_robertson_odestep_fixed2, false},
        {"odestep_sdirk3", "odestep::sdirk3 (order 3)", bench_step_stiff_robertson_odestep_sdirk3, false},
        {"odestep_radau5", "odestep::radau_iia5 (order 5)", bench_step_stiff_robertson_odestep_radau5, false},
        {"odestep_rodas3", "odestep::rodas3 (Rosenbrock, order 3)", bench_step_stiff_robertson_odestep_rodas3, false},
        {"odeint", "Odeint rosenbrock4 (order 4, uBLAS) do_step", bench_step_stiff_robertson_odeint, false},
        {"odeint_implicit_euler", "Odeint implicit_euler (uBLAS), epsilon 1e-10",
         bench_step_stiff_robertson_odeint_implicit_euler, false}};
#ifdef BENCH_HAVE_SUNDIALS
    // ARKODE keeps its state between steps: each run starts with ARKStepReset (the start hook); odestep's and
    // Odeint's steps need nothing.
    const bench::variant<State> ark_sdirk3{"arkode_sdirk3",
                                           "SUNDIALS ARKODE ARKStep, Alexander's SDIRK 3 as a user table",
                                           bench_step_stiff_robertson_arkode_sdirk3, false,
                                           [](const State& y, double t) { arkode_sdirk3.start(y.data(), t); }};
    variants.push_back({"arkode_be", "SUNDIALS ARKODE ARKStep, backward Euler as a user table (same method)",
                        bench_step_stiff_robertson_arkode_be, true,
                        [](const State& y, double t) { arkode_be.start(y.data(), t); }});
    variants.push_back(ark_sdirk3);
    variants.push_back({"arkode_sdirk4", "SUNDIALS ARKODE ARKStep, built-in ARKODE_SDIRK_5_3_4 (order 4)",
                        bench_step_stiff_robertson_arkode_sdirk4, false,
                        [](const State& y, double t) { arkode_sdirk4.start(y.data(), t); }});
#endif
    // cpu [rounds]: the runs timed by the thread's CPU clock as well (bench/cpu_time.hpp)
    if (argc > 1 && std::strcmp(argv[1], "cpu") == 0)
        return bench::cpu_time<State>(p, variants, argc > 2 ? std::atoi(argv[2]) : 51);
    int rc = bench::main<State>(argc, argv, p, variants);
#ifdef BENCH_HAVE_SUNDIALS
    if (argc < 2 || std::strcmp(argv[1], "check") == 0) {
        // The same table twice, both Newton iterations to 2^-46 = 1.4e-14 (their norms differ, RMS against
        // maximum, so at the default 2^-39 they stop at slightly different iterates): ARKODE's SDIRK 3 against
        // odestep's must agree to round-off, which checks that the user table was set up right.
        static odestep::sdirk3<State> sdirk3_tight;
        if (sdirk3_tight.set_tolerance({0x1p-46, 0x1p-46}) != odestep::status::ok) return 2;
        arkode_sdirk3_tight.set_tolerance(0x1p-46);
        bench::problem<State> q = p;
        q.name = "stiff_robertson_sdirk3_tight";
        const std::vector<bench::variant<State>> pair{
            {"odestep_sdirk3", "odestep::sdirk3, Newton tolerance 2^-46",
             [](State& y, State&, double t, double dt) { return static_cast<int>(sdirk3_tight.step(sys, y, t, dt)); },
             true},
            {"arkode_sdirk3", "ARKODE, the same table, Newton tolerance 2^-46",
             [](State& y, State&, double t, double dt) { return arkode_sdirk3_tight.step(y.data(), t, dt); }, true,
             [](const State& y, double t) { arkode_sdirk3_tight.start(y.data(), t); }}};
        if (bench::check<State>(q, pair) != 0) rc = 1;
        const std::pair<const char*, const bench::arkode_dirk*> arks[] = {
            {"arkode_be", &arkode_be}, {"arkode_sdirk3", &arkode_sdirk3}, {"arkode_sdirk4", &arkode_sdirk4}};
        for (const auto& a : arks) {
            long n = 0, fi = 0, setups = 0, jacs = 0, newton = 0;
            a.second->stats(n, fi, setups, jacs, newton);
            std::printf("STATS\t%s\tper step: f %.2f, Newton iterations %.2f, Jacobians %.2f, factorizations %.2f\n",
                        a.first, double(fi) / double(n), double(newton) / double(n), double(jacs) / double(n),
                        double(setups) / double(n));
        }
    }
#endif
    return rc;
}
