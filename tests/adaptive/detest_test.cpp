// SPDX-License-Identifier: BSL-1.0
// Tolerance proportionality on the DETEST classes A to E (Hull, Enright, Fellen & Sedgwick 1972, "Comparing
// numerical methods for ordinary differential equations", SIAM J. Numer. Anal. 9(4), 603-635): one or more
// problems per class, each with a closed-form solution in long double (detest_problems.hpp), independently of the
// library. The free-running loop (integrate_adaptive) runs DP 5(4), DOP853 and Cash-Karp 5(4) at
// rtol = atol = 1e-3 .. 1e-10 (float: 1e-3 .. 1e-5), every evaluation of f counted. Checked: the achieved
// error within a stated factor of the tolerance, the fitted log-log slope of error against tolerance near 1,
// the evaluations growing as the tolerance tightens, and the count of f calls against the engine's own
// counts of accepted and rejected steps. The double sweeps (about 2e5 evaluations in all) are in the "long"
// suite, run on the host only; the closed-form checks and the float runs also run on the emulated cores.
#include <doctest/doctest.h>
#include <odestep/adaptive/integrate_adaptive.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

#include "detest_problems.hpp"
#include "support/counting.hpp"
#include "support/order_fit.hpp"

namespace {

using odestep::status;
using namespace detest;

// ---------------------------------------------------------------------------------------------------------

constexpr double t_end = 20.0;  // DETEST's interval, [0, 20], for every problem here

struct run_result {
    status s;
    ld error;           // max over accepted steps and components of |y_i - exact_i| / (1 + |exact_i|)
    std::size_t calls;  // evaluations of f
    odestep::step_count accepted;
    odestep::step_count rejected;
};

// One free-running run of Method on Problem at rtol = atol = tol, every accepted state compared with the
// closed form. The error is measured in the tolerance's own scale: a step's error estimate is held below
// tol (1 + |y|) per component, so the global error is reported relative to 1 + |y|.
template <class Method, class Problem, class T>
run_result run(T tol) {
    using State = std::array<T, Problem::n>;
    std::size_t calls = 0;
    auto f = odestep_test::counted(Problem{}, &calls);
    odestep::adaptive_rk<Method, State> engine(odestep::tolerances<State>::uniform(tol, tol));
    State y = Problem::template start<T>();
    ld worst = 0;
    const auto observe = [&](T t, const State& u) {
        const auto ex = Problem::exact(static_cast<ld>(t));
        for (std::size_t i = 0; i < Problem::n; ++i) {
            const ld e = std::fabs(static_cast<ld>(u[i]) - ex[i]) / (1 + std::fabs(ex[i]));
            if (e > worst) worst = e;
        }
    };
    const auto r = odestep::integrate_adaptive(engine, f, y, T(0), static_cast<T>(t_end), observe);
    return {r.status, worst, calls, engine.accepted_steps(), engine.rejected_steps()};
}

// Least-squares slope of log(error) against log(tol) (tests/support/order_fit.hpp).
template <std::size_t K>
double fitted_slope(const std::array<double, K>& tols, const std::array<double, K>& errors) {
    return odestep_test::log_log_slope(tols, errors);
}

// Fitted slope of error against tolerance: 1 for tolerance proportionality (global error ~ h^p and
// h ~ tol^(1/p) for a pair that propagates order p with an estimate of order p, p = 5 and 8 here).
constexpr double slope_low = 0.7;
constexpr double slope_high = 1.3;
// DOP853 is far more accurate than asked at loose tolerances on the decaying problems A1, A2 and C1 (error
// 1e-5 to 1e-7 of the tolerance at 1e-3, against 1e-2 to 1e-4 at 1e-10), so its curve there is flatter:
// measured slopes 0.63 (A2), 0.72 (A1), 0.75 (C1); 0.88 to 1.28 on the other problems. Its lower limit is
// 0.55: the claim for DOP853 is then "never less accurate than proportional", with the bound above.
constexpr double slope_low_dop853 = 0.55;

template <class Method, class Problem>
void proportionality(const char* method) {
    constexpr std::size_t K = 8;
    std::array<double, K> tols{};
    std::array<double, K> errors{};
    std::size_t previous_calls = 0;
    for (std::size_t i = 0; i < K; ++i) {
        const double tol = std::pow(10.0, -static_cast<double>(i + 3));  // 1e-3 .. 1e-10
        const run_result r = run<Method, Problem>(tol);
        REQUIRE(r.s == status::ok);
        tols[i] = tol;
        errors[i] = static_cast<double>(r.error);
        MESSAGE(std::string(method) << " " << std::string(Problem::name) << " tol " << tol << " error " << errors[i]
                                    << " ratio " << errors[i] / tol << " f " << r.calls << " (" << r.accepted << "/"
                                    << r.rejected << ")");
        CHECK(errors[i] <= Problem::bound * tol);
        CHECK(errors[i] > 0.0);  // the run did compare something
        // Work grows (never falls) as the tolerance tightens.
        CHECK(r.calls >= previous_calls);
        previous_calls = r.calls;
        // Every evaluation is accounted for by the engine's counts: f at t0 and the first-step probe, then
        // (stages - 1) new stages per attempt, plus f at every accepted point but the last for a table
        // without FSAL (its first stage there).
        using engine = odestep::adaptive_rk<Method, std::array<double, Problem::n>>;
        const std::size_t attempts = static_cast<std::size_t>(r.accepted + r.rejected);
        const std::size_t expected = engine::fsal
                                         ? 2 + (engine::stages - 1) * attempts
                                         : 1 + static_cast<std::size_t>(r.accepted) + (engine::stages - 1) * attempts;
        CHECK(r.calls == expected);
    }
    const double slope = fitted_slope(tols, errors);
    MESSAGE(std::string(method) << " " << std::string(Problem::name) << " slope " << slope);
    CHECK(slope >= (std::is_same_v<Method, odestep::tables::dop853> ? slope_low_dop853 : slope_low));
    CHECK(slope <= slope_high);
    // Tightening the tolerance from 1e-3 to 1e-10 buys at least three orders of magnitude of accuracy (DOP853
    // on A2 reaches round-off, 2e-14, at 1e-10; all others gain more than four).
    CHECK(errors[K - 1] < 1e-3 * errors[0]);
}

template <class Problem>
void all_methods() {
    proportionality<odestep::tables::dormand_prince54, Problem>("DP5(4)");
    proportionality<odestep::tables::dop853, Problem>("DOP853");
    proportionality<odestep::tables::cash_karp54, Problem>("CK5(4)");
}

// float at float-sized tolerances 1e-3 .. 1e-5: the same bound against the same closed forms (float round-off,
// about 6e-8 per operation, stays well below 1e-5 over a few hundred steps).
template <class Method, class Problem>
void float_runs(const char* method) {
    double previous = 1.0;
    for (int e = 3; e <= 5; ++e) {
        const float tol = std::pow(10.0f, -static_cast<float>(e));
        const run_result r = run<Method, Problem>(tol);
        REQUIRE(r.s == status::ok);
        const double err = static_cast<double>(r.error);
        MESSAGE(std::string(method) << " float " << std::string(Problem::name) << " tol " << tol << " error " << err
                                    << " f " << r.calls);
        CHECK(err <= Problem::bound * static_cast<double>(tol));
        CHECK(err < previous);
        previous = err;
    }
}

// Central difference of Problem::exact against f at t, relative to 1 + |f|.
template <class Problem>
ld closed_form_residual(ld t) {
    const ld h = ld(1e-6);
    const auto up = Problem::exact(t + h);
    const auto down = Problem::exact(t - h);
    std::array<ld, Problem::n> d{};
    Problem{}(t, Problem::exact(t), d);
    ld worst = 0;
    for (std::size_t i = 0; i < Problem::n; ++i) {
        const ld diff = (up[i] - down[i]) / (2 * h);
        const ld e = std::fabs(diff - d[i]) / (1 + std::fabs(d[i]));
        if (e > worst) worst = e;
    }
    return worst;
}

template <class Problem>
void check_closed_form() {
    // At t = 0 the closed form is the initial value.
    const auto y0 = Problem::template start<ld>();
    const auto e0 = Problem::exact(0);
    for (std::size_t i = 0; i < Problem::n; ++i) CHECK(std::fabs(y0[i] - e0[i]) < ld(1e-15));
    // Along [0, 20] it satisfies y' = f(t, y): the central difference's truncation error is h^2 y''' / 6,
    // about 2e-13 times |y'''| at h = 1e-6 (|y'''| reaches 1e5 at D5's pericentre), its rounding about
    // 1e-19 / 1e-6 in long double (1e-16 / 1e-6 where long double is double). A wrong closed form (a sign, a factor) gives a residual of order 1.
    for (int k = 1; k <= 20; ++k) {
        const ld t = ld(k) - ld(0.37);
        CHECK(closed_form_residual<Problem>(t) < ld(1e-7));
    }
}

}  // namespace

TEST_CASE("DETEST: the closed forms used as references solve their equations") {
    check_closed_form<a1>();
    check_closed_form<a2>();
    check_closed_form<a3>();
    check_closed_form<a4>();
    check_closed_form<b2>();
    check_closed_form<c1>();
    check_closed_form<d1>();
    check_closed_form<d5>();
    check_closed_form<e1>();
    // Kepler's equation: E - e sin E = t to rounding (long double is double on the Cortex-M cores), also
    // many turns out and at e = 0.9.
    for (int k = 0; k <= 40; ++k) {
        const ld t = ld(k) * ld(0.5);
        const ld E = kepler_anomaly(ld(0.9), t);
        CHECK(std::fabs(E - ld(0.9) * std::sin(E) - t) < 64 * std::numeric_limits<ld>::epsilon() * (1 + t));
    }
    // DETEST E1's published initial values (Hull et al. 1972) agree with J_{1/2}(1), J_{1/2}'(1).
    const auto y = e1::exact(0);
    CHECK(std::fabs(y[0] - ld(0.6713967071418030)) < ld(1e-15));
    CHECK(std::fabs(y[1] - ld(0.09540051444747446)) < ld(1e-15));
}

TEST_CASE("DETEST class A: error proportional to the tolerance, 1e-3 .. 1e-10" * doctest::test_suite("long")) {
    all_methods<a1>();
    all_methods<a2>();
    all_methods<a3>();
    all_methods<a4>();
}

TEST_CASE("DETEST class B (B2): error proportional to the tolerance" * doctest::test_suite("long")) {
    all_methods<b2>();
}

TEST_CASE("DETEST class C (C1): error proportional to the tolerance" * doctest::test_suite("long")) {
    all_methods<c1>();
}

TEST_CASE("DETEST class D (D1, D5): error proportional to the tolerance" * doctest::test_suite("long")) {
    all_methods<d1>();
    all_methods<d5>();
}

TEST_CASE("DETEST class E (E1): error proportional to the tolerance" * doctest::test_suite("long")) {
    all_methods<e1>();
}

TEST_CASE("DETEST in float at float-sized tolerances (1e-3 .. 1e-5)") {
    float_runs<odestep::tables::dormand_prince54, a1>("DP5(4)");
    float_runs<odestep::tables::dormand_prince54, a3>("DP5(4)");
    float_runs<odestep::tables::dormand_prince54, b2>("DP5(4)");
    float_runs<odestep::tables::dormand_prince54, d1>("DP5(4)");
    float_runs<odestep::tables::dormand_prince54, e1>("DP5(4)");
    float_runs<odestep::tables::cash_karp54, a3>("CK5(4)");
    float_runs<odestep::tables::cash_karp54, d1>("CK5(4)");
}
