// SPDX-License-Identifier: BSL-1.0
// Error control (adaptive/control.hpp) and the course's adaptive stepper (adaptive/adaptive_rk.hpp): the norm
// and controller against hand computations, closed-form solutions to the tolerance, counted evaluations,
// rejection at a sharp change, the substep cap and NaN with their roll-backs, the driving loops and events.
#include <doctest/doctest.h>
#include <odestep/adaptive/adaptive_rk.hpp>
#include <odestep/events/events.hpp>
#include <odestep/integrate.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/problems.hpp"

namespace {

using odestep::status;
using state1 = std::array<double, 1>;
using state2 = std::array<double, 2>;
using state3 = std::array<double, 3>;

// y' = -y: y = exp(-t) from y(0) = 1.
struct decay {
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& dydt) const noexcept {
        dydt[0] = -y[0];
    }
};

// y' = 1000 / (1 + 10^6 (t - 1)^2): y = atan(1000 (t - 1)) + y(0) - atan(-1000) (differentiate atan).
// Flat except for a jump of almost pi inside |t - 1| < 0.01: a step size chosen on the flat part fails there.
struct sharp_step {
    template <class T>
    void operator()(T t, const std::array<T, 1>&, std::array<T, 1>& dydt) const noexcept {
        const T s = T(1000) * (t - T(1));
        dydt[0] = T(1000) / (T(1) + s * s);
    }
    template <class T>
    static T exact(T t) noexcept {
        return std::atan(T(1000) * (t - T(1))) - std::atan(T(-1000));
    }
};

template <class State>
odestep::tolerances<State> tol(double r, double a) {
    using T = typename State::value_type;
    return odestep::tolerances<State>::uniform(static_cast<T>(r), static_cast<T>(a));
}

}  // namespace

static_assert(odestep::check_stepper<odestep::cash_karp54_substeps<state2>>());
static_assert(odestep::check_stepper<odestep::dormand_prince54_substeps<std::array<float, 3>>>());
static_assert(odestep::check_stepper<odestep::adaptive_substeps<odestep::tables::bogacki_shampine32, state1, 8>>());
static_assert(odestep::adaptive_rk<odestep::tables::dormand_prince54, state1>::fsal);
static_assert(odestep::adaptive_rk<odestep::tables::bogacki_shampine32, state1>::fsal);
static_assert(!odestep::adaptive_rk<odestep::tables::cash_karp54, state1>::fsal);
static_assert(!odestep::adaptive_rk<odestep::tables::dop853, state1>::fsal);
// The estimate orders: min(p, phat) + 1 for a pair, 8 for DOP853's combined norm.
static_assert(odestep::adaptive_rk<odestep::tables::dormand_prince54, state1>::estimate_order == 5);
static_assert(odestep::adaptive_rk<odestep::tables::bogacki_shampine32, state1>::estimate_order == 3);
static_assert(odestep::adaptive_rk<odestep::tables::fehlberg78, state1>::estimate_order == 8);
static_assert(odestep::adaptive_rk<odestep::tables::dop853, state1>::estimate_order == 8);
// The worst case of one interval: 2 to start, then 6 new stages per attempt (DP 5(4), FSAL) or all 6 (Cash-Karp).
static_assert(odestep::adaptive_substeps<odestep::tables::dormand_prince54, state1, 10>::rhs_evals_per_step == 62);
static_assert(odestep::adaptive_substeps<odestep::tables::cash_karp54, state1, 10>::rhs_evals_per_step == 62);
static_assert(odestep::adaptive_substeps<odestep::tables::bogacki_shampine32, state1, 10>::rhs_evals_per_step == 32);

TEST_CASE("tolerances: bad values are refused, good ones pass") {
    CHECK(tol<state2>(1e-6, 1e-9).check() == status::ok);
    CHECK(tol<state2>(0.0, 1e-9).check() == status::ok);
    CHECK(tol<state2>(1e-6, 0.0).check() == status::ok);
    CHECK(tol<state2>(0.0, 0.0).check() == status::invalid_tolerance);
    CHECK(tol<state2>(-1e-6, 1e-9).check() == status::invalid_tolerance);
    CHECK(tol<state2>(std::nan(""), 1e-9).check() == status::invalid_tolerance);
    CHECK(tol<state2>(1e-6, std::numeric_limits<double>::infinity()).check() == status::invalid_tolerance);
    const auto per = odestep::tolerances<state2>::per_component({1e-6, 0.0}, {0.0, 1e-3});
    CHECK(per.check() == status::ok);
    const auto bad = odestep::tolerances<state2>::per_component({1e-6, 0.0}, {0.0, 0.0});
    CHECK(bad.check() == status::invalid_tolerance);
}

TEST_CASE("scaled_error_norm: the RMS of err_i / (atol_i + rtol_i max(|y_i|, |y_new_i|)), by hand") {
    // Component 0: sc = 1e-3 + 1e-2 * max(2, 3) = 0.031, err 0.031 -> 1. Component 1: sc = 1e-3 + 1e-2 * 4 =
    // 0.041, err 0.082 -> 2. RMS = sqrt((1 + 4) / 2).
    const auto t = tol<state2>(1e-2, 1e-3);
    const double n = odestep::scaled_error_norm(state2{0.031, -0.082}, state2{2.0, -4.0}, state2{3.0, 1.0}, t);
    CHECK(n == doctest::Approx(std::sqrt(2.5)).epsilon(1e-14));
    // atol = 0 at y = 0 with no error there: that component counts 0, not NaN.
    const auto rel = tol<state2>(1e-3, 0.0);
    CHECK(odestep::scaled_error_norm(state2{0.0, 1e-3}, state2{0.0, 1.0}, state2{0.0, 1.0}, rel) ==
          doctest::Approx(std::sqrt(0.5)));
    // Per-component tolerances: component 1 is measured against its own atol only.
    const auto per = odestep::tolerances<state2>::per_component({1e-2, 0.0}, {0.0, 1e-4});
    CHECK(odestep::scaled_error_norm(state2{0.01, 2e-4}, state2{1.0, 5.0}, state2{1.0, 5.0}, per) ==
          doctest::Approx(std::sqrt((1.0 + 4.0) / 2.0)));
}

TEST_CASE("step_control: the PI factor, its limits, and no growth after a rejection") {
    const odestep::step_control<double> c{};
    CHECK(c.check() == status::ok);
    const auto g = odestep::gains_for(c, 5);
    CHECK(g.alpha == doctest::Approx(0.14));  // 0.7 / k
    CHECK(g.beta == doctest::Approx(0.08));   // 0.4 / k
    // err = 0.5, err_prev = 0.25: 0.9 * 0.5^-0.14 * 0.25^0.08, computed independently here.
    const double f = odestep::step_factor(c, g, 5, 0.5, 0.25, false);
    CHECK(f == doctest::Approx(0.9 * std::pow(0.5, -0.14) * std::pow(0.25, 0.08)));
    CHECK(odestep::step_factor(c, g, 5, 1e-30, 1.0, false) == 5.0);  // max_factor
    CHECK(odestep::step_factor(c, g, 5, 1e-30, 1.0, true) == 1.0);   // no growth right after a rejection
    // Rejected: 0.9 * err^(-1/5), at least min_factor.
    CHECK(odestep::step_factor(c, g, 5, 2.0, 1.0, false) == doctest::Approx(0.9 * std::pow(2.0, -0.2)));
    CHECK(odestep::step_factor(c, g, 5, 1e12, 1.0, false) == 0.2);
    // Bad settings.
    odestep::step_control<double> bad{};
    bad.safety = 1.5;
    CHECK(bad.check() == status::invalid_setting);
    bad = {};
    bad.max_factor = 0.5;
    CHECK(bad.check() == status::invalid_setting);
    bad = {};
    bad.min_factor = std::nan("");
    CHECK(bad.check() == status::invalid_setting);
}

// The PI factor from logarithms (detail::pi_factor, one exp a step) against its closed form
// safety err^(-alpha) err_prev^(beta) evaluated here in long double with powl, for the gains of k = 2 .. 8,
// over err from 1e-8 to 1 and err_prev from 1e-4 to 1 (where the clamps leave it alone): within the
// documented 16 epsilon (relative, the bound control.hpp states; checked at 32). The engines' memory
// (pi_memory: ln err_prev kept, floored at ln 1e-4) gives the same factor on its second step.
template <class T>
void check_pi_factor_against_closed_form() {
    const odestep::step_control<T> c{};
    const long double bound = 32.0L * static_cast<long double>(std::numeric_limits<T>::epsilon());
    int unclamped = 0;
    for (int k = 2; k <= 8; ++k) {
        const auto g = odestep::gains_for(c, k);
        for (int i = 0; i <= 80; ++i) {
            const T err = static_cast<T>(std::pow(10.0L, -8.0L + 0.1L * i));
            for (int j = 0; j <= 8; ++j) {
                const T prev = static_cast<T>(std::pow(10.0L, -4.0L + 0.5L * j));
                const long double closed = 0.9L *
                                           std::pow(static_cast<long double>(err), -static_cast<long double>(g.alpha)) *
                                           std::pow(static_cast<long double>(prev), static_cast<long double>(g.beta));
                if (!(closed > 0.21L && closed < 4.99L)) continue;  // clamped: compared below
                ++unclamped;
                const T f = odestep::step_factor(c, g, k, err, prev, false);
                CHECK(std::fabs(static_cast<long double>(f) / closed - 1.0L) <= bound);
                // The engine's memory: a first accepted step with norm prev, then one with norm err.
                odestep::detail::pi_memory<T> m;
                T log_e = T(0);
                const T first = m.next_step(c, k, T(1), prev, log_e);
                CHECK(first > T(0));
                m.accept(first, T(1), log_e);
                const T second = m.next_step(c, k, T(1), err, log_e);
                CHECK(std::fabs(static_cast<long double>(second) / closed - 1.0L) <= bound);
            }
        }
    }
    CHECK(unclamped > 1000);
    // The floor: a previous norm below 1e-4 counts as 1e-4 (Hairer's codes), and the clamps.
    odestep::detail::pi_memory<T> m;
    T log_e = T(0);
    CHECK(m.next_step(c, 5, T(1), T(1e-30f), log_e) == c.max_factor);
    m.accept(T(1), T(1), log_e);
    const long double floored = 0.9L * std::pow(0.5L, -0.14L) * std::pow(1e-4L, 0.08L);
    CHECK(std::fabs(static_cast<long double>(m.next_step(c, 5, T(1), T(0.5f), log_e)) / floored - 1.0L) <= bound);
    // 0.9 * 1^(-0.14) * (1e-30)^(0.08) = 0.0036: below min_factor.
    CHECK(odestep::step_factor(c, odestep::gains_for(c, 5), 5, T(1), T(1e-30f), false) == c.min_factor);
}

TEST_CASE("step_control: the PI factor from logarithms matches its closed form (double, float, long double)") {
    check_pi_factor_against_closed_form<double>();
    check_pi_factor_against_closed_form<float>();
    check_pi_factor_against_closed_form<long double>();
}

TEST_CASE("initial_step: Hairer's algorithm on y' = y, by hand") {
    // y0 = 1, f0 = 1, rtol = atol = 1e-6: sc = 2e-6, d0 = d1 = 5e5, h0 = 0.01; f1 = 1.01, d2 = 5e5;
    // h1 = (0.01 / 5e5)^(1/5); h = min(100 h0, h1) = h1.
    std::size_t calls = 0;
    auto grow = odestep_test::counted([](double, const state1& y, state1& d) { d[0] = y[0]; }, &calls);
    const double h = odestep::initial_step(grow, 0.0, state1{1.0}, state1{1.0}, 4, tol<state1>(1e-6, 1e-6), 0.0, 1.0);
    CHECK(h == doctest::Approx(std::pow(0.01 / 5e5, 0.2)));
    CHECK(calls == 1);
    const double back =
        odestep::initial_step(grow, 0.0, state1{1.0}, state1{1.0}, 4, tol<state1>(1e-6, 1e-6), 0.0, -1.0);
    CHECK(back < 0.0);
    // The limit bounds it.
    CHECK(odestep::initial_step(grow, 0.0, state1{1.0}, state1{1.0}, 4, tol<state1>(1e-6, 1e-6), 1e-3, 1.0) == 1e-3);
}

TEST_CASE("adaptive_substeps: exp(-t) and the oscillator through integrate, error near the tolerance") {
    SUBCASE("exponential, Cash-Karp (the course's default)") {
        odestep::cash_karp54_substeps<state1> s(tol<state1>(1e-9, 1e-12));
        state1 y{1.0};
        std::size_t observed = 0;
        bool on_grid = true;
        const auto r = odestep::integrate(s, decay{}, y, 0.0, 5.0, 0.5, [&](double t, const state1&) {
            on_grid = on_grid && t == 0.0 + static_cast<double>(observed) * 0.5;  // the grid's own times
            ++observed;
        });
        REQUIRE(r.status == status::ok);
        CHECK(on_grid);
        CHECK(observed == 11);
        CHECK(std::fabs(y[0] - std::exp(-5.0)) < 1e-10);  // exp(-5) = 6.7e-3: rtol 1e-9 of y and more
        CHECK(s.engine().accepted_steps() > 10);          // more than one internal step per interval
    }
    SUBCASE("harmonic oscillator, Dormand-Prince, 10 periods") {
        odestep::dormand_prince54_substeps<state2> s(tol<state2>(1e-10, 1e-10));
        state2 y{1.0, 0.0};
        const double t1 = 20.0 * M_PI;
        const auto r = odestep::integrate_n_steps(s, odestep_test::harmonic{}, y, 0.0, t1 / 100.0, 100);
        REQUIRE(r.status == status::ok);
        // (cos t, -sin t): the global error grows about linearly over the 10 periods.
        CHECK(odestep_test::max_abs_difference(y, state2{std::cos(t1), -std::sin(t1)}) < 1e-7);
    }
    SUBCASE("float at a float-sized tolerance") {
        using f1 = std::array<float, 1>;
        odestep::dormand_prince54_substeps<f1> s(tol<f1>(1e-5, 1e-7));
        f1 y{1.0f};
        const auto r = odestep::integrate(s, decay{}, y, 0.0f, 4.0f, 0.25f);
        REQUIRE(r.status == status::ok);
        CHECK(std::fabs(y[0] - std::exp(-4.0f)) < 2e-6f);
    }
    SUBCASE("backwards in time") {
        odestep::dormand_prince54_substeps<state1> s(tol<state1>(1e-9, 1e-12));
        state1 y{std::exp(-2.0)};
        const auto r = odestep::integrate(s, decay{}, y, 2.0, 0.0, -0.25);
        REQUIRE(r.status == status::ok);
        CHECK(std::fabs(y[0] - 1.0) < 1e-8);
    }
}

TEST_CASE("adaptive_substeps: one interval lands exactly on t + dt and the step size is carried") {
    odestep::dormand_prince54_substeps<state1> s(tol<state1>(1e-8, 1e-8));
    state1 y{1.0};
    REQUIRE(s.step(decay{}, y, 0.0, 1.0) == status::ok);
    const double carried = s.engine().step_size();
    CHECK(carried > 0.0);
    CHECK(carried < 1.0);  // at 1e-8 one step of 1 is too long for exp(-t)
    const auto before = s.engine().accepted_steps();
    REQUIRE(s.step(decay{}, y, 1.0, 1.0) == status::ok);
    // The second interval starts with the carried size: no rejection, no first-step estimate.
    CHECK(s.engine().rejected_steps() == 0);
    CHECK(s.engine().accepted_steps() - before >= 2);
    CHECK(std::fabs(y[0] - std::exp(-2.0)) < 1e-8);
}

TEST_CASE("adaptive_substeps: evaluations counted against the engine's own counts and the published bound") {
    SUBCASE("Dormand-Prince (FSAL): 2 to start, then 6 per attempt, the last stage reused across intervals") {
        std::size_t calls = 0;
        auto f = odestep_test::counted(odestep_test::harmonic{}, &calls);
        odestep::dormand_prince54_substeps<state2> s(tol<state2>(1e-8, 1e-8));
        state2 y{1.0, 0.0};
        const auto r = odestep::integrate(s, f, y, 0.0, 10.0, 0.1);
        REQUIRE(r.status == status::ok);
        const auto attempts = s.engine().accepted_steps() + s.engine().rejected_steps();
        CHECK(calls == 2 + 6 * attempts);
        CHECK(calls <= 100 * decltype(s)::rhs_evals_per_step);
    }
    SUBCASE("Cash-Karp (no FSAL): f at each new point, then 5 more stages per attempt") {
        std::size_t calls = 0;
        auto f = odestep_test::counted(odestep_test::harmonic{}, &calls);
        odestep::cash_karp54_substeps<state2> s(tol<state2>(1e-8, 1e-8));
        state2 y{1.0, 0.0};
        const auto r = odestep::integrate(s, f, y, 0.0, 10.0, 0.1);
        REQUIRE(r.status == status::ok);
        const auto acc = s.engine().accepted_steps();
        const auto rej = s.engine().rejected_steps();
        // The first-step estimate's probe, f at every accepted point but the last, 5 stages per attempt.
        CHECK(calls == 1 + acc + 5 * (acc + rej));
    }
}

TEST_CASE("adaptive_substeps: a sharp change is met with rejections, and the error stays at the tolerance") {
    odestep::dormand_prince54_substeps<state1> s(tol<state1>(1e-8, 1e-8));
    state1 y{0.0};
    const auto r = odestep::integrate(s, sharp_step{}, y, 0.0, 2.0, 0.25);
    REQUIRE(r.status == status::ok);
    CHECK(s.engine().rejected_steps() > 0);
    CHECK(std::fabs(y[0] - sharp_step::exact(2.0)) < 1e-6);
}

TEST_CASE("adaptive_substeps: error tracks the tolerance (1e-4 .. 1e-10)") {
    // exp_sin over [0, 10] with Dormand-Prince: each tenfold tightening of the tolerance cuts the error
    // (tolerance proportionality), and the error is never far above the tolerance asked for.
    double previous = 1.0;
    for (int e = 4; e <= 10; ++e) {
        const double t = std::pow(10.0, -e);
        odestep::dormand_prince54_substeps<state3> s(tol<state3>(t, t));
        auto y = odestep_test::exp_sin::start<double>();
        const auto r = odestep::integrate(s, odestep_test::exp_sin{}, y, 0.0, 10.0, 1.0);
        REQUIRE(r.status == status::ok);
        const double err = odestep_test::max_abs_difference(y, odestep_test::exp_sin::exact(10.0));
        MESSAGE("tol " << t << "  error " << err << "  steps " << s.engine().accepted_steps());
        CHECK(err < 30.0 * t);
        CHECK(err < previous);
        previous = err;
    }
}

TEST_CASE("adaptive_substeps: past the cap, substep_limit with the interval's start state") {
    odestep::adaptive_substeps<odestep::tables::dormand_prince54, state2, 16> s(tol<state2>(1e-12, 1e-12));
    REQUIRE(s.set_max_substeps(3) == status::ok);
    CHECK(s.set_max_substeps(0) == status::invalid_setting);
    CHECK(s.set_max_substeps(17) == status::invalid_setting);
    CHECK(s.max_substeps() == 3);
    state2 y{1.0, 0.0};
    const state2 start = y;
    CHECK(s.step(odestep_test::harmonic{}, y, 0.0, 10.0) == status::substep_limit);
    CHECK(odestep_test::same_bits(y, start));
    // Through integrate: the run stops at the interval's start.
    state2 z{1.0, 0.0};
    double last_t = -1.0;
    const auto r = odestep::integrate(s, odestep_test::harmonic{}, z, 0.0, 100.0, 10.0,
                                      [&](double t, const state2&) { last_t = t; });
    CHECK(r.status == status::substep_limit);
    CHECK(r.t == last_t);
}

TEST_CASE("adaptive_substeps: NaN from f gives non_finite with the interval's start state") {
    odestep::dormand_prince54_substeps<state1> s(tol<state1>(1e-8, 1e-8));
    const auto poisoned = [](double t, const state1& y, state1& d) { d[0] = t > 0.9 ? std::nan("") : -y[0]; };
    state1 y{1.0};
    REQUIRE(s.step(poisoned, y, 0.0, 0.5) == status::ok);
    const state1 start = y;
    const auto before = s.engine().accepted_steps();
    CHECK(s.step(poisoned, y, 0.5, 0.5) == status::non_finite);
    CHECK(s.engine().accepted_steps() > before);  // internal steps were accepted before f gave NaN
    CHECK(odestep_test::same_bits(y, start));
}

TEST_CASE("adaptive_substeps: bad settings and arguments, nothing touched") {
    std::size_t calls = 0;
    auto f = odestep_test::counted(decay{}, &calls);
    state1 y{1.0};
    odestep::dormand_prince54_substeps<state1> bad_tol(tol<state1>(-1.0, 1e-6));
    CHECK(odestep::integrate(bad_tol, f, y, 0.0, 1.0, 0.1).status == status::invalid_tolerance);
    odestep::step_control<double> c{};
    c.max_factor = 0.5;
    odestep::dormand_prince54_substeps<state1> bad_control(tol<state1>(1e-6, 1e-6), c);
    CHECK(odestep::integrate(bad_control, f, y, 0.0, 1.0, 0.1).status == status::invalid_setting);
    odestep::dormand_prince54_substeps<state1> s;
    CHECK(s.step(f, y, 0.0, 0.0) == status::invalid_step);
    CHECK(s.step(f, y, std::nan(""), 0.1) == status::invalid_time);
    CHECK(calls == 0);
    CHECK(y[0] == 1.0);
}

TEST_CASE("adaptive_substeps: events located inside an interval (a falling ball)") {
    // y = (height, velocity), y' = (v, -10), from height 5 at rest: the ground at t = 1 exactly.
    const auto fall = [](double, const state2& y, state2& d) {
        d[0] = y[1];
        d[1] = -10.0;
    };
    const auto height = [](double, const state2& y) { return y[0]; };
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    odestep::dormand_prince54_substeps<state2> s(tol<state2>(1e-10, 1e-10));
    state2 y{5.0, 0.0};
    const auto r = odestep::integrate(s, fall, y, 0.0, 3.0, 0.3, odestep::watch(ground));
    CHECK(r.status == status::stopped_by_event);
    CHECK(r.t == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(std::fabs(y[1] + 10.0) < 1e-9);
    // The stepper's bound gives the event loop's bound.
    CHECK(odestep::max_rhs_evals_per_step<decltype(s)>(1) >= decltype(s)::rhs_evals_per_step);
}

TEST_CASE("adaptive_substeps: the per-tick event loop (event_stepper) reports the ground inside a tick") {
    const auto fall = [](double, const state2& y, state2& d) {
        d[0] = y[1];
        d[1] = -10.0;
    };
    const auto height = [](double, const state2& y) { return y[0]; };
    // A bounce: the velocity reversed (and kept at 0.9 of it), the run goes on.
    const auto bounce = [](double, state2& y) { y[1] = -0.9 * y[1]; };
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling, bounce);
    odestep::event_stepper loop(odestep::dormand_prince54_substeps<state2>(tol<state2>(1e-10, 1e-10)),
                                odestep::watch(ground));
    state2 y{5.0, 0.0};
    REQUIRE(loop.start(0.0, 0.25, y) == status::ok);
    double fired_at = -1.0;
    for (int i = 0; i < 8 && fired_at < 0.0; ++i) {
        const auto r = loop.tick(fall, y);
        REQUIRE(r.status == status::ok);
        if (r.fired > 0) fired_at = r.firings[0].t;
    }
    // From height 5 at rest under g = 10: the ground at t = 1 exactly, then moving up at 0.9 * 10.
    CHECK(fired_at == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(y[1] > 0.0);
}
