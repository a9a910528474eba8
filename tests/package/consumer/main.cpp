// SPDX-License-Identifier: BSL-1.0
// Integrates y' = -y from 0 to 1 with RK4 and exits 0 when y(1) = exp(-1) to RK4's accuracy.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using state = std::array<double, 1>;
    state y{1.0};
    const auto r = odestep::integrate(
        odestep::rk4<state>{}, [](double, const state& s) { return state{-s[0]}; }, y, 0.0, 1.0, 0.01);
    const bool ok = r.status == odestep::status::ok && std::fabs(y[0] - std::exp(-1.0)) < 1e-9;
    std::printf("consumer: y(1) = %.12f %s\n", y[0], ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
