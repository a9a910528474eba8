// SPDX-License-Identifier: BSL-1.0
// The backward Euler step's derivative (sensitivity/implicit.hpp): (I - hA)^-1 on a stiff linear system, the
// closed form of y' = -y^2, and a singular or NaN Jacobian at the new state.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/compare.hpp"

namespace {

using odestep_test::same_bits;
using state2 = std::array<double, 2>;
using state1 = std::array<double, 1>;
template <std::size_t N>
using mat = std::array<std::array<double, N>, N>;
constexpr double eps = std::numeric_limits<double>::epsilon();

TEST_CASE("backward Euler transition: on a stiff y' = A y, Phi is the Pade form (I - hA)^-1") {
    // A with eigenvalues -1000 and -0.5 (h lambda = -100 and -0.05); (I - hA)^-1 of a 2 x 2 matrix by its
    // closed form, adj(M) / det(M).
    const mat<2> a{{{-1000.0, 3.0}, {2.0, -0.5}}};
    const double h = 0.1;
    auto sys = odestep::with_jacobian(
        [&a](double, const state2& y) {
            return state2{a[0][0] * y[0] + a[0][1] * y[1], a[1][0] * y[0] + a[1][1] * y[1]};
        },
        [&a](double, const state2&, mat<2>& J) { J = a; });
    state2 y{1.0, -2.0};
    mat<2> phi{};
    REQUIRE(odestep::backward_euler_transition<state2>{}.step(sys, y, phi, 0.0, h) == odestep::status::ok);
    const double m00 = 1 - h * a[0][0], m01 = -h * a[0][1], m10 = -h * a[1][0], m11 = 1 - h * a[1][1];
    const double det = m00 * m11 - m01 * m10;
    const mat<2> expected{{{m11 / det, -m01 / det}, {-m10 / det, m00 / det}}};
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j) CHECK(std::fabs(phi[i][j] - expected[i][j]) <= 8 * eps);
}

TEST_CASE("backward Euler transition: on y' = -y^2, Phi is 1 / sqrt(1 + 4 h y_n) (the step's closed form)") {
    // y_{n+1} = y_n - h y_{n+1}^2 solves to y_{n+1} = (sqrt(1 + 4 h y_n) - 1) / (2h), whose derivative is
    // 1 / sqrt(1 + 4 h y_n). The Newton tolerance (1.8e-12 relative by default) bounds the agreement.
    auto sys = odestep::with_jacobian([](double, const state1& y) { return state1{-y[0] * y[0]}; },
                                      [](double, const state1& y, mat<1>& J) { J = {{{-2 * y[0]}}}; });
    const double y0 = 1.0;
    const double h = 0.2;  // simplified Newton contracts by about 0.04 per iteration here
    state1 y{y0};
    mat<1> phi{};
    odestep::backward_euler_transition<state1> st;
    REQUIRE(st.step(sys, y, phi, 0.0, h) == odestep::status::ok);
    CHECK(std::fabs(y[0] - (std::sqrt(1 + 4 * h * y0) - 1) / (2 * h)) <= 1e-10);
    CHECK(std::fabs(phi[0][0] - 1 / std::sqrt(1 + 4 * h * y0)) <= 1e-10);
    // propagate with a seed s gives Phi s.
    state1 z{y0};
    std::array<std::array<double, 1>, 1> s{{{2.0}}};
    REQUIRE(st.propagate(sys, z, s, 0.0, h) == odestep::status::ok);
    CHECK(same_bits(y, z));
    CHECK(std::fabs(s[0][0] - 2 * phi[0][0]) <= 4 * eps);
}

TEST_CASE(
    "backward Euler transition: a singular or NaN Jacobian at the new state is singular_matrix, y and Phi "
    "untouched") {
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    const double h = 0.1;
    auto f = [](double, const state1& y) { return state1{-y[0]}; };
    const state1 y0{1.0};
    const mat<1> phi0{{{7.0}}};
    SUBCASE("I - h J singular at t + h") {
        // The Newton iteration uses J at t (= -1, fine); at t + h, J = 1/h makes I - hJ = 0.
        auto sys =
            odestep::with_jacobian(f, [h](double t, const state1&, mat<1>& J) { J = {{{t > 0.0 ? 1 / h : -1.0}}}; });
        state1 y = y0;
        mat<1> phi = phi0;
        CHECK(odestep::backward_euler_transition<state1>{}.step(sys, y, phi, 0.0, h) ==
              odestep::status::singular_matrix);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
    SUBCASE("NaN in J at t + h") {
        auto sys =
            odestep::with_jacobian(f, [qnan](double t, const state1&, mat<1>& J) { J = {{{t > 0.0 ? qnan : -1.0}}}; });
        state1 y = y0;
        mat<1> phi = phi0;
        CHECK(odestep::backward_euler_transition<state1>{}.step(sys, y, phi, 0.0, h) ==
              odestep::status::singular_matrix);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
}

}  // namespace
