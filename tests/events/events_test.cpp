// SPDX-License-Identifier: BSL-1.0
// Events: detection at a step's end, location by re-stepping, actions, the grid kept, re-arming, limits,
// bad input, and the published bound on work per step. Expected values come from closed forms: RK4 is exact
// (up to rounding) for constant acceleration and for y' = 1, so event times there are known to the tolerance.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

namespace {

using state1 = std::array<double, 1>;
using state2 = std::array<double, 2>;
using vec1 = std::array<double, 1>;

constexpr double gravity = 9.8;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct free_fall {  // (y, v)' = (v, -g)
    std::size_t* calls = nullptr;
    state2 operator()(double, const state2& s) const {
        if (calls) ++*calls;
        return {s[1], -gravity};
    }
};

struct clock_rhs {  // y' = 1: y(t) = y0 + t, exact in every Runge-Kutta method
    std::size_t* calls = nullptr;
    state1 operator()(double, const state1&) const {
        if (calls) ++*calls;
        return {1.0};
    }
};

template <class State>
bool same_bits(const State& a, const State& b) {
    return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

auto height = [](double, const state2& s) { return s[0]; };
auto speed = [](double, const state2& s) { return s[1]; };

}  // namespace

TEST_CASE("events: a terminal ground event stops at the closed-form time with the integrator's own state") {
    // Thrown up at v0 = 5 from h = 10: y(t) = h + v0 t - g t^2 / 2 hits 0 at t = (v0 + sqrt(v0^2 + 2 g h)) / g.
    const double h = 10.0, v0 = 5.0;
    const double t_hit = (v0 + std::sqrt(v0 * v0 + 2.0 * gravity * h)) / gravity;
    state2 s{h, v0};
    double last_seen = -1.0;
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{}, s, 0.0, 10.0, 0.1, odestep::watch(ground),
                                      [&](double t, const state2&) { last_seen = t; });
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 0);
    CHECK(r.fired == 1);
    CHECK(r.firings[0] == 1);
    CHECK(r.steps == static_cast<std::size_t>(t_hit / 0.1));  // the grid steps before the impact's step
    CHECK(std::abs(r.t - t_hit) <= 64 * eps * t_hit);
    CHECK(last_seen == r.t);                                              // the observer saw the stop
    CHECK(s[0] > 0.0);                                                    // the last state before the crossing...
    CHECK(s[0] < 64 * eps * std::abs(s[1]) * t_hit);                      // ... within the time tolerance of it
    CHECK(s[1] == doctest::Approx(v0 - gravity * t_hit).epsilon(1e-13));  // the impact speed, closed form
}

TEST_CASE("events: a recorded apex leaves the trajectory bit-identical; a noting action is located to a few ULPs") {
    const double h = 10.0, v0 = 5.0;
    double apex_t = -1.0, apex_y = -1.0;
    auto note_apex = [&](double t, state2& s) {
        apex_t = t;
        apex_y = s[0];
    };
    state2 with{h, v0};
    state2 without{h, v0};
    const auto apex = odestep::make_event<state2>(speed, odestep::direction::falling, note_apex);
    const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{}, with, 0.0, 1.0, 0.1, odestep::watch(apex));
    const auto plain = odestep::integrate(odestep::rk4<state2>{}, free_fall{}, without, 0.0, 1.0, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(plain.status == odestep::status::ok);
    CHECK(r.fired == 1);
    // A callable action may change what the right-hand side reads (a captured parameter): the rest of the
    // step is recomputed from the event (issue 19, defect 7), so the trajectory agrees only to rounding.
    CHECK(with[0] == doctest::Approx(without[0]).epsilon(1e-14));
    CHECK(with[1] == doctest::Approx(without[1]).epsilon(1e-14));
    CHECK(std::abs(apex_t - v0 / gravity) <= 16 * eps);                            // t = v0 / g
    CHECK(apex_y == doctest::Approx(h + v0 * v0 / (2 * gravity)).epsilon(1e-14));  // h + v0^2 / (2 g)
    // `record` is only counted: bit for bit the run without it.
    state2 recorded{h, v0};
    const auto rec = odestep::make_event<state2>(speed, odestep::direction::falling, odestep::record);
    const auto rr =
        odestep::integrate(odestep::rk4<state2>{}, free_fall{}, recorded, 0.0, 1.0, 0.1, odestep::watch(rec));
    REQUIRE(rr.status == odestep::status::ok);
    CHECK(rr.fired == 1);
    CHECK(same_bits(recorded, without));
}

TEST_CASE("events: no firing costs no right-hand-side evaluation and one g evaluation per event per step") {
    std::size_t rhs_with = 0, rhs_without = 0, g_calls = 0;
    auto counted = [&](double, const state2& s) {
        ++g_calls;
        return s[0] + 100.0;  // never crosses
    };
    state2 a{10.0, 5.0};
    state2 b{10.0, 5.0};
    const auto never = odestep::make_event<state2>(counted, odestep::direction::either);
    const auto r1 = odestep::integrate(odestep::rk4<state2>{}, free_fall{&rhs_with}, a, 0.0, 1.0, 0.01,
                                       odestep::watch(never, never));
    const auto r2 = odestep::integrate(odestep::rk4<state2>{}, free_fall{&rhs_without}, b, 0.0, 1.0, 0.01);
    REQUIRE(r1.status == odestep::status::ok);
    REQUIRE(r2.status == odestep::status::ok);
    CHECK(rhs_with == rhs_without);
    CHECK(rhs_with == 4 * 100);
    CHECK(g_calls == 2 * (100 + 1));  // two events, at t0 and at each of the 100 step ends
    CHECK(same_bits(a, b));
}

TEST_CASE("events: g zero at t0 does not fire; a root exactly on a step's end fires once, at that time") {
    // Regressions reported elsewhere: an event firing on the initial state and then re-firing step after step
    // (SciML/DiffEqBase.jl#646); a root equal to a bracket end duplicating the event time (scipy/scipy#17066).
    // y' = 1 from y = 0 with dt = 0.25: y is exact at every grid time (binary fractions).
    auto at_half = [](double, const state1& y) { return y[0] - 0.5; };
    auto at_zero = [](double, const state1& y) { return y[0]; };
    double fired_at = -1.0;
    const auto half =
        odestep::make_event<state1>(at_half, odestep::direction::either, [&](double t, state1&) { fired_at = t; });
    const auto zero = odestep::make_event<state1>(at_zero, odestep::direction::either, odestep::record);
    state1 y{0.0};
    const auto r =
        odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 2.0, 0.25, odestep::watch(half, zero));
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.firings[0] == 1);
    CHECK(fired_at == 0.5);    // exactly the grid time 2 * 0.25
    CHECK(r.firings[1] == 0);  // zero at t0, then only moves away
    CHECK(y[0] == 2.0);
}

TEST_CASE("events: two roots inside one step are missed without probes and found with one") {
    // As in scipy/scipy#9228 (two zeros skipped when the solver steps over both), made deliberate here.
    // g = (y - 0.3)(y - 0.7) along y = t: positive at both ends of the step [0, 1], negative in between.
    auto two = [](double, const state1& y) { return (y[0] - 0.3) * (y[0] - 0.7); };
    std::array<double, 4> times{};
    std::size_t n = 0;
    auto note = [&](double t, state1&) {
        if (n < times.size()) times[n] = t;
        ++n;
    };
    const auto ev = odestep::make_event<state1>(two, odestep::direction::either, note);
    state1 y{0.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0, odestep::watch(ev));
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.fired == 0);  // documented: same sign at both ends, no probe
    y = {0.0};
    n = 0;
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0,
                           odestep::watch(ev).with_limits({0, 8, 1}));  // one probe, at t = 0.5
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(r.fired == 2);
    CHECK(std::abs(times[0] - 0.3) <= 8 * eps);
    CHECK(std::abs(times[1] - 0.7) <= 8 * eps);
    CHECK(y[0] == 1.0);
}

TEST_CASE("events: after a location the scan goes on from its bracket's end: three crossings in one step in order") {
    // y = t over one tick [0, 1]; g1 = y - 0.5 and g2 = (y - 0.3)(y - 0.7) (which crosses at 0.3 and 0.7,
    // positive at both ends: seen because g1's location reads it at 0.5), both recorded, so that the scan goes
    // on through the step's own result after each. Closed form: g2 at 0.3, g1 at 0.5, g2 at 0.7.
    auto g1 = [](double, const state1& y) { return y[0] - 0.5; };
    auto g2 = [](double, const state1& y) { return (y[0] - 0.3) * (y[0] - 0.7); };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{},
        odestep::watch(odestep::make_event<state1>(g1, odestep::direction::either, odestep::record),
                       odestep::make_event<state1>(g2, odestep::direction::either, odestep::record)));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 1.0, y) == odestep::status::ok);
    const auto r = loop.tick(clock_rhs{}, y);
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(r.fired == 3);
    CHECK(r.firings[0].event == 1);
    CHECK(std::abs(r.firings[0].t - 0.3) <= 8 * eps);
    CHECK(r.firings[1].event == 0);
    CHECK(std::abs(r.firings[1].t - 0.5) <= 8 * eps);
    CHECK(r.firings[2].event == 1);
    CHECK(std::abs(r.firings[2].t - 0.7) <= 8 * eps);
    CHECK(y[0] == 1.0);
}

TEST_CASE("events: a probe whose re-step meets NaN rolls the step back with non_finite") {
    // y' = 1, except NaN at t = 0.25 exactly: the step of 1 from 0 evaluates f at 0, 0.5 and 1 and is finite;
    // the probe at 0.5 re-steps 0.5 from 0, whose RK4 stages are at 0, 0.25, 0.25 and 0.5. The step is rolled
    // back: the state at its start, non_finite, nothing fired.
    auto hole = [](double t, const state1&) {
        return state1{t == 0.25 ? std::numeric_limits<double>::quiet_NaN() : 1.0};
    };
    auto far = [](double, const state1& y) { return y[0] - 10.0; };
    state1 y{0.0};
    const auto r = odestep::integrate(
        odestep::rk4<state1>{}, hole, y, 0.0, 1.0, 1.0,
        odestep::watch(odestep::make_event<state1>(far, odestep::direction::either)).with_limits({0, 8, 1}));
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == 0.0);
    CHECK(y[0] == 0.0);
    CHECK(r.fired == 0);
}

TEST_CASE("events: a state-resetting action re-triggers every period and the grid is kept") {
    // Re-triggering right after a state reset (SciML/DifferentialEquations.jl#590: an event repeated at the
    // same time with fixed steps).
    // Sawtooth: y' = 1, and when y rises through 1 it is reset to 0: firings at t = 1, 2, ..., 10.
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    std::array<double, 16> times{};
    std::size_t n = 0;
    auto reset = [&](double t, state1& y) {
        if (n < times.size()) times[n] = t;
        ++n;
        y[0] = 0.0;
    };
    std::size_t observed = 0;
    bool on_grid = true;
    state1 y{0.0};
    const auto r =
        odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 10.5, 0.3,
                           odestep::watch(odestep::make_event<state1>(top, odestep::direction::rising, reset)),
                           [&](double t, const state1&) {
                               on_grid = on_grid && (t == 10.5 || t == static_cast<double>(observed) * 0.3);
                               ++observed;
                           });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(on_grid);
    CHECK(observed == 36);  // t0 and 35 steps: the observer sees the grid only
    REQUIRE(r.fired == 10);
    for (std::size_t k = 0; k < 10; ++k) CHECK(std::abs(times[k] - static_cast<double>(k + 1)) <= 64 * eps * 10.0);
    CHECK(y[0] == doctest::Approx(0.5));  // reset at t = 10, then half a unit
}

TEST_CASE("events: an action that leaves g at its root chatters into event_limit; a band stops it") {
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    // The action puts y back just below the root: without a band the event re-arms and fires again at once.
    auto stay = [](double, state1& y) { y[0] = 1.0 - 1e-12; };
    state1 y{0.0};
    auto ev = odestep::make_event<state1>(top, odestep::direction::rising, stay);
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 3.0, 0.3, odestep::watch(ev));
    CHECK(r.status == odestep::status::event_limit);
    CHECK(r.fired == 8);         // the default limit per step
    CHECK(y[0] == 1.0 - 1e-12);  // the state after the last firing that happened
    CHECK(std::abs(r.t - 1.0) <= 1e-11);
    // With a band of 0.5, it re-arms only once |y - 1| > 0.5 has been seen, which the rising y never shows.
    y = {0.0};
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 3.0, 0.3, odestep::watch(ev.with_band(0.5)));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
    // A dead time of 0.5 keeps it disarmed until t = 1.5, and by then y is past the level: no second firing.
    y = {0.0};
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 3.0, 0.3,
                           odestep::watch(ev.with_dead_time(0.5)));
    CHECK(r.status == odestep::status::ok);
    CHECK(r.fired == 1);
}

TEST_CASE("events: max_firings silences an event after that many") {
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    auto reset = [](double, state1& y) { y[0] = 0.0; };
    state1 y{0.0};
    const auto ev = odestep::make_event<state1>(top, odestep::direction::rising, reset).with_max_firings(3);
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 10.0, 0.25, odestep::watch(ev));
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.fired == 3);
    CHECK(y[0] == doctest::Approx(7.0));  // reset at t = 3, then free for 7
}

TEST_CASE("events: the earliest event in a step wins; simultaneous ones fire in the order given") {
    // Simultaneous events: a hang in SciML/DiffEqBase.jl#837 and #889, only the first firing in
    // SciML/ModelingToolkit.jl#3819. Here both fire once, in order, and the run goes on.
    auto at = [](double level) { return [level](double, const state1& y) { return y[0] - level; }; };
    std::array<std::size_t, 4> order{};
    std::size_t n = 0;
    auto note = [&](std::size_t id) {
        return [&order, &n, id](double, state1&) {
            if (n < order.size()) order[n] = id;
            ++n;
        };
    };
    state1 y{0.0};
    // In one step [0, 1]: levels 0.75 (event 0), 0.25 (event 1) and 0.25 again (event 2).
    const auto r =
        odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0,
                           odestep::watch(odestep::make_event<state1>(at(0.75), odestep::direction::rising, note(0)),
                                          odestep::make_event<state1>(at(0.25), odestep::direction::rising, note(1)),
                                          odestep::make_event<state1>(at(0.25), odestep::direction::rising, note(2))));
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(n == 3);
    CHECK(order[0] == 1);
    CHECK(order[1] == 2);
    CHECK(order[2] == 0);
}

TEST_CASE("events: a NaN from g is a status, not a hang, and the state is the last good one") {
    auto bad = [](double, const state1& y) { return y[0] > 0.55 ? std::numeric_limits<double>::quiet_NaN() : 1.0; };
    state1 y{0.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25,
                                odestep::watch(odestep::make_event<state1>(bad, odestep::direction::either)));
    CHECK(r.status == odestep::status::non_finite_event);
    CHECK(r.t == 0.5);
    CHECK(y[0] == 0.5);
    // NaN already at t0: nothing is touched.
    y = {1.0};
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25,
                           odestep::watch(odestep::make_event<state1>(bad, odestep::direction::either)));
    CHECK(r.status == odestep::status::non_finite_event);
    CHECK(r.t == 0.0);
    CHECK(y[0] == 1.0);
}

TEST_CASE("events: negative or NaN tolerance, band and dead time are rejected before anything is touched") {
    auto g = [](double, const state1& y) { return y[0] - 0.5; };
    const auto ev = odestep::make_event<state1>(g, odestep::direction::either);
    const double bad[] = {-1e-9, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
    for (double v : bad) {
        state1 y{0.0};
        std::size_t calls = 0;
        CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{&calls}, y, 0.0, 1.0, 0.25,
                                 odestep::watch(ev.with_tolerance(v)))
                  .status == odestep::status::invalid_tolerance);
        CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{&calls}, y, 0.0, 1.0, 0.25,
                                 odestep::watch(ev.with_band(v)))
                  .status == odestep::status::invalid_tolerance);
        CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{&calls}, y, 0.0, 1.0, 0.25,
                                 odestep::watch(ev.with_dead_time(v)))
                  .status == odestep::status::invalid_tolerance);
        CHECK(calls == 0);
        CHECK(y[0] == 0.0);
    }
    // and the bad arguments of integrate itself, as without events
    state1 y{0.0};
    CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.0, odestep::watch(ev)).status ==
          odestep::status::invalid_step);
    CHECK(odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, -0.1, odestep::watch(ev)).status ==
          odestep::status::wrong_direction);
}

TEST_CASE("events: a coarse user tolerance is honoured and still brackets the root from before") {
    auto g = [](double, const state1& y) { return y[0] - 0.3; };
    double when = -1.0;
    state1 y{0.0};
    const auto ev = odestep::make_event<state1>(g, odestep::direction::rising, [&](double t, state1&) {
                        when = t;
                        return odestep::event_result::stop;
                    }).with_tolerance(1e-3);
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0, odestep::watch(ev));
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(when <= 0.3);
    CHECK(when >= 0.3 - 1e-3);
    CHECK(y[0] == doctest::Approx(when));  // the state at the reported time
}

TEST_CASE("events: integrating backwards, a falling crossing in time order is located") {
    // y' = 1 from y(1) = 1 back to t = 0: y = t falls through 0.4 at t = 0.4.
    auto g = [](double, const state1& y) { return y[0] - 0.4; };
    state1 y{1.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 1.0, 0.0, -0.25,
                                      odestep::watch(odestep::make_event<state1>(g, odestep::direction::falling)));
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - 0.4) <= 8 * eps);
    CHECK(y[0] >= 0.4);
}

TEST_CASE("events: float events are located to a few float ULPs without touching double") {
    using statef = std::array<float, 2>;
    auto fall = [](float, const statef& s) { return statef{s[1], -9.8f}; };
    auto ground = [](float, const statef& s) { return s[0]; };
    statef s{10.0f, 5.0f};
    const auto r = odestep::integrate(odestep::rk4<statef>{}, fall, s, 0.0f, 10.0f, 0.1f,
                                      odestep::watch(odestep::make_event<statef>(ground, odestep::direction::falling)));
    CHECK(r.status == odestep::status::stopped_by_event);
    // The closed form, evaluated in double by the test: (v0 + sqrt(v0^2 + 2 g h)) / g, with g as the float 9.8f.
    const double g = static_cast<double>(9.8f);
    const double t_hit = (5.0 + std::sqrt(25.0 + 2.0 * g * 10.0)) / g;
    CHECK(std::abs(static_cast<double>(r.t) - t_hit) <=
          64.0 * static_cast<double>(std::numeric_limits<float>::epsilon()) * t_hit);
}

TEST_CASE("events: a bouncing ball (e = 0.7) meets the closed-form impact times, and its Zeno storm is reported") {
    // Dropped from h = 1 at rest; impact speeds v_k = e^k v_1 with v_1 = sqrt(2 g h); impact times
    // t_1 = sqrt(2 h / g), t_{k+1} = t_k + 2 e^k v_1 / g. RK4 is exact for constant gravity.
    const double e = 0.7, h0 = 1.0;
    const double v1 = std::sqrt(2 * gravity * h0);
    std::array<double, 64> impacts{};
    std::size_t n = 0;
    auto bounce = [&](double t, state2& s) {
        if (n < impacts.size()) impacts[n] = t;
        ++n;
        s[1] = -e * s[1];
    };
    state2 s{h0, 0.0};
    const auto floor = odestep::make_event<state2>(height, odestep::direction::falling, bounce);
    const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{}, s, 0.0, 10.0, 0.01, odestep::watch(floor));
    // The flights shrink geometrically (the total time is t_1 (1 + e) / (1 - e) = 2.1304 s): eventually more
    // than the limit of bounces fall inside one step, and the loop says so instead of tunnelling through.
    CHECK(r.status == odestep::status::event_limit);
    CHECK(r.t < std::sqrt(2 * h0 / gravity) * (1 + e) / (1 - e));
    CHECK(s[0] >= 0.0);  // never below the floor
    double t_k = std::sqrt(2 * h0 / gravity);
    for (std::size_t k = 0; k < 12; ++k) {
        CHECK(std::abs(impacts[k] - t_k) <= 1e-12);
        t_k += 2.0 * std::pow(e, static_cast<double>(k + 1)) * v1 / gravity;
    }
}

TEST_CASE("events: the bouncing ball comes to rest with a latch in its action") {
    const double e = 0.7;
    bool resting = false;
    auto fall = [&](double, const state2& s) { return resting ? state2{0.0, 0.0} : state2{s[1], -gravity}; };
    auto bounce = [&](double, state2& s) {
        if (-s[1] * e < 0.1) {  // too slow to bounce visibly again: lie still
            resting = true;
            s = {0.0, 0.0};
        } else {
            s[1] = -e * s[1];
        }
    };
    state2 s{1.0, 0.0};
    const auto floor = odestep::make_event<state2>(height, odestep::direction::falling, bounce);
    const auto r = odestep::integrate(odestep::rk4<state2>{}, fall, s, 0.0, 10.0, 0.01, odestep::watch(floor));
    CHECK(r.status == odestep::status::ok);
    CHECK(resting);
    CHECK(s[0] == 0.0);
    // impact k has speed e^(k-1) v_1; the latch takes the first impact with e^k v_1 < 0.1:
    // k = ceil(ln(0.1 / v_1) / ln e) = 11 with v_1 = sqrt(2 g)
    const double v1 = std::sqrt(2 * gravity);
    const auto k = static_cast<std::size_t>(std::ceil(std::log(0.1 / v1) / std::log(e)));
    CHECK(k == 11);
    CHECK(r.fired == k);
}

TEST_CASE("events: Newton's form with velocity Verlet, g(t, x, v) and action(t, x, v)") {
    using vec = std::array<double, 1>;
    auto a = [](double, const vec&) { return vec{-gravity}; };
    auto ground = [](double, const vec& x, const vec&) { return x[0]; };
    vec x{10.0};
    vec v{5.0};
    std::size_t bounces = 0;
    auto bounce = [&](double, vec&, vec& vel) {
        ++bounces;
        vel[0] = -vel[0];
    };
    // Velocity Verlet is exact for constant acceleration too.
    const auto r =
        odestep::integrate(odestep::velocity_verlet<vec>{}, a, x, v, 0.0, 3.0, 0.1,
                           odestep::watch(odestep::make_event<vec>(ground, odestep::direction::falling, bounce)));
    REQUIRE(r.status == odestep::status::ok);
    CHECK(bounces == 1);
    // elastic: after the bounce at t_hit the ball retraces its fall: x(2) = x(2 t_hit - 2) mirrored in time
    const double t_hit = (5.0 + std::sqrt(25.0 + 2.0 * gravity * 10.0)) / gravity;
    const double u = 3.0 - t_hit;
    const double v_hit = 5.0 - gravity * t_hit;
    CHECK(x[0] == doctest::Approx(-v_hit * u - gravity * u * u / 2).epsilon(1e-12));
}

TEST_CASE("events: Adams-Bashforth-Moulton restarts its history after a state change") {
    // Coffee: T' = -r (T - Ts); a serving of cream (-5 C) when T falls through 67 C.
    const double r = 0.03, Ts = 17.0;
    auto cool = [&](double, const state1& T) { return state1{-r * (T[0] - Ts)}; };
    auto at67 = [](double, const state1& T) { return T[0] - 67.0; };
    auto cream = [](double, state1& T) { T[0] -= 5.0; };
    state1 T{85.0};
    double t_cream = -1.0;
    auto note = [&](double t, state1& y) {
        t_cream = t;
        cream(t, y);
    };
    const auto res =
        odestep::integrate(odestep::adams_bashforth_moulton4<state1>{}, cool, T, 0.0, 20.0, 0.1,
                           odestep::watch(odestep::make_event<state1>(at67, odestep::direction::falling, note)));
    REQUIRE(res.status == odestep::status::ok);
    // T reaches 67 at ln((85 - 17) / (67 - 17)) / r; after it, T = Ts + (62 - Ts) e^{-r (t - t_cream)}.
    CHECK(t_cream == doctest::Approx(std::log(68.0 / 50.0) / r).epsilon(1e-9));
    CHECK(T[0] == doctest::Approx(Ts + 45.0 * std::exp(-r * (20.0 - t_cream))).epsilon(1e-9));
}

TEST_CASE("events: the per-tick event stepper advances exactly one dt and lists the firings with their times") {
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    auto reset = [](double, state1& y) { y[0] = 0.0; };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{}, odestep::watch(odestep::make_event<state1>(top, odestep::direction::rising, reset)));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
    std::size_t fired = 0;
    for (std::size_t n = 0; n < 11; ++n) {
        const auto r = loop.tick(clock_rhs{}, y);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.t == static_cast<double>(n + 1) * 0.3);
        if (r.fired) {
            ++fired;
            CHECK(r.firings[0].event == 0);
            CHECK(std::abs(r.firings[0].t - static_cast<double>(fired)) <= 64 * eps * 3.0);
        }
    }
    CHECK(fired == 3);  // at t = 1, 2, 3 (ticks end at 0.3 .. 3.3)
    CHECK(loop.ticks() == 11);
    CHECK(loop.firings(0) == 3);
}

TEST_CASE("events: a tick event left unarmed by its dead time is armed again by the quiet ticks after it") {
    // y' = 1 from 0, reset to 0 when it reaches 1: the crossings are at t = 1, 2, 3 (closed form, RK4 exact).
    // With a dead time of 0.5 the event is not armed for the ticks to 1.2 and 1.5 after each firing; the
    // quiet ticks that follow must arm it again, or the crossings at 2 and 3 are missed.
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    auto reset = [](double, state1& y) { y[0] = 0.0; };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{},
        odestep::watch(odestep::make_event<state1>(top, odestep::direction::rising, reset).with_dead_time(0.5)));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
    std::size_t fired = 0;
    for (std::size_t n = 0; n < 11; ++n) {
        const auto r = loop.tick(clock_rhs{}, y);
        REQUIRE(r.status == odestep::status::ok);
        if (r.fired) {
            ++fired;
            CHECK(std::abs(r.firings[0].t - static_cast<double>(fired)) <= 64 * eps * 3.0);
        }
    }
    CHECK(fired == 3);
    CHECK(loop.firings(0) == 3);
}

TEST_CASE("events: the per-tick loop and integrate locate the same crossings, bit for bit") {
    // One engine, one grid: a pebble thrown up at 20 m/s against quadratic drag (k = 0.05 / m), its apex and
    // its landing recorded by a noting action, stepped by ticks and by integrate, fire at the same times to the
    // bit, and the finder takes the same iterations (as many g evaluations): it starts from the events' values
    // at the step's start, which the quiet ticks keep as integrate's quiet steps do.
    struct drag {
        state2 operator()(double, const state2& s) const { return {s[1], -gravity - 0.05 * s[1] * std::abs(s[1])}; }
    };
    std::size_t g_calls = 0;
    auto counted_speed = [&g_calls](double, const state2& s) {
        ++g_calls;
        return s[1];
    };
    auto counted_height = [&g_calls](double, const state2& s) {
        ++g_calls;
        return s[0];
    };
    std::array<double, 2> by_integrate{-1.0, -1.0};
    auto note = [&](std::size_t i) { return [&by_integrate, i](double t, state2&) { by_integrate[i] = t; }; };
    state2 y{0.0, 20.0};
    const auto r = odestep::integrate(
        odestep::rk4<state2>{}, drag{}, y, 0.0, 4.0, 0.01,
        odestep::watch(odestep::make_event<state2>(counted_speed, odestep::direction::falling, note(0)),
                       odestep::make_event<state2>(counted_height, odestep::direction::falling, note(1))));
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(r.fired == 2);
    const std::size_t g_by_integrate = g_calls;
    g_calls = 0;
    std::array<double, 2> by_ticks{-1.0, -1.0};
    auto tick_note = [](double, state2&) {};
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state2>{},
        odestep::watch(odestep::make_event<state2>(counted_speed, odestep::direction::falling, tick_note),
                       odestep::make_event<state2>(counted_height, odestep::direction::falling, tick_note)));
    state2 z{0.0, 20.0};
    REQUIRE(loop.start(0.0, 0.01, z) == odestep::status::ok);
    for (int n = 0; n < 400; ++n) {
        const auto t = loop.tick(drag{}, z);
        REQUIRE(t.status == odestep::status::ok);
        for (std::size_t k = 0; k < t.fired; ++k) by_ticks[t.firings[k].event] = t.firings[k].t;
    }
    CHECK(by_ticks[0] > 0.0);
    CHECK(by_ticks[1] > by_ticks[0]);
    CHECK(std::memcmp(by_ticks.data(), by_integrate.data(), sizeof by_ticks) == 0);
    CHECK(std::memcmp(z.data(), y.data(), sizeof z) == 0);
    CHECK(g_calls == g_by_integrate);
}

TEST_CASE("events: after a terminal tick the next tick goes from the event back to the grid and on to its own") {
    auto half = [](double, const state1& y) { return y[0] - 0.5; };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{}, odestep::watch(odestep::make_event<state1>(half, odestep::direction::rising)));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
    CHECK(loop.tick(clock_rhs{}, y).status == odestep::status::ok);
    const auto r = loop.tick(clock_rhs{}, y);
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - 0.5) <= 8 * eps);
    CHECK(loop.time() == r.t);
    CHECK(loop.ticks() == 2);  // the stopped tick counted its period (issue 19, defect 10)
    // The next call completes the stopped tick's period (to 0.6) and then takes its own, to 0.9: one call
    // per period of the timer.
    const auto next = loop.tick(clock_rhs{}, y);
    CHECK(next.status == odestep::status::ok);
    CHECK(next.t == 3 * 0.3);
    CHECK(loop.ticks() == 3);
    CHECK(y[0] == doctest::Approx(0.9));
    // before start: a status, nothing touched
    auto fresh = odestep::make_event_stepper(
        odestep::rk4<state1>{}, odestep::watch(odestep::make_event<state1>(half, odestep::direction::rising)));
    state1 z{0.25};
    CHECK(fresh.tick(clock_rhs{}, z).status == odestep::status::invalid_time);
    CHECK(z[0] == 0.25);
}

TEST_CASE("events: start after a tick that stopped inside its period begins a fresh clock, as a new loop's") {
    // A loop stopped off the grid (at y = 0.5, t = 0.5) and started again at t0 = 0.1 with dt = 0.2: its first
    // tick is one step of exactly dt, bit for bit a new loop's (a step back to the grid would be
    // (0.1 + 0.2) - 0.1 = 0.20000000000000004 long), and ends on t0 + dt.
    auto half = [](double, const state1& y) { return y[0] - 0.5; };
    const auto ev = odestep::make_event<state1>(half, odestep::direction::rising);
    auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
    REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::ok);
    REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::stopped_by_event);
    y = state1{0.0};
    REQUIRE(loop.start(0.1, 0.2, y) == odestep::status::ok);
    const auto r = loop.tick(clock_rhs{}, y);
    auto twin = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
    state1 z{0.0};
    REQUIRE(twin.start(0.1, 0.2, z) == odestep::status::ok);
    const auto rz = twin.tick(clock_rhs{}, z);
    CHECK(r.status == odestep::status::ok);
    CHECK(rz.status == odestep::status::ok);
    CHECK(r.t == 0.1 + 0.2);
    CHECK(rz.t == r.t);
    CHECK(std::memcmp(y.data(), z.data(), sizeof y) == 0);
    CHECK(loop.ticks() == 1);
    CHECK(loop.reached() == 1);
}

TEST_CASE("events: rearm measures crossings from the caller's new state and keeps max_firings and the dead time") {
    auto top = [](double, const state1& y) { return y[0] - 1.0; };
    auto reset = [](double, state1& y) { y[0] = 0.0; };
    const auto ev = odestep::make_event<state1>(top, odestep::direction::rising, reset);
    // The caller moves y across the zero between ticks (0.3 -> 2): without rearm the next tick sees g go from
    // -0.7 to +1.3 and fires; with it, g is measured from +1 and nothing fires.
    for (const bool reread : {false, true}) {
        auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
        REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::ok);
        y[0] = 2.0;
        if (reread) REQUIRE(loop.rearm(y) == odestep::status::ok);
        const auto r = loop.tick(clock_rhs{}, y);
        CHECK(r.status == odestep::status::ok);
        CHECK(r.fired == (reread ? 0u : 1u));
    }
    // max_firings(1): fired at t = 1 (y reset to 0); the caller sets y = 0.5 and rearms at t = 1.2. y reaches
    // 1 again at t = 1.7, and the event, used up, stays quiet.
    {
        auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev.with_max_firings(1)));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
        for (int n = 0; n < 4; ++n) REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::ok);
        REQUIRE(loop.firings(0) == 1);
        y[0] = 0.5;
        REQUIRE(loop.rearm(y) == odestep::status::ok);
        for (int n = 0; n < 6; ++n) CHECK(loop.tick(clock_rhs{}, y).fired == 0);
        CHECK(loop.firings(0) == 1);
        CHECK(y[0] == doctest::Approx(2.3));  // 0.5 at t = 1.2, then y' = 1 to t = 3
    }
    // dead time 1: fired at t = 1; the caller sets y = 0.9 and rearms at t = 1.2. y reaches 1 at t = 1.3,
    // inside the dead time, so the event is not armed there; it re-arms at t = 2.1, above its zero, and y
    // never comes back below it.
    {
        auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev.with_dead_time(1.0)));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
        for (int n = 0; n < 4; ++n) REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::ok);
        REQUIRE(loop.firings(0) == 1);
        y[0] = 0.9;
        REQUIRE(loop.rearm(y) == odestep::status::ok);
        for (int n = 0; n < 6; ++n) CHECK(loop.tick(clock_rhs{}, y).fired == 0);
        CHECK(loop.firings(0) == 1);
    }
    // A NaN from g on rearm: a status, and the events' memory is untouched (the next tick still fires from
    // the last tick's values).
    {
        auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, odestep::watch(ev));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.3, y) == odestep::status::ok);
        for (int n = 0; n < 3; ++n) REQUIRE(loop.tick(clock_rhs{}, y).status == odestep::status::ok);  // t = 0.9
        const state1 bad{std::numeric_limits<double>::quiet_NaN()};
        CHECK(loop.rearm(bad) == odestep::status::non_finite_event);
        const auto r = loop.tick(clock_rhs{}, y);  // 0.9 -> 1.2: crosses at 1
        CHECK(r.fired == 1);
        CHECK(std::abs(r.firings[0].t - 1.0) <= 64 * eps);
    }
}

TEST_CASE("events: g values whose products underflow or overflow still give the right crossings") {
    // The quiet tick's test multiplies each g by its last value. Scaled by 1e-200 the products underflow to
    // zero, scaled by 1e200 they overflow to Inf; either sends the tick to the full test, which must find the
    // one crossing at t = 5 (y' = 1 from 0) and no NaN.
    for (const double scale : {1e-200, 1e200}) {
        auto g = [scale](double, const state1& y) { return scale * (y[0] - 5.0); };
        auto loop = odestep::make_event_stepper(
            odestep::rk4<state1>{},
            odestep::watch(odestep::make_event<state1>(g, odestep::direction::rising, odestep::record)));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.25, y) == odestep::status::ok);
        std::size_t fired = 0;
        for (int n = 0; n < 40; ++n) {
            const auto r = loop.tick(clock_rhs{}, y);
            REQUIRE(r.status == odestep::status::ok);
            if (r.fired) {
                ++fired;
                CHECK(std::abs(r.firings[0].t - 5.0) <= 64 * eps * 5.0);
            }
        }
        CHECK(fired == 1);
        CHECK(y[0] == 10.0);  // 40 ticks of 0.25, exact
    }
}

TEST_CASE("events: the tick counter has 64 bits on every target, and its time conversion is exact to one rounding") {
    using loop_type = decltype(odestep::make_event_stepper(
        odestep::rk4<state1>{}, odestep::watch(odestep::make_event<state1>(clock_rhs{}, odestep::direction::rising))));
    static_assert(std::is_same_v<decltype(std::declval<const loop_type&>().ticks()), std::uint64_t>);
    // The split conversion (a 32-bit target's) against integers exact in double: below 2^32 the low half's,
    // above it hi 2^32 + lo.
    CHECK(odestep::detail::count_halves<double>(4294967295u) == 4294967295.0);
    CHECK(odestep::detail::count_halves<double>((std::uint64_t{1} << 32) + 5) == 4294967301.0);
    CHECK(odestep::detail::count_halves<double>((std::uint64_t{3} << 40) + 7) == 3298534883335.0);
    CHECK(odestep::detail::count_value<double>((std::uint64_t{3} << 40) + 7) == 3298534883335.0);
    // float: 2^33 + 1 is not a float; its nearest is 2^33.
    CHECK(odestep::detail::count_halves<float>((std::uint64_t{1} << 33) + 1) == 8589934592.0f);
    CHECK(odestep::detail::count_halves<float>(16777217u) == static_cast<float>(16777217u));
}

TEST_CASE("events: the published bound on right-hand-side evaluations per step holds in the worst case") {
    // The worst case, driven: three events with a ninth-order root (the secant family's slowest case), at levels
    // 2e-12 apart (far more than the tolerance) and listed latest first, so that every location narrows all
    // three in turn; each fires a reset that restarts the step; one probe; the firing limit reached per tick.
    std::size_t calls = 0;
    auto step_fn = [](double level) {
        return [level](double, const state1& y) {
            const double d = y[0] - level;
            const double d3 = d * d * d;
            return d3 * d3 * d3;
        };
    };
    auto back = [](double, state1& y) { y[0] -= 0.05; };
    constexpr odestep::event_limits limits{0, 4, 1};
    auto set = odestep::watch(odestep::make_event<state1>(step_fn(0.31 + 4e-12), odestep::direction::rising, back),
                              odestep::make_event<state1>(step_fn(0.31 + 2e-12), odestep::direction::rising, back),
                              odestep::make_event<state1>(step_fn(0.31), odestep::direction::rising, back))
                   .with_limits(limits);
    auto loop = odestep::make_event_stepper(odestep::rk4<state1>{}, set);
    constexpr std::size_t bound = odestep::max_rhs_evals_per_step<odestep::rk4<state1>>(3, limits);
    // C, the default cap, is Brent's worst case from dt to 4 eps dt: 2 ceil(log2(2^52 / 4)) + 2 = 102
    static_assert(odestep::brent::worst_case_evaluations(1.0, 4 * eps) == 102, "2 n + 2, n = 50");
    static_assert(bound == 4 * ((1 + 4) * (1 + 1) + 4 * 3 * 102) + 4, "S [(1 + F)(1 + P) + F E C] + F");
    // A tick after one that ended early (event_limit here) completes that period first: two steps' worth.
    constexpr std::size_t tick_bound = odestep::max_rhs_evals_per_tick<odestep::rk4<state1>>(3, limits);
    static_assert(tick_bound == 2 * bound, "two steps per tick at most");
    state1 y{0.0};
    REQUIRE(loop.start(0.0, 1.0, y) == odestep::status::ok);
    std::size_t worst = 0;
    std::size_t limited = 0;
    for (int n = 0; n < 4; ++n) {
        calls = 0;
        const bool one_step = loop.reached() == loop.ticks() && loop.time() == static_cast<double>(loop.ticks());
        const auto r = loop.tick(clock_rhs{&calls}, y);
        if (r.status == odestep::status::event_limit) ++limited;
        if (one_step) {  // a tick from its grid time is one step
            if (calls > worst) worst = calls;
            CHECK(calls <= bound);
        }
        CHECK(calls <= tick_bound);
    }
    CHECK(limited >= 1);            // the firing limit was reached: the worst case was driven
    CHECK(worst * 10 > bound * 8);  // and the bound is tight to within 20% (measured: 4568 of 4940)
}

TEST_CASE("events: the default root finder locates smooth events in at most 10 re-steps") {
    // Ground event of the drag-free throw, dt = 0.1: count the right-hand-side evaluations of the location.
    std::size_t calls = 0;
    state2 s{10.0, 5.0};
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    const auto r =
        odestep::integrate(odestep::rk4<state2>{}, free_fall{&calls}, s, 0.0, 10.0, 0.1, odestep::watch(ground));
    REQUIRE(r.status == odestep::status::stopped_by_event);
    const std::size_t location = calls - 4 * static_cast<std::size_t>(r.steps + 1);  // beyond the steps themselves
    CHECK(location % 4 == 0);
    CHECK(location / 4 <= 10);
}

TEST_CASE("events: an action that moves the state onto or across another event's zero fires that event too") {
    // Coffee cooling; at 67 C the action sets T (to exactly 62, or past it to 57): the terminal 62 C event
    // fires at the same time, after the first (found by the examples' author: it used to be missed).
    auto cool = [](double, const state1& T) { return state1{-0.03 * (T[0] - 17.0)}; };
    auto at67 = [](double, const state1& T) { return T[0] - 67.0; };
    auto at62 = [](double, const state1& T) { return T[0] - 62.0; };
    for (double set_to : {62.0, 57.0}) {
        auto pour = [set_to](double, state1& T) { T[0] = set_to; };
        state1 T{85.0};
        const auto r =
            odestep::integrate(odestep::rk4<state1>{}, cool, T, 0.0, 60.0, 0.1,
                               odestep::watch(odestep::make_event<state1>(at67, odestep::direction::falling, pour),
                                              odestep::make_event<state1>(at62, odestep::direction::falling)));
        CHECK(r.status == odestep::status::stopped_by_event);
        CHECK(r.event == 1);
        CHECK(r.firings[0] == 1);
        CHECK(r.firings[1] == 1);
        CHECK(r.t == doctest::Approx(std::log(68.0 / 50.0) / 0.03).epsilon(1e-9));  // T(t) = 17 + 68 e^{-0.03 t}
        CHECK(T[0] == set_to);
    }
}

TEST_CASE("events: a NaN from the right-hand side, in a step or in a re-step, is non_finite with the last good state") {
    auto g = [](double, const state1& y) { return y[0] - 0.6; };
    const auto ev = odestep::make_event<state1>(g, odestep::direction::rising);
    // In the step itself: f is NaN beyond y = 0.55, so the step from 0.5 to 0.75 fails and is rolled back.
    auto nan_above = [](double, const state1& y) {
        return state1{y[0] > 0.55 ? std::numeric_limits<double>::quiet_NaN() : 1.0};
    };
    state1 y{0.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, nan_above, y, 0.0, 1.0, 0.25, odestep::watch(ev));
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == 0.5);
    CHECK(y[0] == 0.5);
    // Only in a re-step: f is NaN for t in (0.52, 0.58), a time the step's stages (0.5, 0.625, 0.75) never
    // reach but the location's first re-step (to about t = 0.6, its midpoint stage near 0.55) does.
    auto nan_between = [](double t, const state1&) {
        return state1{t > 0.52 && t < 0.58 ? std::numeric_limits<double>::quiet_NaN() : 1.0};
    };
    y = {0.0};
    r = odestep::integrate(odestep::rk4<state1>{}, nan_between, y, 0.0, 1.0, 0.25, odestep::watch(ev));
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == 0.5);
    CHECK(y[0] == 0.5);
}
