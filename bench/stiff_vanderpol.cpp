// Van der Pol with mu = 1000 (2 states, double), y1' = y2, y2' = mu (1 - y1^2) y2 - y1 from y = (2, 0): the slow
// branch, t from 0 to 800 with dt = 1 (800 steps; the first jump is at t = 807), stiff (eigenvalue about -3000).
// odestep's implicit steppers and RODAS3 against Boost.Odeint's rosenbrock4 and implicit_euler (uBLAS), each with
// the exact Jacobian, at the same step size; y(800) from DOP853 in long double with steps of 2.5e-4.
#include <boost/numeric/odeint/stepper/implicit_euler.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>

#include "harness.hpp"

namespace {
using State = std::array<double, 2>;
using Jac = odestep::jacobian_t<State>;
namespace ublas = boost::numeric::ublas;

template <class T, class Y, class D>
void van_der_pol(const Y& y, D& d) {
    d[0] = y[1];
    d[1] = T(1e3) * (T(1) - y[0] * y[0]) * y[1] - y[0];
}
template <class T, class Y, class M>
void van_der_pol_jacobian(const Y& y, M& j) {
    j(0, 0) = T(0), j(0, 1) = T(1);
    j(1, 0) = T(-2e3) * y[0] * y[1] - T(1), j(1, 1) = T(1e3) * (T(1) - y[0] * y[0]);
}
struct array_matrix {  // odestep's jacobian_t seen through (i, j)
    Jac& m;
    double& operator()(std::size_t i, std::size_t k) { return m[i][k]; }
};

constexpr auto rhs = [](double, const State& y, State& d) { van_der_pol<double>(y, d); };
constexpr auto jac = [](double, const State& y, Jac& j) {
    array_matrix m{j};
    van_der_pol_jacobian<double>(y, m);
};
const auto sys = odestep::with_jacobian(rhs, jac);

struct odeint_rhs {
    void operator()(const ublas::vector<double>& y, ublas::vector<double>& d, double) const {
        van_der_pol<double>(y, d);
    }
};
struct odeint_jac {
    void operator()(const ublas::vector<double>& y, ublas::matrix<double>& j, double,
                    ublas::vector<double>& dfdt) const {
        van_der_pol_jacobian<double>(y, j);
        dfdt[0] = dfdt[1] = 0;
    }
    void operator()(const ublas::vector<double>& y, ublas::matrix<double>& j, double) const {
        van_der_pol_jacobian<double>(y, j);
    }
};
boost::numeric::odeint::rosenbrock4<double> odeint_ros4;
boost::numeric::odeint::implicit_euler<double> odeint_ie(1e-10);  // its stopping test: ||dx||_2 <= 1e-10
ublas::vector<double> ux(2);
void to_ublas(const State& y) {
    for (std::size_t i = 0; i < 2; ++i) ux[i] = y[i];
}
void from_ublas(State& y) {
    for (std::size_t i = 0; i < 2; ++i) y[i] = ux[i];
}
}  // namespace

BENCH_STEP int bench_step_stiff_vanderpol_odestep(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::backward_euler<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_vanderpol_odestep_fixed2(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::backward_euler<State, odestep::fixed_newton<2>>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_vanderpol_odestep_sdirk3(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::sdirk3<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_vanderpol_odestep_radau5(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::radau_iia5<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_vanderpol_odestep_rodas3(State& y, State&, double t, double dt) {
    return static_cast<int>(odestep::rodas3<State>{}.step(sys, y, t, dt));
}
BENCH_STEP int bench_step_stiff_vanderpol_odeint(State& y, State&, double t, double dt) {
    to_ublas(y);
    odeint_ros4.do_step(std::make_pair(odeint_rhs{}, odeint_jac{}), ux, t, dt);
    from_ublas(y);
    return 0;
}
BENCH_STEP int bench_step_stiff_vanderpol_odeint_implicit_euler(State& y, State&, double t, double dt) {
    to_ublas(y);
    odeint_ie.do_step(std::make_pair(odeint_rhs{}, odeint_jac{}), ux, t, dt);
    from_ublas(y);
    return 0;
}

int main(int argc, char** argv) {
    auto f = [](long double, const auto& y, auto& d) { van_der_pol<long double>(y, d); };
    const State y0{2, 0};
    const int steps = 800;
    // DOP853 needs |h lambda| < 3 (lambda about -3000): 2.5e-4
    bench::problem<State> p{"stiff_vanderpol", y0, 0.0, 1.0, steps,
                            bench::reference_solution<2>(f, y0, 0.0L, 800.0L, 3200000),
                            // backward Euler variants agree to their Newton tolerances
                            1e-9,
                            // backward Euler at h = 1: about 1e-3 relative at t = 800
                            5e-2, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::backward_euler, newton<10>, exact Jacobian", bench_step_stiff_vanderpol_odestep, true},
         {"odestep_fixed2", "odestep::backward_euler, fixed_newton<2> (constant cost)",
          bench_step_stiff_vanderpol_odestep_fixed2, false},
         {"odestep_sdirk3", "odestep::sdirk3 (order 3)", bench_step_stiff_vanderpol_odestep_sdirk3, false},
         {"odestep_radau5", "odestep::radau_iia5 (order 5)", bench_step_stiff_vanderpol_odestep_radau5, false},
         {"odestep_rodas3", "odestep::rodas3 (Rosenbrock, order 3)", bench_step_stiff_vanderpol_odestep_rodas3, false},
         {"odeint", "Odeint rosenbrock4 (order 4, uBLAS) do_step", bench_step_stiff_vanderpol_odeint, false},
         {"odeint_implicit_euler", "Odeint implicit_euler (uBLAS), epsilon 1e-10",
          bench_step_stiff_vanderpol_odeint_implicit_euler, false}});
}
