// SPDX-License-Identifier: BSL-1.0
// The adaptive engine's rules as other libraries' test suites probed them (issue 25): max_step bounds every
// step, the last one included; f is never called again after it returned NaN or Inf; an empty run (t0 == t1)
// is what integrate() makes of it.
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>
#include <odestep/integrate.hpp>

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
