// SPDX-License-Identifier: BSL-1.0
// Regression tests for issue 24's fuzz findings (A, B, C), the empty-run rule and integrate with a const event
// set. Each case is the finding's minimal program against the public API. Expected values are closed forms or
// the state the run was given: y' = 1 (a clock) is exact in every Runge-Kutta method.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

namespace {

using state1 = std::array<double, 1>;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

struct clock_rhs {  // y' = 1
    state1 operator()(double, const state1&) const { return {1.0}; }
};

struct growth {  // y' = y
    state1 operator()(double, const state1& y) const { return {y[0]}; }
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The last observation of a run.
struct last_seen {
    double* t;
    state1* y;
    std::size_t* count;
    void operator()(double time, const state1& s) const {
        *t = time;
        *y = s;
        ++*count;
    }
};

}  // namespace

TEST_CASE("issue 24 A: a run from -0.0 to +0.0 ends on t1 bit for bit, with and without events") {
    const double minus_zero = -0.0;
    state1 y{1.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, minus_zero, 0.0, 0.1);
    CHECK(r.status == odestep::status::ok);
    CHECK(same_bits(r.t, 0.0));
    CHECK(r.steps == 0);
    CHECK(y[0] == 1.0);
    const auto ev =
        odestep::make_event<state1>([](double t, const state1&) { return t - 1.0; }, odestep::direction::rising);
    const auto e = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, minus_zero, 0.0, 0.1, odestep::watch(ev));
    CHECK(e.status == odestep::status::ok);
    CHECK(same_bits(e.t, 0.0));
    // and the other way: +0.0 to -0.0 ends on -0.0
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, minus_zero, 0.1);
    CHECK(r.status == odestep::status::ok);
    CHECK(same_bits(r.t, minus_zero));
}

TEST_CASE("issue 24, the empty-run rule: a run with no step ends as its first step would, ok only on a finite state") {
    // The rule (docs/reference.md): an empty run (t0 == t1, or n = 0 steps) evaluates no f and hands back
    // the state untouched; ok (at t1) if that state is finite, non_finite (at t0) if it holds a NaN or Inf,
    // as a run with steps returns at its first step. So ok always means a finite state.
    state1 y{not_a_number};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 0.0, 0.1);
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == 0.0);
    CHECK(r.steps == 0);
    CHECK(std::isnan(y[0]));
    // as the same run with one step ends
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 0.1, 0.1);
    CHECK(r.status == odestep::status::non_finite);
    r = odestep::integrate_n_steps(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 0.1, 0);
    CHECK(r.status == odestep::status::non_finite);
    // with events whose g is finite there (a timer): the same
    const auto timer =
        odestep::make_event<state1>([](double t, const state1&) { return t - 1.0; }, odestep::direction::rising);
    const auto e = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 0.0, 0.1, odestep::watch(timer));
    CHECK(e.status == odestep::status::non_finite);
    // Newton's form: x finite, v NaN
    using vec = std::array<double, 1>;
    vec x{0.0};
    vec v{not_a_number};
    const auto n = odestep::integrate(
        odestep::velocity_verlet<vec>{}, [](double, const vec&) { return vec{-1.0}; }, x, v, 0.0, 0.0, 0.1);
    CHECK(n.status == odestep::status::non_finite);
    // a finite state: ok, at t1
    y = {2.0};
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 3.0, 3.0, 0.1);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.t == 3.0);
    CHECK(y[0] == 2.0);
}

TEST_CASE("issue 24 B: a stopping action that changed the state at a step's start is observed with the new state") {
    // g = 2 (t - 0.5) - u rising, u the spacing of doubles above 0.5: g(0.5) = -u and g(0.5 + u) = u, so the
    // root lies strictly between the grid time 0.5 (dt 0.25) and the next double: it is located at the
    // step's start, 0.5, already observed with y = 0.5. The action sets y = 100 and stops the run there.
    const double u = std::nextafter(0.5, 1.0) - 0.5;
    auto stop_at_100 = [](double, state1& y) {
        y[0] = 100.0;
        return odestep::event_result::stop;
    };
    const auto ev = odestep::make_event<state1>([u](double t, const state1&) { return 2 * (t - 0.5) - u; },
                                                odestep::direction::rising, stop_at_100);
    double t_seen = -1.0;
    state1 y_seen{-1.0};
    std::size_t seen = 0;
    state1 y{0.0};
    auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25, odestep::watch(ev),
                                last_seen{&t_seen, &y_seen, &seen});
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(r.t == 0.5);
    CHECK(y[0] == 100.0);
    CHECK(t_seen == r.t);  // the last observation is the state handed back
    CHECK(y_seen[0] == 100.0);
    CHECK(seen == 4);  // 0, 0.25, 0.5, and 0.5 again after the action
    // on the interpolant
    y = {0.0};
    seen = 0;
    r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.25,
                           odestep::watch<odestep::on_interpolant<>>(ev), last_seen{&t_seen, &y_seen, &seen});
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(r.t == 0.5);
    CHECK(t_seen == r.t);
    CHECK(y_seen[0] == 100.0);
    CHECK(y[0] == 100.0);
}

TEST_CASE("issue 24 C: an interpolant that overflows inside a finite step is non_finite with the step's start") {
    // y' = y, y0 = 1e260, dt = 1e10: RK4's step ends at y0 (1 + h + h^2/2 + h^3/6 + h^4/24), about 4.2e298,
    // finite, and so is f there; but h f(y1) is past the largest double, so the Hermite interpolant's value
    // is -Inf or NaN inside the step. A timer event at t = h / 2 (its g finite whatever y is) lies inside the
    // step. The action must never be handed that value, and the run hands back the last state where the step
    // and every g were finite: the step's start, at t = 0.
    const double y0 = 1e260;
    const double h = 1e10;
    const double y1 = y0 * (1 + h + h * h / 2 + h * h * h / 6 + h * h * h * h / 24);
    REQUIRE(std::isfinite(y1));
    REQUIRE(std::isinf(h * y1));
    bool handed_non_finite = false;
    std::size_t actions = 0;
    const auto ev =
        odestep::make_event<state1>([h](double t, const state1&) { return t - h / 2; }, odestep::direction::rising,
                                    [&](double, state1& y) {
                                        ++actions;
                                        handed_non_finite = handed_non_finite || !std::isfinite(y[0]);
                                    });
    state1 y{y0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, growth{}, y, 0.0, h, h,
                                      odestep::watch<odestep::on_interpolant<>>(ev));
    CHECK_FALSE(handed_non_finite);
    CHECK(actions == 0);
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == 0.0);
    CHECK(y[0] == y0);
    // with a probe the interpolant is read at the probe first: the same
    y = {y0};
    const auto p = odestep::integrate(odestep::rk4<state1>{}, growth{}, y, 0.0, h, h,
                                      odestep::watch<odestep::on_interpolant<>>(ev).with_limits({0, 8, 1}));
    CHECK(p.status == odestep::status::non_finite);
    CHECK(p.t == 0.0);
    CHECK(y[0] == y0);
    CHECK(actions == 0);
    // an event on y (1e280, inside the step): the interpolant's value is not handed to g either
    const auto on_y =
        odestep::make_event<state1>([](double, const state1& s) { return s[0] - 1e280; }, odestep::direction::rising);
    y = {y0};
    const auto q = odestep::integrate(odestep::rk4<state1>{}, growth{}, y, 0.0, h, h,
                                      odestep::watch<odestep::on_interpolant<>>(on_y));
    CHECK(q.status == odestep::status::non_finite);
    CHECK(q.t == 0.0);
    CHECK(y[0] == y0);
}

TEST_CASE("issue 24 item 4: integrate takes a const event set") {
    const auto ev =
        odestep::make_event<state1>([](double t, const state1&) { return t - 0.55; }, odestep::direction::rising);
    const auto set = odestep::watch(ev);
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.1, set);
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - 0.55) <= 4 * std::numeric_limits<double>::epsilon());
    // with an observer, and Newton's form
    std::size_t seen = 0;
    y = {0.0};
    const auto o = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.1, set,
                                      [&](double, const state1&) { ++seen; });
    CHECK(o.status == odestep::status::stopped_by_event);
    CHECK(seen == 7);  // 0, 0.1, ..., 0.5 and the event
    using vec = std::array<double, 1>;
    const auto ground = odestep::watch(
        odestep::make_event<vec>([](double, const vec& x, const vec&) { return x[0]; }, odestep::direction::falling));
    vec x{1.0};
    vec v{0.0};
    const auto n = odestep::integrate(
        odestep::velocity_verlet<vec>{}, [](double, const vec&) { return vec{-2.0}; }, x, v, 0.0, 2.0, 0.1, ground);
    CHECK(n.status == odestep::status::stopped_by_event);
    CHECK(std::abs(n.t - 1.0) <= 8 * std::numeric_limits<double>::epsilon());  // x = 1 - t^2 reaches 0 at 1
}

TEST_CASE("issue 24 (found by fuzz_events): a crossing whose bracket the finder's cap left wide is not a zero at t0") {
    // g = sqrt(y) - 1e-3 along y = t is -1e-3 at t0 = 0 (far from zero) and crosses at t = 1e-6. g is concave,
    // so the finder's first iterate (a secant or a bisection) lands after the root: with a cap of one
    // iteration the bracket stays [0, s], its left end at t0. Before the fix the crossing was taken for a zero
    // at the start (located within the window after t0) and never fired: the run ended ok with no firing.
    const auto ev = odestep::make_event<state1>([](double, const state1& y) { return std::sqrt(y[0]) - 1e-3; },
                                                odestep::direction::rising);
    state1 y{0.0};
    const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 0.1,
                                      odestep::watch(ev).with_limits({1, 8, 0}));
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.fired == 1);
    CHECK(r.t >= 0.0);
    CHECK(r.t <= 1e-6);  // the bracket's left end: at or before the root
}

TEST_CASE(
    "issue 24 (found by fuzz_free_events): a crossing inside an earlier firing's wide bracket fires when "
    "the action moved g back") {
    // y' = 1 from 0 over one step of 2; g = y - 0.5 rising; the action subtracts 0.4 from y. In closed form g
    // crosses at t = 0.5, 0.9, 1.3, 1.7: four firings and y(2) = 2 - 4 (0.4) = 0.4. With the finder capped at
    // one or two iterations the first firing's bracket stays wide (it holds the second crossing); before the
    // fix that crossing was taken for the first firing's own, and the run ended ok at y = 1.6, g = 1.1 > 0:
    // on the wrong side, a crossing missed. Both location modes, bisection (its brackets are predictable).
    for (const std::size_t cap : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{0}}) {
        CAPTURE(cap);
        std::size_t calls = 0;
        auto back = [&calls](double, state1& s) {
            s[0] -= 0.4;
            ++calls;
        };
        auto g = [](double, const state1& s) { return s[0] - 0.5; };
        const auto ev = odestep::make_event<state1>(g, odestep::direction::rising, back);
        state1 y{0.0};
        const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 2.0, 2.0,
                                          odestep::watch<odestep::bisection>(ev).with_limits({cap, 8, 0}));
        CHECK(r.status == odestep::status::ok);
        CHECK(calls == 4);
        CHECK(y[0] < 0.5);  // never ok on the wrong side
        CHECK(std::abs(y[0] - 0.4) <= 1e-12);
        std::size_t calls_i = 0;
        auto back_i = [&calls_i](double, state1& s) {
            s[0] -= 0.4;
            ++calls_i;
        };
        state1 z{0.0};
        const auto ri = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, z, 0.0, 2.0, 2.0,
                                           odestep::watch<odestep::on_interpolant<odestep::bisection>>(
                                               odestep::make_event<state1>(g, odestep::direction::rising, back_i))
                                               .with_limits({cap, 8, 0}));
        CHECK(ri.status == odestep::status::ok);
        CHECK(calls_i == 4);
        CHECK(std::abs(z[0] - 0.4) <= 1e-12);
    }
}

TEST_CASE(
    "issue 24 (found by fuzz_free_events): an event with a wide tolerance sharing a crossing does not move a "
    "precise event's firing to the step's start") {
    // y' = 1 (exact in every method) from 0, g = y^2 - 1/2 rising for both events: A (tolerance 0, a callable
    // action that notes where it ran) and B (the same g, a record with a tolerance of 4, wider than the
    // step). The crossing is at t = sqrt(1/2) in closed form (not a float: g is not exactly zero at the
    // located times, so the bracket keeps two ends). Location narrows A's bracket to adjacent times around
    // it, then B's, on [start, b]: B's tolerance keeps the whole of it. Before the fix the bracket's start
    // became the step's (B's), and A fired there, at t = 0 (grid, one step of 1) or at a free-running step's
    // start, with g = -1/2: the action saw a state its event had not reached. Every location mode and loop.
    auto g = [](double, const state1& s) { return s[0] * s[0] - 0.5; };
    struct where {
        double t = -1.0;
        double y = -1.0;
        std::size_t calls = 0;
    };
    const auto check = [](const where& w) {
        CHECK(w.calls == 1);
        CHECK(std::abs(w.t - std::sqrt(0.5)) <= 1e-12);
        CHECK(std::abs(w.y - std::sqrt(0.5)) <= 1e-12);
    };
    const auto events = [&](where& w) {
        auto note = [&w](double t, state1& s) {
            w.t = t;
            w.y = s[0];
            ++w.calls;
        };
        auto b = odestep::make_event<state1>(g, odestep::direction::rising, odestep::record);
        b.tolerance = 4.0;
        return std::make_tuple(odestep::make_event<state1>(g, odestep::direction::rising, note), b);
    };
    {
        where w;
        auto [a, b] = events(w);
        state1 y{0.0};
        const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0, odestep::watch(a, b));
        CHECK(r.status == odestep::status::ok);
        check(w);
    }
    {
        where w;
        auto [a, b] = events(w);
        state1 y{0.0};
        const auto r = odestep::integrate(odestep::rk4<state1>{}, clock_rhs{}, y, 0.0, 1.0, 1.0,
                                          odestep::watch<odestep::on_interpolant<>>(a, b));
        CHECK(r.status == odestep::status::ok);
        check(w);
    }
    {
        where w;
        auto [a, b] = events(w);
        state1 y{0.0};
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> dp(
            odestep::tolerances<state1>::uniform(1e-6, 1e-6));
        dp.set_step_size(1.0);
        const auto r = odestep::integrate_adaptive(dp, clock_rhs{}, y, 0.0, 1.0, odestep::watch(a, b));
        CHECK(r.status == odestep::status::ok);
        check(w);
    }
}

TEST_CASE("issue 24 (found by fuzz_events): a grid stop under half an ULP after the step's start is observed") {
    // y' = 1e20 from y(0) = -1e20 (exact in RK4: y = 1e20 (t - 1), y(1) = 0 exactly); a terminal event
    // g = y |y| - 6.4e7 (rising, zero at y = 8000) crosses 8e-17 after t = 1, in the second step, under half
    // an ULP of 1 (1.1e-16). The Illinois finder's first point, 5.6e-17 into the step, lies before the root
    // (g < 0 there): the bracket's start moves off the step's start, and the run stops at t = 1 with y in
    // (0, 8000] while the observation at t = 1 saw y = 0. Before the fix the loop judged by time alone and did
    // not observe the stop: the observer's last state (0) was not the one handed back.
    struct fast {
        state1 operator()(double, const state1&) const { return {1e20}; }
    };
    const auto ev = odestep::make_event<state1>([](double, const state1& y) { return y[0] * std::abs(y[0]) - 6.4e7; },
                                                odestep::direction::rising, odestep::terminal);
    for (const bool on_interpolant : {false, true}) {
        CAPTURE(on_interpolant);
        state1 y{-1e20};
        double t_seen = -1.0;
        state1 y_seen{-1.0};
        std::size_t seen = 0;
        const last_seen observe{&t_seen, &y_seen, &seen};
        const auto r = on_interpolant
                           ? odestep::integrate(odestep::rk4<state1>{}, fast{}, y, 0.0, 3.0, 1.0,
                                                odestep::watch<odestep::on_interpolant<odestep::illinois>>(ev), observe)
                           : odestep::integrate(odestep::rk4<state1>{}, fast{}, y, 0.0, 3.0, 1.0,
                                                odestep::watch<odestep::illinois>(ev), observe);
        CHECK(r.status == odestep::status::stopped_by_event);
        CHECK(r.t == 1.0);
        CHECK(y[0] > 0.0);
        CHECK(y[0] <= 8000.0);
        CHECK(seen == 3);  // t = 0, 1, and the stop
        CHECK(t_seen == r.t);
        CHECK(same_bits(y_seen[0], y[0]));
    }
}
