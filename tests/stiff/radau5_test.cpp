// SPDX-License-Identifier: BSL-1.0
// Host only: error-controlled Radau IIA 5 (odestep::radau5, radau5_substeps, the free-running loops) from the
// natural initial conditions of the stiff test problems, against published or independently computed
// references; its constants against independent computations; its failures.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/counting.hpp"
#include "support/order_fit.hpp"
#include "support/stiff_engine_checks.hpp"
#include "support/stiff_problems.hpp"

namespace {

using odestep_test::state2;
using odestep_test::state3;
using odestep_test::state8;
using S3 = state3<double>;

// Robertson at t = 40 and t = 1e5 from (1, 0, 0): SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-12,
// atol=1e-20, exact Jacobian), run once for these tests (LSODA at the same tolerances agrees to 5e-12
// relative in every component at t = 40, to 5e-11 at t = 1e5). Hairer & Wanner's ten digits at t = 40
// (support/stiff_problems.hpp) agree to their last digit.
constexpr std::array<double, 3> robertson_40{0.7158270687194083, 9.185534764557791e-06, 0.28416374574583075};
constexpr std::array<double, 3> robertson_1e5{0.017865921142100307, 7.274751468436623e-08, 0.982134006110391};

template <std::size_t N>
double worst_relative(const std::array<double, N>& y, const std::array<double, N>& reference) {
    double worst = 0;
    for (std::size_t i = 0; i < N; ++i) worst = std::fmax(worst, std::fabs(y[i] / reference[i] - 1));
    return worst;
}

static_assert(odestep::check_stepper<odestep::radau5_substeps<S3>>());
static_assert(odestep::is_stepper_v<odestep::radau5_substeps<S3>>);
static_assert(odestep::radau5_substeps<S3>::rhs_evals_per_step ==
              2 + 1000 * (3 + 3 * odestep::radau5<S3>::max_newton_iterations + 2));

// ---- the constants, each against a computation that does not use them

TEST_CASE("radau5 constants: T^-1 T = I and T^-1 A^-1 T is the block form of gamma and alpha +- i beta") {
    using L = long double;
    using co = odestep::tables::radau5_coefficients<L>;
    constexpr auto tab = odestep::tables::radau_iia5::table<L>;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            L p = 0;
            for (std::size_t k = 0; k < 3; ++k) p += co::t_inv[i][k] * co::t[k][j];
            CHECK(std::fabs(p - (i == j ? 1.0L : 0.0L)) < 1e-17L);
        }
    // A^-1 column by column through the library's LU (an independent path from the typed eigenvalues)
    odestep::linalg::matrix<L, 3> a = tab.a;
    odestep::linalg::pivots<3> piv{};
    REQUIRE(odestep::linalg::lu_factor(a, piv) == odestep::status::ok);
    odestep::linalg::matrix<L, 3> ainv{};
    for (std::size_t j = 0; j < 3; ++j) {
        std::array<L, 3> e{};
        e[j] = 1;
        odestep::linalg::lu_solve(a, piv, e);
        for (std::size_t i = 0; i < 3; ++i) ainv[i][j] = e[i];
    }
    const L expected[3][3] = {{co::gamma, 0, 0}, {0, co::alpha, -co::beta}, {0, co::beta, co::alpha}};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            L p = 0;
            for (std::size_t k = 0; k < 3; ++k)
                for (std::size_t m = 0; m < 3; ++m) p += co::t_inv[i][k] * ainv[k][m] * co::t[m][j];
            CHECK(std::fabs(p - expected[i][j]) < 1e-15L);
        }
}

TEST_CASE("radau5 constants: gamma and alpha + i beta are the roots of det(I - z A), the (3,2)-Pade denominator") {
    // Q(z) = 1 - 3z/5 + 3z^2/20 - z^3/60 (HW II Sec. IV.5: the Radau IIA 5 stability function is the (2,3)
    // Pade approximant (1 + 2z/5 + z^2/20) / Q(z) of e^z); evaluated in complex arithmetic.
    using L = long double;
    using co = odestep::tables::radau5_coefficients<L>;
    auto q = [](L x, L y, L& qr, L& qi) {
        // powers of z = x + i y
        const L z2r = x * x - y * y, z2i = 2 * x * y;
        const L z3r = z2r * x - z2i * y, z3i = z2r * y + z2i * x;
        qr = 1 - 3 * x / 5 + 3 * z2r / 20 - z3r / 60;
        qi = -3 * y / 5 + 3 * z2i / 20 - z3i / 60;
    };
    L qr = 0, qi = 0;
    q(co::gamma, 0, qr, qi);
    CHECK(std::fabs(qr) < 1e-17L);
    q(co::alpha, co::beta, qr, qi);
    CHECK(std::fabs(qr) < 1e-17L);
    CHECK(std::fabs(qi) < 1e-17L);
}

TEST_CASE("radau5 constants: the table's stability function is the Pade form, its order and stage order hold") {
    using L = long double;
    constexpr auto tab = odestep::tables::radau_iia5::table<L>;
    // R(z) = 1 + z b^T (I - z A)^-1 1, solved with the library's LU, against the closed form
    for (L z : {-0.5L, -3.0L, -40.0L, -1e4L, 0.7L}) {
        odestep::linalg::matrix<L, 3> m{};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) m[i][j] = (i == j ? 1 : 0) - z * tab.a[i][j];
        odestep::linalg::pivots<3> piv{};
        REQUIRE(odestep::linalg::lu_factor(m, piv) == odestep::status::ok);
        std::array<L, 3> ones{1, 1, 1};
        odestep::linalg::lu_solve(m, piv, ones);
        const L r = 1 + z * (tab.b[0] * ones[0] + tab.b[1] * ones[1] + tab.b[2] * ones[2]);
        const L pade = (1 + 2 * z / 5 + z * z / 20) / (1 - 3 * z / 5 + 3 * z * z / 20 - z * z * z / 60);
        CHECK(std::fabs(r - pade) < 1e-16L * (1 + std::fabs(pade)));
    }
    // B(5): sum b_i c_i^(k-1) = 1/k; C(3): sum_j a_ij c_j^(k-1) = c_i^k / k
    for (int k = 1; k <= 5; ++k) {
        L s = 0;
        for (std::size_t i = 0; i < 3; ++i) s += tab.b[i] * std::pow(tab.c[i], L(k - 1));
        CHECK(std::fabs(s - 1.0L / k) < 1e-17L);
    }
    for (int k = 1; k <= 3; ++k)
        for (std::size_t i = 0; i < 3; ++i) {
            L s = 0;
            for (std::size_t j = 0; j < 3; ++j) s += tab.a[i][j] * std::pow(tab.c[j], L(k - 1));
            CHECK(std::fabs(s - std::pow(tab.c[i], L(k)) / k) < 1e-17L);
        }
}

TEST_CASE("radau5 constants: the estimate's weights e make h f0 + e.Z vanish to O(h^4): 1 + e.c = e.c^2 = e.c^3 = 0") {
    // With stage order 3, Z_i = h sum_j a_ij f(t + c_j h) and A c^(k-1) = c^k / k, the bracket of the estimate is
    // h (f0 + sum_i e_i (c_i f0 + c_i^2 h f0' / 2 + c_i^3 h^2 f0'' / 6) + O(h^3)): zero for these three conditions,
    // which determine e uniquely (a Vandermonde system).
    using L = long double;
    using co = odestep::tables::radau5_coefficients<L>;
    constexpr auto tab = odestep::tables::radau_iia5::table<L>;
    L s1 = 1, s2 = 0, s3 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        s1 += co::e[i] * tab.c[i];
        s2 += co::e[i] * tab.c[i] * tab.c[i];
        s3 += co::e[i] * tab.c[i] * tab.c[i] * tab.c[i];
    }
    CHECK(std::fabs(s1) < 1e-17L);
    CHECK(std::fabs(s2) < 1e-17L);
    CHECK(std::fabs(s3) < 1e-17L);
}

TEST_CASE("radau5: the collocation polynomial is exact for a cubic solution, at any output time") {
    // y' = 3 t^2 + 1, y(0) = 0: y = t^3 + t, a cubic, which the collocation polynomial of degree 3 reproduces
    using S1 = std::array<double, 1>;
    auto f = [](double t, const S1&) { return S1{3 * t * t + 1}; };
    odestep::radau5<S1> engine(odestep::tolerances<S1>::uniform(1e-3, 1e-3));
    std::array<double, 7> times{0.05, 0.3, 0.77, 1.0, 1.4, 2.2, 3.0};
    std::size_t seen = 0;
    double worst = 0;
    S1 y{0};
    const auto r = odestep::integrate_times(engine, f, y, 0.0, times, [&](double t, const S1& u) {
        worst = std::fmax(worst, std::fabs(u[0] - (t * t * t + t)));
        ++seen;
    });
    CHECK(r.status == odestep::status::ok);
    CHECK(seen == times.size());
    CHECK(worst < 1e-12);
}

// ---- Robertson from (1, 0, 0)

TEST_CASE("radau5_substeps: Robertson from (1, 0, 0) on a 0.1 grid to 40, error <= 10 rtol, slope near 1") {
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    const std::array<double, 3> rtols{1e-4, 1e-6, 1e-8};
    std::array<double, 3> errors{};
    for (std::size_t k = 0; k < 3; ++k) {
        // atol 1e-6 rtol: y2 ~ 1e-5 is measured relatively
        odestep::radau5_substeps<S3> stepper(odestep::tolerances<S3>::uniform(rtols[k], rtols[k] * 1e-6));
        S3 y{1, 0, 0};
        double mass = 0;
        const auto r = odestep::integrate(stepper, sys, y, 0.0, 40.0, 0.1, [&](double, const S3& u) {
            mass = std::fmax(mass, std::fabs(u[0] + u[1] + u[2] - 1));
        });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.steps == 400);
        errors[k] = worst_relative(y, robertson_40);
        MESSAGE("rtol " << rtols[k] << ": worst relative error " << errors[k] << ", accepted "
                        << stepper.engine().accepted_steps() << ", rejected " << stepper.engine().rejected_steps());
        CHECK(errors[k] <= 10 * rtols[k]);
        CHECK(mass < 1e-12);
    }
    const double slope = odestep_test::log_log_slope(rtols, errors);
    MESSAGE("slope of the error against rtol: " << slope);
    CHECK(slope >= 0.7);
    CHECK(slope <= 1.3);
}

TEST_CASE("radau5_substeps: Robertson from (1, 0, 0) on a 1.0 grid to 1e5, every interval ok") {
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    odestep::radau5_substeps<S3> stepper(odestep::tolerances<S3>::uniform(1e-6, 1e-12));
    S3 y{1, 0, 0};
    const auto r = odestep::integrate(stepper, sys, y, 0.0, 1e5, 1.0);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.steps == 100000);
    const double err = worst_relative(y, robertson_1e5);
    MESSAGE("worst relative error at 1e5: " << err);
    CHECK(err <= 1e-5);
}

TEST_CASE("radau5_substeps: exp(sin t) on a 1.0 grid to 20: error <= 100 rtol over the grid, slope near 1") {
    // a smooth problem with a closed-form solution (support/problems.hpp), on a grid coarse enough that the
    // error control, not the grid, sets the steps
    const std::array<double, 3> rtols{1e-4, 1e-6, 1e-8};
    const std::array<double, 3> errors = odestep_test::check_exp_sin_on_grid<odestep::radau5_substeps>(rtols);
    const double slope = odestep_test::log_log_slope(rtols, errors);
    MESSAGE("slope of the error against rtol: " << slope);
    CHECK(slope >= 0.7);
    CHECK(slope <= 1.3);
}

TEST_CASE("radau5_substeps: Robertson with a difference Jacobian (f alone) on a 0.1 grid to 40") {
    odestep::radau5_substeps<S3> stepper(odestep::tolerances<S3>::uniform(1e-6, 1e-12));
    S3 y{1, 0, 0};
    const auto r = odestep::integrate(stepper, odestep_test::robertson{}, y, 0.0, 40.0, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(worst_relative(y, robertson_40) <= 1e-5);
}

TEST_CASE("radau5: Robertson to 1e11 on a logarithmic grid, against the Test Set's reference") {
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    odestep::radau5<S3> engine(odestep::tolerances<S3>::uniform(1e-8, 1e-14));
    std::array<double, 12> times{};
    for (std::size_t i = 0; i < times.size(); ++i) times[i] = std::pow(10.0, double(i));
    S3 y{1, 0, 0};
    std::size_t seen = 0;
    const auto r = odestep::integrate_times(engine, sys, y, 0.0, times, [&](double, const S3& u) {
        CHECK(std::fabs(u[0] + u[1] + u[2] - 1) < 1e-12);
        ++seen;
    });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(seen == times.size());
    const double err = worst_relative(y, odestep_test::robertson_at_1e11);
    MESSAGE("worst relative error at 1e11: " << err << " after " << r.steps << " steps");
    CHECK(err <= 1e-6);
}

TEST_CASE("radau5: Robertson to 40 at rtol 1e-6: the work against SciPy Radau's anchor (839 f / 36 J / 128 LU)") {
    std::size_t calls = 0;
    const auto sys = odestep::with_jacobian(odestep_test::counted(odestep_test::robertson{}, &calls),
                                            odestep_test::robertson_jacobian{});
    odestep::radau5<S3> engine(odestep::tolerances<S3>::uniform(1e-6, 1e-12));  // SciPy's anchor: the same tolerances
    S3 y{1, 0, 0};
    const auto r = odestep::integrate_adaptive(engine, sys, y, 0.0, 40.0);
    REQUIRE(r.status == odestep::status::ok);
    const double err = worst_relative(y, robertson_40);
    const auto lu = 2 * engine.decompositions();  // one real and one complex factorization each, as SciPy counts
    MESSAGE("f " << calls << ", Jacobians " << engine.jacobian_evaluations() << ", LU " << lu << ", accepted "
                 << engine.accepted_steps() << ", rejected " << engine.rejected_steps() << ", Newton iterations "
                 << engine.newton_iterations() << ", worst relative error " << err);
    CHECK(calls <= 839 * 3 / 2);
    CHECK(double(engine.jacobian_evaluations()) <= 0.4 * double(engine.accepted_steps()));
    CHECK(err <= 1e-5);
}

TEST_CASE("radau5_substeps: float Robertson at rtol 1e-3 on a 0.1 grid to 40, within 1e-2") {
    using F3 = state3<float>;
    odestep::radau5_substeps<F3> stepper(odestep::tolerances<F3>::uniform(1e-3f, 1e-9f));
    F3 y{1, 0, 0};
    const auto r = odestep::integrate(stepper, odestep_test::robertson{}, y, 0.0f, 40.0f, 0.1f);
    REQUIRE(r.status == odestep::status::ok);
    double worst = 0;
    for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(double(y[i]) / robertson_40[i] - 1));
    MESSAGE("float: worst relative error " << worst);
    CHECK(worst <= 1e-2);
}

// ---- Van der Pol (mu = 1000), HIRES, OREGO

TEST_CASE("radau5_substeps: Van der Pol mu = 1000 from (2, 0) on a 0.1 grid to 2000, |y1| <= 2.1 throughout") {
    const auto sys = odestep::with_jacobian(odestep_test::van_der_pol{}, odestep_test::van_der_pol_jacobian{});
    using S2 = state2<double>;
    odestep::radau5_substeps<S2> stepper(odestep::tolerances<S2>::uniform(1e-7, 1e-7));
    S2 y{2, 0};
    double largest = 0;
    const auto r = odestep::integrate(stepper, sys, y, 0.0, 2000.0, 0.1,
                                      [&](double, const S2& u) { largest = std::fmax(largest, std::fabs(u[0])); });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(largest <= 2.1);
    const double err = worst_relative(y, odestep_test::van_der_pol_at_2000);
    MESSAGE("Van der Pol: worst relative error at 2000 " << err << ", accepted " << stepper.engine().accepted_steps());
    CHECK(err <= 1e-3);
}

TEST_CASE("radau5_substeps: HIRES on a 0.1 grid to 321.8122, against the Test Set") {
    const auto sys = odestep::with_jacobian(odestep_test::hires{}, odestep_test::hires_jacobian{});
    using S8 = state8<double>;
    odestep::radau5_substeps<S8> stepper(odestep::tolerances<S8>::uniform(1e-7, 1e-7));
    S8 y = odestep_test::hires_start;
    const auto r = odestep::integrate(stepper, sys, y, 0.0, 321.8122, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    const double err = worst_relative(y, odestep_test::hires_at_end);
    MESSAGE("HIRES: worst relative error " << err);
    CHECK(err <= 1e-5);
}

TEST_CASE("radau5_substeps: OREGO from (1, 2, 3) on a 0.1 grid to 360, against the Test Set") {
    const auto sys = odestep::with_jacobian(odestep_test::orego{}, odestep_test::orego_jacobian{});
    odestep::radau5_substeps<S3> stepper(odestep::tolerances<S3>::uniform(1e-7, 1e-7));
    S3 y{1, 2, 3};
    const auto r = odestep::integrate(stepper, sys, y, 0.0, 360.0, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    const double err = worst_relative(y, odestep_test::orego_at_360);
    MESSAGE("OREGO: worst relative error " << err);
    CHECK(err <= 1e-4);
}

TEST_CASE("radau5: an exactly singular E1 is a rejected attempt with h halved, then the run goes on") {
    // y' = gamma y with J = gamma and a first step of exactly 1: E1 = (gamma / h) I - J is zero, in any T
    using S1 = std::array<double, 1>;
    const double g = odestep::tables::radau5_coefficients<double>::gamma;
    auto f = [g](double, const S1& y) { return S1{g * y[0]}; };
    auto j = [g](double, const S1&, odestep::jacobian_t<S1>& m) { m[0][0] = g; };
    odestep::radau5<S1> engine(odestep::tolerances<S1>::uniform(1e-8, 1e-8));
    engine.set_step_size(1.0);
    S1 y{1};
    const auto r = odestep::integrate_adaptive(engine, odestep::with_jacobian(f, j), y, 0.0, 1.0);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(engine.rejected_steps() >= 1);
    CHECK(y[0] == doctest::Approx(std::exp(g)).epsilon(1e-6));
}

TEST_CASE("radau5_substeps and rodas4_substeps: Prothero-Robinson with lambda = -1e6 on a 0.1 grid, exact sin t") {
    // y' = lambda (y - sin t) + cos t, y(0) = 0: y = sin t (support/stiff_problems.hpp), a closed form
    using S1 = std::array<double, 1>;
    const auto sys = odestep::with_jacobian(odestep_test::prothero_robinson<double>{-1e6},
                                            odestep_test::prothero_robinson_jacobian<double>{-1e6});
    for (double rtol : {1e-4, 1e-6, 1e-8}) {
        double worst_radau = 0;
        double worst_rodas = 0;
        odestep::radau5_substeps<S1> radau(odestep::tolerances<S1>::uniform(rtol, rtol));
        odestep::rodas4_substeps<S1> rodas(odestep::tolerances<S1>::uniform(rtol, rtol));
        S1 y{0};
        S1 z{0};
        REQUIRE(odestep::integrate(radau, sys, y, 0.0, 10.0, 0.1, [&](double t, const S1& u) {
                    worst_radau = std::fmax(worst_radau, std::fabs(u[0] - std::sin(t)));
                }).status == odestep::status::ok);
        REQUIRE(odestep::integrate(rodas, sys, z, 0.0, 10.0, 0.1, [&](double t, const S1& u) {
                    worst_rodas = std::fmax(worst_rodas, std::fabs(u[0] - std::sin(t)));
                }).status == odestep::status::ok);
        MESSAGE("rtol " << rtol << ": Radau " << worst_radau << ", Rodas4 " << worst_rodas);
        CHECK(worst_radau <= 10 * rtol);
        CHECK(worst_rodas <= 10 * rtol);
    }
}

// ---- failures: a clear status, y bit for bit as it was

TEST_CASE("radau5_substeps: NaN from f, NaN in the Jacobian and the attempt cap leave y bit for bit") {
    SUBCASE("f gives NaN past t = 1.05: non_finite on the interval that reaches it") {
        odestep_test::check_nan_past_a_time<odestep::radau5_substeps>();
    }
    SUBCASE("a Jacobian with NaN: singular_matrix") { odestep_test::check_nan_jacobian<odestep::radau5_substeps>(); }
    SUBCASE("the attempt cap: substep_limit, y as given") {
        odestep_test::check_attempt_cap<odestep::radau5_substeps, 4>();
    }
    SUBCASE("bad settings are refused before anything is evaluated") {
        odestep_test::check_bad_newton_settings<odestep::radau5_substeps>();
    }
}

}  // namespace
