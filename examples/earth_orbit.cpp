// SPDX-License-Identifier: BSL-1.0
// Course material: the Earth around the Sun in astronomical units and years, GM = 4 pi^2 AU^3/yr^2,
// r0 = 1 AU, v0 = 2 pi AU/yr (a circular orbit), for 10 years with Euler, Euler-Cromer and velocity
// Verlet at dt = 0.01 and 0.001 yr. Prints the largest and the final relative energy error and the final
// relative change of angular momentum.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {
using vec = std::array<double, 2>;
const double pi = std::acos(-1.0);
const double gm = 4 * pi * pi;

struct sun {  // a = -GM x / |x|^3
    vec operator()(double, const vec& x) const noexcept {
        const double r2 = x[0] * x[0] + x[1] * x[1];
        const double r3 = r2 * std::sqrt(r2);
        return {-gm * x[0] / r3, -gm * x[1] / r3};
    }
};

double energy(const vec& x, const vec& v) {  // per unit mass
    return 0.5 * (v[0] * v[0] + v[1] * v[1]) - gm / std::sqrt(x[0] * x[0] + x[1] * x[1]);
}
double angular_momentum(const vec& x, const vec& v) { return x[0] * v[1] - x[1] * v[0]; }

template <class Stepper>
int run(const char* name, double dt) {
    vec x{1.0, 0.0};
    vec v{0.0, 2 * pi};
    const double e0 = energy(x, v);
    const double l0 = angular_momentum(x, v);
    double worst = 0.0;
    const auto r = odestep::integrate(Stepper{}, sun{}, x, v, 0.0, 10.0, dt, [&](double, const vec& q, const vec& p) {
        worst = std::fmax(worst, std::fabs((energy(q, p) - e0) / e0));
    });
    if (r.status != odestep::status::ok) return 1;
    std::printf("%-16s %-6g %6zu %14.6e %14.6e %14.6e\n", name, dt, r.steps, worst, (energy(x, v) - e0) / std::fabs(e0),
                (angular_momentum(x, v) - l0) / l0);
    return 0;
}
}  // namespace

int main() {
    std::printf("# Earth-Sun, GM = 4 pi^2, r0 = 1 AU, v0 = 2 pi AU/yr, 10 years\n");
    std::printf("%-16s %-6s %6s %14s %14s %14s\n", "method", "dt", "steps", "max|dE/E0|", "dE/|E0|", "dL/L0");
    int failed = 0;
    for (double dt : {0.01, 0.001}) {
        failed += run<odestep::newtonian_euler<vec>>("euler", dt);
        failed += run<odestep::euler_cromer<vec>>("euler_cromer", dt);
        failed += run<odestep::velocity_verlet<vec>>("velocity_verlet", dt);
    }
    return failed;
}
