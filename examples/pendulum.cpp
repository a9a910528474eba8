// SPDX-License-Identifier: BSL-1.0
// Course material: the pendulum theta'' = -(g/L) sin theta, g/L = 1, dt = 0.1, for 50 periods from
// theta0 = pi/4 at rest: relative energy error with RK2 (the midpoint method), RK4, velocity Verlet and
// Forest-Ruth; and from theta0 = pi/40, the largest deviation from the small-angle solution theta0 cos t.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {
using angle = std::array<double, 1>;
using phase = std::array<double, 2>;  // theta, omega, for the Runge-Kutta methods

struct gravity {
    angle operator()(double, const angle& theta) const noexcept { return {-std::sin(theta[0])}; }
};
struct pendulum_rhs {
    phase operator()(double, const phase& y) const noexcept { return {y[1], -std::sin(y[0])}; }
};

double energy(double theta, double omega) { return 0.5 * omega * omega + (1 - std::cos(theta)); }

// The period from theta0 at rest: 4 K(k), k = sin(theta0 / 2), K by the arithmetic-geometric mean.
double period(double theta0) {
    double a = 1.0;
    double b = std::cos(theta0 / 2);  // sqrt(1 - k^2)
    for (int i = 0; i < 8; ++i) {
        const double m = (a + b) / 2;
        b = std::sqrt(a * b);
        a = m;
    }
    return 4 * (std::acos(-1.0) / (2 * a));
}

struct errors {
    double worst = 0.0;
    double last = 0.0;
};

template <class Stepper>
errors run_newtonian(double theta0, double t_end, double dt) {
    angle x{theta0};
    angle v{0.0};
    const double e0 = energy(theta0, 0.0);
    errors e;
    const auto r =
        odestep::integrate(Stepper{}, gravity{}, x, v, 0.0, t_end, dt, [&](double, const angle& q, const angle& p) {
            e.worst = std::fmax(e.worst, std::fabs(energy(q[0], p[0]) - e0) / e0);
        });
    e.last = (energy(x[0], v[0]) - e0) / e0;
    if (r.status != odestep::status::ok) e.worst = -1;
    return e;
}

template <class Stepper>
errors run_first_order(double theta0, double t_end, double dt) {
    phase y{theta0, 0.0};
    const double e0 = energy(theta0, 0.0);
    errors e;
    const auto r = odestep::integrate(Stepper{}, pendulum_rhs{}, y, 0.0, t_end, dt, [&](double, const phase& s) {
        e.worst = std::fmax(e.worst, std::fabs(energy(s[0], s[1]) - e0) / e0);
    });
    e.last = (energy(y[0], y[1]) - e0) / e0;
    if (r.status != odestep::status::ok) e.worst = -1;
    return e;
}
}  // namespace

int main() {
    const double pi = std::acos(-1.0);
    const double dt = 0.1;
    const double theta0 = pi / 4;
    const double t_end = 50 * period(theta0);
    std::printf("# pendulum, g/L = 1, theta0 = pi/4, dt = %g, 50 periods of %.9f\n", dt, period(theta0));
    std::printf("%-16s %14s %14s\n", "method", "max|dE/E0|", "dE/E0");
    const errors all[] = {run_first_order<odestep::midpoint<phase>>(theta0, t_end, dt),
                          run_first_order<odestep::rk4<phase>>(theta0, t_end, dt),
                          run_newtonian<odestep::velocity_verlet<angle>>(theta0, t_end, dt),
                          run_newtonian<odestep::forest_ruth<angle>>(theta0, t_end, dt)};
    const char* names[] = {"rk2", "rk4", "velocity_verlet", "forest_ruth"};
    for (int i = 0; i < 4; ++i) {
        if (all[i].worst < 0) return 1;
        std::printf("%-16s %14.6e %14.6e\n", names[i], all[i].worst, all[i].last);
    }
    // Small angle: theta0 cos t differs from the pendulum by its longer period (T = 2 pi (1 + theta0^2/16 + ...)),
    // which the checker computes; velocity Verlet at dt = 0.01 adds a phase error of about 1% of that.
    const double small = pi / 40;
    angle x{small};
    angle v{0.0};
    double deviation = 0.0;
    const double t_small = 10 * 2 * pi;
    const auto r = odestep::integrate(odestep::velocity_verlet<angle>{}, gravity{}, x, v, 0.0, t_small, 0.01,
                                      [&](double t, const angle& q, const angle&) {
                                          deviation = std::fmax(deviation, std::fabs(q[0] - small * std::cos(t)));
                                      });
    if (r.status != odestep::status::ok) return 1;
    std::printf("small_angle theta0 %.9f max_deviation %.6e over 10 periods (velocity Verlet, dt = 0.01)\n", small,
                deviation);
    return 0;
}
