// SPDX-License-Identifier: BSL-1.0
// Course material: a projectile launched at 30 m/s from h = 2 m against quadratic drag,
// a = -g ez - (C2/m) |v| v with C2/m = 0.1 per metre, g = 9.8. A terminal ground event (y falls through 0)
// ends each flight and gives the range; a golden-section search over the launch angle finds the longest.
// Also prints the drag-free range at 45 degrees from the ground (v0^2 / g), and, as the checker's
// reference, the range at the optimum again with a ten times smaller step and with DOP853.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

#include "support/golden.hpp"

namespace {
using state = std::array<double, 4>;  // x, y, vx, vy
constexpr double g = 9.8;
constexpr double v0 = 30.0;
constexpr double dt = 0.01;

struct drag_rhs {
    double k;  // C2 / m
    state operator()(double, const state& s) const noexcept {
        const double speed = std::sqrt(s[2] * s[2] + s[3] * s[3]);
        return {s[2], s[3], -k * speed * s[2], -g - k * speed * s[3]};
    }
};

// The range (x where y falls through 0) of a launch at `angle` from height h; NaN if the run does not end
// at the ground.
template <class Stepper>
double range(double angle, double h, double k, double step) {
    state s{0.0, h, v0 * std::cos(angle), v0 * std::sin(angle)};
    // From h = 0 the event starts unarmed (g = 0 at t0) and arms once y > 0 has been seen.
    const auto ground =
        odestep::make_event<state>([](double, const state& y) { return y[1]; }, odestep::direction::falling);
    const auto r = odestep::integrate(Stepper{}, drag_rhs{k}, s, 0.0, 100.0, step, odestep::watch(ground));
    if (r.status != odestep::status::stopped_by_event) return std::nan("");
    return s[0];
}

double rk4_range(double angle) { return range<odestep::rk4<state>>(angle, 2.0, 0.1, dt); }

}  // namespace

int main() {
    const double pi = std::acos(-1.0);
    std::printf("# projectile: v0 = %g m/s, g = %g, RK4 dt = %g\n", v0, g, dt);
    // Without drag from the ground RK4 is exact (the acceleration is constant), so only the event's location
    // and rounding separate the range from v0^2 / g.
    const double flat = range<odestep::rk4<state>>(pi / 4, 0.0, 0.0, dt);
    std::printf("nodrag45 range %.17g\n", flat);
    int rounds = 0;
    const double best = example::golden_max(rk4_range, 0.0, pi / 2, 1e-6, rounds);
    std::printf("drag h 2 k 0.1 optimum_angle %.17g rad %.10f deg golden_rounds %d\n", best, best * 180 / pi, rounds);
    std::printf("range_opt rk4 %.17g\n", rk4_range(best));
    std::printf("range_opt rk4_dt/10 %.17g\n", range<odestep::rk4<state>>(best, 2.0, 0.1, dt / 10));
    std::printf("range_opt dop853 %.17g\n", range<odestep::dop853<state>>(best, 2.0, 0.1, dt));
    std::printf("range_minus rk4 %.17g\n", rk4_range(best - 0.01));
    std::printf("range_plus rk4 %.17g\n", rk4_range(best + 0.01));
    return 0;
}
