// SPDX-License-Identifier: BSL-1.0
// The backward Euler step's derivative (sensitivity/implicit.hpp): (I - hA)^-1 on a stiff linear system, the
// closed form of y' = -y^2, and a singular or NaN Jacobian at the new state.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "sensitivity/helpers.hpp"
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

// ---- every implicit table

namespace implicit_tables {

using sensitivity_test::mat;
using sensitivity_test::max_difference;
using sensitivity_test::max_entry;

// The stability function R(z) = P(z) / Q(z) of each implicit table, from the literature (not from the
// table): the coefficients of P and Q, lowest power first.
//   backward Euler: the (0, 1) Pade approximant 1 / (1 - z);
//   trapezoid and implicit midpoint: the (1, 1) Pade approximant (1 + z/2) / (1 - z/2);
//   Gauss 4: the (2, 2) Pade approximant (1 + z/2 + z^2/12) / (1 - z/2 + z^2/12);
//   Radau IIA 5: the (2, 3) Pade approximant (1 + 2z/5 + z^2/20) / (1 - 3z/5 + 3z^2/20 - z^3/60)
//   (Hairer & Wanner, Solving ODE II, Sec. IV.3, (3.30), and Sec. IV.5, Theorems 5.3 and 5.5: the s-stage Gauss
//   method has the (s, s) Pade approximant, Radau IIA the (s - 1, s));
//   Alexander's SDIRK 3: Q(z) = (1 - gamma z)^3 and P(z) the Taylor polynomial of (1 - gamma z)^3 e^z to z^2,
//   1 + (1 - 3 gamma) z + (1/2 - 3 gamma + 3 gamma^2) z^2; its z^3 term, 1/6 - 3 gamma/2 + 3 gamma^2 - gamma^3,
//   vanishes by the choice of gamma (L-stability) (HW II Sec. IV.6, the stability function of an SDIRK method
//   of order p >= s; Alexander 1977, SIAM J. Numer. Anal. 14, 1006-1021).
struct rational {
    std::array<long double, 5> p;
    std::array<long double, 5> q;
};
constexpr long double g = 0.4358665215084589994160194511935568425293L;  // Alexander's gamma (the cubic's root)
constexpr rational backward_euler_r{{1.0L, 0, 0, 0}, {1.0L, -1.0L, 0, 0}};
constexpr rational trapezoid_r{{1.0L, 0.5L, 0, 0}, {1.0L, -0.5L, 0, 0}};
constexpr rational gauss4_r{{1.0L, 0.5L, 1.0L / 12, 0}, {1.0L, -0.5L, 1.0L / 12, 0}};
constexpr rational radau5_r{{1.0L, 2.0L / 5, 1.0L / 20, 0}, {1.0L, -3.0L / 5, 3.0L / 20, -1.0L / 60}};
constexpr rational sdirk3_r{{1.0L, 1 - 3 * g, 0.5L - 3 * g + 3 * g* g, 0}, {1.0L, -3 * g, 3 * g* g, -g* g* g}};
// RODAS3 (gamma = 1/2, four stages, order 3, L-stable): a Rosenbrock method's stability function is that of
// the DIRK method with the same gamma, P(z) / (1 - gamma z)^s with deg P <= s (HW II Sec. IV.7); order 3 makes
// P the Taylor polynomial of (1 - z/2)^4 e^z to z^3 and L-stability (R(infinity) = 0) its z^4 term zero:
// R(z) = (1 - z + z^3/6) / (1 - z/2)^4. A test below also checks it against 1 + z b^T (I - z(alpha +
// Gamma))^-1 1 from the published table.
constexpr rational rodas3_r{{1.0L, -1.0L, 0, 1.0L / 6, 0}, {1.0L, -2.0L, 1.5L, -0.5L, 1.0L / 16}};

// R(z) = P(z) / Q(z) at a scalar z.
long double evaluate(const rational& r, long double z) {
    long double p = 0.0L;
    long double q = 0.0L;
    for (std::size_t k = 5; k-- > 0;) {
        p = p * z + r.p[k];
        q = q * z + r.q[k];
    }
    return p / q;
}
// R(hA) of a 2 x 2 A with distinct real eigenvalues l1, l2, by Sylvester's formula
// R(hA) = R(h l1) (A - l2 I) / (l1 - l2) + R(h l2) (A - l1 I) / (l2 - l1), in long double: scalar R only, no
// matrix powers (whose entries, 1e8 for (hA)^4 at h lambda = -100, would leave little accuracy where long
// double is double, as on the Cortex-M targets).
mat<double, 2> stability_matrix(const rational& r, const mat<double, 2>& a, double h) {
    const auto wide = [](double x) { return static_cast<long double>(x); };
    const long double a00 = wide(a[0][0]), a01 = wide(a[0][1]), a10 = wide(a[1][0]), a11 = wide(a[1][1]);
    const long double half_trace = (a00 + a11) / 2;
    const long double det = a00 * a11 - a01 * a10;
    const long double root = std::sqrt(half_trace * half_trace - det);
    const long double l1 = half_trace < 0 ? half_trace - root : half_trace + root;  // the larger in magnitude
    const long double l2 = det / l1;                                                // without cancellation
    const long double hl = static_cast<long double>(h);
    const long double r1 = evaluate(r, hl * l1) / (l1 - l2);
    const long double r2 = evaluate(r, hl * l2) / (l2 - l1);
    const long double m[2][2] = {{a00, a01}, {a10, a11}};
    mat<double, 2> out{};
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j) {
            const long double id = i == j ? 1.0L : 0.0L;
            out[i][j] = static_cast<double>(r1 * (m[i][j] - l2 * id) + r2 * (m[i][j] - l1 * id));
        }
    return out;
}

using state2 = std::array<double, 2>;
const mat<double, 2> stiff_a{{{-1000.0, 3.0}, {2.0, -0.5}}};  // eigenvalues about -1000 and -0.494

template <class Transition>
mat<double, 2> phi_on_linear(double h) {
    auto sys = odestep::with_jacobian(
        [](double, const state2& y) {
            return state2{stiff_a[0][0] * y[0] + stiff_a[0][1] * y[1], stiff_a[1][0] * y[0] + stiff_a[1][1] * y[1]};
        },
        [](double, const state2&, mat<double, 2>& J) { J = stiff_a; });
    state2 y{1.0, -2.0};
    mat<double, 2> phi{};
    REQUIRE(Transition{}.step(sys, y, phi, 0.0, h) == odestep::status::ok);
    return phi;
}

TEST_CASE("implicit transitions: on a stiff y' = A y, Phi is the published Pade or rational form R(hA)") {
    for (double h : {0.001, 0.1}) {  // h lambda = -1 and -100 on the stiff mode
        INFO("h = " << h);
        const auto check = [h](const char* name, const mat<double, 2>& phi, const rational& r) {
            INFO(name);
            const mat<double, 2> expected = stability_matrix(r, stiff_a, h);
            CHECK(max_difference(phi, expected) <= 64 * eps * max_entry(expected));
        };
        check("backward Euler", phi_on_linear<odestep::backward_euler_transition<state2>>(h), backward_euler_r);
        check("trapezoid", phi_on_linear<odestep::trapezoid_transition<state2>>(h), trapezoid_r);
        check("implicit midpoint", phi_on_linear<odestep::implicit_midpoint_transition<state2>>(h), trapezoid_r);
        check("Gauss 4", phi_on_linear<odestep::gauss4_transition<state2>>(h), gauss4_r);
        check("SDIRK 3", phi_on_linear<odestep::sdirk3_transition<state2>>(h), sdirk3_r);
        check("Radau IIA 5", phi_on_linear<odestep::radau_iia5_transition<state2>>(h), radau5_r);
    }
}

// A float transition's Phi on the stiff y' = A y (stiff_a) at h = 0.1 against R(hA) in double from the
// method's stability function r, to float round-off (the transition compiles without a double promotion).
template <class Transition, class R>
void check_float_on_stiff_linear(R r) {
    using statef = std::array<float, 2>;
    auto sys = odestep::with_jacobian(
        [](float, const statef& y) {
            return statef{-1000.0f * y[0] + 3.0f * y[1], 2.0f * y[0] - 0.5f * y[1]};
        },
        [](float, const statef&, mat<float, 2>& J) {
            J = {{{-1000.0f, 3.0f}, {2.0f, -0.5f}}};
        });
    statef y{1.0f, -2.0f};
    mat<float, 2> phi{};
    REQUIRE(Transition{}.step(sys, y, phi, 0.0f, 0.1f) == odestep::status::ok);
    const mat<double, 2> expected = stability_matrix(r, stiff_a, static_cast<double>(0.1f));
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j)
            CHECK(std::fabs(static_cast<double>(phi[i][j]) - expected[i][j]) <=
                  64 * static_cast<double>(std::numeric_limits<float>::epsilon()) * max_entry(expected));
}

TEST_CASE("implicit transitions: in float, Radau IIA 5's Phi on y' = A y is R(hA) to float round-off") {
    check_float_on_stiff_linear<odestep::radau_iia5_transition<std::array<float, 2>>>(radau5_r);
}

// Phi against central differences of the plain step, e^2 convergence over a sweep (sensitivity_test). A fixed
// number of Newton iterations makes the plain step a smooth function of y_n, converged to round-off here
// (simplified Newton contracts by about |h J| per iteration), so the differences carry no tolerance noise.
template <template <class, class> class Plain, template <class, class> class Transition, class F, std::size_t N>
void differences(F f, const std::array<double, N>& y, double dt, double e0) {
    using state = std::array<double, N>;
    using newton = odestep::fixed_newton<30>;
    sensitivity_test::check_against_differences<Plain<state, newton>, Transition<state, newton>>(f, y, 0.0, dt, e0);
}

TEST_CASE(
    "implicit transitions: on Lorenz and the pendulum, Phi is the limit of central differences of the plain "
    "step, their error falling as e^2") {
    using namespace sensitivity_test;  // NOLINT: the problems
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    const std::array<double, 3> y0{1.0, 2.0, 20.0};
    differences<odestep::backward_euler, odestep::backward_euler_transition>(lz, y0, 0.01, 0.4);
    differences<odestep::trapezoid, odestep::trapezoid_transition>(lz, y0, 0.01, 0.4);
    differences<odestep::implicit_midpoint, odestep::implicit_midpoint_transition>(lz, y0, 0.01, 0.4);
    differences<odestep::gauss4, odestep::gauss4_transition>(lz, y0, 0.01, 0.4);
    differences<odestep::sdirk3, odestep::sdirk3_transition>(lz, y0, 0.01, 0.4);
    differences<odestep::radau_iia5, odestep::radau_iia5_transition>(lz, y0, 0.01, 0.4);
    auto pd = odestep::with_jacobian(pendulum{}, pendulum_jacobian{});
    differences<odestep::radau_iia5, odestep::radau_iia5_transition>(pd, std::array<double, 2>{2.0, 0.5}, 0.2, 0.2);
    differences<odestep::sdirk3, odestep::sdirk3_transition>(pd, std::array<double, 2>{2.0, 0.5}, 0.2, 0.2);
}

TEST_CASE("implicit transitions: with the default Newton, Phi agrees with the fixed-iteration one to the tolerance") {
    using namespace sensitivity_test;  // NOLINT: the problems
    using state = std::array<double, 3>;
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    const state y0{1.0, 2.0, 20.0};
    state a = y0;
    state b = y0;
    mat<double, 3> pa{};
    mat<double, 3> pb{};
    REQUIRE(odestep::gauss4_transition<state>{}.step(lz, a, pa, 0.0, 0.01) == odestep::status::ok);
    REQUIRE(odestep::gauss4_transition<state, odestep::fixed_newton<30>>{}.step(lz, b, pb, 0.0, 0.01) ==
            odestep::status::ok);
    CHECK(max_difference(pa, pb) <= 1e-9 * max_entry(pb));
    // propagate with a seed s is Phi s.
    state c = y0;
    std::array<std::array<double, 1>, 3> s{{{1.0}, {-2.0}, {0.5}}};
    REQUIRE(odestep::gauss4_transition<state>{}.propagate(lz, c, s, 0.0, 0.01) == odestep::status::ok);
    CHECK(same_bits(a, c));
    for (std::size_t i = 0; i < 3; ++i)
        CHECK(std::fabs(s[i][0] - (pa[i][0] - 2.0 * pa[i][1] + 0.5 * pa[i][2])) <= 16 * eps * max_entry(pa));
}

TEST_CASE("implicit transitions: a singular or NaN stage matrix is singular_matrix, y and Phi untouched") {
    const double h = 0.5;
    auto f = [](double, const state1& y) { return state1{-y[0]}; };
    const state1 y0{1.0};
    const mat<double, 1> phi0{{{7.0}}};
    SUBCASE("implicit midpoint: 1 - h/2 J = 0 at the stage") {
        // The plain step's J at t = 0 is -1; at the stage (t = h/2), J = 4 makes 1 - (1/2)(1/2) 4 = 0 exactly.
        auto sys = odestep::with_jacobian(
            f, [](double t, const state1&, mat<double, 1>& J) { J = {{{t > 0.0 ? 4.0 : -1.0}}}; });
        state1 y = y0;
        mat<double, 1> phi = phi0;
        CHECK(odestep::implicit_midpoint_transition<state1>{}.step(sys, y, phi, 0.0, h) ==
              odestep::status::singular_matrix);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
    SUBCASE("Radau IIA 5: NaN in J at the stages") {
        const double qnan = std::numeric_limits<double>::quiet_NaN();
        auto sys = odestep::with_jacobian(
            f, [qnan](double t, const state1&, mat<double, 1>& J) { J = {{{t > 0.0 ? qnan : -1.0}}}; });
        state1 y = y0;
        mat<double, 1> phi = phi0;
        CHECK(odestep::radau_iia5_transition<state1>{}.step(sys, y, phi, 0.0, h) == odestep::status::singular_matrix);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
}

// ---- the Rosenbrock method

TEST_CASE("rosenbrock transition: RODAS3's stability function, from its published table, is the closed form") {
    // 1 + z b^T (I - z B)^-1 1 with B = alpha + Gamma lower triangular (Sandu et al. 1997's RODAS3), by forward
    // substitution in long double, against (1 - z + z^3/6) / (1 - z/2)^4.
    const auto& tab = odestep::tables::rodas3::table<long double>;
    for (long double z : {-0.3L, -2.0L, -100.0L, 0.7L}) {
        std::array<long double, 4> x{};
        long double r = 1.0L;
        for (std::size_t i = 0; i < 4; ++i) {
            long double sum = 1.0L;
            for (std::size_t j = 0; j < i; ++j) sum += z * (tab.alpha[i][j] + tab.gamma[i][j]) * x[j];
            x[i] = sum / (1.0L - z * tab.gamma[i][i]);
            r += z * tab.b[i] * x[i];
        }
        const long double closed = (1.0L - z + z * z * z / 6.0L) / std::pow(1.0L - z / 2.0L, 4);
        CHECK(std::fabs(r - closed) <= 64 * std::numeric_limits<long double>::epsilon() * (1.0L + std::fabs(closed)));
    }
}

TEST_CASE("rosenbrock transition: on a stiff y' = A y, RODAS3's Phi is R(hA)") {
    for (double h : {0.001, 0.1}) {
        INFO("h = " << h);
        const mat<double, 2> expected = stability_matrix(rodas3_r, stiff_a, h);
        CHECK(max_difference(phi_on_linear<odestep::rodas3_transition<state2>>(h), expected) <=
              64 * eps * max_entry(expected));
    }
    // In float (the transition compiles without a double promotion), to float round-off.
    check_float_on_stiff_linear<odestep::rodas3_transition<std::array<float, 2>>>(rodas3_r);
}

// A Duffing oscillator with a time-dependent stiffness, so that J depends on t and the step's df/dt on y.
struct forced_duffing {
    template <class T>
    std::array<T, 2> operator()(T t, const std::array<T, 2>& y) const {
        return {y[1], -(T(1) + T(0.5) * std::cos(T(3) * t)) * y[0] - y[0] * y[0] * y[0] - T(0.1) * y[1]};
    }
};
struct forced_duffing_jacobian {
    template <class T>
    void operator()(T t, const std::array<T, 2>& y, mat<T, 2>& J) const {
        J = {{{T(0), T(1)}, {-(T(1) + T(0.5) * std::cos(T(3) * t)) - T(3) * y[0] * y[0], T(-0.1)}}};
    }
};

TEST_CASE(
    "rosenbrock transition: on Lorenz, the pendulum and a forced Duffing oscillator, RODAS3's Phi is the limit "
    "of central differences of the plain step, their error falling as e^2") {
    using namespace sensitivity_test;  // NOLINT: the problems and the check
    using s3 = std::array<double, 3>;
    using s2 = std::array<double, 2>;
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    check_against_differences<odestep::rodas3<s3>, odestep::rodas3_transition<s3>>(lz, s3{1.0, 2.0, 20.0}, 0.0, 0.01,
                                                                                   0.4);
    auto pd = odestep::with_jacobian(pendulum{}, pendulum_jacobian{});
    check_against_differences<odestep::rodas3<s2>, odestep::rodas3_transition<s2>>(pd, s2{2.0, 0.5}, 0.0, 0.2, 0.2);
    auto du = odestep::with_jacobian(forced_duffing{}, forced_duffing_jacobian{});
    check_against_differences<odestep::rodas3<s2>, odestep::rodas3_transition<s2>>(du, s2{1.5, -0.5}, 0.7, 0.2, 0.2);
}

TEST_CASE(
    "rosenbrock transition: on the pendulum and a forced Duffing oscillator, Phi meets Richardson-extrapolated "
    "central differences to the differences' own error") {
    // (4 D(e/2) - D(e)) / 3 of the central differences D has error O(e^4) plus the plain step's noise over e:
    // about 1e-12 at e = 0.01 for the pendulum, whose f has no t, and 5e-8 for the forced oscillator, whose
    // step's df/dt difference carries eps |f| / delta (delta = 1.2e-8 at t = 0.7) of rounding that varies with
    // y. Sharp enough to see the second-derivative term's own error (relative sqrt(eps) on a term of size
    // h^2 |f''| |f|) stay small, a coarser difference step (1e-3 instead of sqrt(eps): 7e-7 and 5e-7) and the
    // term's absence (1e-3 to 3e-2). Both problems have third derivatives, so that the forward difference of J
    // along u_i is not exact by accident (Lorenz is quadratic).
    using namespace sensitivity_test;  // NOLINT: the problems
    using s2 = std::array<double, 2>;
    const auto check = [](auto sys, const s2& y0, double t, double h, double tolerance) {
        s2 y = y0;
        mat<double, 2> phi{};
        REQUIRE(odestep::rodas3_transition<s2>{}.step(sys, y, phi, t, h) == odestep::status::ok);
        const mat<double, 2> d1 = central_difference<odestep::rodas3<s2>>(sys, y0, t, h, 0.01);
        const mat<double, 2> d2 = central_difference<odestep::rodas3<s2>>(sys, y0, t, h, 0.005);
        mat<double, 2> richardson{};
        for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t j = 0; j < 2; ++j) richardson[i][j] = (4 * d2[i][j] - d1[i][j]) / 3;
        INFO("|Phi - Richardson| = " << max_difference(phi, richardson));
        CHECK(max_difference(phi, richardson) <= tolerance);
    };
    check(odestep::with_jacobian(pendulum{}, pendulum_jacobian{}), s2{2.0, 0.5}, 0.0, 0.2, 1e-10);
    check(odestep::with_jacobian(forced_duffing{}, forced_duffing_jacobian{}), s2{1.5, -0.5}, 0.7, 0.2, 1.5e-7);
}

TEST_CASE(
    "rosenbrock transition: propagate is Phi s, and a NaN Jacobian at a stage is non_finite, y and Phi untouched") {
    using namespace sensitivity_test;  // NOLINT: the problems
    using s3 = std::array<double, 3>;
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    const s3 y0{1.0, 2.0, 20.0};
    s3 a = y0;
    mat<double, 3> phi{};
    REQUIRE(odestep::rodas3_transition<s3>{}.step(lz, a, phi, 0.0, 0.01) == odestep::status::ok);
    s3 b = y0;
    std::array<std::array<double, 1>, 3> s{{{1.0}, {-2.0}, {0.5}}};
    REQUIRE(odestep::rodas3_transition<s3>{}.propagate(lz, b, s, 0.0, 0.01) == odestep::status::ok);
    CHECK(same_bits(a, b));
    for (std::size_t i = 0; i < 3; ++i)
        CHECK(std::fabs(s[i][0] - (phi[i][0] - 2.0 * phi[i][1] + 0.5 * phi[i][2])) <= 1e-9 * max_entry(phi));
    // J is NaN away from y_n only: the plain step (J at y_n) succeeds, the stage derivatives do not.
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    auto bad = odestep::with_jacobian(lorenz{}, [&y0, qnan](double, const s3& y, mat<double, 3>& J) {
        lorenz_jacobian{}(0.0, y, J);
        if (y != y0) J[1][1] = qnan;
    });
    s3 c = y0;
    mat<double, 3> phi0{};
    phi0[0][0] = 7.0;
    mat<double, 3> p = phi0;
    CHECK(odestep::rodas3_transition<s3>{}.step(bad, c, p, 0.0, 0.01) == odestep::status::non_finite);
    CHECK(same_bits(c, y0));
    CHECK(same_bits(p, phi0));
}

}  // namespace implicit_tables

}  // namespace
