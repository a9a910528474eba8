// SPDX-License-Identifier: BSL-1.0
// The free-running adaptive loop (integrate_adaptive), dense output (dense_step, hermite_cubic) and sampling
// at chosen times (integrate_times): closed forms, the interpolants' orders fitted, the Arenstorf orbit.
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/order_fit.hpp"
#include "support/problems.hpp"

namespace {

using odestep::status;
using state2 = std::array<double, 2>;
using state3 = std::array<double, 3>;
using state4 = std::array<double, 4>;

template <class State>
odestep::tolerances<State> tol(double r, double a) {
    using T = typename State::value_type;
    return odestep::tolerances<State>::uniform(static_cast<T>(r), static_cast<T>(a));
}

using odestep_test::arenstorf;

// The error at the middle of one step of size h from the exact state at t = 0.3 (exp_sin), through the
// engine's accepted step and its interpolant; the tolerance is loose enough that the step is accepted.
template <class Method>
double midpoint_error(double h, double theta) {
    odestep::adaptive_rk<Method, state3> engine(tol<state3>(1e3, 1e3));
    engine.set_step_size(h);
    odestep::dense_step<Method, state3> dense;
    odestep_test::exp_sin f;
    const double t0 = 0.3;
    double t = t0;
    auto y = odestep_test::exp_sin::exact(t0);
    bool accepted = false;
    REQUIRE(engine.attempt(f, t, y, t0 + h, accepted, dense) == status::ok);
    REQUIRE(accepted);
    REQUIRE(t == t0 + h);
    REQUIRE(dense.complete(f, engine) == status::ok);
    state3 u;
    dense.at_theta(theta, u);
    return odestep_test::max_abs_difference(u, odestep_test::exp_sin::exact(t0 + theta * h));
}

template <class Method>
double interpolant_order(double theta, double h0 = 0.2) {
    std::array<double, 5> errors{};
    for (std::size_t i = 0; i < errors.size(); ++i) errors[i] = midpoint_error<Method>(h0 / std::pow(2.0, i), theta);
    MESSAGE("theta " << theta << " errors " << errors[0] << " .. " << errors[4]);
    return odestep_test::fitted_order(errors);
}

}  // namespace

TEST_CASE("dense output: the interpolants' local orders, fitted (DP 5(4): 5 = 4 + 1; DOP853: 8; Hermite: 4)") {
    // The local error of an order-q interpolant is O(h^(q+1)) (HNW I, Sec. II.6). The step's end value is of
    // order 5, so inside the step the interpolant's own error dominates.
    for (double theta : {0.3, 0.5, 0.8}) {
        const double dp5 = interpolant_order<odestep::tables::dormand_prince54>(theta);
        const double hermite_ck = interpolant_order<odestep::tables::cash_karp54>(theta);
        const double hermite_bs = interpolant_order<odestep::tables::bogacki_shampine32>(theta);
        MESSAGE("DP5 " << dp5 << "  Hermite/CK " << hermite_ck << "  Hermite/BS " << hermite_bs);
        CHECK(dp5 == doctest::Approx(5.0).epsilon(0.06));
        CHECK(hermite_ck == doctest::Approx(4.0).epsilon(0.06));
        // BS 3(2)'s own step is order 3 (local error h^4), as is the Hermite interpolant: 4 either way.
        CHECK(hermite_bs == doctest::Approx(4.0).epsilon(0.08));
        // DOP853's extension, order 7: local error h^8 (from h = 1.6, where the errors stay above rounding).
        const double d853 = interpolant_order<odestep::tables::dop853>(theta, 1.6);
        MESSAGE("DOP853 " << d853);
        CHECK(d853 == doctest::Approx(8.0).epsilon(0.08));
    }
}

TEST_CASE("hermite_cubic: exact for a cubic, matching both ends") {
    // y = t^3 - 2 t, y' = 3 t^2 - 2 on [1, 3]: a cubic is reproduced exactly (to rounding).
    using s1 = std::array<double, 1>;
    const auto y = [](double t) { return t * t * t - 2.0 * t; };
    const auto dy = [](double t) { return 3.0 * t * t - 2.0; };
    s1 out{};
    for (double theta : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        odestep::hermite_cubic(s1{y(1.0)}, s1{dy(1.0)}, s1{y(3.0)}, s1{dy(3.0)}, 2.0, theta, out);
        CHECK(out[0] == doctest::Approx(y(1.0 + 2.0 * theta)).epsilon(1e-14));
    }
}

TEST_CASE("integrate_adaptive: the oscillator, every accepted step observed, error at the tolerance") {
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state2> engine(tol<state2>(1e-10, 1e-10));
    state2 y{1.0, 0.0};
    const double t1 = 4.0 * M_PI;
    std::size_t seen = 0;
    double worst = 0.0;
    double last_t = -1.0;
    bool increasing = true;
    const auto r =
        odestep::integrate_adaptive(engine, odestep_test::harmonic{}, y, 0.0, t1, [&](double t, const state2& s) {
            increasing = increasing && t > last_t;
            last_t = t;
            ++seen;
            const double e = odestep_test::max_abs_difference(s, state2{std::cos(t), -std::sin(t)});
            worst = e > worst ? e : worst;
        });
    REQUIRE(r.status == status::ok);
    CHECK(r.t == t1);
    CHECK(last_t == t1);
    CHECK(increasing);
    CHECK(seen == r.steps + 1);
    CHECK(r.steps == engine.accepted_steps());
    CHECK(worst < 1e-8);
}

TEST_CASE("integrate_adaptive: bounded by max_attempts, NaN and bad arguments, the state the last good one") {
    SUBCASE("the attempt cap") {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state2> engine(tol<state2>(1e-10, 1e-10));
        state2 y{1.0, 0.0};
        state2 seen{};
        double seen_t = 0.0;
        const auto r = odestep::integrate_adaptive(
            engine, odestep_test::harmonic{}, y, 0.0, 100.0,
            [&](double t, const state2& s) {
                seen = s;
                seen_t = t;
            },
            5);
        CHECK(r.status == status::substep_limit);
        CHECK(r.t == seen_t);
        CHECK(odestep_test::same_bits(y, seen));
        CHECK(engine.accepted_steps() + engine.rejected_steps() == 5);
    }
    SUBCASE("NaN from f") {
        odestep::adaptive_rk<odestep::tables::cash_karp54, state2> engine(tol<state2>(1e-8, 1e-8));
        const auto poisoned = [](double t, const state2& y, state2& d) {
            d[0] = y[1];
            d[1] = t > 2.0 ? std::nan("") : -y[0];
        };
        state2 y{1.0, 0.0};
        state2 seen{};
        double seen_t = 0.0;
        const auto r = odestep::integrate_adaptive(engine, poisoned, y, 0.0, 5.0, [&](double t, const state2& s) {
            seen = s;
            seen_t = t;
        });
        CHECK(r.status == status::non_finite);
        CHECK(r.t == seen_t);
        CHECK(r.t <= 2.0);
        CHECK(odestep_test::same_bits(y, seen));
    }
    SUBCASE("bad arguments touch nothing") {
        std::size_t calls = 0;
        auto f = odestep_test::counted(odestep_test::harmonic{}, &calls);
        odestep::adaptive_rk<odestep::tables::cash_karp54, state2> engine(tol<state2>(0.0, 0.0));
        state2 y{1.0, 0.0};
        CHECK(odestep::integrate_adaptive(engine, f, y, 0.0, 1.0).status == status::invalid_tolerance);
        engine.set_tolerance(tol<state2>(1e-6, 1e-6));
        CHECK(odestep::integrate_adaptive(engine, f, y, 0.0, std::numeric_limits<double>::infinity()).status ==
              status::invalid_time);
        CHECK(odestep::integrate_adaptive(engine, f, y, 0.0, 1.0, 0).status == status::invalid_setting);
        CHECK(calls == 0);
    }
}

TEST_CASE("integrate_times: the states at chosen times, the steps unchanged") {
    const std::array<double, 6> times{0.0, 0.37, 1.0, 2.5, 2.5001, 7.0};
    for (int which = 0; which < 3; ++which) {
        CAPTURE(which);
        const auto run = [&](auto engine, double allowance) {
            using E = decltype(engine);
            E free_engine = engine;
            // The reference: integrate_adaptive to the last time.
            auto y_free = odestep_test::exp_sin::start<double>();
            double worst_free = 0.0;  // the largest error at the steps' ends
            REQUIRE(odestep::integrate_adaptive(free_engine, odestep_test::exp_sin{}, y_free, 0.0, 7.0,
                                                [&](double t, const state3& s) {
                                                    const double e = odestep_test::max_abs_difference(
                                                        s, odestep_test::exp_sin::exact(t));
                                                    worst_free = e > worst_free ? e : worst_free;
                                                })
                        .status == status::ok);
            auto y = odestep_test::exp_sin::start<double>();
            std::size_t k = 0;
            double worst = 0.0;
            bool same_times = true;
            const auto r = odestep::integrate_times(
                engine, odestep_test::exp_sin{}, y, 0.0, times, [&](double t, const state3& s) {
                    same_times = same_times && k < times.size() && t == times[k];
                    ++k;
                    const double e = odestep_test::max_abs_difference(s, odestep_test::exp_sin::exact(t));
                    worst = e > worst ? e : worst;
                });
            REQUIRE(r.status == status::ok);
            CHECK(k == times.size());
            CHECK(same_times);
            // Between the steps' ends: DP 5(4)'s extension adds little to the solution's own error; cubic
            // Hermite (order 3) between Cash-Karp's steps (chosen for its order 5) adds up to ~25 times that
            // error here (measured 1.1e-6 against 4.4e-8): the price of the generic interpolant.
            MESSAGE("interpolated " << worst << "  at the steps' ends " << worst_free);
            CHECK(worst < allowance * worst_free);
            // The same steps as without output times: the same count and the same final state, bit for bit.
            CHECK(engine.accepted_steps() == free_engine.accepted_steps());
            CHECK(odestep_test::same_bits(y, y_free));
        };
        if (which == 0)
            run(odestep::adaptive_rk<odestep::tables::dormand_prince54, state3>(tol<state3>(1e-8, 1e-8)), 2.0);
        if (which == 1) run(odestep::adaptive_rk<odestep::tables::cash_karp54, state3>(tol<state3>(1e-8, 1e-8)), 50.0);
        if (which == 2) run(odestep::adaptive_rk<odestep::tables::dop853, state3>(tol<state3>(1e-8, 1e-8)), 2.0);
    }
    SUBCASE("times out of order are refused before anything") {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state3> engine(tol<state3>(1e-8, 1e-8));
        auto y = odestep_test::exp_sin::start<double>();
        std::size_t seen = 0;
        const std::array<double, 3> bad{1.0, 0.5, 2.0};
        const auto r = odestep::integrate_times(engine, odestep_test::exp_sin{}, y, 0.0, bad,
                                                [&](double, const state3&) { ++seen; });
        CHECK(r.status == status::invalid_time);
        CHECK(seen == 0);
        const std::array<double, 2> not_finite{1.0, std::nan("")};
        CHECK(odestep::integrate_times(engine, odestep_test::exp_sin{}, y, 0.0, not_finite, [](double, const state3&) {
              }).status == status::invalid_time);
        // Forward from 0, a time before 0 is going back.
        const std::array<double, 2> before_start{-1.0, 2.0};
        CHECK(
            odestep::integrate_times(engine, odestep_test::exp_sin{}, y, 0.0, before_start, [](double, const state3&) {
            }).status == status::invalid_time);
        CHECK(engine.accepted_steps() == 0);
    }
}

TEST_CASE("Arenstorf orbit: one period with DP 5(4) and DOP853, error and evaluations per tolerance") {
    // The error is |y(T) - y(0)| (max norm over the four components); the evaluations are counted.
    const auto run = [](auto engine, double t) {
        std::size_t calls = 0;
        auto f = odestep_test::counted(arenstorf{}, &calls);
        auto y = arenstorf::start();
        const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, arenstorf::period);
        REQUIRE(r.status == status::ok);
        const double err = odestep_test::max_abs_difference(y, arenstorf::start());
        MESSAGE("tol " << t << "  error " << err << "  f evals " << calls << "  accepted " << engine.accepted_steps()
                       << "  rejected " << engine.rejected_steps());
        return err;
    };
    double previous_dp5 = 1e300;
    double previous_d853 = 1e300;
    for (int e = 3; e <= 11; e += 2) {
        const double t = std::pow(10.0, -e);
        const double dp5 = run(odestep::adaptive_rk<odestep::tables::dormand_prince54, state4>(tol<state4>(t, t)), t);
        const double d853 = run(odestep::adaptive_rk<odestep::tables::dop853, state4>(tol<state4>(t, t)), t);
        // The orbit amplifies local errors strongly (the close approaches to the light body), so the error at
        // T is far above the tolerance; what must hold is that it falls as the tolerance does.
        CHECK(dp5 < previous_dp5);
        CHECK(d853 < previous_d853);
        previous_dp5 = dp5;
        previous_d853 = d853;
    }
    CHECK(previous_dp5 < 1e-6);  // at 1e-11
    CHECK(previous_d853 < 1e-7);
}

TEST_CASE("integrate_adaptive and integrate_times in float, at float-sized tolerances") {
    using f2 = std::array<float, 2>;
    odestep::adaptive_rk<odestep::tables::dormand_prince54, f2> engine(tol<f2>(1e-5, 1e-6));
    f2 y{1.0f, 0.0f};
    const auto r = odestep::integrate_adaptive(engine, odestep_test::harmonic{}, y, 0.0f, 6.0f);
    REQUIRE(r.status == status::ok);
    CHECK(std::fabs(y[0] - std::cos(6.0f)) < 1e-4f);
    CHECK(std::fabs(y[1] + std::sin(6.0f)) < 1e-4f);
    odestep::adaptive_rk<odestep::tables::bogacki_shampine32, f2> bs(tol<f2>(1e-5, 1e-6));
    f2 z{1.0f, 0.0f};
    const std::array<float, 3> times{1.0f, 2.0f, 3.0f};
    float worst = 0.0f;
    const auto rt = odestep::integrate_times(bs, odestep_test::harmonic{}, z, 0.0f, times, [&](float t, const f2& s) {
        const float e = std::fabs(s[0] - std::cos(t));
        worst = e > worst ? e : worst;
    });
    REQUIRE(rt.status == status::ok);
    CHECK(worst < 1e-4f);
}

TEST_CASE("integrate_adaptive: a blow-up ends in step_too_small with the last accepted state") {
    // y' = y^2, y(0) = 1: y = 1 / (1 - t), infinite at t = 1; the steps shrink toward the blow-up until
    // they fall below ten ULPs of t.
    using s1 = std::array<double, 1>;
    odestep::adaptive_rk<odestep::tables::dormand_prince54, s1> engine(tol<s1>(1e-8, 1e-8));
    s1 y{1.0};
    s1 seen{};
    const auto r = odestep::integrate_adaptive(
        engine, [](double, const s1& v, s1& d) { d[0] = v[0] * v[0]; }, y, 0.0, 2.0,
        [&](double, const s1& v) { seen = v; });
    CHECK(r.status == status::step_too_small);
    // The numerical solution blows up within the tolerance's reach of t = 1 (measured: 1 + 2.2e-10).
    CHECK(std::fabs(r.t - 1.0) < 1e-6);
    CHECK(odestep_test::same_bits(y, seen));
    CHECK(y[0] > 1e8);
    CHECK(std::isfinite(y[0]));
}
