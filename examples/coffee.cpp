// SPDX-License-Identifier: BSL-1.0
// Course material: coffee at 85 C cooling by Newton's law, dT/dt = -r (T - Ts), r = 0.03 per minute,
// Ts = 17 C; a serving of cream lowers it by 5 C. When should the cream go in to reach 62 C soonest?
//   A: cream at the start (80 C), then a terminal event when T falls through 62 C (integrate);
//   B: cream by an event action when T falls through 67 C, and a terminal event at 62 C, run one tick at a
//      time with the per-tick event stepper, as a control loop would, printing what each tick reported.
// In B the cream leaves T = 62 C plus the few ULPs by which the located state is still above 67 C, so the
// 62 C event fires in the same tick, right after the cream: the loop restarts the rest of the tick from
// the cream, sees T cross 62 C and locates that crossing too. (Crossings are measured from g's value after
// an action: had the cream left T at exactly 62 C, or below it, the 62 C event would never fire.)
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace {
using state = std::array<double, 1>;  // T in C
constexpr double r = 0.03;            // per minute
constexpr double Ts = 17.0;
constexpr double dt = 0.1;  // minutes

struct cooling {
    state operator()(double, const state& T) const noexcept { return {-r * (T[0] - Ts)}; }
};

auto below = [](double level) { return [level](double, const state& T) { return T[0] - level; }; };
}  // namespace

int main() {
    std::printf("# coffee: T0 = 85 C, Ts = %g C, r = %g /min, cream -5 C, target 62 C, RK4 dt = %g min\n", Ts, r, dt);
    // A: cream first, then cool to 62.
    state a{85.0 - 5.0};
    const auto drinkable = odestep::make_event<state>(below(62.0), odestep::direction::falling);
    const auto ra = odestep::integrate(odestep::rk4<state>{}, cooling{}, a, 0.0, 60.0, dt, odestep::watch(drinkable));
    if (ra.status != odestep::status::stopped_by_event) return 1;
    std::printf("A cream_at 0 t62 %.17g T %.17g\n", ra.t, a[0]);

    // B: cream when the black coffee falls through 67, then cool to 62.
    const auto cream =
        odestep::make_event<state>(below(67.0), odestep::direction::falling, [](double, state& T) { T[0] -= 5.0; });
    auto loop = odestep::make_event_stepper(odestep::rk4<state>{}, odestep::watch(cream, drinkable));
    state b{85.0};
    if (loop.start(0.0, dt, b) != odestep::status::ok) return 1;
    double t_cream = -1.0, t62 = -1.0;
    for (std::size_t tick = 1; tick <= 600; ++tick) {  // tick n covers ((n - 1) dt, n dt]
        const auto res = loop.tick(cooling{}, b);
        for (std::size_t k = 0; k < res.fired && k < res.firings.size(); ++k) {
            const auto& f = res.firings[k];
            std::printf("B tick %zu event %s t %.17g\n", tick, f.event == 0 ? "cream" : "t62", f.t);
            if (f.event == 0) {
                t_cream = f.t;
            } else {
                t62 = f.t;
            }
        }
        if (res.status == odestep::status::stopped_by_event) {
            std::printf("B stop tick %zu status %s event %zu t %.17g T %.17g\n", tick, odestep::to_string(res.status),
                        res.event, res.t, b[0]);
            break;
        }
        if (res.status != odestep::status::ok) return 1;
    }
    if (t_cream < 0 || t62 < 0) return 1;
    std::printf("B cream_at %.17g t62 %.17g gap %.3g\n", t_cream, t62, t62 - t_cream);
    std::printf("sooner %s\n", t62 < ra.t ? "B" : "A");
    return 0;
}
