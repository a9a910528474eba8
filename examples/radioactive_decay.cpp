// SPDX-License-Identifier: BSL-1.0
// Course material: radioactive decay dN/dt = -lambda N, lambda = 1, dt = 0.01, with Euler and RK4;
// N(t)/N0 at t = 1 and t = 2 against exp(-t).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace {
using state = std::array<double, 1>;
constexpr double lambda = 1.0;
}  // namespace

int main() {
    auto decay = [](double, const state& n) { return state{-lambda * n[0]}; };
    const double dt = 0.01;
    std::printf("# dN/dt = -N, N(0) = 1, dt = %g\n", dt);
    std::printf("%-3s %19s %19s %19s %12s %12s\n", "t", "euler", "rk4", "exp(-t)", "euler_rel", "rk4_rel");
    state euler{1.0};
    state rk4{1.0};
    double t = 0.0;
    for (double t_next : {1.0, 2.0}) {
        // Each leg lands exactly on t_next; the steppers carry no history, so legs compose.
        if (odestep::integrate(odestep::euler<state>{}, decay, euler, t, t_next, dt).status != odestep::status::ok ||
            odestep::integrate(odestep::rk4<state>{}, decay, rk4, t, t_next, dt).status != odestep::status::ok)
            return 1;
        t = t_next;
        const double exact = std::exp(-lambda * t);
        std::printf("%-3g %19.12e %19.12e %19.12e %12.4e %12.4e\n", t, euler[0], rk4[0], exact,
                    (euler[0] - exact) / exact, (rk4[0] - exact) / exact);
    }
    return 0;
}
