// SPDX-License-Identifier: BSL-1.0
// Course material: a ball dropped from h = 1 m at rest, g = 9.8, bouncing with restitution e = 0.7: an
// event on the height (falling through 0) whose action reverses the velocity, v = -e v. RK4 with
// dt = 0.01 (exact for constant gravity, so the impact times are the closed form's to rounding).
// Prints the first 10 impact times, then the two ways the run can end:
//   (a) no latch: the flights shrink geometrically and would all fit before the Zeno time
//       t_1 (1 + e) / (1 - e); once more impacts than the loop allows fall inside one step, it stops
//       with status event_limit instead of tunnelling through the floor;
//   (b) a latch: once the rebound speed e |v| is below 0.1 m/s, the action puts the ball at rest on the
//       floor and sets a flag that turns the right-hand side off; the run reaches t = 5 with status ok.
//
// Data: bouncing_ball.csv (t, y, v of run (b) at every step, and at every impact before and after it).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using state = std::array<double, 2>;  // y, v
constexpr double g = 9.8;
constexpr double e = 0.7;
constexpr double h = 1.0;
constexpr double dt = 0.01;
constexpr double t_end = 5.0;

struct ball_rhs {
    const bool* resting;
    state operator()(double, const state& s) const noexcept { return *resting ? state{0.0, 0.0} : state{s[1], -g}; }
};

auto height = [](double, const state& s) { return s[0]; };
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "bouncing_ball.csv");
    data.csv.header("t", "y", "v");
    std::printf("# bouncing ball: h = %g m, e = %g, g = %g, RK4 dt = %g\n", h, e, g, dt);
    // (a) no latch
    std::array<double, 10> impacts{};
    std::size_t n = 0;
    auto bounce = [&](double t_hit, state& s) {
        if (n < impacts.size()) impacts[n] = t_hit;
        ++n;
        s[1] = -e * s[1];
    };
    bool never = false;
    state s{h, 0.0};
    const auto floor_a = odestep::make_event<state>(height, odestep::direction::falling, bounce);
    const auto a =
        odestep::integrate(odestep::rk4<state>{}, ball_rhs{&never}, s, 0.0, t_end, dt, odestep::watch(floor_a));
    if (n < impacts.size()) return 1;
    for (std::size_t k = 0; k < impacts.size(); ++k) std::printf("impact %zu %.17g\n", k + 1, impacts[k]);
    std::printf("nolatch status %s t %.17g impacts %zu y %.17g\n", odestep::to_string(a.status), a.t, a.fired, s[0]);

    // (b) a latch in the action
    bool resting = false;
    double rest_t = -1.0;
    std::size_t m = 0;
    auto bounce_or_rest = [&](double t_hit, state& y) {
        ++m;
        data.csv(t_hit, y);               // the impact, before the action
        if (e * std::fabs(y[1]) < 0.1) {  // too slow to bounce visibly again: lie still
            resting = true;
            rest_t = t_hit;
            y = {0.0, 0.0};  // g = 0 now, and it stays 0: the event does not re-arm
        } else {
            y[1] = -e * y[1];
        }
        data.csv(t_hit, y);  // and after it
    };
    s = {h, 0.0};
    const auto floor_b = odestep::make_event<state>(height, odestep::direction::falling, bounce_or_rest);
    const auto b = odestep::integrate(odestep::rk4<state>{}, ball_rhs{&resting}, s, 0.0, t_end, dt,
                                      odestep::watch(floor_b), data.csv);
    std::printf("latch status %s t %.17g impacts %zu rest_t %.17g y %.17g v %.17g resting %d\n",
                odestep::to_string(b.status), b.t, b.fired, rest_t, s[0], s[1], resting ? 1 : 0);
    return m == b.fired && data.good() ? 0 : 1;
}
