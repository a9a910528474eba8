// SPDX-License-Identifier: BSL-1.0
// The property the event loop publishes (issue 19): every call returns within the published bound of
// evaluations, whatever the event functions return. Right-hand-side and event-function calls are counted
// (tests/support/counting.hpp) for each tick (max_rhs_evals_per_tick, max_g_evals_per_tick) and for whole
// runs of integrate (at most the per-step bounds times the steps, plus the evaluations at t0), over a set of
// adversarial event functions: impure ones (a sensor's one glitch, a sign that flips on every read, a
// pseudo-random one), NaN at unpredictable reads, storms of crossings far denser than the step, a timer
// whose root falls between t_s + dt and the grid time, and chattering actions; with several limits and
// steppers (one step, a multistep history, an embedded pair).
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

// The adversaries. Each reads and writes its own counter (the property must hold for g that is not a pure
// function of (t, y)); `kind` picks one.
struct adversary {
    unsigned kind = 0;
    std::size_t* reads = nullptr;
    std::uint32_t* seed = nullptr;
    const std::size_t* watchdog = nullptr;  // past this many reads NaN: a call that would hang ends (and fails)

    double random() const {  // a 32-bit linear congruential generator (Numerical Recipes' constants)
        *seed = *seed * 1664525u + 1013904223u;
        return static_cast<double>(*seed) / 4294967296.0;  // [0, 1)
    }
    double operator()(double t, const state1& y) const {
        const std::size_t n = ++*reads;
        if (n > *watchdog) return std::numeric_limits<double>::quiet_NaN();
        switch (kind) {
            case 0: return n == 7 ? 1.0 : -1.0;      // one glitch, positive
            case 1: return n % 2 == 0 ? 1.0 : -1.0;  // flips on every read
            case 2: return random() - 0.5;           // noise
            case 3:
                return random() < 0.05 ? std::numeric_limits<double>::quiet_NaN() : y[0] - 0.55;  // NaN now and then
            case 4: return std::sin(1e4 * t);               // a storm: 1600 roots per step
            case 5: return t - std::nextafter(-0.5, -1.0);  // the timer of defect 1
            case 6: return y[0] - 0.55;                     // a plain level (actions chatter)
            default: return random() < 0.5 ? 0.0 : -0.0;    // zeros of both signs
        }
    }
};

struct clock_rhs {  // y' = 1
    state1 operator()(double, const state1&) const { return {1.0}; }
};

// The actions: put the state back just below the level (chatter), a jump, a stop, record.
struct chatter {
    void operator()(double, state1& y) const { y[0] = 0.55 - 1e-12; }
};
struct jump {
    void operator()(double, state1& y) const { y[0] += 0.25; }
};

template <class Stepper, class Set>
void check_ticks(const Set& set, std::size_t& rhs_calls, std::size_t& g_calls, std::size_t& watchdog) {
    constexpr std::size_t E = Set::size;
    const std::size_t rhs_bound = odestep::max_rhs_evals_per_tick<Stepper>(E, set.limits);
    const std::size_t g_bound = odestep::max_g_evals_per_tick<double>(E, set.limits);
    watchdog = g_bound + 1;
    auto loop = odestep::make_event_stepper(Stepper{}, set);
    state1 y{0.0};
    g_calls = 0;
    if (loop.start(-3.3, 0.7, y) != odestep::status::ok) return;  // NaN at t0 (kind 3): nothing to tick
    CHECK(g_calls <= E);
    const auto f = odestep_test::counted(clock_rhs{}, &rhs_calls);
    for (int n = 0; n < 12; ++n) {
        rhs_calls = 0;
        g_calls = 0;
        const auto r = loop.tick(f, y);
        CHECK(rhs_calls <= rhs_bound);
        CHECK(g_calls <= g_bound);
        CHECK(r.fired <= 2 * set.limits.max_firings_per_step);
        if (r.status == odestep::status::non_finite_event || r.status == odestep::status::non_finite)
            CHECK(std::isfinite(y[0]));  // the last good state
    }
}

template <class Stepper, class Set>
void check_run(Set set, std::size_t& rhs_calls, std::size_t& g_calls, std::size_t& watchdog) {
    constexpr std::size_t E = Set::size;
    const std::size_t rhs_bound = odestep::max_rhs_evals_per_step<Stepper>(E, set.limits);
    const std::size_t g_bound = odestep::max_g_evals_per_step<double>(E, set.limits);
    watchdog = 13 * g_bound + E + 1;  // 12 steps and t0
    state1 y{0.0};
    rhs_calls = 0;
    g_calls = 0;
    std::size_t rhs_then = 0;
    std::size_t g_then = 0;
    bool first = true;
    // Per step: the evaluations between two observations (the first observation is at t0, after g at t0).
    auto observe = [&](double, const state1&) {
        if (!first) {
            CHECK(rhs_calls - rhs_then <= rhs_bound);
            CHECK(g_calls - g_then <= g_bound);
        }
        first = false;
        rhs_then = rhs_calls;
        g_then = g_calls;
    };
    const auto f = odestep_test::counted(clock_rhs{}, &rhs_calls);
    const auto r = odestep::integrate(Stepper{}, f, y, -3.3, -3.3 + 12 * 0.7, 0.7, set, observe);
    // and the last step, which ended the run without an observation if it was not ok
    CHECK(rhs_calls - rhs_then <= rhs_bound);
    CHECK(g_calls - g_then <= g_bound);
    CHECK(r.steps <= 12);
}

template <class Stepper>
void check_all() {
    const odestep::event_limits limit_sets[] = {{}, {3, 2, 1}, {0, 1, 0}, {0, 0, 0}, {5, 4, 3}};
    for (unsigned kind = 0; kind < 8; ++kind) {
        for (const auto& limits : limit_sets) {
            CAPTURE(kind);
            CAPTURE(limits.max_iterations);
            CAPTURE(limits.max_firings_per_step);
            CAPTURE(limits.probes);
            std::size_t rhs_calls = 0;
            std::size_t g_calls = 0;
            std::uint32_t seed = 12345u + kind;
            std::size_t watchdog = 0;
            const adversary g{kind, &g_calls, &seed, &watchdog};
            const auto e_chatter = odestep::make_event<state1>(g, odestep::direction::either, chatter{});
            const auto e_jump = odestep::make_event<state1>(g, odestep::direction::rising, jump{});
            const auto e_stop = odestep::make_event<state1>(g, odestep::direction::falling);
            const auto e_record = odestep::make_event<state1>(g, odestep::direction::either, odestep::record);
            const auto wide = e_jump.with_tolerance(1e154).with_band(0.5).with_max_firings(2);
            check_ticks<Stepper>(odestep::watch(e_chatter).with_limits(limits), rhs_calls, g_calls, watchdog);
            check_ticks<Stepper>(odestep::watch(e_jump, e_record, e_stop).with_limits(limits), rhs_calls, g_calls,
                                 watchdog);
            check_ticks<Stepper>(odestep::watch(wide, e_chatter).with_limits(limits), rhs_calls, g_calls, watchdog);
            check_run<Stepper>(odestep::watch(e_chatter).with_limits(limits), rhs_calls, g_calls, watchdog);
            check_run<Stepper>(odestep::watch(e_jump, e_record, e_stop).with_limits(limits), rhs_calls, g_calls,
                               watchdog);
            check_run<Stepper>(odestep::watch(wide, e_record).with_limits(limits), rhs_calls, g_calls, watchdog);
        }
    }
}

}  // namespace

TEST_CASE("event bounds: every tick and every step returns within the published bound, whatever g returns") {
    check_all<odestep::rk4<state1>>();
    check_all<odestep::adams_bashforth_moulton4<state1>>();
    check_all<odestep::dormand_prince54<state1>>();
}
