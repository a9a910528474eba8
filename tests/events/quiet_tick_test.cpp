// SPDX-License-Identifier: BSL-1.0
// The per-tick loop's quiet tick (issue 24 item 5): what it keeps of the contract now that it stores no time
// and proves the events' values finite with one sum. Expected values: y' = 1 (a clock) is exact in every
// Runge-Kutta method, so y = t; grid times are t0 + n dt as the contract defines them (docs/events.md),
// computed here from the definition; the state after an error is the one the tick was given.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cstdint>
#include <limits>

namespace {

using state1 = std::array<double, 1>;
constexpr double inf = std::numeric_limits<double>::infinity();

struct clock_rhs {  // y' = 1
    state1 operator()(double, const state1&) const { return {1.0}; }
};

// g = 1 while y <= 0.5, then `beyond` (+Inf or -Inf): no crossing of zero in either direction when beyond is
// +Inf (the same side as before), a jump through zero when it is -Inf.
struct jumps_to {
    double beyond;
    double operator()(double, const state1& y) const { return y[0] > 0.5 ? beyond : 1.0; }
};

}  // namespace

TEST_CASE("quiet tick: an Inf from g on the same side is non_finite_event, the tick not counted, y the last good") {
    for (const double beyond : {inf, -inf}) {
        CAPTURE(beyond);
        auto loop = odestep::make_event_stepper(
            odestep::rk4<state1>{},
            odestep::watch(odestep::make_event<state1>(jumps_to{beyond}, odestep::direction::either)));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 0.25, y) == odestep::status::ok);
        // Ticks to 0.25 and 0.5: g = 1 at both, every event armed, the quiet path.
        for (int k = 1; k <= 2; ++k) {
            const auto r = loop.tick(clock_rhs{}, y);
            REQUIRE(r.status == odestep::status::ok);
            CHECK(r.fired == 0);
        }
        REQUIRE(y[0] == 0.5);
        // The tick to 0.75 meets g = beyond: an error, and nothing moves.
        const auto r = loop.tick(clock_rhs{}, y);
        CHECK(r.status == odestep::status::non_finite_event);
        CHECK(r.fired == 0);
        CHECK(r.t == 0.5);
        CHECK(y[0] == 0.5);
        CHECK(loop.time() == 0.5);
        CHECK(loop.ticks() == 2);
        CHECK(loop.reached() == 2);
    }
}

TEST_CASE("quiet tick: time() and r.t are the grid times t0 + n dt after quiet ticks and after an early end") {
    // dt = 0.25 and t0 = 0.5: every grid time t0 + n dt is exact in binary. A terminal event at y = 1.1
    // (rising) ends the tick to 1.25 early; the next tick completes that period and takes its own, to 1.5.
    const double t0 = 0.5, dt = 0.25;
    auto grid = [&](std::uint64_t n) { return t0 + static_cast<double>(n) * dt; };
    auto at_level = [](double, const state1& y) { return y[0] - 1.1; };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<state1>{},
        odestep::watch(odestep::make_event<state1>(at_level, odestep::direction::rising, odestep::terminal)));
    state1 y{t0};
    REQUIRE(loop.start(t0, dt, y) == odestep::status::ok);
    CHECK(loop.time() == t0);
    for (std::uint64_t n = 1; n <= 2; ++n) {  // to 0.75 and 1.0: quiet
        const auto r = loop.tick(clock_rhs{}, y);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.t == grid(n));
        CHECK(loop.time() == grid(n));
        CHECK(y[0] == grid(n));
        CHECK(loop.reached() == n);
    }
    // To 1.25: stops at the root, t = 1.1 to the event's tolerance, off the grid.
    auto r = loop.tick(clock_rhs{}, y);
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(r.t == doctest::Approx(1.1).epsilon(1e-9));
    CHECK(r.t > grid(2));
    CHECK(r.t < grid(3));
    CHECK(loop.time() == r.t);
    CHECK(loop.reached() == 2);
    CHECK(loop.ticks() == 3);
    // The next tick: the rest of the period to 1.25, then its own to 1.5; then a quiet tick to 1.75.
    r = loop.tick(clock_rhs{}, y);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.t == grid(4));
    CHECK(loop.time() == grid(4));
    CHECK(loop.reached() == 4);
    r = loop.tick(clock_rhs{}, y);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.t == grid(5));
    CHECK(loop.time() == grid(5));
    CHECK(y[0] == doctest::Approx(grid(5)).epsilon(1e-14));
}
