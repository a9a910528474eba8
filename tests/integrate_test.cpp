// SPDX-License-Identifier: BSL-1.0
// The fixed-step loops: landing on t1, time from a counter, direction, observers, and every bad input.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>

#include "support/compare.hpp"

namespace {

using state1 = std::array<double, 1>;

struct growth {  // y' = y
    void operator()(double, const state1& y, state1& dydt) const noexcept { dydt[0] = y[0]; }
};

// Records what the observer saw.
struct recorder {
    std::array<double, 64> t{};
    std::array<double, 64> y{};
    std::size_t calls = 0;
    void operator()(double time, const state1& state) {
        if (calls < t.size()) {
            t[calls] = time;
            y[calls] = state[0];
        }
        ++calls;
    }
};

using odestep_test::same_bits;

constexpr double qnan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("integrate: lands exactly on t1, shortening only the last step") {
    odestep::rk4<state1> stepper;
    state1 y{1.0};
    recorder seen;
    const auto r = odestep::integrate(stepper, growth{}, y, 0.0, 1.0, 0.3, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 4);
    CHECK(r.t == 1.0);
    REQUIRE(seen.calls == 5);
    // grid t0 + i dt from the counter, then t1 itself
    CHECK(seen.t[0] == 0.0);
    CHECK(seen.t[1] == 0.3);
    CHECK(seen.t[2] == 2.0 * 0.3);
    CHECK(seen.t[3] == 3.0 * 0.3);
    CHECK(seen.t[4] == 1.0);
    // and the state there is RK4's, to RK4's accuracy: y(1) = e
    CHECK(y[0] == doctest::Approx(std::exp(1.0)).epsilon(1e-4));
}

TEST_CASE("integrate: a quotient a few ULPs below a whole number takes that many steps, no sliver step") {
    // 0.3 / 0.1 = 2.9999999999999996 in double: three steps, not three plus a step of 5e-17.
    odestep::euler<state1> stepper;
    state1 y{1.0};
    recorder seen;
    const auto r = odestep::integrate(stepper, growth{}, y, 0.0, 0.3, 0.1, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 3);
    CHECK(seen.t[3] == 0.3);
    // Euler: y = (1 + h)^n up to the ULP-sized difference of the last step
    CHECK(y[0] == doctest::Approx(1.1 * 1.1 * 1.1).epsilon(1e-14));
}

TEST_CASE("integrate: the observer sees the initial state and every step, and the state it sees is y") {
    odestep::euler<state1> stepper;
    state1 y{1.0};
    recorder seen;
    const auto r = odestep::integrate(stepper, growth{}, y, 0.0, 1.0, 0.125, seen);
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(seen.calls == 9);
    double expected = 1.0;  // Euler on y' = y: y_n = (1 + h)^n, exact in binary for h = 1/8
    for (std::size_t i = 0; i < seen.calls; ++i) {
        CHECK(seen.t[i] == 0.125 * static_cast<double>(i));
        CHECK(seen.y[i] == expected);
        expected *= 1.125;
    }
}

TEST_CASE("integrate: a negative dt integrates backwards and lands on t1") {
    odestep::rk4<state1> stepper;
    state1 y{std::exp(1.0)};
    recorder seen;
    const auto r = odestep::integrate(stepper, growth{}, y, 1.0, 0.0, -0.01, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 100);
    CHECK(r.t == 0.0);
    CHECK(seen.t[1] == 1.0 - 0.01);
    CHECK(y[0] == doctest::Approx(1.0).epsilon(1e-9));  // y(0) = 1; RK4 at h = 0.01: error ~ 1e-10
}

TEST_CASE(
    "integrate: time comes from the step counter, so a float run of 10^6 steps of 1e-3 ends within one ULP of 1000") {
    // A running sum t += 1e-3f would end near 991.1; t0 + i * dt is within one rounding of i * dt.
    using statef = std::array<float, 1>;
    odestep::euler<statef> stepper;
    statef y{0.0f};
    float last_seen = -1.0f;
    std::size_t mismatches = 0;
    std::size_t i = 0;
    const auto r = odestep::integrate_n_steps(
        stepper, [](float, const statef&) { return statef{1.0f}; }, y, 0.0f, 1e-3f, 1000000,
        [&](float t, const statef&) {
            if (t != static_cast<float>(i) * 1e-3f) ++mismatches;
            last_seen = t;
            ++i;
        });
    CHECK(r.status == odestep::status::ok);
    CHECK(mismatches == 0);
    // 10^6 * float(1e-3) = 1000.0000475, which rounds to the float next to 1000 (ULP 6.1e-5)
    CHECK(last_seen == 1000000.0f * 1e-3f);
    CHECK(r.t == 1000000.0f * 1e-3f);
    CHECK(std::fabs(r.t - 1000.0f) < 1e-4f);
}

TEST_CASE("integrate: bitwise the same as calling step by hand at t0 + i dt") {
    using state2 = std::array<double, 2>;
    auto sho = [](double, const state2& y) { return state2{y[1], -y[0]}; };
    odestep::rk4<state2> stepper;
    state2 a{1.0, 0.0};
    state2 b = a;
    const auto r = odestep::integrate(stepper, sho, a, 0.0, 2.0, 0.25);
    REQUIRE(r.status == odestep::status::ok);
    for (int i = 0; i < 8; ++i) REQUIRE(stepper.step(sho, b, 0.25 * i, 0.25) == odestep::status::ok);
    CHECK(same_bits(a, b));
}

TEST_CASE("integrate_n_steps: takes exactly n steps of dt and reports t0 + n dt") {
    odestep::euler<state1> stepper;
    state1 y{1.0};
    recorder seen;
    const auto r = odestep::integrate_n_steps(stepper, growth{}, y, 2.0, 0.5, 4, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 4);
    CHECK(r.t == 4.0);
    CHECK(seen.calls == 5);
    CHECK(y[0] == 1.5 * 1.5 * 1.5 * 1.5);  // exact in binary
}

TEST_CASE("integrate: an empty interval is zero steps, and the observer sees the initial state once") {
    odestep::rk4<state1> stepper;
    state1 y{3.0};
    recorder seen;
    const auto r = odestep::integrate(stepper, growth{}, y, 5.0, 5.0, 0.1, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 0);
    CHECK(r.t == 5.0);
    CHECK(seen.calls == 1);
    CHECK(y[0] == 3.0);
}

TEST_CASE("integrate: every bad argument returns its status before anything is touched") {
    struct bad_case {
        const char* what;
        double t0, t1, dt;
        odestep::status expected;
    };
    const bad_case cases[] = {
        {"dt zero", 0.0, 1.0, 0.0, odestep::status::invalid_step},
        {"dt NaN", 0.0, 1.0, qnan, odestep::status::invalid_step},
        {"dt +Inf", 0.0, 1.0, inf, odestep::status::invalid_step},
        {"dt -Inf", 0.0, 1.0, -inf, odestep::status::invalid_step},
        {"dt zero, empty interval", 1.0, 1.0, 0.0, odestep::status::invalid_step},
        {"dt away from t1 (forward)", 0.0, 1.0, -0.1, odestep::status::wrong_direction},
        {"dt away from t1 (backward)", 1.0, 0.0, 0.1, odestep::status::wrong_direction},
        {"t0 NaN", qnan, 1.0, 0.1, odestep::status::invalid_time},
        {"t0 -Inf", -inf, 1.0, 0.1, odestep::status::invalid_time},
        {"t1 NaN", 0.0, qnan, 0.1, odestep::status::invalid_time},
        {"t1 +Inf", 0.0, inf, 0.1, odestep::status::invalid_time},
        {"t1 - t0 overflows", -1e308, 1e308, 1e300, odestep::status::invalid_time},
        {"more steps than the counter holds", 0.0, 1e30, 1e-30, odestep::status::too_many_steps},
        {"dt so small the quotient is Inf", 0.0, 1e300, 1e-300, odestep::status::too_many_steps},
    };
    for (const auto& c : cases) {
        INFO(c.what);
        odestep::rk4<state1> stepper;
        state1 y{0.5};
        recorder seen;
        const auto r = odestep::integrate(stepper, growth{}, y, c.t0, c.t1, c.dt, seen);
        CHECK(r.status == c.expected);
        CHECK(r.steps == 0);
        CHECK(seen.calls == 0);  // nothing observed
        CHECK(y[0] == 0.5);      // nothing touched
    }
}

TEST_CASE("integrate_n_steps: bad t0 and dt return their status before anything is touched") {
    const double bad_dt[] = {0.0, qnan, inf, -inf};
    for (double dt : bad_dt) {
        odestep::rk4<state1> stepper;
        state1 y{0.5};
        recorder seen;
        const auto r = odestep::integrate_n_steps(stepper, growth{}, y, 0.0, dt, 10, seen);
        CHECK(r.status == odestep::status::invalid_step);
        CHECK(seen.calls == 0);
        CHECK(y[0] == 0.5);
    }
    odestep::rk4<state1> stepper;
    state1 y{0.5};
    const auto r = odestep::integrate_n_steps(stepper, growth{}, y, qnan, 0.1, 10);
    CHECK(r.status == odestep::status::invalid_time);
    CHECK(y[0] == 0.5);
}

TEST_CASE(
    "integrate: dt against t1 is wrong_direction even when (t1 - t0) / dt underflows to -0, nothing observed or "
    "touched") {
    // -1e-300 / 1e300 underflows to -0, which is not < 0: the run once went one "last step" of t1 - t0 against
    // dt's sign, with status ok.
    struct bad_case {
        double t0, t1, dt;
    };
    for (const bad_case c : {bad_case{0.0, -1e-300, 1e300}, bad_case{0.0, 1e-300, -1e300}}) {
        INFO("t1 ", c.t1, ", dt ", c.dt);
        std::size_t calls = 0;
        auto f = [&calls](double, const state1& y) {
            ++calls;
            return y;
        };
        state1 y{0.5};
        recorder seen;
        const auto r = odestep::integrate(odestep::rk4<state1>{}, f, y, c.t0, c.t1, c.dt, seen);
        CHECK(r.status == odestep::status::wrong_direction);
        CHECK(r.steps == 0);
        CHECK(seen.calls == 0);
        CHECK(calls == 0);
        CHECK(y[0] == 0.5);
        // Newton's equations take the same loop.
        state1 x{0.25};
        state1 v{0.75};
        const auto rn = odestep::integrate(
            odestep::velocity_verlet<state1>{}, [](double, const state1& p) { return p; }, x, v, c.t0, c.t1, c.dt,
            [&seen](double, const state1&, const state1&) { ++seen.calls; });
        CHECK(rn.status == odestep::status::wrong_direction);
        CHECK(seen.calls == 0);
        CHECK(x[0] == 0.25);
        CHECK(v[0] == 0.75);
    }
}

TEST_CASE("integrate_n_steps: a run whose last time t0 + n dt overflows is invalid_time, nothing observed or touched") {
    // t0 + n dt past the largest double once ran on with status ok, r.t = -Inf, and f and the observer called
    // at t = -Inf; integrate refuses the same run with invalid_time.
    const double big = std::numeric_limits<double>::max();
    struct bad_case {
        double t0, dt;
        odestep::step_count n;
    };
    for (const bad_case c : {bad_case{big, -big, 3}, bad_case{0.0, big, 2}, bad_case{-big, -1e300, 1}}) {
        INFO("t0 ", c.t0, ", dt ", c.dt, ", n ", c.n);
        std::size_t calls = 0;
        auto f = [&calls](double, const state1& y) {
            ++calls;
            return y;
        };
        state1 y{0.5};
        recorder seen;
        const auto r = odestep::integrate_n_steps(odestep::rk4<state1>{}, f, y, c.t0, c.dt, c.n, seen);
        CHECK(r.status == odestep::status::invalid_time);
        CHECK(r.steps == 0);
        CHECK(seen.calls == 0);
        CHECK(calls == 0);
        CHECK(y[0] == 0.5);
        state1 x{0.25};
        state1 v{0.75};
        const auto rn = odestep::integrate_n_steps(
            odestep::velocity_verlet<state1>{}, [](double, const state1& p) { return p; }, x, v, c.t0, c.dt, c.n,
            [&seen](double, const state1&, const state1&) { ++seen.calls; });
        CHECK(rn.status == odestep::status::invalid_time);
        CHECK(seen.calls == 0);
        CHECK(x[0] == 0.25);
        CHECK(v[0] == 0.75);
    }
}

TEST_CASE("integrate: a run near the largest double stops at t1, with every time finite and on the grid") {
    // From 0.5 max to 0.8 max in steps of 0.1 max: 3 steps. The grid's rounding allowance, written
    // 2 eps (|t0| + |t1|), overflowed to Inf there, and the plan counted grid times past t1: f and the observer
    // were called at t = Inf, and the observer saw 7 steps, the times going up to Inf and back to t1.
    const double big = std::numeric_limits<double>::max();
    const double t0 = 0.5 * big;
    const double t1 = 0.8 * big;
    const double dt = 0.1 * big;
    bool f_finite_times = true;
    auto f = [&f_finite_times](double t, const state1&) {
        f_finite_times = f_finite_times && std::isfinite(t);
        return state1{0.0};
    };
    state1 y{0.5};
    recorder seen;
    const auto r = odestep::integrate(odestep::rk4<state1>{}, f, y, t0, t1, dt, seen);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 3);
    CHECK(r.t == t1);
    CHECK(f_finite_times);
    REQUIRE(seen.calls == 4);
    for (std::size_t i = 0; i < 3; ++i) CHECK(seen.t[i] == t0 + static_cast<double>(i) * dt);  // t0 + i dt
    CHECK(seen.t[3] == t1);
    CHECK(y[0] == 0.5);
}

TEST_CASE("integrate: with dt below the grid's rounding the observer times still rise to t1, never past it and back") {
    // float, t0 = 0.99609375, dt = 1e-7 (1.7 ULPs there), t1 = t0 + 40 ULPs: the grid's rounding,
    // 2 eps (|t0| + |t1|), is 4 ULPs, so grid times up to 4 ULPs past t1 "reach" it. The run once observed
    // grid times past t1 and then t1 itself, going back (fuzzing found it). Every time must be a grid time
    // t0 + i dt, the last one t1, in order along dt; no step longer than dt plus the grid's rounding.
    using statef = std::array<float, 1>;
    const float t0 = 0.99609375f;
    const float t1 = 0.99609613418579102f;
    const float dt = 1e-7f;
    struct times {
        std::array<float, 64> t{};
        std::size_t n = 0;
        void operator()(float time, const statef&) {
            if (n < t.size()) t[n] = time;
            ++n;
        }
    };
    times seen;
    statef y{1.0f};
    const auto r = odestep::integrate(
        odestep::euler<statef>{}, [](float, const statef&) { return statef{0.0f}; }, y, t0, t1, dt, std::ref(seen));
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.t == t1);
    REQUIRE(seen.n == r.steps + 1);
    REQUIRE(seen.n <= seen.t.size());
    const float rounding = 2.0f * std::numeric_limits<float>::epsilon() * (t0 + t1);
    for (std::size_t i = 0; i + 1 < seen.n; ++i) {
        INFO("observation ", i);
        CHECK(seen.t[i] == t0 + static_cast<float>(i) * dt);  // on the grid
        CHECK(seen.t[i] < t1);                                // before t1: the last step goes forward
        if (i > 0) CHECK(seen.t[i] >= seen.t[i - 1]);
        CHECK(seen.t[i + 1] - seen.t[i] <= dt + rounding);
    }
    CHECK(seen.t[seen.n - 1] == t1);
}

TEST_CASE("integrate: a NaN or Inf from the right-hand side rolls the step back to the last good state") {
    for (const double poison : {qnan, inf, -inf}) {
        INFO("poison ", poison);
        // y' = y until t = 0.5, then the right-hand side returns poison
        auto f = [poison](double t, const state1& y) { return state1{t < 0.5 - 1e-12 ? y[0] : poison}; };
        odestep::rk4<state1> stepper;
        state1 y{1.0};
        recorder seen;
        const auto r = odestep::integrate(stepper, f, y, 0.0, 1.0, 0.125, seen);
        CHECK(r.status == odestep::status::non_finite);
        // steps from 0, 0.125, 0.25 complete; the step from 0.375 evaluates at 0.4375 and 0.5 and fails
        CHECK(r.steps == 3);
        CHECK(r.t == 0.375);
        // y is exactly the state after three good steps, as a separate run computes it
        state1 expected{1.0};
        const auto r3 = odestep::integrate_n_steps(stepper, growth{}, expected, 0.0, 0.125, 3);
        REQUIRE(r3.status == odestep::status::ok);
        CHECK(same_bits(y, expected));
        CHECK(seen.calls == 4);  // initial state and three steps, no poisoned state
    }
}

TEST_CASE("integrate: a state that overflows to Inf is rolled back, the caller keeps the finite one") {
    // y' = y^2, y(0) = 1 blows up at t = 1; with Euler and h = 0.25 the iterates grow doubly exponentially
    // and overflow double within a dozen steps, long before t1 = 0.99.
    auto f = [](double, const state1& y) { return state1{y[0] * y[0]}; };
    odestep::euler<state1> stepper;
    state1 y{1e100};
    const auto r = odestep::integrate(stepper, f, y, 0.0, 10.0, 0.25);
    CHECK(r.status == odestep::status::non_finite);
    CHECK(std::isfinite(y[0]));
    CHECK(y[0] > 1e150);  // the last good state is the large finite one
    CHECK(r.t == 0.25 * static_cast<double>(r.steps));
}

TEST_CASE("integrate: a huge but finite state whose components sum past the double range is not rejected") {
    // The finiteness test sums the components first; an overflowing sum must fall back to the exact test.
    using state2 = std::array<double, 2>;
    auto still = [](double, const state2&) { return state2{0.0, 0.0}; };
    odestep::rk4<state2> stepper;
    state2 y{1.5e308, 1.5e308};
    const auto r = odestep::integrate(stepper, still, y, 0.0, 1.0, 0.5);
    CHECK(r.status == odestep::status::ok);
    CHECK(y[0] == 1.5e308);
}

TEST_CASE(
    "integrate: a float run over [0, 1000] at dt = 0.001f takes 10^6 steps, the observer sees 10^6 + 1 "
    "states and no step is longer than dt, with events as without") {
    // float(0.001) is 0.0010000000474974513, so 1000 / dt is 999999.95: the old count (a slack of 16 eps times
    // the quotient) took 999 999 steps and made the last one 2 dt long.
    using statef = std::array<float, 1>;
    auto one = [](float, const statef&) { return statef{1.0f}; };
    struct watcher {
        std::size_t states = 0;
        float last_t = 0.0f;
        float longest = 0.0f;
        void operator()(float t, const statef&) {
            if (states > 0 && t - last_t > longest) longest = t - last_t;
            last_t = t;
            ++states;
        }
    };
    {
        statef y{0.0f};
        watcher w;
        const auto r = odestep::integrate(odestep::euler<statef>{}, one, y, 0.0f, 1000.0f, 0.001f, std::ref(w));
        CHECK(r.status == odestep::status::ok);
        CHECK(r.steps == 1000000);
        CHECK(w.states == 1000001);
        CHECK(w.last_t == 1000.0f);
        CHECK(w.longest <= 0.001f + 2.0f * 6.103515625e-05f);  // dt plus the rounding of two times near 1000
    }
    {
        statef y{0.0f};
        watcher w;
        auto never = odestep::make_event<statef>([](float, const statef& s) { return s[0] + 1.0f; },
                                                 odestep::direction::falling, odestep::record);
        const auto r = odestep::integrate(odestep::euler<statef>{}, one, y, 0.0f, 1000.0f, 0.001f,
                                          odestep::watch(never), std::ref(w));
        CHECK(r.status == odestep::status::ok);
        CHECK(r.steps == 1000000);
        CHECK(w.states == 1000001);
        CHECK(w.longest <= 0.001f + 2.0f * 6.103515625e-05f);
    }
}
