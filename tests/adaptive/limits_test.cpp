// SPDX-License-Identifier: BSL-1.0
// Regression tests for the three defects fuzz_adaptive found (tests/fuzz/fuzz_adaptive.cpp; the inputs are in
// tests/fuzz/corpus/fuzz_adaptive/regression-*): each fails on the code before its fix.
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/counting.hpp"

namespace {

using odestep::status;
using state1 = std::array<double, 1>;

struct decay {
    void operator()(double, const state1& y, state1& dydt) const noexcept { dydt[0] = -y[0]; }
};

}  // namespace

TEST_CASE("adaptive_substeps: an interval emptied by rounding (t + dt == t) is ok only for a finite y") {
    // t = 1e20 has an ULP of 16384: t + 1 == t. Nothing to integrate and nothing evaluated; but a NaN y was
    // reported ok before the fix, where any step that evaluates f at y reports non_finite.
    std::size_t calls = 0;
    odestep_test::counting<decay> f{decay{}, &calls};
    odestep::dormand_prince54_substeps<state1> s;
    state1 y{2.0};
    CHECK(s.step(f, y, 1e20, 1.0) == status::ok);
    CHECK(y[0] == 2.0);
    state1 bad{std::numeric_limits<double>::quiet_NaN()};
    CHECK(s.step(f, bad, 1e20, 1.0) == status::non_finite);
    CHECK(std::isnan(bad[0]));
    CHECK(calls == 0);
}

TEST_CASE("adaptive_rk: a controller factor that underflows the step keeps the published evaluation bound") {
    // min_factor and safety of the smallest double: after the first accepted step h * factor underflows to 0.
    // Before the fix the next attempt went back to the first-step estimate, one evaluation more per attempt
    // than integrate_adaptive's bound rhs_evals_to_start + max_attempts * rhs_evals_per_attempt.
    using engine_t = odestep::adaptive_rk<odestep::tables::dormand_prince54, state1>;
    odestep::step_control<double> c;
    c.safety = std::numeric_limits<double>::denorm_min();
    c.min_factor = std::numeric_limits<double>::denorm_min();
    engine_t e(odestep::tolerances<state1>::uniform(1e-6, 1e-6), c);
    REQUIRE(e.settings_status() == status::ok);
    std::size_t calls = 0;
    odestep_test::counting<decay> f{decay{}, &calls};
    state1 y{1.0};
    const odestep::step_count attempts = 5;
    const auto r = odestep::integrate_adaptive(e, f, y, 0.0, 10.0, attempts);
    CHECK(r.status == status::substep_limit);
    CHECK(r.steps == attempts);
    CHECK(calls <= engine_t::rhs_evals_to_start + attempts * engine_t::rhs_evals_per_attempt);
    CHECK(e.step_size() > 0.0);
}
