// SPDX-License-Identifier: BSL-1.0
// Course material: Euler's method on dy/dx = -x y, y(0) = 1, h = 0.5 from x = 0 to 3, tabulated against
// the exact solution y = exp(-x^2 / 2).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using state = std::array<double, 1>;
    auto f = [](double x, const state& y) { return state{-x * y[0]}; };
    std::printf("# dy/dx = -x y, y(0) = 1, Euler with h = 0.5; exact y = exp(-x^2/2)\n");
    std::printf("%-4s %19s %19s %12s %12s\n", "x", "y", "exact", "abs_err", "rel_err");
    state y{1.0};
    const auto r = odestep::integrate(odestep::euler<state>{}, f, y, 0.0, 3.0, 0.5, [](double x, const state& s) {
        const double exact = std::exp(-x * x / 2.0);
        std::printf("%-4g %19.12e %19.12e %12.4e %12.4e\n", x, s[0], exact, std::fabs(s[0] - exact),
                    std::fabs(s[0] - exact) / exact);
    });
    return r.status == odestep::status::ok ? 0 : 1;
}
