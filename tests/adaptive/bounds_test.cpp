// SPDX-License-Identifier: BSL-1.0
// The error bound of every embedded pair and every interpolant (issue 25): the largest global error, as a
// multiple of the tolerance, over the DETEST problems with closed forms (detest_problems.hpp) at
// rtol = atol = 1e-3 .. 1e-10. At the steps' ends (integrate_adaptive) for Bogacki-Shampine 3(2),
// Fehlberg 4(5), Cash-Karp 5(4), Dormand-Prince 5(4), Fehlberg 7(8) and DOP853; between them (integrate_times
// on 400 equally spaced times) for the interpolant each pair gets: DP 5(4)'s and DOP853's own continuous
// extensions, cubic Hermite for the others. The bounds are the measured largest ratios with a margin
// (docs/adaptive.md, "Error bounds", has the table); the sweep is in the host-only "long" suite.
#include <doctest/doctest.h>
#include <odestep/adaptive/integrate_adaptive.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "detest_problems.hpp"

namespace {

using odestep::status;
using namespace detest;

constexpr double t_end = 20.0;        // DETEST's interval
constexpr std::size_t samples = 400;  // output times for the interpolant, t_end i / samples
constexpr int tightest = 10;          // tolerances 1e-3 .. 1e-10

// The largest |y_i - exact_i| / (1 + |exact_i|) (the tolerance's scale) of one run at tol, at the accepted
// steps (dense false) or at the sample times from the interpolant (dense true).
template <class Method, class Problem>
ld worst_error(double tol, bool dense) {
    using State = std::array<double, Problem::n>;
    odestep::adaptive_rk<Method, State> engine(odestep::tolerances<State>::uniform(tol, tol));
    State y = Problem::template start<double>();
    ld worst = 0;
    const auto observe = [&](double t, const State& u) {
        const auto ex = Problem::exact(static_cast<ld>(t));
        for (std::size_t i = 0; i < Problem::n; ++i) {
            const ld e = std::fabs(static_cast<ld>(u[i]) - ex[i]) / (1 + std::fabs(ex[i]));
            if (e > worst) worst = e;
        }
    };
    status s;
    if (dense) {
        std::array<double, samples> times{};
        for (std::size_t i = 0; i < samples; ++i) times[i] = t_end * static_cast<double>(i + 1) / double(samples);
        s = odestep::integrate_times(engine, Problem{}, y, 0.0, times, observe).status;
    } else {
        s = odestep::integrate_adaptive(engine, Problem{}, y, 0.0, t_end, observe).status;
    }
    REQUIRE(s == status::ok);
    return worst;
}

struct worst_ratio {
    double ratio = 0.0;
    const char* problem = "";
    int exponent = 0;  // tol = 10^-exponent
};

template <class Method, class Problem>
void sweep(worst_ratio& w, bool dense) {
    for (int e = 3; e <= tightest; ++e) {
        const double tol = std::pow(10.0, -static_cast<double>(e));
        const double ratio = static_cast<double>(worst_error<Method, Problem>(tol, dense)) / tol;
        if (ratio > w.ratio) w = {ratio, Problem::name, e};
    }
}

// The smooth classes (A, B, C, E), whose global error stays near the tolerance, and the Kepler orbit D1,
// whose phase error grows along the run (detest_test.cpp derives why).
template <class Method>
void check_pair(const char* name, double steps_bound, double dense_bound, double d1_steps_bound,
                double d1_dense_bound) {
    for (const bool dense : {false, true}) {
        worst_ratio w;
        sweep<Method, a1>(w, dense);
        sweep<Method, a2>(w, dense);
        sweep<Method, a3>(w, dense);
        sweep<Method, a4>(w, dense);
        sweep<Method, b2>(w, dense);
        sweep<Method, c1>(w, dense);
        sweep<Method, e1>(w, dense);
        worst_ratio d;
        sweep<Method, d1>(d, dense);
        MESSAGE((std::string(name) + (dense ? " interpolant" : " steps") + ": A-C, E worst " + std::to_string(w.ratio) +
                 " (" + w.problem + " at 1e-" + std::to_string(w.exponent) + "); D1 worst " + std::to_string(d.ratio) +
                 " (at 1e-" + std::to_string(d.exponent) + ")"));
        CHECK(w.ratio <= (dense ? dense_bound : steps_bound));
        CHECK(d.ratio <= (dense ? d1_dense_bound : d1_steps_bound));
    }
}

}  // namespace

TEST_CASE("error bounds: every pair at its steps and its interpolant between them, DETEST 1e-3 .. 1e-10" *
          doctest::test_suite("long")) {
    // Bounds: 1.5 times the largest ratio measured (docs/adaptive.md), in the order steps, interpolant, D1
    // steps, D1 interpolant. Hermite after a pair of order 5 or 8 is not tolerance-proportional: its O(h^4)
    // error falls more slowly than the pair's as the tolerance tightens, so its bound is its ratio at 1e-10.
    check_pair<odestep::tables::bogacki_shampine32>("BS3(2)", 27, 27, 370, 370);  // 17.9, 17.9, 245, 245
    check_pair<odestep::tables::fehlberg45>("RKF4(5)", 38, 2100, 750, 950);       // 25.4, 1360, 502, 629
    check_pair<odestep::tables::cash_karp54>("CK5(4)", 12, 7200, 660, 670);       // 7.6, 4794, 435, 442
    check_pair<odestep::tables::dormand_prince54>("DP5(4)", 6, 19, 1300, 1500);   // 3.7, 12.3, 861, 984
    check_pair<odestep::tables::fehlberg78>("RKF7(8)", 2.5, 4.4e5, 33, 51000);    // 1.5, 2.9e5, 21.5, 33736
    check_pair<odestep::tables::dop853>("DOP853", 7.5, 28, 15, 16);               // 4.9, 18.2, 10.0, 10.4
}
