// SPDX-License-Identifier: BSL-1.0
// The one pre-run check (detail/preflight.hpp): a stepper whose settings are bad (predictor_corrector with a
// NaN tolerance, adaptive_substeps with a negative one) is refused by every loop before anything is evaluated
// or observed: f (or a), the event functions and the observer all count their calls, and each must see none.
// The expected statuses are the settings' own (settings_status() documents them); the state must be the
// caller's, bit for bit.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <limits>

#include "support/counting.hpp"

namespace {

using state1 = std::array<double, 1>;
using odestep::status;
using odestep_test::counted;

// predictor_corrector with a tolerance that settings_status() refuses (invalid_tolerance).
odestep::predictor_corrector<state1> bad_corrector() {
    odestep::predictor_corrector<state1> s;
    s.tolerance = std::numeric_limits<double>::quiet_NaN();
    return s;
}

// adaptive_substeps with a negative relative tolerance (invalid_tolerance).
odestep::adaptive_substeps<odestep::tables::cash_karp54, state1> bad_substeps() {
    return odestep::adaptive_substeps<odestep::tables::cash_karp54, state1>(
        odestep::tolerances<state1>::uniform(-1e-6, 1e-9));
}

struct calls {
    std::size_t f = 0;
    std::size_t g = 0;
    std::size_t observed = 0;
    void require_none() const {
        CHECK(f == 0);
        CHECK(g == 0);
        CHECK(observed == 0);
    }
};

}  // namespace

TEST_CASE("preflight: the settings are checked by the stepper types the loops are tested with") {
    CHECK(bad_corrector().settings_status() == status::invalid_tolerance);
    CHECK(bad_substeps().settings_status() == status::invalid_tolerance);
}

TEST_CASE("preflight: integrate and integrate_n_steps refuse bad settings before the first observation") {
    calls n;
    const auto f = counted([](double, const state1& y) { return state1{-y[0]}; }, &n.f);
    const auto observe = counted([](double, const state1&) {}, &n.observed);
    state1 y{1.0};
    auto s = bad_substeps();
    const auto r = odestep::integrate(s, f, y, 0.0, 1.0, 0.1, observe);
    CHECK(r.status == status::invalid_tolerance);
    CHECK(r.t == 0.0);
    CHECK(r.steps == 0);
    CHECK(odestep::integrate_n_steps(s, f, y, 0.0, 0.1, 10, observe).status == status::invalid_tolerance);
    CHECK(y[0] == 1.0);
    n.require_none();

    // Newton's equations: predictor_corrector used to be refused only inside its first step, after the
    // initial state had been observed and a(t, x, v) evaluated.
    const auto a = counted([](double, const state1& x, const state1&) { return state1{-x[0]}; }, &n.f);
    const auto observe_xv = counted([](double, const state1&, const state1&) {}, &n.observed);
    state1 x{1.0};
    state1 v{0.0};
    auto pc = bad_corrector();
    CHECK(odestep::integrate(pc, a, x, v, 0.0, 1.0, 0.1, observe_xv).status == status::invalid_tolerance);
    CHECK(odestep::integrate_n_steps(pc, a, x, v, 0.0, 0.1, 10, observe_xv).status == status::invalid_tolerance);
    CHECK(x[0] == 1.0);
    CHECK(v[0] == 0.0);
    n.require_none();
}

TEST_CASE("preflight: the event loops refuse bad settings before an event function or f is evaluated") {
    calls n;
    const auto f = counted([](double, const state1&) { return state1{1.0}; }, &n.f);
    const auto g = counted([](double, const state1& y) { return y[0] - 0.5; }, &n.g);
    const auto observe = counted([](double, const state1&) {}, &n.observed);
    state1 y{0.0};
    const auto r =
        odestep::integrate(bad_substeps(), f, y, 0.0, 1.0, 0.25,
                           odestep::watch(odestep::make_event<state1>(g, odestep::direction::rising)), observe);
    CHECK(r.status == status::invalid_tolerance);
    CHECK(r.t == 0.0);
    CHECK(r.fired == 0);
    CHECK(y[0] == 0.0);
    n.require_none();

    const auto a = counted([](double, const state1&, const state1&) { return state1{-1.0}; }, &n.f);
    const auto height = counted([](double, const state1& x, const state1&) { return x[0]; }, &n.g);
    const auto observe_xv = counted([](double, const state1&, const state1&) {}, &n.observed);
    state1 x{1.0};
    state1 v{0.0};
    const auto rn = odestep::integrate(bad_corrector(), a, x, v, 0.0, 2.0, 0.25,
                                       odestep::watch(odestep::make_event<state1>(height, odestep::direction::falling)),
                                       observe_xv);
    CHECK(rn.status == status::invalid_tolerance);
    CHECK(x[0] == 1.0);
    CHECK(v[0] == 0.0);
    n.require_none();
}

TEST_CASE("preflight: event_stepper::start refuses bad settings before reading the event functions") {
    calls n;
    const auto height = counted([](double, const state1& x, const state1&) { return x[0]; }, &n.g);
    auto loop = odestep::make_event_stepper(
        bad_corrector(), odestep::watch(odestep::make_event<state1>(height, odestep::direction::falling)));
    const state1 x{1.0};
    const state1 v{0.0};
    CHECK(loop.start(0.0, 0.1, x, v) == status::invalid_tolerance);
    n.require_none();
    // Not started: a tick is refused as before start.
    state1 xt{1.0};
    state1 vt{0.0};
    const auto a = counted([](double, const state1& p, const state1&) { return state1{-p[0]}; }, &n.f);
    CHECK(loop.tick(a, xt, vt).status == status::invalid_time);
    n.require_none();
    // The clock is still checked first, as the grid clock checks it.
    CHECK(loop.start(0.0, 0.0, x, v) == status::invalid_step);
    CHECK(loop.start(std::numeric_limits<double>::infinity(), 0.1, x, v) == status::invalid_time);
    n.require_none();
}

TEST_CASE("preflight: the adaptive loops and the substep form refuse bad settings before f is evaluated") {
    calls n;
    const auto f = counted([](double, const state1& y) { return state1{-y[0]}; }, &n.f);
    const auto observe = counted([](double, const state1&) {}, &n.observed);
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> engine(
        odestep::tolerances<state1>::uniform(1e-6, std::numeric_limits<double>::quiet_NaN()));
    REQUIRE(engine.settings_status() == status::invalid_tolerance);
    state1 y{1.0};
    CHECK(odestep::integrate_adaptive(engine, f, y, 0.0, 1.0, observe).status == status::invalid_tolerance);
    const std::array<double, 3> times{0.25, 0.5, 1.0};
    CHECK(odestep::integrate_times(engine, f, y, 0.0, times, observe).status == status::invalid_tolerance);
    // With no times the settings are still checked first.
    const std::array<double, 0> none{};
    CHECK(odestep::integrate_times(engine, f, y, 0.0, none, observe).status == status::invalid_tolerance);
    // A good engine with a cap of no attempts: invalid_setting, nothing evaluated.
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> good;
    CHECK(odestep::integrate_adaptive(good, f, y, 0.0, 1.0, observe, 0).status == status::invalid_setting);
    CHECK(odestep::integrate_times(good, f, y, 0.0, times, observe, 0).status == status::invalid_setting);
    // The substep form's own step (one interval) checks the same settings first.
    auto s = bad_substeps();
    CHECK(s.step(f, y, 0.0, 0.1) == status::invalid_tolerance);
    CHECK(y[0] == 1.0);
    n.require_none();
}
