// SPDX-License-Identifier: BSL-1.0
// RODAS3 and the Rosenbrock stepper: the order conditions of Hairer & Wanner's Table IV.7.1, the transformed
// coefficients against KPP's published ones, the stability function, the observed order (autonomous and not),
// Robertson, the statuses of every failure with y kept bit for bit, and the fixed evaluation count.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstring>
#include <limits>

#include "support/order_fit.hpp"
#include "support/stiff_problems.hpp"

namespace {

using odestep_test::state1;
using odestep_test::state3;
using real = long double;

template <class T, std::size_t N>
bool same_bits(const std::array<T, N>& a, const std::array<T, N>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The residuals of the order conditions of Hairer & Wanner, Solving ODE II, Table IV.7.1, in long double, with
// beta_ij = alpha_ij + gamma_ij (j < i), beta'_i = sum_{j<i} beta_ij, alpha_i = sum_j alpha_ij.
struct rosenbrock_conditions {
    std::array<real, 8> residual{};  // orders 1; 2; 3, 3; 4, 4, 4, 4
};

template <std::size_t S>
rosenbrock_conditions conditions(const odestep::rosenbrock_tableau<real, S>& t) {
    const real g = t.gamma[0][0];
    std::array<std::array<real, S>, S> beta{};
    std::array<real, S> bp{};
    std::array<real, S> al{};
    for (std::size_t i = 0; i < S; ++i)
        for (std::size_t j = 0; j < i; ++j) {
            beta[i][j] = t.alpha[i][j] + t.gamma[i][j];
            bp[i] += beta[i][j];
            al[i] += t.alpha[i][j];
        }
    real c[8] = {};
    for (std::size_t j = 0; j < S; ++j) {
        c[0] += t.b[j];
        c[1] += t.b[j] * bp[j];
        c[2] += t.b[j] * al[j] * al[j];
        c[4] += t.b[j] * al[j] * al[j] * al[j];
        for (std::size_t k = 0; k < S; ++k) {
            c[3] += t.b[j] * beta[j][k] * bp[k];
            c[5] += t.b[j] * al[j] * t.alpha[j][k] * bp[k];
            c[6] += t.b[j] * beta[j][k] * al[k] * al[k];
            for (std::size_t l = 0; l < S; ++l) c[7] += t.b[j] * beta[j][k] * beta[k][l] * bp[l];
        }
    }
    const real target[8] = {1,     0.5L - g,       1.0L / 3,          1.0L / 6 - g + g * g,
                            0.25L, 0.125L - g / 3, 1.0L / 12 - g / 3, 1.0L / 24 - g / 2 + 1.5L * g * g - g * g * g};
    rosenbrock_conditions r;
    for (std::size_t i = 0; i < 8; ++i) r.residual[i] = std::fabs(c[i] - target[i]);
    return r;
}

// R(z) = 1 + z b^T (I - z B)^-1 1 with B = (alpha_ij + gamma_ij), lower triangular (Hairer & Wanner, Solving
// ODE II, Sec. IV.7: the stability function of a Rosenbrock method), by forward substitution.
using cplx = std::complex<long double>;
cplx rodas3_r(cplx z) {
    const auto& t = odestep::tables::rodas3::table<real>;
    std::array<cplx, 4> x{};
    for (std::size_t i = 0; i < 4; ++i) {
        cplx sum = 1;
        for (std::size_t j = 0; j < i; ++j) sum += z * (t.alpha[i][j] + t.gamma[i][j]) * x[j];
        x[i] = sum / (cplx(1) - z * t.gamma[i][i]);
    }
    cplx s = 0;
    for (std::size_t i = 0; i < 4; ++i) s += t.b[i] * x[i];
    return cplx(1) + z * s;
}

template <class F>
struct counted {
    F f;
    std::size_t* calls;
    template <class T, class S>
    void operator()(T t, const S& y, S& d) const {
        ++*calls;
        f(t, y, d);
    }
};

template <class T>
struct forced {  // y' = -(y - sin t) + cos t: y = sin t; non-autonomous, so df/dt takes part
    state1<T> operator()(T t, const state1<T>& y) const noexcept { return {-(y[0] - std::sin(t)) + std::cos(t)}; }
};

}  // namespace

TEST_CASE("rosenbrock: RODAS3 meets every order condition of Hairer & Wanner's Table IV.7.1 up to order 3, not 4") {
    const auto r = conditions(odestep::tables::rodas3::table<real>);
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("condition " << i);
        CHECK(r.residual[i] <= 8 * LDBL_EPSILON);
    }
    real worst_fourth = 0;
    for (std::size_t i = 4; i < 8; ++i) worst_fourth = std::max(worst_fourth, r.residual[i]);
    CHECK(worst_fourth > 1e-2L);  // sum b alpha^3 = 1/3, not 1/4: the order is exactly 3
    // a coefficient off by one part in a million breaks the conditions it enters
    auto broken = odestep::tables::rodas3::table<real>;
    broken.gamma[3][2] *= 1 + 1e-6L;
    CHECK(conditions(broken).residual[3] > 1e-8L);
}

TEST_CASE("rosenbrock: the transformed coefficients are KPP's published RODAS3 ones") {
    // KPP's Rosenbrock integrator (Sandu & Sander 2006), subroutine Rodas3: ros_A = (0, 2, 0, 2, 0, 1),
    // ros_C = (4, 1, -1, 1, -1, -8/3), ros_M = (2, 0, 1, 1), ros_Alpha = (0, 0, 1, 1), ros_Gamma = (1/2, 3/2, 0, 0).
    constexpr auto co = odestep::detail::transform_rosenbrock(odestep::tables::rodas3::table<double>);
    const double a[4][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {2, 0, 0, 0}, {2, 0, 1, 0}};
    const double c[4][4] = {{0, 0, 0, 0}, {4, 0, 0, 0}, {1, -1, 0, 0}, {1, -1, -8.0 / 3, 0}};
    const double m[4] = {2, 0, 1, 1};
    const double node[4] = {0, 0, 1, 1};
    const double gamma_i[4] = {0.5, 1.5, 0, 0};
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            CHECK(co.a[i][j] == doctest::Approx(a[i][j]).epsilon(1e-15));
            CHECK(co.gc[i][j] / 0.5 == doctest::Approx(c[i][j]).epsilon(1e-15));
        }
        CHECK(co.m[i] == doctest::Approx(m[i]).epsilon(1e-15));
        CHECK(co.node[i] == node[i]);
        CHECK(co.time_weight[i] / 0.5 == doctest::Approx(gamma_i[i]).epsilon(1e-15));
    }
    // the second stage's input is the first's (KPP: ros_NewF(2) = .FALSE.)
    CHECK(co.reuses_previous[1]);
    CHECK(!co.reuses_previous[2]);
    CHECK(!co.reuses_previous[3]);
}

TEST_CASE("rosenbrock: RODAS3 is A-stable and L-stable, and a step on y' = lambda y is R(h lambda)") {
    long double worst = 0;
    for (long double y = 1e-3L; y <= 1e8L; y *= 1.1L) worst = std::max(worst, std::abs(rodas3_r(cplx(0, y))));
    CHECK(worst <= 1 + 8 * LDBL_EPSILON);
    long double plane = 0;
    for (long double x = 1e-2L; x <= 1e6L; x *= 1.5L)
        for (long double y = 0; y <= 1e6L; y = y * 1.5L + 1e-2L)
            plane = std::max(plane, std::abs(rodas3_r(cplx(-x, y))));
    CHECK(plane <= 1 + 8 * LDBL_EPSILON);
    CHECK(std::abs(rodas3_r(cplx(-1e6L, 0))) < 1e-5L);  // R(z) = O(1/z)
    // the stepper on y' = -q / rc with its exact Jacobian, h / rc = 10, 40 steps: R(-10)^40
    const double rc = 0.5;
    state1<double> q{1};
    const auto sys =
        odestep::with_jacobian(odestep_test::rc_circuit<double>{rc}, odestep_test::rc_jacobian<double>{rc});
    REQUIRE(odestep::integrate_n_steps(odestep::rodas3<state1<double>>{}, sys, q, 0.0, 5.0, 40).status ==
            odestep::status::ok);
    const long double expected = std::pow(rodas3_r(cplx(-10)).real(), 40.0L);
    // 40 steps of a few rounding errors each, through stage weights up to 4 (and long double is double on ARM)
    CHECK(std::fabs(static_cast<long double>(q[0]) / expected - 1) < 1e-12L);
}

TEST_CASE("rosenbrock: RODAS3 shows order 3, autonomous and not (df/dt by differences)") {
    auto error_exp_sin = [](std::size_t steps) {
        state3<double> y{1, 1, 0};
        const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
        REQUIRE(odestep::integrate_n_steps(odestep::rodas3<state3<double>>{}, sys, y, 0.0, 10.0 / double(steps), steps)
                    .status == odestep::status::ok);
        return std::fmax(std::fabs(y[0] - std::exp(std::sin(10.0))),
                         std::fmax(std::fabs(y[1] - std::cos(10.0)), std::fabs(y[2] - std::sin(10.0))));
    };
    std::array<double, 4> e{};
    for (std::size_t i = 0; i < 4; ++i) e[i] = error_exp_sin(100u << i);
    CHECK(odestep_test::fitted_order(e) == doctest::Approx(3.0).epsilon(0.03));
    auto error_forced = [](std::size_t steps) {
        state1<double> y{0};
        REQUIRE(odestep::integrate_n_steps(odestep::rodas3<state1<double>>{}, forced<double>{}, y, 0.0,
                                           10.0 / double(steps), steps)
                    .status == odestep::status::ok);
        return std::fabs(y[0] - std::sin(10.0));
    };
    for (std::size_t i = 0; i < 4; ++i) e[i] = error_forced(20u << i);
    MESSAGE("forced: " << e[0] << " ... " << e[3]);
    CHECK(odestep_test::fitted_order(e) == doctest::Approx(3.0).epsilon(0.05));
}

TEST_CASE("rosenbrock: RODAS3's embedded solution has order 2 exactly, and its error weights are KPP's (0, 0, 0, 1)") {
    auto embedded = odestep::tables::rodas3::table<real>;
    embedded.b = embedded.b_embedded;
    const auto r = conditions(embedded);
    CHECK(r.residual[0] <= 8 * LDBL_EPSILON);
    CHECK(r.residual[1] <= 8 * LDBL_EPSILON);
    CHECK(std::max(r.residual[2], r.residual[3]) > 1e-2L);  // not order 3
    // KPP's Rodas3: ros_E = (0, 0, 0, 1), ros_ELO = 3
    constexpr auto co = odestep::detail::transform_rosenbrock(odestep::tables::rodas3::table<double>);
    const double e[4] = {0, 0, 0, 1};
    for (std::size_t i = 0; i < 4; ++i) CHECK(co.e[i] == doctest::Approx(e[i]).epsilon(1e-15));
    CHECK(odestep::rodas3<state3<double>>::error_estimate);
    CHECK(odestep::rodas3<state3<double>>::embedded_order == 2);
}

TEST_CASE("rosenbrock: RODAS3's estimate is a local error of order 3, and the step with it is the plain step") {
    // one step of exp(sin t) (support/problems.hpp) from t = 0.3 with h = 0.1 / 2^k: |err| ~ C h^3
    using s3 = state3<double>;
    const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
    std::array<double, 4> errs{};
    std::array<double, 4> hs{};
    for (std::size_t k = 0; k < 4; ++k) {
        hs[k] = 0.1 / double(1u << k);
        s3 y = odestep_test::exp_sin::exact(0.3);
        s3 plain = y;
        s3 err{};
        REQUIRE(odestep::rodas3<s3>{}.step(sys, y, 0.3, hs[k], err) == odestep::status::ok);
        REQUIRE(odestep::rodas3<s3>{}.step(sys, plain, 0.3, hs[k]) == odestep::status::ok);
        CHECK(same_bits(y, plain));
        errs[k] = std::sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
    }
    const double slope = odestep_test::log_log_slope(hs, errs);
    MESSAGE("RODAS3 estimate: slope " << slope);
    CHECK(slope > 2.8);
    CHECK(slope < 3.2);
}

TEST_CASE("rosenbrock: at dt = 0.1 from Robertson's (1, 0, 0) the steps say ok, and the estimate says they are wrong") {
    // The fixed-step form promises a finite state and the method's cost, not accuracy: RODAS3 at dt = 0.1 ends
    // far from the solution (y1 ~ 1e57) with every status ok. The estimate is how a fixed-step caller sees it.
    using s3 = state3<double>;
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    const auto tol = odestep::tolerances<s3>::uniform(1e-3, 1e-9);
    s3 y{1, 0, 0};
    double worst = 0;
    for (int n = 0; n < 400; ++n) {
        const s3 before = y;
        s3 err{};
        REQUIRE(odestep::rodas3<s3>{}.step(sys, y, 0.1 * n, 0.1, err) == odestep::status::ok);
        worst = std::max(worst, odestep::scaled_error_norm(err, before, y, tol));
    }
    MESSAGE("largest scaled estimate " << worst << ", y1 at 40: " << y[0]);
    CHECK(std::fabs(y[0] / odestep_test::robertson_at_40[0] - 1) > 1);  // wrong, as the issue found
    CHECK(worst > 100);                                                 // and the estimate says so
}

TEST_CASE("rosenbrock: Rodas4 from Hairer & Wanner's transformed coefficients: order 4, embedded order 3, nodes") {
    constexpr auto t = odestep::tables::rodas4::table<real>;
    const auto r = conditions(t);
    for (std::size_t i = 0; i < 8; ++i) {
        INFO("condition " << i);
        CHECK(r.residual[i] <= 1e-13L);  // the published coefficients have 16 digits
    }
    auto embedded = t;
    embedded.b = t.b_embedded;
    const auto re = conditions(embedded);
    for (std::size_t i = 0; i < 4; ++i) CHECK(re.residual[i] <= 1e-13L);
    real worst_fourth = 0;
    for (std::size_t i = 4; i < 8; ++i) worst_fourth = std::max(worst_fourth, re.residual[i]);
    CHECK(worst_fourth > 1e-4L);  // the embedded solution is of order 3 exactly
    // rodas.f's nodes C2 = 0.386, C3 = 0.21, C4 = 0.63 (c5 = c6 = 1) and gamma_i (KPP's ros_Gamma)
    const real alpha[6] = {0, 0.386L, 0.21L, 0.63L, 1, 1};
    const real gamma[6] = {0.25L, -0.1043L, 0.1035L, -0.0362L, 0, 0};
    for (std::size_t i = 0; i < 6; ++i) {
        real a = 0;
        real g = 0;
        for (std::size_t j = 0; j < 6; ++j) {
            a += t.alpha[i][j];
            g += t.gamma[i][j];
        }
        CHECK(std::fabs(a - alpha[i]) < 1e-14L);
        CHECK(std::fabs(g - gamma[i]) < 1e-14L);
    }
    // and the transformation back gives the published a, C, m and KPP's error weights E = (0, 0, 0, 0, 0, 1)
    constexpr auto co = odestep::detail::transform_rosenbrock(t);
    using rd = odestep::tables::rodas4;
    for (std::size_t i = 0; i < 6; ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            CHECK(std::fabs(co.a[i][j] - rd::a<real>[i][j]) < 1e-13L);
            CHECK(std::fabs(co.gc[i][j] / t.gamma[0][0] - rd::c<real>[i][j]) < 1e-12L);
        }
        CHECK(std::fabs(co.e[i] - (i == 5 ? 1 : 0)) < 1e-13L);
    }
    // L-stable: R(z) = 1 + z b^T (I - z B)^-1 1 (B = alpha + Gamma) vanishes at infinity
    auto stability = [&](cplx z) {
        std::array<cplx, 6> x{};
        for (std::size_t i = 0; i < 6; ++i) {
            cplx sum = 1;
            for (std::size_t j = 0; j < i; ++j) sum += z * (t.alpha[i][j] + t.gamma[i][j]) * x[j];
            x[i] = sum / (cplx(1) - z * t.gamma[i][i]);
        }
        cplx acc = 0;
        for (std::size_t i = 0; i < 6; ++i) acc += t.b[i] * x[i];
        return cplx(1) + z * acc;
    };
    CHECK(std::abs(stability(cplx(-1e8L, 0))) < 1e-6L);
    long double worst = 0;
    for (long double y = 1e-3L; y <= 1e6L; y *= 1.3L) worst = std::max(worst, std::abs(stability(cplx(0, y))));
    CHECK(worst <= 1 + 1e-12L);
}

TEST_CASE("rosenbrock: Rodas4 shows order 4 with fixed steps") {
    auto error_exp_sin = [](std::size_t steps) {
        state3<double> y{1, 1, 0};
        const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
        REQUIRE(odestep::integrate_n_steps(odestep::rosenbrock<odestep::tables::rodas4, state3<double>>{}, sys, y, 0.0,
                                           10.0 / double(steps), steps)
                    .status == odestep::status::ok);
        return std::fmax(std::fabs(y[0] - std::exp(std::sin(10.0))),
                         std::fmax(std::fabs(y[1] - std::cos(10.0)), std::fabs(y[2] - std::sin(10.0))));
    };
    std::array<double, 4> e{};
    for (std::size_t i = 0; i < 4; ++i) e[i] = error_exp_sin(50u << i);
    MESSAGE("Rodas4: " << e[0] << " ... " << e[3] << ", order " << odestep_test::fitted_order(e));
    CHECK(odestep_test::fitted_order(e) == doctest::Approx(4.0).epsilon(0.05));
}

TEST_CASE("rosenbrock: RODAS3 on Robertson reaches Hairer & Wanner's values at t = 40, in double and float") {
    state3<double> y{1, 0, 0};
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    REQUIRE(odestep_test::robertson_schedule(odestep::rodas3<state3<double>>{}, sys, y, 40.0, 20).status ==
            odestep::status::ok);
    for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(y[i] / odestep_test::robertson_at_40[i] - 1) < 3e-5);
    CHECK(std::fabs(y[0] + y[1] + y[2] - 1) < 1e-14);
    state3<float> yf{1, 0, 0};
    REQUIRE(odestep_test::robertson_schedule(odestep::rodas3<state3<float>>{}, odestep_test::robertson{}, yf, 40.0f, 20)
                .status == odestep::status::ok);
    for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(double(yf[i]) / odestep_test::robertson_at_40[i] - 1) < 1e-3);
}

TEST_CASE("rosenbrock: every step makes exactly the published evaluations, one Jacobian and one factorization") {
    using s = state3<double>;
    using st = odestep::rodas3<s>;
    static_assert(st::rhs_evals_with_jacobian == 4);  // f(t, y), df/dt, stages 3 and 4 (stage 2 reuses stage 1)
    static_assert(st::rhs_evals_per_step == 4 + 3);
    static_assert(st::newton_iterations == 0 && st::factorizations_per_step == 1 && st::implicit);
    static_assert(odestep::check_stepper<st>());
    std::size_t calls = 0;
    std::size_t jacobians = 0;
    const counted<odestep_test::robertson> f{{}, &calls};
    auto j = [&](double t, const s& y, odestep::jacobian_t<s>& m) {
        ++jacobians;
        odestep_test::robertson_jacobian{}(t, y, m);
    };
    s y{1, 1e-5, 0};
    for (int n = 0; n < 5; ++n) {
        calls = 0;
        REQUIRE(st{}.step(f, y, 1e-3 * n, 1e-3) == odestep::status::ok);
        CHECK(calls == st::rhs_evals_per_step);
        calls = 0;
        jacobians = 0;
        REQUIRE(st{}.step(odestep::with_jacobian(f, j), y, 1e-3 * n, 1e-3) == odestep::status::ok);
        CHECK(calls == st::rhs_evals_with_jacobian);
        CHECK(jacobians == 1);
    }
}

TEST_CASE(
    "rosenbrock: NaN from f (first or a later stage) is non_finite, from J or a singular matrix "
    "singular_matrix; y kept bit for bit") {
    using s = state3<float>;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const odestep::rodas3<s> st;
    s y{1, 0.5f, 0.25f};
    const s before = y;
    CHECK(st.step([nan](float, const s&) { return s{nan, 0, 0}; }, y, 0, 0.1f) == odestep::status::non_finite);
    CHECK(same_bits(y, before));
    // finite at (t, y) and at t + delta, NaN at the third stage's time t + h
    auto late = [nan](float t, const s& v) { return t > 0.05f ? s{nan, 0, 0} : s{-v[0], -v[1], -v[2]}; };
    auto zero = [](float, const s&, odestep::jacobian_t<s>& m) { m = {}; };
    CHECK(st.step(odestep::with_jacobian(late, zero), y, 0, 0.1f) == odestep::status::non_finite);
    CHECK(same_bits(y, before));
    auto f = [](float, const s& v) { return s{-v[0], -v[1], -v[2]}; };
    auto nan_j = [nan](float, const s&, odestep::jacobian_t<s>& m) {
        m = {};
        m[2][0] = nan;
    };
    CHECK(st.step(odestep::with_jacobian(f, nan_j), y, 0, 0.1f) == odestep::status::singular_matrix);
    CHECK(same_bits(y, before));
    // gamma = 1/2, h = 0.5: J = 4 I makes I - h gamma J = 0
    auto four = [](float, const s&, odestep::jacobian_t<s>& m) { m = {{{4, 0, 0}, {0, 4, 0}, {0, 0, 4}}}; };
    CHECK(st.step(odestep::with_jacobian(f, four), y, 0, 0.5f) == odestep::status::singular_matrix);
    CHECK(same_bits(y, before));
}
