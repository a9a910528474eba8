// SPDX-License-Identifier: BSL-1.0
// Course material: a pebble thrown straight up at v0 = 50 m/s against quadratic drag,
// a = -g - (g / vt^2) v |v| (terminal speed vt = 30 m/s, g = 9.8), with RK4 at three step sizes and two
// events: the apex (v falls through 0; an action notes t and y) and the ground (y falls through 0;
// terminal). Prints the apex time and height, the time of flight and the impact speed, and how many
// re-steps each event location took (right-hand-side evaluations beyond the 4 of each step, over 4).
//
// The drag term v|v| has a jump in its second derivative at v = 0, so the RK4 step that contains the apex
// is less accurate than the others (its error depends on where in the step the apex falls). Two variants:
// "record" only notes the apex and leaves the trajectory alone; "split" also sets v = 0 there (it is zero to
// the location's tolerance), which changes the state, so the loop restarts the step from the apex and no
// step straddles the kink.
//
// Data: pebble.csv (t, y, v of the dt = 0.01 "record" run; the drag-free flight is the plot's closed form).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using state = std::array<double, 2>;  // y (up), v
constexpr double g = 9.8;
constexpr double vt = 30.0;
constexpr double v0 = 50.0;

struct drag_rhs {
    std::size_t* calls;
    state operator()(double, const state& s) const noexcept {
        ++*calls;
        return {s[1], -g - (g / (vt * vt)) * s[1] * std::fabs(s[1])};
    }
};

struct flight {
    bool ok = false;
    double apex_t = -1.0, apex_y = -1.0, ground_t = -1.0, impact_speed = -1.0;
    std::size_t apex_evals = 0, ground_evals = 0;  // right-hand-side calls of each location
};

flight throw_pebble(double dt, bool split, odestep::csv_observer* csv) {
    flight out;
    std::size_t calls = 0;
    std::size_t calls_at_grid = 0;  // calls when the observer last saw a grid time
    auto note_apex = [&](double t_ev, state& s) {
        out.apex_t = t_ev;
        out.apex_y = s[0];
        out.apex_evals = calls - calls_at_grid - 4;  // minus the step that saw the sign change
        if (split) s[1] = 0.0;
    };
    const auto apex =
        odestep::make_event<state>([](double, const state& s) { return s[1]; }, odestep::direction::falling, note_apex);
    // y = 0 at t0: the ground event arms only once y > 0 has been seen (events.hpp, begin/rearm).
    const auto ground =
        odestep::make_event<state>([](double, const state& s) { return s[0]; }, odestep::direction::falling);
    state s{0.0, v0};
    const auto r = odestep::integrate(odestep::rk4<state>{}, drag_rhs{&calls}, s, 0.0, 60.0, dt,
                                      odestep::watch(apex, ground), [&](double t, const state& y) {
                                          calls_at_grid = calls;
                                          if (csv != nullptr) (*csv)(t, y);
                                      });
    out.ok = r.status == odestep::status::stopped_by_event && r.event == 1 && r.firings[0] == 1 && r.fired == 2;
    out.ground_t = r.t;
    out.impact_speed = std::fabs(s[1]);
    // r.steps grid steps, then the step that ended at the ground, the rest of the apex's step taken again
    // from the apex (4, after a callable action) and f at the apex for the way g heads next (1); what is left
    // is the two locations.
    out.ground_evals = calls - 4 * (r.steps + 1) - 4 - 1 - out.apex_evals;
    return out;
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "pebble.csv");
    data.csv.header("t", "y", "v");
    std::printf("# pebble: v0 = %g m/s up, vt = %g m/s, g = %g, RK4\n", v0, vt, g);
    std::printf("%-3s %-6s %-5s %22s %22s %22s %22s %6s %6s\n", "", "apex", "dt", "apex_t", "apex_h", "flight_t",
                "impact_v", "re_apx", "re_gnd");
    std::size_t locations = 0, total = 0, worst = 0;
    for (bool split : {false, true}) {
        for (double dt : {0.1, 0.05, 0.01}) {
            const flight f = throw_pebble(dt, split, !split && dt == 0.01 ? &data.csv : nullptr);
            if (!f.ok || f.apex_evals % 4 != 0 || f.ground_evals % 4 != 0) {
                std::printf("FAIL: dt = %g: the run did not end as expected\n", dt);
                return 1;
            }
            const std::size_t re[2] = {f.apex_evals / 4, f.ground_evals / 4};
            for (std::size_t n : re) {
                ++locations;
                total += n;
                if (n > worst) worst = n;
            }
            std::printf("%-3s %-6s %-5g %22.17g %22.17g %22.17g %22.17g %6zu %6zu\n", "run", split ? "split" : "record",
                        dt, f.apex_t, f.apex_y, f.ground_t, f.impact_speed, re[0], re[1]);
        }
    }
    std::printf("resteps locations %zu mean %.3f max %zu\n", locations,
                static_cast<double>(total) / static_cast<double>(locations), worst);
    return data.good() ? 0 : 1;
}
