// SPDX-License-Identifier: BSL-1.0
// The C API's loops ask the library's one pre-run check (detail::preflight) with the method's uniform_steps,
// which only the C method table knows: a uniform-step method (Adams-Bashforth 4) over a span that is not a
// whole number of steps, and the grid's bad arguments, are refused before f is evaluated or the observer
// called. Expected statuses: odestep.h's documentation of odestep_integrate_d (step_mismatch for a shortened
// last step of a uniform-step method; invalid_step, invalid_time, wrong_direction for a bad grid).
// Compiled with ODESTEP_C_EXACT_STATES 2, as tests/capi/single_step_test.cpp (methods.hpp).
#include "methods.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <limits>

namespace {

namespace capi = odestep::capi;

using capi_test::ab4_method;
using capi_test::verlet_method;

struct counts {
    std::size_t f = 0;
    std::size_t observed = 0;
};

void decay(double, const double* y, double* d, void* ctx) {
    ++static_cast<counts*>(ctx)->f;
    d[0] = -y[0];
}
void spring(double, const double* x, double* a, void* ctx) {
    ++static_cast<counts*>(ctx)->f;
    a[0] = -x[0];
}
void watch(double, const double*, void* ctx) { ++static_cast<counts*>(ctx)->observed; }
void watch_xv(double, const double*, const double*, void* ctx) { ++static_cast<counts*>(ctx)->observed; }

}  // namespace

TEST_CASE("C API preflight: a uniform-step method's shortened last step is refused before f or the observer runs") {
    counts n;
    const odestep_system_d sys{decay, &n, 1};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &ab4_method) == ODESTEP_OK);
    double y[1] = {1.0};
    odestep_run_d run{};
    CHECK(capi::integrate<double>(&s, &sys, y, 0.0, 1.0, 0.3, watch, &n, &run) == ODESTEP_STEP_MISMATCH);
    CHECK(y[0] == 1.0);
    CHECK(run.t == 0.0);
    CHECK(run.steps == 0);
    CHECK(n.f == 0);
    CHECK(n.observed == 0);
    // The grid's own bad arguments, through the same check.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(capi::integrate<double>(&s, &sys, y, 0.0, 1.0, 0.0, watch, &n, &run) == ODESTEP_INVALID_STEP);
    CHECK(capi::integrate<double>(&s, &sys, y, 0.0, nan, 0.25, watch, &n, &run) == ODESTEP_INVALID_TIME);
    CHECK(capi::integrate<double>(&s, &sys, y, 0.0, 1.0, -0.25, watch, &n, &run) == ODESTEP_WRONG_DIRECTION);
    CHECK(n.f == 0);
    CHECK(n.observed == 0);
    // A whole number of steps runs (the check refuses only what it should): 4 steps observed, and 5 in all.
    CHECK(capi::integrate<double>(&s, &sys, y, 0.0, 1.0, 0.25, watch, &n, &run) == ODESTEP_OK);
    CHECK(n.observed == 5);
}

TEST_CASE("C API preflight: Newton's loop refuses a bad grid before a or the observer runs") {
    counts n;
    const odestep_newton_d sys{spring, &n, 1};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &verlet_method) == ODESTEP_OK);
    double x[1] = {1.0};
    double v[1] = {0.0};
    CHECK(capi::integrate_newton<double>(&s, &sys, x, v, 0.0, 1.0, 0.0, watch_xv, &n, nullptr) == ODESTEP_INVALID_STEP);
    CHECK(capi::integrate_newton<double>(&s, &sys, x, v, std::numeric_limits<double>::infinity(), 1.0, 0.1, watch_xv,
                                         &n, nullptr) == ODESTEP_INVALID_TIME);
    CHECK(x[0] == 1.0);
    CHECK(v[0] == 0.0);
    CHECK(n.f == 0);
    CHECK(n.observed == 0);
}
