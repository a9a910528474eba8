// SPDX-License-Identifier: BSL-1.0
// Tolerance proportionality on the DETEST classes A to E (Hull, Enright, Fellen & Sedgwick 1972, "Comparing
// numerical methods for ordinary differential equations", SIAM J. Numer. Anal. 9(4), 603-635): one or more
// problems per class, each with a closed-form solution written here in long double, independently of the
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

#include "support/counting.hpp"
#include "support/order_fit.hpp"

namespace {

using odestep::status;
using ld = long double;

const ld pi_ld = std::acos(ld(-1));

// The error bound's factor, error <= bound * tol, per problem. The controller keeps each step's local error
// estimate below tol (1 + |y|), and a pair propagating its higher order (all three here) commits a local error
// far below its estimate; the global error is the sum of the local ones carried by the flow.
//
// Classes A, B, C, E (decaying or bounded, non-expanding flows): the global error stays near the tolerance.
// The largest ratio measured over these problems, the three methods and 1e-3 .. 1e-10 is 7.6 (Cash-Karp on
// A3, whose exp(sin t) swings by a factor e^2 every period); 10 leaves a little room and no more.
constexpr double smooth_bound = 10.0;
// Class D (Kepler orbits): a local error changes the energy, hence the period, and the phase error grows
// linearly with t; near pericentre it is multiplied by the speed and acceleration there. An energy error dE
// changes the mean motion by 3 dE (a = -1 / 2E, n = a^(-3/2)), so after 20 time units the phase is off by
// about 60 dE, and near pericentre (acceleration 1 / (1 - e)^2: 1.2 for D1, 100 for D5) the velocity by
// 60 dE / (1 - e)^2. One local error of size tol at pericentre changes E by v dv + dr / r^2, up to
// 5 tol (D1) and 130 tol (D5). Hence ratios of 10^2..10^3 for D1 and 10^4..10^5 for D5 with any method that
// controls the error per step (measured: up to 860 for D1, DP 5(4) at 1e-3, and 1.5e5 for D5, DP 5(4) at
// 1e-5). The bounds are about twice and three times those; the proportionality itself is checked by the
// slope, which is the claim here.

// ---------------------------------------------------------------------------------------------------------
// The problems. Each: n components, f templated on T, start<T>(), exact(t) in long double on [0, 20] (DETEST's
// interval for every problem used here). The closed forms are checked against f by central differences in
// the first test case.

// A1: y' = -y, y(0) = 1  =>  y = exp(-t).
struct a1 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = -y[0];
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {std::exp(-t)}; }
};

// A2: y' = -y^3 / 2, y(0) = 1  =>  y = 1 / sqrt(t + 1) (y^-2 = t + 1: d/dt y^-2 = -2 y^-3 y' = 1).
struct a2 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A2";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = -y[0] * y[0] * y[0] / T(2);
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {1 / std::sqrt(t + 1)}; }
};

// A3: y' = y cos t, y(0) = 1  =>  y = exp(sin t).
struct a3 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A3";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T t, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = y[0] * std::cos(t);
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {std::exp(std::sin(t))}; }
};

// A4: y' = (y / 4)(1 - y / 20), y(0) = 1  =>  the logistic curve y = 20 / (1 + 19 exp(-t / 4)).
struct a4 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A4";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = y[0] / T(4) * (T(1) - y[0] / T(20));
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {20 / (1 + 19 * std::exp(-t / 4))}; }
};

// B2: y' = A y, A = [[-1, 1, 0], [1, -2, 1], [0, 1, -1]], y(0) = (2, 0, 1). A is symmetric with eigenpairs
// 0: (1, 1, 1), -1: (1, 0, -1), -3: (1, -2, 1); y(0) = (1, 1, 1) + (1, 0, -1) / 2 + (1, -2, 1) / 2, so
// y = (1, 1, 1) + exp(-t) (1, 0, -1) / 2 + exp(-3t) (1, -2, 1) / 2.
struct b2 {
    static constexpr std::size_t n = 3;
    static constexpr const char* name = "B2";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 3>& y, std::array<T, 3>& d) const noexcept {
        d[0] = -y[0] + y[1];
        d[1] = y[0] - T(2) * y[1] + y[2];
        d[2] = y[1] - y[2];
    }
    template <class T>
    static std::array<T, 3> start() noexcept {
        return {T(2), T(0), T(1)};
    }
    static std::array<ld, 3> exact(ld t) noexcept {
        const ld a = std::exp(-t) / 2;
        const ld b = std::exp(-3 * t) / 2;
        return {1 + a + b, 1 - 2 * b, 1 - a + b};
    }
};

// C1: the decay chain y1' = -y1, yi' = y(i-1) - yi (i = 2..9), y10' = y9, y(0) = (1, 0, ..., 0). By induction
// yi = t^(i-1) exp(-t) / (i-1)! for i <= 9 (the Poisson probabilities), and y10 = 1 - (y1 + ... + y9) (the
// sum of f is zero).
struct c1 {
    static constexpr std::size_t n = 10;
    static constexpr const char* name = "C1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 10>& y, std::array<T, 10>& d) const noexcept {
        d[0] = -y[0];
        for (std::size_t i = 1; i < 9; ++i) d[i] = y[i - 1] - y[i];
        d[9] = y[8];
    }
    template <class T>
    static std::array<T, 10> start() noexcept {
        std::array<T, 10> y{};
        y[0] = T(1);
        return y;
    }
    static std::array<ld, 10> exact(ld t) noexcept {
        std::array<ld, 10> y{};
        ld term = std::exp(-t);  // t^k e^-t / k!, k = 0
        ld sum = 0;
        for (std::size_t k = 0; k < 9; ++k) {
            y[k] = term;
            sum += term;
            term *= t / static_cast<ld>(k + 1);
        }
        y[9] = 1 - sum;
        return y;
    }
};

// D1-D5: the Kepler problem x'' = -x / r^3 from (1 - e, 0) with velocity (0, sqrt((1 + e) / (1 - e))): an
// ellipse of semi-major axis 1 and eccentricity e (D1..D5: e = 0.1, 0.3, 0.5, 0.7, 0.9), period 2 pi. With
// the eccentric anomaly E from Kepler's equation E - e sin E = t (mean motion 1, pericentre at t = 0):
//   x = cos E - e, y = sqrt(1 - e^2) sin E, x' = -sin E / (1 - e cos E), y' = sqrt(1 - e^2) cos E / (1 - e cos E)
// (Danby, Fundamentals of Celestial Mechanics, ch. 6). E by Newton in long double from Danby's starter.
ld kepler_anomaly(ld e, ld mean) noexcept {
    const ld two_pi = 2 * pi_ld;
    const ld turns = std::floor(mean / two_pi + ld(0.5));
    const ld m = mean - turns * two_pi;  // in [-pi, pi]
    ld E = m + (m < 0 ? -ld(0.85) : ld(0.85)) * e;
    for (int i = 0; i < 60; ++i) {
        const ld step = (E - e * std::sin(E) - m) / (1 - e * std::cos(E));
        E -= step;
        if (std::fabs(step) <= 4 * std::numeric_limits<ld>::epsilon() * (1 + std::fabs(E))) break;
    }
    return E + turns * two_pi;
}

template <int Tenths>
struct kepler_d {
    static constexpr std::size_t n = 4;
    static constexpr const char* name = Tenths == 1   ? "D1"
                                        : Tenths == 3 ? "D2"
                                        : Tenths == 5 ? "D3"
                                        : Tenths == 7 ? "D4"
                                                      : "D5";
    static constexpr double bound = Tenths == 1 ? 2e3 : 5e5;
    template <class T>
    void operator()(T, const std::array<T, 4>& y, std::array<T, 4>& d) const noexcept {
        const T r2 = y[0] * y[0] + y[1] * y[1];
        const T r3 = r2 * std::sqrt(r2);
        d[0] = y[2];
        d[1] = y[3];
        d[2] = -y[0] / r3;
        d[3] = -y[1] / r3;
    }
    template <class T>
    static std::array<T, 4> start() noexcept {
        const ld e = ld(Tenths) / 10;
        return {static_cast<T>(1 - e), T(0), T(0), static_cast<T>(std::sqrt((1 + e) / (1 - e)))};
    }
    static std::array<ld, 4> exact(ld t) noexcept {
        const ld e = ld(Tenths) / 10;
        const ld E = kepler_anomaly(e, t);
        const ld s = std::sin(E);
        const ld c = std::cos(E);
        const ld b = std::sqrt(1 - e * e);
        const ld q = 1 - e * c;
        return {c - e, b * s, -s / q, b * c / q};
    }
};
using d1 = kepler_d<1>;
using d5 = kepler_d<9>;

// E1: y'' + y' / (t + 1) + (1 - 1 / (4 (t + 1)^2)) y = 0, Bessel's equation of order 1/2 in x = t + 1, with
// y(0) = J_{1/2}(1) and y'(0) = J_{1/2}'(1), so y = J_{1/2}(t + 1) = sqrt(2 / (pi x)) sin x (Abramowitz &
// Stegun 10.1.11). DETEST's initial values 0.6713967071418030, 0.09540051444747446 are these to 16 digits.
struct e1 {
    static constexpr std::size_t n = 2;
    static constexpr const char* name = "E1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T t, const std::array<T, 2>& y, std::array<T, 2>& d) const noexcept {
        const T x = t + T(1);
        d[0] = y[1];
        d[1] = -(y[1] / x + (T(1) - T(1) / (T(4) * x * x)) * y[0]);
    }
    template <class T>
    static std::array<T, 2> start() noexcept {
        const auto y = exact(0);
        return {static_cast<T>(y[0]), static_cast<T>(y[1])};
    }
    static std::array<ld, 2> exact(ld t) noexcept {
        const ld x = t + 1;
        const ld k = std::sqrt(2 / pi_ld);
        const ld r = std::sqrt(x);
        return {k * std::sin(x) / r, k * (std::cos(x) / r - std::sin(x) / (2 * x * r))};
    }
};

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
