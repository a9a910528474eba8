// SPDX-License-Identifier: BSL-1.0
// Course material: a planet in a circular orbit, GM = 1, from x = (4, 0) with v = (0, 1/2) (circular:
// v^2 = GM / r), integrated with velocity Verlet. Counts the turning points of x(t) (where v_x changes
// sign, two per orbit) over 10 1/4 orbits, and estimates the period from the times of the turning points.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {
using vec = std::array<double, 2>;

struct gravity {  // a = -GM x / |x|^3, GM = 1
    vec operator()(double, const vec& x) const noexcept {
        const double r2 = x[0] * x[0] + x[1] * x[1];
        const double r3 = r2 * std::sqrt(r2);
        return {-x[0] / r3, -x[1] / r3};
    }
};
}  // namespace

int main() {
    const double pi = std::acos(-1.0);
    const double period = 2 * pi * std::pow(4.0, 1.5);  // Kepler's third law, GM = 1
    const double dt = 0.01;
    vec x{4.0, 0.0};
    vec v{0.0, 0.5};
    int turning_points = 0;
    double first = 0.0;
    double last = 0.0;
    double prev_t = 0.0;
    double prev_vx = v[0];
    const auto r = odestep::integrate(
        odestep::velocity_verlet<vec>{}, gravity{}, x, v, 0.0, 10.25 * period, dt,
        [&](double t, const vec&, const vec& vel) {
            if (prev_vx != 0.0 && (prev_vx < 0.0) != (vel[0] < 0.0)) {  // v_x starts at 0: no turn there
                // linear interpolation of the zero of v_x inside the step
                const double tz = prev_t + (t - prev_t) * prev_vx / (prev_vx - vel[0]);
                if (turning_points == 0) first = tz;
                last = tz;
                ++turning_points;
            }
            prev_t = t;
            prev_vx = vel[0];
        });
    if (r.status != odestep::status::ok) return 1;
    const double measured = 2.0 * (last - first) / (turning_points - 1);
    std::printf("# Kepler orbit GM = 1 from (4, 0), v = (0, 0.5), velocity Verlet, dt = %g, t = 10.25 periods\n", dt);
    std::printf("turning_points %d\n", turning_points);
    std::printf("orbits %d\n", turning_points / 2);
    std::printf("period %.9f\n", measured);
    std::printf("radius %.9f\n", std::sqrt(x[0] * x[0] + x[1] * x[1]));
    return 0;
}
