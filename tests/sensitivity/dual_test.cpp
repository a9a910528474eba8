// SPDX-License-Identifier: BSL-1.0
// odestep::dual (sensitivity/dual.hpp): each operation's derivative against its closed form, the Jacobian of
// a templated right-hand side against the hand-written one, and the step's Phi through with_dual_jacobian.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "support/compare.hpp"

namespace {

using odestep_test::same_bits;
using d2 = odestep::dual<double, 2>;
constexpr double eps = std::numeric_limits<double>::epsilon();

template <std::size_t N>
using mat = std::array<std::array<double, N>, N>;

// |a - b| <= tol (|b| + tiny), relative.
bool close(double a, double b, double tol = 4 * eps) { return std::fabs(a - b) <= tol * (std::fabs(b) + 1e-300); }

TEST_CASE("dual: arithmetic carries the derivatives of the calculus rules") {
    const d2 x = d2::variable(1.5, 0);
    const d2 y = d2::variable(-0.75, 1);
    // d(xy) = (y, x); d(x/y) = (1/y, -x/y^2); d(x + 2 - y) = (1, -1); d(3/x) = (-3/x^2, 0); d(-x) = (-1, 0).
    const d2 p = x * y;
    CHECK(p.value == 1.5 * -0.75);
    CHECK(p.grad[0] == -0.75);
    CHECK(p.grad[1] == 1.5);
    const d2 q = x / y;
    CHECK(close(q.grad[0], 1 / -0.75));
    CHECK(close(q.grad[1], -1.5 / (0.75 * 0.75)));
    const d2 s = x + 2.0 - y;
    CHECK(s.value == 1.5 + 2.0 + 0.75);
    CHECK(s.grad[0] == 1.0);
    CHECK(s.grad[1] == -1.0);
    const d2 r = 3.0 / x;
    CHECK(close(r.grad[0], -3.0 / (1.5 * 1.5)));
    CHECK(r.grad[1] == 0.0);
    CHECK((-x).grad[0] == -1.0);
    d2 c = x;
    c *= y;
    c += x;
    c -= 1.0;
    c /= y;  // (xy + x - 1) / y: d/dx = (y + 1)/y, d/dy = (x y - (x y + x - 1)) / y^2 = (1 - x) / y^2
    CHECK(close(c.grad[0], (-0.75 + 1) / -0.75));
    CHECK(close(c.grad[1], (1 - 1.5) / (0.75 * 0.75)));
    CHECK(x > y);
    CHECK(y < 0.0);
    CHECK(x == 1.5);
    CHECK(x != y);
    CHECK(x >= x);
    CHECK(y <= x);
}

TEST_CASE("dual: sqrt, sin, cos, tan, exp, log, pow and abs have their closed-form derivatives") {
    using std::cos;
    using std::exp;
    using std::log;
    using std::pow;
    using std::sin;
    using std::sqrt;
    using std::tan;
    const double a = 0.7;
    const d2 x = d2::variable(a, 0);
    CHECK(close(sqrt(x).grad[0], 0.5 / std::sqrt(a)));
    CHECK(close(sin(x).grad[0], std::cos(a)));
    CHECK(close(cos(x).grad[0], -std::sin(a)));
    CHECK(close(tan(x).grad[0], 1 / (std::cos(a) * std::cos(a)), 16 * eps));
    CHECK(close(exp(x).grad[0], std::exp(a)));
    CHECK(close(log(x).grad[0], 1 / a));
    CHECK(close(pow(x, 2.5).grad[0], 2.5 * std::pow(a, 1.5)));
    const d2 y = d2::variable(1.3, 1);
    const d2 p = pow(x, y);  // d/dx = y x^(y-1), d/dy = x^y log x
    CHECK(close(p.grad[0], 1.3 * std::pow(a, 0.3), 16 * eps));
    CHECK(close(p.grad[1], std::pow(a, 1.3) * std::log(a), 16 * eps));
    CHECK(abs(-x).grad[0] == 1.0);
    CHECK(fabs(-x).value == a);
    CHECK(abs(x).grad[0] == 1.0);
    // A composite: d/dx exp(sin x) sqrt(x) = exp(sin x) (cos x sqrt x + 1 / (2 sqrt x)).
    const d2 g = exp(sin(x)) * sqrt(x);
    CHECK(close(g.grad[0], std::exp(std::sin(a)) * (std::cos(a) * std::sqrt(a) + 0.5 / std::sqrt(a)), 16 * eps));
}

TEST_CASE("dual: float stays float") {
    using df = odestep::dual<float, 1>;
    const df x = df::variable(0.5f, 0);
    const df y = sin(x) * 2.0f + x / 3.0f;
    static_assert(std::is_same_v<decltype(y.value), float>);
    CHECK(std::fabs(y.grad[0] - (2.0f * std::cos(0.5f) + 1.0f / 3.0f)) <= 4 * std::numeric_limits<float>::epsilon());
}

// Lorenz, written once as a template on its scalar.
auto lorenz = [](double, const auto& y) {
    using S = std::decay_t<decltype(y[0])>;
    return std::array<S, 3>{10.0 * (y[1] - y[0]), y[0] * (28.0 - y[2]) - y[1], y[0] * y[1] - 8.0 / 3.0 * y[2]};
};
// The pendulum in the in-place form.
auto pendulum_inplace = [](double, const auto& y, auto& dydt) {
    using std::sin;
    dydt[0] = y[1];
    dydt[1] = -sin(y[0]);
};

TEST_CASE("dual: the compound assignments with the operand itself (x *= x, x /= x, x += x)") {
    // d(x^2) = 2x dx, d(x/x) = 0, d(2x) = 2 dx: the in-place forms must read b before writing *this.
    d2 x = d2::variable(1.5, 0);
    x *= static_cast<const d2&>(x);  // the cast: clang's -Wself-assign-overloaded
    CHECK(x.value == 2.25);
    CHECK(x.grad[0] == 3.0);
    CHECK(x.grad[1] == 0.0);
    d2 y = d2::variable(-0.75, 1);
    y /= static_cast<const d2&>(y);
    CHECK(y.value == 1.0);
    CHECK(y.grad[1] == 0.0);
    d2 w = d2::variable(0.5, 0);
    w += static_cast<const d2&>(w);
    CHECK(w.value == 1.0);
    CHECK(w.grad[0] == 2.0);
}

TEST_CASE("dual: the Jacobian of a templated f is the hand-written one") {
    const std::array<double, 3> y{1.0, 2.0, 20.0};
    mat<3> j{};
    odestep::dual_jacobian(lorenz, 0.0, y, j);
    // d f / d y of Lorenz by hand: [[-10, 10, 0], [28 - y2, -1, -y0], [y1, y0, -8/3]].
    const mat<3> hand{{{-10.0, 10.0, 0.0}, {28.0 - y[2], -1.0, -y[0]}, {y[1], y[0], -8.0 / 3.0}}};
    CHECK(same_bits(j, hand));
    mat<2> jp{};
    odestep::dual_jacobian(pendulum_inplace, 0.0, std::array<double, 2>{0.4, 0.0}, jp);
    CHECK(jp[0][0] == 0.0);
    CHECK(jp[0][1] == 1.0);
    CHECK(jp[1][0] == -std::cos(0.4));
    CHECK(jp[1][1] == 0.0);
}

TEST_CASE("dual: RK4's Phi through with_dual_jacobian is the one from the hand-written Jacobian") {
    using state = std::array<double, 3>;
    auto by_dual = odestep::with_dual_jacobian(lorenz);
    auto by_hand = odestep::with_jacobian(lorenz, [](double, const state& y, mat<3>& J) {
        J = {{{-10.0, 10.0, 0.0}, {28.0 - y[2], -1.0, -y[0]}, {y[1], y[0], -8.0 / 3.0}}};
    });
    state y1{1.0, 2.0, 20.0};
    state y2 = y1;
    mat<3> p1{};
    mat<3> p2{};
    REQUIRE(odestep::rk4_transition<state>{}.step(by_dual, y1, p1, 0.0, 0.01) == odestep::status::ok);
    REQUIRE(odestep::rk4_transition<state>{}.step(by_hand, y2, p2, 0.0, 0.01) == odestep::status::ok);
    CHECK(same_bits(y1, y2));
    // The same Phi to round-off: the dual path forms each stage's J Z as f's directional derivatives along
    // Z's columns (jacobian_times), in f's order of operations, where the hand path multiplies J by Z.
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            CHECK(std::fabs(p1[i][j] - p2[i][j]) <= 8 * eps * (std::fabs(p2[i][j]) + 1));
    // jacobian_times itself: J z for a 3 x 2 z against the hand Jacobian's product on Lorenz, to round-off.
    const std::array<std::array<double, 2>, 3> zd{{{1.0, 0.5}, {-2.0, 0.0}, {0.25, 3.0}}};
    std::array<std::array<double, 2>, 3> jz{};
    by_dual.jacobian_times(0.0, state{1.0, 2.0, 20.0}, zd, jz);
    const mat<3> hand{{{-10.0, 10.0, 0.0}, {8.0, -1.0, -1.0}, {2.0, 1.0, -8.0 / 3.0}}};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 2; ++j)
            CHECK(std::fabs(jz[i][j] - (hand[i][0] * zd[0][j] + hand[i][1] * zd[1][j] + hand[i][2] * zd[2][j])) <=
                  4 * eps * 30);
    // An rvalue f is moved in and works as well.
    auto moved = odestep::with_dual_jacobian([](double, const auto& y, auto& dydt) { dydt = {y[1], -y[0]}; });
    std::array<double, 2> z{1.0, 0.0};
    mat<2> pz{};
    REQUIRE(odestep::heun_transition<std::array<double, 2>>{}.step(moved, z, pz, 0.0, 0.1) == odestep::status::ok);
    // Heun on the oscillator: R(hA) = I + hA + (hA)^2/2 with A = [[0, 1], [-1, 0]], (hA)^2 = -h^2 I.
    CHECK(std::fabs(pz[0][0] - (1 - 0.005)) <= 4 * eps);
    CHECK(std::fabs(pz[0][1] - 0.1) <= 4 * eps);
    CHECK(std::fabs(pz[1][0] + 0.1) <= 4 * eps);
}

TEST_CASE("dual: Kepler's acceleration Hessian by dual numbers drives the splitting transition") {
    using state = std::array<double, 2>;
    auto kepler = [](double, const auto& x) {
        using std::sqrt;
        using S = std::decay_t<decltype(x[0])>;
        const S r2 = x[0] * x[0] + x[1] * x[1];
        const S k = 1.0 / (r2 * sqrt(r2));
        return std::array<S, 2>{-k * x[0], -k * x[1]};
    };
    mat<2> h{};
    const state x0{1.0, 0.2};
    odestep::dual_jacobian(kepler, 0.0, x0, h);
    // d a / d x = -(I - 3 x x^T / r^2) / r^3 (the Hessian of 1/r, negated).
    const double r2 = 1.04;
    const double r3 = r2 * std::sqrt(r2);
    CHECK(close(h[0][0], -(1 - 3 * 1.0 * 1.0 / r2) / r3, 8 * eps));
    CHECK(close(h[0][1], 3 * 1.0 * 0.2 / (r2 * r3), 8 * eps));
    CHECK(close(h[1][0], h[0][1], 8 * eps));
    CHECK(close(h[1][1], -(1 - 3 * 0.2 * 0.2 / r2) / r3, 8 * eps));
    auto a = odestep::with_dual_jacobian(kepler);
    state x = x0;
    state v{-0.3, 1.1};
    odestep::phase_matrix_t<state> phi{};
    REQUIRE(odestep::yoshida6_transition<state>{}.step(a, x, v, phi, 0.0, 0.1) == odestep::status::ok);
    // Symplectic: Phi^T J Phi = J.
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 4; ++j) {
            double s = 0.0;
            for (std::size_t k = 0; k < 2; ++k) s += phi[k][i] * phi[2 + k][j] - phi[2 + k][i] * phi[k][j];
            const double expected = (i < 2 && j == i + 2) ? 1.0 : (j < 2 && i == j + 2) ? -1.0 : 0.0;
            CHECK(std::fabs(s - expected) <= 64 * eps);
        }
}

}  // namespace
