// SPDX-License-Identifier: BSL-1.0
// Regression tests for the event loop's defects of issue 19 (and defect 5 of issue 20), one test case per
// defect, each naming the tracker or test suite whose pattern it follows. Expected values come from closed
// forms: y' = 1 (a clock) is exact in every Runge-Kutta method, so event times along it are the roots of g.
//
// A hang is caught, not waited for: the event functions here are wrapped in a watchdog that counts its calls
// and returns NaN once they exceed the published bound for the whole run, which ends any loop with
// non_finite_event (every test then checks that status did not come).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "support/counting.hpp"

namespace {

using state1 = std::array<double, 1>;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

struct clock_rhs {  // y' = 1: y(t) = y0 + t, exact in every Runge-Kutta method
    state1 operator()(double, const state1&) const { return {1.0}; }
};

// g, which returns NaN once it has been called more than `limit` times: a hang becomes non_finite_event.
template <class G>
struct watchdog {
    G g;
    std::size_t* calls;
    std::size_t limit;
    template <class... A>
    double operator()(double t, const A&... y) const {
        ++*calls;
        if (*calls > limit) return not_a_number;
        return g(t, y...);
    }
};
template <class G>
watchdog<G> guarded(G g, std::size_t* calls, std::size_t limit) {
    return watchdog<G>{g, calls, limit};
}

constexpr std::size_t g_bound_1 = odestep::max_g_evals_per_step<double>(1);  // one event, default limits

}  // namespace

TEST_CASE("defect 1: a crossing at the grid time that the re-step to t_s + h does not see is located, not a hang") {
    // Issue 19's reproducer. From t0 = -3.3 with dt = 0.7 the fourth step starts at t_3 = -1.2000000000000002;
    // t_3 + dt is -0.5000000000000002 while the grid time t_4 = t0 + 4 dt is -0.5. A timer event g = t - c
    // with c = nextafter(-0.5, -1) between the two is positive at t_4 (computed: -3.3 + 4 * 0.7 == -0.5).
    REQUIRE(-3.3 + 4 * 0.7 == -0.5);
    REQUIRE(-3.3 + 3 * 0.7 + 0.7 < -0.5);
    const double c = std::nextafter(-0.5, -1.0);
    std::size_t calls = 0;
    const std::size_t steps = 5;
    auto g = guarded([c](double t, const state1&) { return t - c; }, &calls, (steps + 1) * g_bound_1);
    double when = 0.0;
    const auto ev = odestep::make_event<state1>(g, odestep::direction::rising, [&](double t, state1&) { when = t; });
    state1 y{0.0};
    const auto r =
        odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, -3.3, -3.3 + 5 * 0.7, 0.7, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
    // The root is c; the event's time is at or before it, within the default tolerance (4 eps (|t| + |dt|)).
    CHECK(when <= c);
    CHECK(when >= c - 4 * eps * 1.2);
}

TEST_CASE("defect 1: an event function that is not a pure function of (t, y) cannot hang a run or a tick") {
    // Firmware's g is often a sensor: here one glitch, positive at the step's end and negative when location
    // reads it again (the fuzzer's hang-no-firing-inner-loop, tests/fuzz/). The glitch cannot be located
    // (nothing crosses when it is read again): no firing, and the call returns within its published bound.
    for (std::size_t glitch_at = 2; glitch_at < 12; ++glitch_at) {
        std::size_t calls = 0;
        const std::size_t ticks = 10;
        auto sensor = [&calls, glitch_at](double, const state1&) { return calls == glitch_at ? 1.0 : -1.0; };
        auto g = guarded(sensor, &calls, (ticks + 1) * g_bound_1);
        for (const auto d : {odestep::direction::rising, odestep::direction::either}) {
            calls = 0;
            auto loop = odestep::make_event_stepper(odestep::rk4<state1>{},
                                                    odestep::watch(odestep::make_event<state1>(g, d, odestep::record)));
            state1 y{0.0};
            REQUIRE(loop.start(0.0, 0.25, y) == odestep::status::ok);
            for (std::size_t n = 0; n < ticks; ++n) {
                const std::size_t before = calls;
                const auto r = loop.tick(clock_rhs{}, y);
                CHECK(r.status != odestep::status::non_finite_event);  // the watchdog never bit
                CHECK(calls - before <= g_bound_1);
            }
            CHECK(loop.ticks() == ticks);
        }
    }
}

TEST_CASE("defect 2: a crossing fires once after an action that moves the state but not g (Julia's jump tests)") {
    // The pattern of OrdinaryDiffEq.jl's callback tests: a time event whose affect! adds to u. Here
    // g = t - 0.55 rising, action y += 1, y' = 1 from 0 to 1 with dt 0.1: one firing, y(1) = 1 + 1.
    std::size_t fired = 0;
    const auto ev =
        odestep::make_event<state1>([](double t, const state1&) { return t - 0.55; }, odestep::direction::rising,
                                    [&](double, state1& y) {
                                        ++fired;
                                        y[0] += 1.0;
                                    });
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.1, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    CHECK(fired == 1);
    CHECK(std::abs(y[0] - 2.0) <= 16 * eps);
    // Decay with a dose: u' = -u / 2, u(0) = 1, u += 1 at t = 5.55 (g = t - 5.55): the closed form is
    // u(10) = e^{-5} + e^{-(10 - 5.55) / 2}.
    auto decay = [](double, const state1& u) { return state1{-0.5 * u[0]}; };
    std::size_t doses = 0;
    const auto dose =
        odestep::make_event<state1>([](double t, const state1&) { return t - 5.55; }, odestep::direction::rising,
                                    [&](double, state1& u) {
                                        ++doses;
                                        u[0] += 1.0;
                                    });
    state1 u{1.0};
    const auto d = odestep::integrate(odestep::rk4<state1>{}, decay, u, 0.0, 10.0, 0.1, odestep::watch(dose));
    CHECK(d.status == odestep::status::ok);
    CHECK(doses == 1);
    // (RK4 with dt 0.1 on u' = -u / 2 alone ends 2.7e-7 relative from e^{-5}, measured; two doses would
    // give 0.21 instead of 0.115)
    CHECK(u[0] == doctest::Approx(std::exp(-5.0) + std::exp(-(10.0 - 5.55) / 2)).epsilon(1e-6));
}

TEST_CASE("defect 3: integrate again from a stopped_by_event state continues (CVODE's and SciPy's restart)") {
    // CVODE returns CV_ROOT_RETURN and the user calls CVode again; SciPy users restart solve_ivp from
    // sol.t_events. Here: y - 0.55 rising, terminal; then integrate from (r.t, y) to 1.
    const auto ev =
        odestep::make_event<state1>([](double, const state1& y) { return y[0] - 0.55; }, odestep::direction::rising);
    state1 y{0.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.1, odestep::watch(ev));
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - 0.55) <= 8 * eps);
    const double t_stop = r.t;
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, t_stop, 1.0, 0.1, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 0);
    CHECK(r.t == 1.0);
    CHECK(std::abs(y[0] - 1.0) <= 8 * eps);
    // The same with rearm in the per-tick loop: the caller rearms at the stop (as after changing the state),
    // and the event does not fire again there.
    auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
    y = {0.0};
    REQUIRE(loop.start(0.0, 0.1, y) == odestep::status::ok);
    std::size_t stops = 0;
    for (int n = 0; n < 10; ++n) {
        const auto t = loop.tick(clock_rhs{}, y);
        if (t.status == odestep::status::stopped_by_event) {
            ++stops;
            REQUIRE(loop.rearm(y) == odestep::status::ok);
        }
    }
    CHECK(stops == 1);
}

TEST_CASE("defect 4: the per-tick loop with an Adams stepper goes on after a terminal tick") {
    const auto ev =
        odestep::make_event<state1>([](double, const state1& y) { return y[0] - 0.55; }, odestep::direction::rising);
    auto loop = odestep::make_event_stepper(odestep::adams_bashforth_moulton4<state1>{}, odestep::watch(ev));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.1, y) == odestep::status::ok);
    std::size_t stops = 0;
    for (int n = 0; n < 20; ++n) {
        const auto r = loop.tick(clock_rhs{}, y);
        CHECK((r.status == odestep::status::ok || r.status == odestep::status::stopped_by_event));
        if (r.status == odestep::status::stopped_by_event) ++stops;
    }
    CHECK(stops == 1);
    CHECK(loop.ticks() == 20);
    CHECK(loop.time() == 20 * 0.1);
    CHECK(std::abs(y[0] - 2.0) <= 64 * eps);  // ABM4 is exact for y' = 1 too
}

TEST_CASE("defect 5: a root exactly on a step's end is reported at that time, and times never run backwards") {
    // As scipy/scipy#17066 (an event exactly at a bracket's end). 15 * 0.1 == 1.5 while 14 * 0.1 + 0.1 is
    // 1.5000000000000002: the event is at the grid time 1.5 itself.
    REQUIRE(15 * 0.1 == 1.5);
    REQUIRE(14 * 0.1 + 0.1 > 1.5);
    double when = 0.0;
    const auto ev =
        odestep::make_event<state1>([](double t, const state1&) { return t - 1.5; }, odestep::direction::rising,
                                    [&](double t, state1& y) {
                                        when = t;
                                        y[0] += 1.0;
                                    });
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 2.0, 0.1, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
    CHECK(when == 1.5);
    CHECK(std::abs(y[0] - 3.0) <= 16 * eps);
    // Per tick (the reproducer's second half): the firing times and the tick times never run backwards.
    auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
    y = {0.0};
    REQUIRE(loop.start(0.0, 0.1, y) == odestep::status::ok);
    double last = 0.0;
    for (int n = 0; n < 20; ++n) {
        const auto t = loop.tick(clock_rhs{}, y);
        REQUIRE(t.status == odestep::status::ok);
        for (std::size_t k = 0; k < t.fired; ++k) {
            CHECK(t.firings[k].t >= last);
            last = t.firings[k].t;
        }
        CHECK(t.t >= last);
        last = t.t;
    }
    CHECK(loop.firings(0) == 1);
}

TEST_CASE("defect 6: a terminal root within tolerance after a grid time is not observed twice (scipy#17066)") {
    // The class of scipy/scipy#17066 and #19418 (a duplicated event time at a bracket's end): y' = 1 from 0,
    // terminal at y = nextafter(1, 2), dt 0.25. The root is one ULP after the grid time 1.
    const double level = std::nextafter(1.0, 2.0);
    const auto ev = odestep::make_event<state1>([level](double, const state1& y) { return y[0] - level; },
                                                odestep::direction::rising);
    std::array<double, 16> times{};
    std::size_t n = 0;
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 2.0, 0.25, odestep::watch(ev),
                                      [&](double t, const state1&) {
                                          if (n < times.size()) times[n] = t;
                                          ++n;
                                      });
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.t >= 1.0);
    CHECK(r.t <= level);
    REQUIRE(n >= 2);
    for (std::size_t k = 1; k < n && k < times.size(); ++k) CHECK(times[k] > times[k - 1]);
    CHECK(times[n - 1] == r.t);
}

TEST_CASE("defect 7: an action that changes only a parameter takes effect for the rest of the step") {
    // A DC motor's winding, L i' = u - R i (L = R = 1, u = 1): i = 1 - e^{-t}. A limit switch at i = 0.5
    // (t = ln 2) sets the captured input u = 0; then i = 0.5 e^{-(t - ln 2)}, so i(1) = e^{-1}.
    double u = 1.0;
    auto winding = [&u](double, const state1& i) { return state1{u - i[0]}; };
    const auto limit = odestep::make_event<state1>([](double, const state1& i) { return i[0] - 0.5; },
                                                   odestep::direction::rising, [&u](double, state1&) { u = 0.0; });
    state1 i{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, winding, i, 0.0, 1.0, 0.05, odestep::watch(limit));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
    CHECK(i[0] == doctest::Approx(std::exp(-1.0)).epsilon(1e-7));  // RK4, dt 0.05: error about 1e-8
}

TEST_CASE("defect 8: non_finite_event hands back a state where every event function is finite") {
    // Event 0 (3 y - 1.8 rising: 3 * 0.6 rounds below 1.8, so g is -2.2e-16 at y = 0.6 and positive at the
    // next double: no exact zero) moves the state back by 0.3. Event 1's g is NaN for y in (0.59, 0.6], where
    // event 0 is located (the bracket's left end), and for y in (0.29, 0.3], where its action puts the
    // state; finite at the ends of every step and at the bracket's right end. The action's NaN sends the loop
    // back to a state where every g is finite: not the bracket's left end, where only event 0's was read.
    REQUIRE(3 * 0.6 - 1.8 < 0.0);
    REQUIRE(3 * std::nextafter(0.6, 1.0) - 1.8 > 0.0);
    const auto e0 = odestep::make_event<state1>([](double, const state1& y) { return 3 * y[0] - 1.8; },
                                                odestep::direction::rising, [](double, state1& y) { y[0] -= 0.3; });
    const auto e1 = odestep::make_event<state1>(
        [](double, const state1& y) {
            const bool bad = (y[0] > 0.59 && y[0] <= 0.6) || (y[0] > 0.29 && y[0] <= 0.3);
            return bad ? not_a_number : 1.0;
        },
        odestep::direction::either, odestep::record);
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25, odestep::watch(e0, e1));
    CHECK(r.status == odestep::status::non_finite_event);
    // The last point where both were read finite: the step's start.
    CHECK(r.t == 0.5);
    CHECK(y[0] == 0.5);
}

TEST_CASE("defect 9: event_limits whose bounds do not fit std::size_t are refused with invalid_setting") {
    const auto ev =
        odestep::make_event<state1>([](double, const state1& y) { return y[0] - 0.55; }, odestep::direction::rising);
    constexpr std::size_t most = std::numeric_limits<std::size_t>::max();
    const odestep::event_limits bad[] = {{0, 8, most}, {most, 8, 0}, {0, most, 0}, {0, 8, most / 2}};
    for (const auto& limits : bad) {
        state1 y{0.0};
        std::size_t calls = 0;
        auto f = odestep_test::counted(clock_rhs{}, &calls);
        const auto r =
            odestep::integrate(odestep::rk4<state1>{}, f, y, 0.0, 1.0, 0.1, odestep::watch(ev).with_limits(limits));
        CHECK(r.status == odestep::status::invalid_setting);
        CHECK(calls == 0);
        CHECK(y[0] == 0.0);
        auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev).with_limits(limits));
        CHECK(loop.start(0.0, 0.1, y) == odestep::status::invalid_setting);
        // and the published bounds saturate instead of wrapping
        CHECK(odestep::max_rhs_evals_per_step<odestep::rk4<state1>>(1, limits) == most);
        CHECK(odestep::max_g_evals_per_step<double>(1, limits) == most);
    }
}

TEST_CASE("defect 10: one tick per timer period stays in step with the timer whatever fires") {
    // A hardware-in-the-loop model: one tick() per timer interrupt. A terminal event that fires again and
    // again (g = sin(2 pi y / 0.35) along y = t, either direction: every 0.175) must not make the model fall
    // behind its timer: after 1000 calls it has done 1000 ticks, and its time is in the last period.
    const double pi = std::acos(-1.0);
    const auto ev = odestep::make_event<state1>(
        [pi](double, const state1& y) { return std::sin(2 * pi * y[0] / 0.35); }, odestep::direction::either);
    auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.1, y) == odestep::status::ok);
    std::size_t stops = 0;
    for (int n = 1; n <= 1000; ++n) {
        const auto r = loop.tick(clock_rhs{}, y);
        REQUIRE((r.status == odestep::status::ok || r.status == odestep::status::stopped_by_event));
        if (r.status == odestep::status::stopped_by_event) ++stops;
        CHECK(loop.ticks() == static_cast<std::uint64_t>(n));
        CHECK(r.t >= (n - 1) * 0.1);  // inside the call's own period (a root within tolerance after its start
                                      // stops at the start)
        CHECK(r.t <= n * 0.1);
    }
    CHECK(stops > 500);  // 571 roots in (0, 100]: most periods stop
    CHECK(loop.ticks() == 1000);
}

TEST_CASE("issue 20 defect 5: a tick whose grid time overflows is refused, not ok at Inf") {
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{}, odestep::watch(odestep::make_event<state1>(
                                    [](double, const state1& y) { return y[0] + 1.0; }, odestep::direction::either)));
    state1 y{0.0};
    const double big = std::numeric_limits<double>::max() / 4;
    auto zero = [](double, const state1&) { return state1{0.0}; };
    REQUIRE(loop.start(big, big, y) == odestep::status::ok);
    std::size_t refused = 0;
    for (int n = 0; n < 8; ++n) {
        const auto r = loop.tick(zero, y);
        if (r.status == odestep::status::ok) {
            CHECK(std::isfinite(r.t));
        } else {
            CHECK(r.status == odestep::status::invalid_time);
            CHECK(loop.time() == 4 * big);  // the last finite grid time: big + 3 big
            ++refused;
        }
        CHECK(y[0] == 0.0);
    }
    CHECK(refused == 5);  // t0 + n dt = (n + 1) big overflows from n = 4 on: 3 ticks, then 5 refusals
}

TEST_CASE("sharper: g exactly zero at a representable time fires at that time") {
    // g = t - 0.1 along the grid 0, 0.25, ...: the root 0.1 (the double nearest 0.1) is representable, and g
    // is exactly zero there; the event is reported at 0.1, not at the last time before it.
    double when = -1.0;
    const auto ev = odestep::make_event<state1>([](double t, const state1&) { return t - 0.1; },
                                                odestep::direction::rising, [&](double t, state1&) { when = t; });
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
    CHECK(when == 0.1);
    // and along the state: y = 0.3 is reached at the time where y(t) == 0.3 exactly
    double at = -1.0;
    double y_at = -1.0;
    const auto level =
        odestep::make_event<state1>([](double, const state1& s) { return s[0] - 0.3; }, odestep::direction::rising,
                                    [&](double t, state1& s) {
                                        at = t;
                                        y_at = s[0];
                                    });
    y = {0.0};
    CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25, odestep::watch(level)).status ==
          odestep::status::ok);
    CHECK(y_at <= 0.3);
    CHECK(y_at >= 0.3 - 4 * eps);
    CHECK(std::abs(at - 0.3) <= 4 * eps);
}

TEST_CASE("sharper: the action of an either event is told which way the crossing went (Julia's affect_neg!)") {
    // One g with two behaviours: g = sin(2 pi t) along the clock, either direction; it falls through zero at
    // 0.5 and 1.5 and rises at 1 and 2 (zero at t0: not armed there).
    const double pi = std::acos(-1.0);
    std::array<odestep::direction, 8> seen{};
    std::array<double, 8> when{};
    std::size_t n = 0;
    const auto ev = odestep::make_event<state1>([pi](double t, const state1&) { return std::sin(2 * pi * t); },
                                                odestep::direction::either,
                                                [&](double t, state1&, odestep::direction crossed) {
                                                    if (n < seen.size()) {
                                                        seen[n] = crossed;
                                                        when[n] = t;
                                                    }
                                                    ++n;
                                                });
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 2.2, 0.1, odestep::watch(ev));
    CHECK(r.status == odestep::status::ok);
    REQUIRE(n == 4);
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK(std::abs(when[k] - 0.5 * static_cast<double>(k + 1)) <= 1e-12);
        CHECK(seen[k] == (k % 2 == 0 ? odestep::direction::falling : odestep::direction::rising));
    }
}

TEST_CASE("sharper: every root is located to a bracket of adjacent representable times") {
    // dt 0.25: g = (t - c)^3, a triple root (the root finder narrows it slowly, so that its tolerance, not
    // luck, decides the bracket), at times c that no grid time hits; the event's time (the last time before
    // the crossing, or c itself where g is exactly zero there) and the next representable time after it
    // bracket c. (With the earlier tolerance, 4 eps (|t| + |dt|), 0.3 was located 1 ULP before and
    // 7.389056098930650 3 ULPs before.)
    for (const double c : {0.3, 0.7071067811865476, 1.1, 3.14159265358979, 7.389056098930650}) {
        double when = -1.0;
        const auto ev = odestep::make_event<state1>(
            [c](double t, const state1&) {
                const double d = t - c;
                return d * d * d;
            },
            odestep::direction::rising, [&](double t, state1&) { when = t; });
        state1 y{0.0};
        const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 8.0, 0.25, odestep::watch(ev));
        CHECK(r.status == odestep::status::ok);
        CHECK(r.fired == 1);
        CAPTURE(c);
        CAPTURE(when);
        // t - c changes sign between when and the next double (or is zero at when)
        CHECK(when <= c);
        CHECK(std::nextafter(when, 10.0) >= c);
    }
}
