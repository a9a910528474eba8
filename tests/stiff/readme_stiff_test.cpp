// SPDX-License-Identifier: BSL-1.0
// The README's stiff snippet, exactly (tests/stiff/check_readme_snippet.cmake compares the lines between the
// markers with the README's block), run from Robertson's natural start and checked against the reference.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "support/stiff_problems.hpp"

TEST_CASE("README: the stiff snippet runs Robertson from (1, 0, 0) on a 0.1 grid to 40 and says ok") {
    // README snippet begin
    // Robertson's kinetics from its natural start y = (1, 0, 0), observed on a 0.1 grid to t = 40.
    using state = std::array<double, 3>;
    auto f = [](double, const state& y) {
        return state{-0.04 * y[0] + 1e4 * y[1] * y[2], 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1],
                     3e7 * y[1] * y[1]};
    };
    auto J = [](double, const state& y, odestep::jacobian_t<state>& j) {  // optional: else forward differences
        j[0] = {-0.04, 1e4 * y[2], 1e4 * y[1]};
        j[1] = {0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]};
        j[2] = {0.0, 6e7 * y[1], 0.0};
    };
    odestep::radau5_substeps<state> stepper(odestep::tolerances<state>::uniform(1e-6, 1e-12));  // rtol, atol
    state y{1.0, 0.0, 0.0};
    auto r = odestep::integrate(stepper, odestep::with_jacobian(f, J), y, 0.0, 40.0, 0.1);
    // r.status == ok; y = (0.7158271, 9.185535e-06, 0.2841637), 3.7e-9 from the reference
    // README snippet end
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.steps == 400);
    // SciPy 1.10.1 solve_ivp Radau at rtol 1e-12 (tests/stiff/radau5_test.cpp has the provenance)
    const std::array<double, 3> reference{0.7158270687194083, 9.185534764557791e-06, 0.28416374574583075};
    double worst = 0;
    for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(y[i] / reference[i] - 1));
    MESSAGE("worst relative error " << worst << "; y = " << y[0] << ", " << y[1] << ", " << y[2]);
    CHECK(worst < 1e-8);
}

TEST_CASE("docs/stiff.md: RK4 follows Robertson to t = 40 at dt = 8.2e-4, not at 8.6e-4 (its stability limit)") {
    // The intro's figure for an explicit method on the problem: RK4 is accurate while h |lambda| of the fast
    // mode stays inside its stability interval (-2.785, 0), and loses the solution just past it. The
    // reference is Hairer & Wanner's ten digits at t = 40 (support/stiff_problems.hpp).
    using odestep_test::state3;
    const auto relative_error = [](double dt, odestep::step_count expected_steps) {
        state3<double> y{1.0, 0.0, 0.0};
        const auto r = odestep::integrate(odestep::rk4<state3<double>>{}, odestep_test::robertson{}, y, 0.0, 40.0, dt);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.steps == expected_steps);  // ceil(40 / dt)
        return std::fabs(y[0] - odestep_test::robertson_at_40[0]) / odestep_test::robertson_at_40[0];
    };
    CHECK(relative_error(8.2e-4, 48781) < 1e-8);
    CHECK(relative_error(8.6e-4, 46512) > 1e-3);
}
