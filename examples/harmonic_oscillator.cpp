// SPDX-License-Identifier: BSL-1.0
// Course material: the simple harmonic oscillator (k = m = 1) after 10 periods with Euler,
// Euler-Richardson (the explicit midpoint method) and RK4, at dt = 0.1 and 0.01. Prints the state, the
// amplitude and the energy relative to the start. Euler's energy grows exactly as (1 + dt^2) per step.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {

using state = std::array<double, 2>;  // x, v

struct oscillator {
    void operator()(double, const state& y, state& dydt) const noexcept {
        dydt[0] = y[1];   // x' = v
        dydt[1] = -y[0];  // v' = -k/m x
    }
};

template <class Stepper>
int run(const char* name, double dt) {
    const double ten_periods = 20.0 * std::acos(-1.0);
    state y{1.0, 0.0};
    const double e0 = 0.5 * (y[0] * y[0] + y[1] * y[1]);
    const auto r = odestep::integrate(Stepper{}, oscillator{}, y, 0.0, ten_periods, dt);
    if (r.status != odestep::status::ok) return 1;
    const double e = 0.5 * (y[0] * y[0] + y[1] * y[1]);
    std::printf("%-17s %-5g %6zu %19.12e %19.12e %19.12e %19.12e\n", name, dt, r.steps, y[0], y[1],
                std::sqrt(y[0] * y[0] + y[1] * y[1]), e / e0);
    return 0;
}

}  // namespace

int main() {
    std::printf(
        "# x'' = -x, x(0) = 1, v(0) = 0, integrated to t = 20 pi (10 periods); exact: x = 1, v = 0, E/E0 = 1\n");
    std::printf("%-17s %-5s %6s %19s %19s %19s %19s\n", "method", "dt", "steps", "x", "v", "amplitude", "E/E0");
    int failed = 0;
    for (double dt : {0.1, 0.01}) {
        failed += run<odestep::euler<state>>("euler", dt);
        failed += run<odestep::euler_richardson<state>>("euler_richardson", dt);
        failed += run<odestep::rk4<state>>("rk4", dt);
    }
    return failed;
}
