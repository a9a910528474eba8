// SPDX-License-Identifier: BSL-1.0
// Course material: curveballs (problem 3.13). A baseball (149 g) leaves the pitcher's hand 1.8 m above
// the ground and 18 m from home plate, with drag and the Magnus force:
//     a = g - C_D |v| v + C_M (omega x v),   C_D = 6e-3 /m, C_M = 4e-4, g = 9.8 m/s^2 downwards,
// x towards the plate, y to the side, z up. A terminal event at the plate (x = 18 m) gives the height and the
// sideways deflection there; Brent's method (odestep::brent) finds the launch angle for a given height.
//   (a) A 40 m/s fastball without drag or spin: the angle above the horizontal that crosses the plate at
//       1.5 m (a parabola: the checker has the closed form).
//   (b) The same with drag: the angle for 1.5 m, and how far the ball drops below 1.5 m at (a)'s angle.
//   (c) At (b)'s angle, topspin omega = 200 rad/s about y, then backspin: the change of height at the plate.
//   (d) A 35 m/s curveball with 200 rad/s about the vertical: the sideways deflection at the plate, at the
//       angle that brings the same pitch without spin to 1.5 m.
// The force depends on v, so the stepper is Euler-Richardson for Newton's equations (dt = 0.1 ms), the
// course's method for velocity-dependent forces.
//
// Data: curveball.csv, one data set per pitch (fastball without drag, with drag, topspin, backspin,
// curveball without and with spin): t, x, y, z, vx, vy, vz.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "support/csv_file.hpp"

namespace {
using vec = std::array<double, 3>;
constexpr double g = 9.8;
constexpr double plate = 18.0;
constexpr double release_height = 1.8;
constexpr double dt = 1e-4;

struct pitch {
    double speed, cd, cm;
    vec omega;
};

struct baseball {
    pitch p;
    vec operator()(double, const vec&, const vec& v) const noexcept {
        const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        const vec& w = p.omega;
        return {-p.cd * speed * v[0] + p.cm * (w[1] * v[2] - w[2] * v[1]),
                -p.cd * speed * v[1] + p.cm * (w[2] * v[0] - w[0] * v[2]),
                -p.cd * speed * v[2] + p.cm * (w[0] * v[1] - w[1] * v[0]) - g};
    }
};

struct at_plate {
    bool ok;
    double t, y, z;
};

// Throws at `angle` above the horizontal; the state when the ball reaches the plate.
template <class Observer>
at_plate throw_ball(const pitch& p, double angle, Observer&& observe) {
    vec x{0.0, 0.0, release_height};
    vec v{p.speed * std::cos(angle), 0.0, p.speed * std::sin(angle)};
    const auto reach = odestep::make_event<vec>([](double, const vec& q, const vec&) { return q[0] - plate; },
                                                odestep::direction::rising);
    const auto r = odestep::integrate(odestep::newtonian_euler_richardson<vec>{}, baseball{p}, x, v, 0.0, 10.0, dt,
                                      odestep::watch(reach), observe);
    return {r.status == odestep::status::stopped_by_event, r.t, x[1], x[2]};
}

at_plate throw_ball(const pitch& p, double angle) {
    return throw_ball(p, angle, [](double, const vec&, const vec&) {});
}

// The launch angle that brings the pitch to `height` at the plate (NaN if the search fails).
double aim(const pitch& p, double height) {
    auto miss = [&p, height](double angle) {
        const at_plate a = throw_ball(p, angle);
        return a.ok ? a.z - height : std::nan("");
    };
    const double lo = -0.2;
    const double hi = 0.3;
    const auto b = odestep::brent::narrow(miss, lo, miss(lo), hi, miss(hi), 1e-12, 200);
    return b.converged && !b.failed ? b.b : std::nan("");
}

void print(const char* name, const pitch& p, double angle, const at_plate& a) {
    std::printf("pitch %-14s %4g %5g %6g %6g %6g %6g %22.17g %20.17g %22.17g %22.17g\n", name, p.speed, p.cd, p.cm,
                p.omega[0], p.omega[1], p.omega[2], angle, a.t, a.y, a.z);
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "curveball.csv");
    std::printf("# baseball from (0, 0, %g) m towards the plate at x = %g m; Euler-Richardson, dt = %g s\n",
                release_height, plate, dt);
    std::printf("pitch %-14s %4s %5s %6s %6s %6s %6s %22s %20s %22s %22s\n", "case", "v0", "C_D", "C_M", "wx", "wy",
                "wz", "angle_rad", "t_plate", "y_plate", "z_plate");
    const pitch plain{40.0, 0.0, 0.0, {0.0, 0.0, 0.0}};
    const pitch drag{40.0, 6e-3, 0.0, {0.0, 0.0, 0.0}};
    const pitch topspin{40.0, 6e-3, 4e-4, {0.0, 200.0, 0.0}};
    const pitch backspin{40.0, 6e-3, 4e-4, {0.0, -200.0, 0.0}};
    const pitch curve_plain{35.0, 6e-3, 4e-4, {0.0, 0.0, 0.0}};
    const pitch curve{35.0, 6e-3, 4e-4, {0.0, 0.0, 200.0}};

    const double angle_a = aim(plain, 1.5);
    const double angle_b = aim(drag, 1.5);
    const double angle_d = aim(curve_plain, 1.5);
    if (std::isnan(angle_a) || std::isnan(angle_b) || std::isnan(angle_d)) return 1;

    struct {
        const char* name;
        const pitch& p;
        double angle;
    } const cases[] = {{"a_nodrag", plain, angle_a},      {"b_drag", drag, angle_b},
                       {"b_drag_at_a", drag, angle_a},    {"c_topspin", topspin, angle_b},
                       {"c_backspin", backspin, angle_b}, {"d_nospin", curve_plain, angle_d},
                       {"d_curve", curve, angle_d}};
    data.csv.header("t", "x", "y", "z", "vx", "vy", "vz");
    data.csv.every(10);  // every millisecond
    for (const auto& c : cases) {
        const bool plotted = std::string_view(c.name) != "b_drag_at_a";
        const at_plate a = plotted ? throw_ball(c.p, c.angle, data.csv) : throw_ball(c.p, c.angle);
        if (!a.ok) return 1;
        print(c.name, c.p, c.angle, a);
        if (plotted) data.next_block();
    }
    return data.good() ? 0 : 1;
}
