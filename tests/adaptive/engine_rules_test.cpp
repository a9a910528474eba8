// SPDX-License-Identifier: BSL-1.0
// The adaptive engine's rules as other libraries' test suites probed them (issue 25): max_step bounds every
// step, the last one included; f is never called again after it returned NaN or Inf; an empty run (t0 == t1)
// is what integrate() makes of it.
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>
#include <odestep/integrate.hpp>
#include <odestep/rk/explicit_rk.hpp>
#include <odestep/stiff/integrate.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/counting.hpp"

namespace {

using odestep::status;
using state1 = std::array<double, 1>;
using state3 = std::array<double, 3>;

// y' = 0: every error estimate is zero, so the controller grows the step as far as it is allowed; only
// max_step and the interval limit it.
struct still {
    void operator()(double, const state1&, state1& d) const noexcept { d[0] = 0.0; }
};

struct lorenz {
    void operator()(double, const state3& x, state3& d) const noexcept {
        d[0] = 10.0 * (x[1] - x[0]);
        d[1] = x[0] * (28.0 - x[2]) - x[1];
        d[2] = x[0] * x[1] - 8.0 / 3.0 * x[2];
    }
};

// The accepted steps' sizes, as the engine's accept sink sees them (the h each step was taken with).
struct step_sizes {
    double largest = 0.0;
    std::size_t count = 0;
    template <class State, class Stages>
    void operator()(double, const State&, double h, const Stages&, const State&) {
        largest = std::fabs(h) > largest ? std::fabs(h) : largest;
        ++count;
    }
};

// Runs engine.attempt to t1 as integrate_adaptive does, with the sink.
template <class Engine, class F, class State>
status run_with_sink(Engine& e, F& f, State& y, double t0, double t1, step_sizes& sizes) {
    double t = t0;
    for (int n = 0; n < 100000 && t != t1; ++n) {
        bool accepted = false;
        const status s = e.attempt(f, t, y, t1, accepted, sizes);
        if (s != status::ok) return s;
    }
    return t == t1 ? status::ok : status::substep_limit;
}

}  // namespace

TEST_CASE("max_step: no step is longer, the last one included (span 1.005, max_step 1)") {
    // Issue 25 (SciPy's and Odeint's max_step): the rule that lands a step on t1 when the end is within 1%
    // stretched the step past max_step (one step of 1.005). At least ceil(1.005 / 1) = 2 steps are needed.
    odestep::step_control<double> c;
    c.max_step = 1.0;
    const auto tol = odestep::tolerances<state1>::uniform(1e-6, 1e-6);
    still f;
    // Every engine starts with a step of max_step (set_step_size), so the first step is 1 and the end is
    // within 1% of it.
    {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e(tol, c);
        e.set_step_size(1.0);
        state1 y{1.0};
        step_sizes sizes;
        REQUIRE(run_with_sink(e, f, y, 0.0, 1.005, sizes) == status::ok);
        CHECK(sizes.largest <= 1.0);
        CHECK(sizes.count >= 2);
    }
    {  // integrate_adaptive: the observed times are 0, the steps' ends, 1.005
        odestep::adaptive_rk<odestep::tables::cash_karp54, state1> e(tol, c);
        e.set_step_size(1.0);
        state1 y{1.0};
        double last = 0.0;
        double largest = 0.0;
        const auto r = odestep::integrate_adaptive(e, f, y, 0.0, 1.005, [&](double t, const state1&) {
            largest = t - last > largest ? t - last : largest;
            last = t;
        });
        CHECK(r.status == status::ok);
        CHECK(r.t == 1.005);
        CHECK(r.steps >= 2);
        CHECK(largest <= 1.0);
    }
    {  // integrate_times: the same steps
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e(tol, c);
        e.set_step_size(1.0);
        state1 y{1.0};
        const std::array<double, 2> times{0.5, 1.005};
        const auto r = odestep::integrate_times(e, f, y, 0.0, times, [](double, const state1&) {});
        CHECK(r.status == status::ok);
        CHECK(r.steps >= 2);
    }
    {  // adaptive_substeps: one interval of 1.005 needs two internal steps
        odestep::adaptive_substeps<odestep::tables::dormand_prince54, state1> s(tol, c);
        s.engine().set_step_size(1.0);
        state1 y{1.0};
        CHECK(s.step(f, y, 0.0, 1.005) == status::ok);
        CHECK(s.engine().accepted_steps() >= 2);
    }
    {  // backwards: the same bound on |h|
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e(tol, c);
        e.set_step_size(1.0);
        state1 y{1.0};
        step_sizes sizes;
        REQUIRE(run_with_sink(e, f, y, 0.0, -1.005, sizes) == status::ok);
        CHECK(sizes.largest <= 1.0);
        CHECK(sizes.count >= 2);
    }
}

TEST_CASE("max_step: Lorenz with max_step 0.01 never takes a step longer than 0.01") {
    // Issue 25: the run's last step was 0.010000000000168541 (the rounded remainder within 1% of the end). At
    // tol 1e-4 every step is max_step (the tolerance alone would allow longer ones) from y(0) = (-8, 8, 27).
    odestep::step_control<double> c;
    c.max_step = 0.01;
    const auto tol = odestep::tolerances<state3>::uniform(1e-4, 1e-4);
    lorenz f;
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state3> e(tol, c);
    state3 y{-8.0, 8.0, 27.0};
    step_sizes sizes;
    REQUIRE(run_with_sink(e, f, y, 0.0, 10.0, sizes) == status::ok);
    CHECK(sizes.largest <= 0.01);
    CHECK(sizes.count >= 1000);
    // The same through integrate_adaptive's observed times: the differences of consecutive times are the steps
    // to the rounding of t (a few 1e-15 near t = 10; the defect was 1.7e-13).
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state3> e2(tol, c);
    state3 y2{-8.0, 8.0, 27.0};
    double last = 0.0;
    double largest = 0.0;
    const auto r = odestep::integrate_adaptive(e2, f, y2, 0.0, 10.0, [&](double t, const state3&) {
        largest = t - last > largest ? t - last : largest;
        last = t;
    });
    CHECK(r.status == status::ok);
    CHECK(largest <= 0.01 + 4 * std::numeric_limits<double>::epsilon() * 10.0);
}

namespace {

// y' = -y until t = 1.5, NaN past it (a table lookup out of range, a model that traps): counts its calls
// after the first one that returned NaN. GSL's drivers return at the first failing call.
struct fails_past {
    std::size_t* calls_after_nan;
    bool* failed;
    void operator()(double t, const state1& y, state1& d) const noexcept {
        if (*failed) ++*calls_after_nan;
        if (t > 1.5) {
            d[0] = std::numeric_limits<double>::quiet_NaN();
            *failed = true;
        } else {
            d[0] = -y[0];
        }
    }
};

template <class Method>
void no_call_after_nan() {
    const auto tol = odestep::tolerances<state1>::uniform(1e-8, 1e-8);
    {  // integrate_adaptive
        std::size_t after = 0;
        bool failed = false;
        fails_past f{&after, &failed};
        odestep::adaptive_rk<Method, state1> e(tol);
        state1 y{1.0};
        const auto r = odestep::integrate_adaptive(e, f, y, 0.0, 3.0);
        CHECK(r.status == status::non_finite);
        CHECK(failed);
        CHECK(after == 0);
        CHECK(r.t <= 1.5);
        CHECK(std::fabs(y[0] - std::exp(-r.t)) < 1e-6);  // the last accepted state, at r.t
    }
    {  // integrate_times (DOP853 completes its interpolant with three more stages)
        std::size_t after = 0;
        bool failed = false;
        fails_past f{&after, &failed};
        odestep::adaptive_rk<Method, state1> e(tol);
        state1 y{1.0};
        const std::array<double, 4> times{0.5, 1.0, 1.45, 3.0};
        const auto r = odestep::integrate_times(e, f, y, 0.0, times, [](double, const state1&) {});
        CHECK(r.status == status::non_finite);
        CHECK(after == 0);
    }
    {  // adaptive_substeps under integrate
        std::size_t after = 0;
        bool failed = false;
        fails_past f{&after, &failed};
        odestep::adaptive_substeps<Method, state1> s(tol);
        state1 y{1.0};
        const auto r = odestep::integrate(s, f, y, 0.0, 3.0, 0.25);
        CHECK(r.status == status::non_finite);
        CHECK(r.t == 1.5);
        CHECK(after == 0);
    }
}

}  // namespace

TEST_CASE("non-finite f: no call of f after the first NaN, in every pair and loop") {
    // Issue 25: DP 5(4) called f 5 more times, with NaN states, after its first NaN (the rest of the step).
    no_call_after_nan<odestep::tables::bogacki_shampine32>();
    no_call_after_nan<odestep::tables::fehlberg45>();
    no_call_after_nan<odestep::tables::cash_karp54>();
    no_call_after_nan<odestep::tables::dormand_prince54>();
    no_call_after_nan<odestep::tables::fehlberg78>();
    no_call_after_nan<odestep::tables::dop853>();
}

namespace {

// What a run with no step makes of its initial state: status, observations, evaluations.
struct empty_outcome {
    status s;
    std::size_t observed;
    std::size_t calls;
    bool y_is_nan;
};

struct decay1 {
    void operator()(double, const state1& y, state1& d) const noexcept { d[0] = -y[0]; }
};

}  // namespace

TEST_CASE("an empty run (t0 == t1) with a NaN y0: the adaptive loops do what integrate() does") {
    // The reference is integrate() itself (include/odestep/integrate.hpp: run_grid over a plan of zero steps,
    // the empty-run rule of docs/reference.md): non_finite, y0 observed once at t0, nothing evaluated, y0
    // untouched. So ok always means a finite state.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto run = [&](auto&& call) {
        std::size_t calls = 0;
        std::size_t observed = 0;
        odestep_test::counting<decay1> f{decay1{}, &calls};
        state1 y{nan};
        const auto observe = [&](double t, const state1&) {
            CHECK(t == 2.0);
            ++observed;
        };
        const status s = call(f, y, observe);
        return empty_outcome{s, observed, calls, std::isnan(y[0])};
    };
    const empty_outcome grid = run([](auto& f, state1& y, const auto& observe) {
        return odestep::integrate(odestep::rk4<state1>{}, f, y, 2.0, 2.0, 0.1, observe).status;
    });
    CHECK(grid.s == status::non_finite);
    CHECK(grid.observed == 1);
    CHECK(grid.calls == 0);
    CHECK(grid.y_is_nan);
    const empty_outcome substeps = run([](auto& f, state1& y, const auto& observe) {
        odestep::dormand_prince54_substeps<state1> s;
        return odestep::integrate(s, f, y, 2.0, 2.0, 0.1, observe).status;
    });
    const empty_outcome adaptive = run([](auto& f, state1& y, const auto& observe) {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e;
        return odestep::integrate_adaptive(e, f, y, 2.0, 2.0, observe).status;
    });
    const empty_outcome times = run([](auto& f, state1& y, const auto& observe) {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e;
        const std::array<double, 1> at{2.0};
        return odestep::integrate_times(e, f, y, 2.0, at, observe).status;
    });
    const empty_outcome radau = run([](auto& f, state1& y, const auto& observe) {
        odestep::radau5<state1> e;
        return odestep::integrate_adaptive(e, f, y, 2.0, 2.0, observe).status;
    });
    const empty_outcome radau_times = run([](auto& f, state1& y, const auto& observe) {
        odestep::radau5<state1> e;
        const std::array<double, 1> at{2.0};
        return odestep::integrate_times(e, f, y, 2.0, at, observe).status;
    });
    for (const empty_outcome& o : {substeps, adaptive, times, radau, radau_times}) {
        CHECK(o.s == grid.s);
        CHECK(o.observed == grid.observed);
        CHECK(o.calls == grid.calls);
        CHECK(o.y_is_nan == grid.y_is_nan);
    }
    // The solution object and the sampler: the same rule (nothing stored past y0, nothing handed out).
    {
        state1 y{nan};
        static odestep::solution<odestep::tables::dormand_prince54, state1, 4> sol;
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> e;
        CHECK(odestep::integrate_adaptive(e, decay1{}, y, 2.0, 2.0, sol).status == status::non_finite);
        odestep::adaptive_sampler<odestep::tables::dormand_prince54, state1> run_at(e, 2.0, y, 2.0);
        state1 u{7.0};
        CHECK(run_at.advance_to(decay1{}, 2.0, u) == status::non_finite);
        CHECK(u[0] == 7.0);
    }
    // A step is not a run: adaptive_substeps::step over an interval that rounding empties (t + dt == t, dt not
    // zero) reports non_finite for a NaN y, as a step that evaluates f at y does (rk4's step with that dt;
    // tests/adaptive/limits_test.cpp has the finite case).
    std::size_t calls = 0;
    odestep_test::counting<decay1> f{decay1{}, &calls};
    state1 y{nan};
    odestep::dormand_prince54_substeps<state1> s;
    CHECK(s.step(f, y, 1e20, 1.0) == status::non_finite);
    state1 y_rk4{nan};
    CHECK(odestep::rk4<state1>{}.step(f, y_rk4, 1e20, 1.0) == status::non_finite);
}
