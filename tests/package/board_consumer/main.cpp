// SPDX-License-Identifier: BSL-1.0
// The image of docs/cortex-m.md's recipe: RK4 on y' = -y from y(0) = 1 to t = 1 with dt = 0.1, printed through
// semihosting; the exit status (main's return value) becomes QEMU's.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

extern "C" double closed_form(double t);  // closed_form.c: exp(-t)

int main() {
    using state = std::array<double, 1>;
    auto decay = [](double, const state& y) { return state{-y[0]}; };
    odestep::rk4<state> stepper;
    state y{1.0};
    auto r = odestep::integrate(stepper, decay, y, 0.0, 1.0, 0.1);
    // RK4's global error on y' = -y with h = 0.1 is h^4/120 * t * exp(-t) to leading order: 3.1e-7 at t = 1.
    const double error = std::fabs(y[0] - closed_form(1.0));
    const bool ok = r.status == odestep::status::ok && r.steps == 10 && error < 1e-6;
    std::printf("y(1) = %.6f, exp(-1) = %.6f: %s\n", y[0], closed_form(1.0), ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
