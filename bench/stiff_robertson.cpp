// Robertson's kinetics (3 states, double), stiff, from t = 1 to 41 with dt = 0.1 (400 steps): odestep's implicit
// steppers and RODAS3 against Boost.Odeint's rosenbrock4 and implicit_euler (uBLAS), every one with the exact
// Jacobian, at the same step size. The start at t = 1 skips the initial layer, where a Jacobian frozen at the
// step's start cannot see the stiffness yet (docs/stiff.md); y(1) and y(41) come from DOP853 in long double.
#include <boost/numeric/odeint/stepper/implicit_euler.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>

#include "harness.hpp"

namespace {
using State = std::array<double, 3>;
using Jac = odestep::jacobian_t<State>;
namespace ublas = boost::numeric::ublas;

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

int main(int argc, char** argv) {
    auto f = [](long double, const auto& y, auto& d) { robertson<long double>(y, d); };
    // DOP853 needs |h lambda| < 3 here (lambda down to about -3e3): 2e-5 over [0, 1] and 1e-4 over [1, 41].
    const State y0 = bench::reference_solution<3>(f, State{1, 0, 0}, 0.0L, 1.0L, 50000);
    const int steps = 400;
    bench::problem<State> p{"stiff_robertson", y0, 1.0, 0.1, steps,
                            bench::reference_solution<3>(f, y0, 1.0L, 41.0L, 400000),
                            // backward Euler variants agree to their Newton tolerances (1.8e-12 relative)
                            1e-9,
                            // backward Euler at h = 0.1: 7e-4 relative error in y3 at t = 41 (y2 is tiny)
                            5e-3, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::backward_euler, newton<10>, exact Jacobian", bench_step_stiff_robertson_odestep, true},
         {"odestep_fixed2", "odestep::backward_euler, fixed_newton<2> (constant cost)",
          bench_step_stiff_robertson_odestep_fixed2, false},
         {"odestep_sdirk3", "odestep::sdirk3 (order 3)", bench_step_stiff_robertson_odestep_sdirk3, false},
         {"odestep_radau5", "odestep::radau_iia5 (order 5)", bench_step_stiff_robertson_odestep_radau5, false},
         {"odestep_rodas3", "odestep::rodas3 (Rosenbrock, order 3)", bench_step_stiff_robertson_odestep_rodas3, false},
         {"odeint", "Odeint rosenbrock4 (order 4, uBLAS) do_step", bench_step_stiff_robertson_odeint, false},
         {"odeint_implicit_euler", "Odeint implicit_euler (uBLAS), epsilon 1e-10",
          bench_step_stiff_robertson_odeint_implicit_euler, false}});
}
