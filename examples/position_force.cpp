// SPDX-License-Identifier: BSL-1.0
// Course material: a position-dependent force (problem 3.4). A particle dropped from rest at height h falls
// under Newton's gravity, a = -g / (1 + y/R)^2 (g = 9.8 m/s^2 at the surface, R = 6.37e6 m), instead of
// the constant g. Velocity Verlet (a force of position alone) with a terminal ground event gives the
// impact speed; the constant-g speed is sqrt(2 g h). Brent's method (odestep::brent) then finds the
// height at which the impact speed is 1 % below the constant-g one, once with dt = 0.01 s and once with
// dt = 0.005 s, so that the 1 % is the force law's and not the step's.
//
// Data: position_force.csv (h, impact speed under each law).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using vec = std::array<double, 1>;
constexpr double g = 9.8;
constexpr double radius = 6.37e6;

struct gravity {
    vec operator()(double, const vec& y) const noexcept {
        const double s = 1.0 + y[0] / radius;
        return {-g / (s * s)};
    }
};

// The impact speed from height h, or NaN if the run does not end at the ground.
double impact_speed(double h, double dt) {
    vec y{h};
    vec v{0.0};
    const auto ground =
        odestep::make_event<vec>([](double, const vec& x, const vec&) { return x[0]; }, odestep::direction::falling);
    const auto r =
        odestep::integrate(odestep::velocity_verlet<vec>{}, gravity{}, y, v, 0.0, 1e5, dt, odestep::watch(ground));
    if (r.status != odestep::status::stopped_by_event) return std::nan("");
    return std::fabs(v[0]);
}

// 1 - v / sqrt(2 g h) - 0.01: negative below the height sought, positive above.
double shortfall(double h, double dt) { return 1.0 - impact_speed(h, dt) / std::sqrt(2 * g * h) - 0.01; }

// The height at which the impact speed is 1 % below the constant-g one, to 1e-6 m.
double one_percent_height(double dt, std::size_t& evaluations) {
    const double lo = 1e4;
    const double hi = 1e6;
    auto f = [dt](double h) { return shortfall(h, dt); };
    const auto b = odestep::brent::narrow(f, lo, f(lo), hi, f(hi), 1e-6, 200);
    evaluations = b.evaluations + 2;
    return b.converged && !b.failed ? b.b : std::nan("");
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "position_force.csv");
    data.csv.header("h", "v_newton", "v_constant_g");
    std::printf("# dropped from rest, a = -g / (1 + y/R)^2, g = %g, R = %g m, velocity Verlet, ground event\n", g,
                radius);
    std::printf("%-6s %-10s %22s %22s %14s\n", "impact", "h", "v", "sqrt(2 g h)", "v/sqrt(2gh)");
    for (double h : {1e2, 1e3, 1e4, 1e5, 1e6}) {
        const double v = impact_speed(h, 0.01);
        if (std::isnan(v)) return 1;
        std::printf("%-6s %-10g %22.17g %22.17g %14.10f\n", "impact", h, v, std::sqrt(2 * g * h),
                    v / std::sqrt(2 * g * h));
    }
    for (int i = 0; i <= 60; ++i) {
        const double h = std::pow(10.0, 2.0 + i / 12.0);
        data.csv.row(h, impact_speed(h, 0.01), std::sqrt(2 * g * h));
    }
    for (double dt : {0.01, 0.005}) {
        std::size_t evaluations = 0;
        const double h = one_percent_height(dt, evaluations);
        if (std::isnan(h)) return 1;
        std::printf("one_percent dt %g h %.17g m ratio %.17g brent_evaluations %zu\n", dt, h,
                    impact_speed(h, dt) / std::sqrt(2 * g * h), evaluations);
    }
    return data.good() ? 0 : 1;
}
