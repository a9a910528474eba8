// SPDX-License-Identifier: BSL-1.0
// examples/quickstart.cpp: a harmonic oscillator integrated with RK4 for ten time units.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using state = std::array<double, 2>;                                   // x, v
    auto sho = [](double, const state& y) { return state{y[1], -y[0]}; };  // x'' = -x

    odestep::rk4<state> stepper;
    state y{1.0, 0.0};
    const auto r = odestep::integrate(stepper, sho, y, 0.0, 10.0, 0.01);
    if (r.status != odestep::status::ok) {
        std::printf("stopped: %s at t = %g\n", odestep::to_string(r.status), r.t);
        return 1;
    }
    std::printf("status %s after %llu steps, t = %g\n", odestep::to_string(r.status),
                static_cast<unsigned long long>(r.steps), r.t);
    std::printf("x = %.12f (exact cos 10 = %.12f)\n", y[0], std::cos(10.0));
    std::printf("v = %.12f (exact -sin 10 = %.12f)\n", y[1], -std::sin(10.0));
    return 0;
}
