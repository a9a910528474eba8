// SPDX-License-Identifier: BSL-1.0
// Course material: the trajectory of a steel ball (problem 3.7) and two falling objects (problem 3.8).
// Gravity g = 9.8 m/s^2, quadratic drag a = -(C2/m) |v| v or linear drag a = -(C1/m) v; a terminal
// ground event ends each flight. The forces depend on v: Euler-Richardson for Newton's equations with
// dt = 0.1 ms.
//
// 3.7 (a) v0 = 15 m/s from the ground without drag: the best angle (golden-section search) and the range,
//         v0^2 / g at 45 degrees.
//     (b) the same from h = 2 m: the best angle is below 45 degrees; the range there, and at 2 % more and
//         less angle.
//     (c) a 7 kg ball with C2 = 0.1 kg/m (C2/m = 0.1/7 per metre) from 2 m at 30 m/s: the best angle and the
//         range. (The exaggerated C2/m = 0.1 is the projectile example.)
// 3.8 From h = 10 m, one object dropped and one thrown horizontally at 30 m/s: their times to the ground
//     without drag, with quadratic drag C2/m = 0.1 per metre, and with linear drag of the same terminal
//     speed (C1/m = g / vt, vt = sqrt(g m / C2)). With quadratic drag the thrown one lands later: its
//     speed, and so its drag, is larger, and the drag's vertical part slows its fall. With linear drag the
//     vertical motion does not depend on the horizontal one, and both land together.
//
// Data: steel_ball_ranges.csv (angle in degrees, range for (a), (b), (c)), two_objects.csv (one data set
// per object and drag law: t, x, y, vx, vy).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"
#include "support/golden.hpp"

namespace {
using vec = std::array<double, 2>;  // x, y (up)
constexpr double g = 9.8;
constexpr double dt = 1e-4;

enum class drag { none, quadratic, linear };

struct ball {
    drag law;
    double k;  // C2/m (quadratic) or C1/m (linear)
    vec operator()(double, const vec&, const vec& v) const noexcept {
        if (law == drag::quadratic) {
            const double speed = std::hypot(v[0], v[1]);
            return {-k * speed * v[0], -g - k * speed * v[1]};
        }
        if (law == drag::linear) return {-k * v[0], -g - k * v[1]};
        return {0.0, -g};
    }
};

struct landing {
    bool ok;
    double t, x;
};

// From (0, h) with velocity (vx, vy) to the ground.
template <class Observer>
landing fly(const ball& b, double h, double vx, double vy, Observer&& observe) {
    vec x{0.0, h};
    vec v{vx, vy};
    // From h = 0 the event starts unarmed (g = 0 at t0) and arms once y > 0 has been seen.
    const auto ground =
        odestep::make_event<vec>([](double, const vec& q, const vec&) { return q[1]; }, odestep::direction::falling);
    const auto r = odestep::integrate(odestep::newtonian_euler_richardson<vec>{}, b, x, v, 0.0, 100.0, dt,
                                      odestep::watch(ground), observe);
    return {r.status == odestep::status::stopped_by_event, r.t, x[0]};
}

double range(const ball& b, double h, double v0, double angle) {
    const landing l = fly(b, h, v0 * std::cos(angle), v0 * std::sin(angle), [](double, const vec&, const vec&) {});
    return l.ok ? l.x : std::nan("");
}
}  // namespace

int main(int argc, char** argv) {
    const double pi = std::acos(-1.0);
    const double deg = pi / 180;
    example::csv_file ranges(argc, argv, "steel_ball_ranges.csv");
    example::csv_file objects(argc, argv, "two_objects.csv");
    std::printf("# steel ball and two objects, g = %g, Euler-Richardson dt = %g s, ground event\n", g, dt);

    struct launch {
        const char* name;
        ball b;
        double h, v0;
    };
    const launch launches[] = {{"a_nodrag_ground", {drag::none, 0.0}, 0.0, 15.0},
                               {"b_nodrag_h2", {drag::none, 0.0}, 2.0, 15.0},
                               {"c_steel_7kg", {drag::quadratic, 0.1 / 7}, 2.0, 30.0}};
    ranges.csv.header("angle_deg", "range_a", "range_b", "range_c");
    for (int i = 5; i <= 85; ++i) {
        const double a = i * deg;
        ranges.csv.row(static_cast<double>(i), range(launches[0].b, launches[0].h, launches[0].v0, a),
                       range(launches[1].b, launches[1].h, launches[1].v0, a),
                       range(launches[2].b, launches[2].h, launches[2].v0, a));
    }
    for (const launch& l : launches) {
        int rounds = 0;
        const double best =
            example::golden_max([&l](double a) { return range(l.b, l.h, l.v0, a); }, 0.0, pi / 2, 1e-7, rounds);
        const double r = range(l.b, l.h, l.v0, best);
        if (std::isnan(r)) return 1;
        std::printf("range %-16s k %.17g h %g v0 %g angle %.12f deg range %.12f m\n", l.name, l.b.k, l.h, l.v0,
                    best / deg, r);
        if (l.h > 0 && l.b.law == drag::none) {
            std::printf("range_2%% %-13s lower %.12f m higher %.12f m\n", l.name, range(l.b, l.h, l.v0, best * 0.98),
                        range(l.b, l.h, l.v0, best * 1.02));
        }
    }

    const double k2 = 0.1;
    const double vt = std::sqrt(g / k2);
    const double h = 10.0;
    const double v0 = 30.0;
    std::printf("# two objects from h = %g m, dropped and thrown at %g m/s; C2/m = %g, vt = %.12f, C1/m = g / vt\n", h,
                v0, k2, vt);
    objects.csv.header("t", "x", "y", "vx", "vy");
    const struct {
        const char* name;
        ball b;
    } laws[] = {
        {"nodrag", {drag::none, 0.0}}, {"quadratic", {drag::quadratic, k2}}, {"linear", {drag::linear, g / vt}}};
    for (const auto& law : laws) {
        std::size_t count = 0;
        auto every_2ms = [&](double t, const vec& x, const vec& v) {
            if (count++ % 20 == 0) objects.csv(t, x, v);
        };
        const landing dropped = fly(law.b, h, 0.0, 0.0, every_2ms);
        objects.next_block();
        count = 0;
        const landing thrown = fly(law.b, h, v0, 0.0, every_2ms);
        objects.next_block();
        if (!dropped.ok || !thrown.ok) return 1;
        std::printf("fall %-9s k %.17g dropped %.12f s thrown %.12f s thrown_x %.12f m\n", law.name, law.b.k, dropped.t,
                    thrown.t, thrown.x);
    }
    return ranges.good() && objects.good() ? 0 : 1;
}
