// SPDX-License-Identifier: BSL-1.0
// Course material: phase space (problem 3.3). The trajectory of an oscillator in the (x, v) plane.
//
// Part 1, the simple harmonic oscillator x'' = -x from x = 1, v = 0 with dt = 0.1 for 3 periods: the exact
// trajectory is the unit circle; Euler spirals outwards (each step multiplies x^2 + v^2 by exactly
// 1 + dt^2), Euler-Cromer stays on the tilted ellipse x^2 + v^2 - dt x v = 1, and velocity Verlet on the
// ellipse (1 - dt^2/4) x^2 + v^2 = 1 - dt^2/4. Printed: the final state and the largest relative change
// of each method's own quadratic invariant.
//
// Part 2, the pendulum theta'' = -sin theta, dt = 0.15 for 167 steps (t = 25.05), from five starts (four at rest, one
// rotating) with Euler, Euler-Cromer, the midpoint method (RK2), RK4, velocity Verlet and Forest-Ruth:
// the phase portrait per method. Printed: the final state and the relative energy change of each orbit.
//
// Data: sho_phase.csv (one data set per method, then the exact circle), pendulum_phase.csv (one data set
// per method, one curve per start; columns t, theta, omega).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using one = std::array<double, 1>;
using two = std::array<double, 2>;  // theta, omega for the first-order methods

struct spring {
    one operator()(double, const one& x) const noexcept { return {-x[0]}; }
};
struct pendulum {
    one operator()(double, const one& x) const noexcept { return {-std::sin(x[0])}; }
};
struct pendulum_rhs {
    two operator()(double, const two& y) const noexcept { return {y[1], -std::sin(y[0])}; }
};

double pendulum_energy(double theta, double omega) { return 0.5 * omega * omega + 1.0 - std::cos(theta); }

constexpr double sho_dt = 0.1;

template <class Stepper, class Invariant>
bool sho_run(const char* name, std::size_t steps, Invariant invariant, example::csv_file& out) {
    one x{1.0};
    one v{0.0};
    const double q0 = invariant(0.0, x[0], v[0]);
    double worst = 0.0;
    const auto r = odestep::integrate_n_steps(
        Stepper{}, spring{}, x, v, 0.0, sho_dt, steps, [&](double t, const one& q, const one& p) {
            worst = std::fmax(worst, std::fabs(invariant(t, q[0], p[0]) / q0 - 1));
            out.csv(t, q, p);
        });
    out.next_block();
    if (r.status != odestep::status::ok) return false;
    std::printf("sho %-16s %4zu %24.17g %24.17g %12.4e\n", name, r.steps, x[0], v[0], worst);
    return true;
}

constexpr double pend_dt = 0.15;
constexpr std::size_t pend_steps = 167;  // to t = 25.05
constexpr std::array<two, 5> starts{{{0.5, 0.0}, {1.2, 0.0}, {2.0, 0.0}, {2.8, 0.0}, {0.0, 2.1}}};

template <class Stepper>
bool pendulum_newtonian(const char* name, example::csv_file& out) {
    for (std::size_t k = 0; k < starts.size(); ++k) {
        one x{starts[k][0]};
        one v{starts[k][1]};
        const double e0 = pendulum_energy(x[0], v[0]);
        const auto r = odestep::integrate_n_steps(Stepper{}, pendulum{}, x, v, 0.0, pend_dt, pend_steps, out.csv);
        out.next_curve();
        if (r.status != odestep::status::ok) return false;
        std::printf("pendulum %-16s %zu %4zu %24.17g %24.17g %14.6e\n", name, k, r.steps, x[0], v[0],
                    pendulum_energy(x[0], v[0]) / e0 - 1);
    }
    out.next_block();
    return true;
}

template <class Stepper>
bool pendulum_first_order(const char* name, example::csv_file& out) {
    for (std::size_t k = 0; k < starts.size(); ++k) {
        two y = starts[k];
        const double e0 = pendulum_energy(y[0], y[1]);
        const auto r = odestep::integrate_n_steps(Stepper{}, pendulum_rhs{}, y, 0.0, pend_dt, pend_steps, out.csv);
        out.next_curve();
        if (r.status != odestep::status::ok) return false;
        std::printf("pendulum %-16s %zu %4zu %24.17g %24.17g %14.6e\n", name, k, r.steps, y[0], y[1],
                    pendulum_energy(y[0], y[1]) / e0 - 1);
    }
    out.next_block();
    return true;
}
}  // namespace

int main(int argc, char** argv) {
    const double pi = std::acos(-1.0);
    example::csv_file sho(argc, argv, "sho_phase.csv");
    example::csv_file pend(argc, argv, "pendulum_phase.csv");
    sho.csv.header("t", "x", "v");
    pend.csv.header("t", "theta", "omega");

    const std::size_t steps = static_cast<std::size_t>(3 * 2 * pi / sho_dt);  // 188 steps, just under 3 periods
    std::printf("# SHO x'' = -x, x(0) = 1, v(0) = 0, dt = %g, %zu steps; invariant of each method\n", sho_dt, steps);
    std::printf("sho %-16s %4s %24s %24s %12s\n", "method", "n", "x", "v", "max|dQ/Q0|");
    const double h = sho_dt;
    // Euler's x^2 + v^2 over its growth (1 + dt^2)^n, n = t / dt: constant if the growth is exactly that.
    bool ok = sho_run<odestep::newtonian_euler<one>>(
        "euler", steps,
        [h](double t, double x, double v) { return (x * x + v * v) / std::pow(1 + h * h, std::round(t / h)); }, sho);
    ok = ok && sho_run<odestep::euler_cromer<one>>(
                   "euler_cromer", steps, [h](double, double x, double v) { return x * x + v * v - h * x * v; }, sho);
    ok = ok && sho_run<odestep::velocity_verlet<one>>(
                   "velocity_verlet", steps,
                   [h](double, double x, double v) { return (1 - h * h / 4) * x * x + v * v; }, sho);
    for (int i = 0; i <= 200; ++i) {
        const double t = 2 * pi * i / 200;
        sho.csv.row(t, std::cos(t), -std::sin(t));
    }

    std::printf("# pendulum theta'' = -sin theta, dt = %g, %zu steps, starts (theta, omega):", pend_dt, pend_steps);
    for (const two& s : starts) std::printf(" (%g, %g)", s[0], s[1]);
    std::printf("\n");
    std::printf("pendulum %-16s %s %4s %24s %24s %14s\n", "method", "k", "n", "theta", "omega", "dE/E0");
    ok = ok && pendulum_newtonian<odestep::newtonian_euler<one>>("euler", pend);
    ok = ok && pendulum_newtonian<odestep::euler_cromer<one>>("euler_cromer", pend);
    ok = ok && pendulum_first_order<odestep::midpoint<two>>("rk2", pend);
    ok = ok && pendulum_first_order<odestep::rk4<two>>("rk4", pend);
    ok = ok && pendulum_newtonian<odestep::velocity_verlet<one>>("velocity_verlet", pend);
    ok = ok && pendulum_newtonian<odestep::forest_ruth<one>>("forest_ruth", pend);
    return ok && sho.good() && pend.good() ? 0 : 1;
}
