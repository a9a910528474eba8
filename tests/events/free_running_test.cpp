// SPDX-License-Identifier: BSL-1.0
// Events on the free-running loops (issue 24 item 2): integrate_adaptive and integrate_times with watch(...),
// for the explicit pairs, Radau IIA 5 and a Rosenbrock pair. Expected values come from closed forms (free fall,
// the bouncing ball's impacts and Zeno time, y' = 1, SciPy's rational test problem y = (t / (t + 10),
// 10 t / (t + 10)^2), whose event roots the test finds by bisection on the closed form), and, for Robertson's
// stiff problem, from SciPy's solvers at tight tolerances (the command is next to the value).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "support/counting.hpp"

namespace {

template <class T>
using dp5 = odestep::adaptive_rk<odestep::tables::dormand_prince54, std::array<T, 2>>;
template <class T>
using dop853 = odestep::adaptive_rk<odestep::tables::dop853, std::array<T, 2>>;
template <class T>
using radau = odestep::radau5<std::array<T, 2>>;
template <class T>
using bs32 = odestep::adaptive_rk<odestep::tables::bogacki_shampine32, std::array<T, 2>>;
template <class T>
using ck54 = odestep::adaptive_rk<odestep::tables::cash_karp54, std::array<T, 2>>;
template <class T>
using rodas = odestep::rosenbrock_adaptive<odestep::tables::rodas4, std::array<T, 2>>;
template <class T>
using sdirk = odestep::sdirk_adaptive<odestep::tables::sdirk4, std::array<T, 2>>;

// The Zeno time of the ball dropped from h with restitution e: t_Z = t_1 (1 + 2 e / (1 - e)), t_1 = sqrt(2 h / g).
double zeno_time(double h, double gravity, double e) {
    const double t1 = std::sqrt(2.0 * h / gravity);
    return t1 * (1.0 + 2.0 * e / (1.0 - e));
}

// Impact k (from 0) of that ball: t_1 (1 + 2 (e + e^2 + ... + e^k)).
double impact_time(double h, double gravity, double e, std::size_t k) {
    const double t1 = std::sqrt(2.0 * h / gravity);
    double sum = 0.0;
    double p = 1.0;
    for (std::size_t j = 1; j <= k; ++j) {
        p *= e;
        sum += p;
    }
    return t1 * (1.0 + 2.0 * sum);
}

struct ball_run {
    odestep::status status;
    double t;
    double lowest;  // the lowest height observed, and the final one
    std::size_t fired;
    std::size_t bounces;
    std::vector<double> impacts;
    double last_seen_t;
    bool last_seen_is_y;
};

// The README's ball (make_event<state>(s[0], falling, s[1] = -e s[1]), dropped from 1 m under 9.81) on
// integrate_adaptive with `engine`.
template <class T, class Engine>
ball_run ball(Engine engine, T e, T t_end) {
    using state = std::array<T, 2>;
    const T gravity = T(9.81);
    auto f = [gravity](T, const state& s) { return state{s[1], -gravity}; };
    ball_run out{odestep::status::ok, 0.0, 1.0, 0, 0, {}, 0.0, false};
    auto ground = odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling,
                                             [&out, e](T t, state& s) {
                                                 ++out.bounces;
                                                 out.impacts.push_back(static_cast<double>(t));
                                                 s[1] = -e * s[1];
                                             });
    state seen{};
    auto observe = [&](T t, const state& s) {
        out.lowest = std::fmin(out.lowest, static_cast<double>(s[0]));
        out.last_seen_t = static_cast<double>(t);
        seen = s;
    };
    state y{T(1), T(0)};
    const auto r = odestep::integrate_adaptive(engine, f, y, T(0), t_end, odestep::watch(ground), observe);
    out.status = r.status;
    out.t = static_cast<double>(r.t);
    out.fired = r.fired;
    out.lowest = std::fmin(out.lowest, static_cast<double>(y[0]));
    out.last_seen_is_y = seen[0] == y[0] && seen[1] == y[1] && out.last_seen_t == out.t;
    return out;
}

// How far below the floor a computed height may be and still be the floor: heights are sums of terms no
// larger than the drop height (the extension's coefficients, each rounded a few times): 16 eps h, as in
// zeno_test.cpp.
template <class T>
double floor_tolerance() {
    return 16.0 * static_cast<double>(std::numeric_limits<T>::epsilon());
}

// How far impact k may lie from the closed form. The continuous extensions of DP 5(4) (order 4), DOP853 (7),
// Radau's collocation polynomial (5) and the Hermite cubic (3) are exact for the ball's quadratic trajectory,
// so what separates the run from the closed form is rounding: the state at an impact is read from the
// extension, whose terms are as large as v_1 h, so the speed after bounce j carries an error of some 16 eps v_1
// (not eps v_j), and every later flight (2 v / g) inherits it; the errors of the k bounces before impact k add
// up, each shifting the flights after it: at most 16 eps (k + 1)^2 (v_1 / v_k) t_Z. Impacts while the speed is
// above 1 m/s are checked (k <= 4; double: 3e-13 at k = 4, against 5e-14 measured).
template <class T>
double impact_tolerance(std::size_t k, double speed_ratio, double t_zeno) {
    const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
    const double n = static_cast<double>(k + 1);
    return 16.0 * eps * n * n * speed_ratio * t_zeno;
}

template <class T, class Engine>
void check_ball(const char* name) {
    CAPTURE(name);
    CAPTURE(sizeof(T));
    const double e = 0.7;
    const double t_zeno = zeno_time(1.0, 9.81, e);
    const ball_run o = ball<T>(Engine{}, T(0.7), T(10));
    CHECK(o.lowest >= -floor_tolerance<T>());
    CHECK(o.status == odestep::status::event_limit);
    CHECK(o.t < t_zeno);
    CHECK(o.fired == o.bounces);
    CHECK(o.bounces >= 8);
    const double v1 = std::sqrt(2.0 * 9.81);
    double speed = v1;
    for (std::size_t k = 0; k < o.impacts.size() && speed > 1.0; ++k, speed *= e) {
        CAPTURE(k);
        CHECK(std::abs(o.impacts[k] - impact_time(1.0, 9.81, e, k)) <= impact_tolerance<T>(k, v1 / speed, t_zeno));
    }
}

}  // namespace

TEST_CASE("free-running events: the README ball never passes the floor and ends with event_limit before t_Z") {
    check_ball<double, dp5<double>>("DP 5(4)");
    check_ball<float, dp5<float>>("DP 5(4)");
    check_ball<double, dop853<double>>("DOP853");
    check_ball<double, radau<double>>("Radau IIA 5");
    check_ball<float, radau<float>>("Radau IIA 5");
    check_ball<double, rodas<double>>("Rodas4");
    check_ball<float, rodas<float>>("Rodas4");
    check_ball<double, sdirk<double>>("SDIRK4");
    check_ball<float, sdirk<float>>("SDIRK4");
}

TEST_CASE("free-running events: the restitution sweep 0.1 ... 0.95 never passes the floor, event_limit before t_Z") {
    // (e = 0.1 in float: the flights fall to a few ULPs of t while the steps stay long; read at the scale of
    // the whole step, the extension put the ball below the floor just after a bounce, BS 3(2), Cash-Karp)
    for (const double e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.95}) {
        CAPTURE(e);
        const double t_zeno = zeno_time(1.0, 9.81, e);
        const ball_run a = ball<double>(dp5<double>{}, e, 60.0);
        const ball_run b = ball<double>(radau<double>{}, e, 60.0);
        const ball_run c = ball<float>(dp5<float>{}, static_cast<float>(e), 60.0f);
        const ball_run d = ball<float>(radau<float>{}, static_cast<float>(e), 60.0f);
        // Hermite pairs, and a Rosenbrock pair (Hermite through its ends): the flights become far shorter than
        // the steps, whose extension must still leave the floor upwards just after a bounce
        const ball_run g = ball<float>(bs32<float>{}, static_cast<float>(e), 60.0f);
        const ball_run k = ball<float>(ck54<float>{}, static_cast<float>(e), 60.0f);
        const ball_run m = ball<float>(rodas<float>{}, static_cast<float>(e), 60.0f);
        for (const ball_run& o : {a, b}) {
            CHECK(o.lowest >= -floor_tolerance<double>());
            CHECK(o.status == odestep::status::event_limit);
            CHECK(o.t < t_zeno);
            CHECK(o.last_seen_is_y);
        }
        for (const ball_run& o : {c, d, g, k, m}) {
            CHECK(o.lowest >= -floor_tolerance<float>());
            CHECK(o.status == odestep::status::event_limit);
            // In float the run's own Zeno time is the closed form's only to the run's error: Radau's Newton
            // iteration stops at the tolerance (1e-4 in float by default), and the state read at each impact
            // carries rounding of the step's terms (eps g h) into the speeds, which at e = 0.1 are soon that
            // small: the impacts then accumulate up to the tolerance, relative, after t_Z (2.6e-5 s measured at
            // e = 0.1, Radau).
            CHECK(o.t < t_zeno * (1.0 + 1e-4));
            CHECK(o.last_seen_is_y);
        }
    }
}

namespace {

// Dropped from h = 10 at rest, a terminal ground event: the impact at sqrt(2 h / g), the speed g t there.
template <class T, class Engine>
void check_free_fall(Engine engine, const char* name) {
    CAPTURE(name);
    CAPTURE(sizeof(T));
    using state = std::array<T, 2>;
    const T gravity = T(9.81);
    const T h = T(10);
    auto f = [gravity](T, const state& s) { return state{s[1], -gravity}; };
    auto ground = odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling);
    T last_t = T(-1);
    state last{};
    std::size_t seen = 0;
    auto observe = [&](T t, const state& s) {
        ++seen;
        last_t = t;
        last = s;
    };
    state y{h, T(0)};
    const auto r = odestep::integrate_adaptive(engine, f, y, T(0), T(100), odestep::watch(ground), observe);
    const double t_hit = std::sqrt(2.0 * 10.0 / static_cast<double>(gravity));
    const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 0);
    CHECK(r.fired == 1);
    // The extension is exact for a quadratic: the root of the rounded interpolant, within the height's
    // rounding (16 eps h) over the impact speed, and the bracket's ULP.
    CHECK(std::abs(static_cast<double>(r.t) - t_hit) <= 16.0 * eps * 10.0 / (9.81 * t_hit) + 2.0 * eps * t_hit);
    CHECK(y[0] >= T(0));
    CHECK(y[0] <= T(16) * std::numeric_limits<T>::epsilon() * h);
    CHECK(std::abs(static_cast<double>(y[1]) + 9.81 * t_hit) <= 1e3 * eps * 9.81 * t_hit);
    // A stopped run's y and t are its last observation.
    CHECK(last_t == r.t);
    CHECK(last[0] == y[0]);
    CHECK(last[1] == y[1]);
    CHECK(seen == r.steps + 2);  // t0, every completed step, the stop
}

}  // namespace

TEST_CASE("free-running events: free fall stops at the closed-form impact time, observed last") {
    check_free_fall<double>(dp5<double>{}, "DP 5(4)");
    check_free_fall<float>(dp5<float>{}, "DP 5(4)");
    check_free_fall<double>(dop853<double>{}, "DOP853");
    check_free_fall<double>(radau<double>{}, "Radau IIA 5");
    check_free_fall<float>(radau<float>{}, "Radau IIA 5");
    check_free_fall<double>(rodas<double>{}, "Rodas4");
}

namespace {

// SciPy's rational test problem (scipy/integrate/_ivp/tests/test_ivp.py, test_events): on [5, 8] from
// (1/3, 2/9), y = (t / (t + 10), 10 t / (t + 10)^2).
using state2 = std::array<double, 2>;
state2 rational(double t, const state2& y) { return {y[1] / t, y[1] * (y[0] + 2.0 * y[1] - 1.0) / (t * (y[0] - 1.0))}; }
state2 rational_solution(double t) { return {t / (t + 10.0), 10.0 * t / ((t + 10.0) * (t + 10.0))}; }
double event_1(double, const state2& y) { return y[0] - std::pow(y[1], 0.7); }
double event_2(double, const state2& y) { return std::pow(y[1], 0.6) - y[0]; }

// The root of g(t, y(t)) in [a, b] on the closed form, by bisection (g changes sign on [a, b]).
template <class G>
double closed_form_root(G g, double a, double b) {
    double ga = g(a, rational_solution(a));
    for (int i = 0; i < 200 && b - a > 0.0; ++i) {
        const double m = a + (b - a) / 2.0;
        if (m == a || m == b) break;
        const double gm = g(m, rational_solution(m));
        if ((gm < 0.0) == (ga < 0.0)) {
            a = m;
            ga = gm;
        } else {
            b = m;
        }
    }
    return a;
}

struct firing {
    std::size_t event;
    double t;
    state2 y;
};

template <class Engine>
void check_scipy_events(const char* name) {
    CAPTURE(name);
    const double root_1 = closed_form_root(event_1, 5.3, 5.7);  // SciPy asserts 5.3 < t < 5.7
    const double root_2 = closed_form_root(event_2, 7.3, 7.7);  // and 7.3 < t < 7.7
    // (tight tolerances: the event times are then the closed form's to about 1e-9)
    const auto tol = odestep::tolerances<state2>::uniform(1e-10, 1e-12);
    const double time_tolerance = 1e-7;
    for (const odestep::direction d :
         {odestep::direction::either, odestep::direction::rising, odestep::direction::falling}) {
        CAPTURE(static_cast<int>(d));
        std::vector<firing> fired;
        auto e1 = odestep::make_event<state2>(event_1, d, [&](double t, state2& y) { fired.push_back({0, t, y}); });
        auto e2 = odestep::make_event<state2>(event_2, d, [&](double t, state2& y) { fired.push_back({1, t, y}); });
        Engine engine(tol);
        state2 y{1.0 / 3.0, 2.0 / 9.0};
        const auto r = odestep::integrate_adaptive(engine, rational, y, 5.0, 8.0, odestep::watch(e1, e2));
        CHECK(r.status == odestep::status::ok);
        CHECK(r.t == 8.0);
        // event_1 rises through zero at root_1, event_2 falls at root_2 (SciPy: direction 1 keeps only the
        // first, -1 only the second)
        const std::size_t expected = d == odestep::direction::either ? 2 : 1;
        REQUIRE(fired.size() == expected);
        CHECK(r.fired == expected);
        for (const firing& x : fired) {
            const double root = x.event == 0 ? root_1 : root_2;
            CHECK(std::abs(x.t - root) < time_tolerance);
            // the state at the event is on the solution and g there is zero (SciPy's isclose(g(t, y), 0))
            const double g = x.event == 0 ? event_1(x.t, x.y) : event_2(x.t, x.y);
            CHECK(std::abs(g) < 1e-8);
            CHECK(std::abs(x.y[0] - rational_solution(x.t)[0]) < 1e-8);
        }
        if (d == odestep::direction::rising) CHECK(fired[0].event == 0);
        if (d == odestep::direction::falling) CHECK(fired[0].event == 1);
    }
    // With event_rational_3 = t - 7.4 terminal: stops at 7.4 (g exactly zero at a representable time: that
    // time or the one before it), after event_1 and before event_2.
    std::size_t recorded = 0;
    auto e1 = odestep::make_event<state2>(event_1, odestep::direction::either, [&](double, state2&) { ++recorded; });
    auto e2 = odestep::make_event<state2>(event_2, odestep::direction::either, odestep::record);
    auto e3 = odestep::make_event<state2>([](double t, const state2&) { return t - 7.4; }, odestep::direction::either);
    Engine engine(tol);
    state2 y{1.0 / 3.0, 2.0 / 9.0};
    const auto r = odestep::integrate_adaptive(engine, rational, y, 5.0, 8.0, odestep::watch(e1, e2, e3));
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 2);
    CHECK(r.firings[0] == 1);
    CHECK(r.firings[1] == 0);
    CHECK(r.firings[2] == 1);
    CHECK(recorded == 1);
    CHECK(r.t <= 7.4);
    CHECK(r.t >= std::nextafter(7.4, 0.0));
    CHECK(std::abs(y[0] - rational_solution(7.4)[0]) < 1e-8);
    // Backwards from 8 (SciPy's second half): both events, in time order (event_2 first).
    std::vector<firing> back;
    auto b1 = odestep::make_event<state2>(event_1, odestep::direction::either, [&](double t, state2& s) {
        back.push_back({0, t, s});
    });
    auto b2 = odestep::make_event<state2>(event_2, odestep::direction::either, [&](double t, state2& s) {
        back.push_back({1, t, s});
    });
    Engine backward(tol);
    state2 y8{4.0 / 9.0, 20.0 / 81.0};
    const auto rb = odestep::integrate_adaptive(backward, rational, y8, 8.0, 5.0, odestep::watch(b1, b2));
    CHECK(rb.status == odestep::status::ok);
    CHECK(rb.t == 5.0);
    REQUIRE(back.size() == 2);
    CHECK(back[0].event == 1);
    CHECK(std::abs(back[0].t - root_2) < time_tolerance);
    CHECK(back[1].event == 0);
    CHECK(std::abs(back[1].t - root_1) < time_tolerance);
}

}  // namespace

TEST_CASE("free-running events: SciPy's event tests (directions, terminal, backwards) against the closed form") {
    check_scipy_events<dp5<double>>("DP 5(4)");
    check_scipy_events<dop853<double>>("DOP853");
    check_scipy_events<radau<double>>("Radau IIA 5");
    check_scipy_events<rodas<double>>("Rodas4");
}

namespace {

// y' = 1 from y(0) = 0: y = t, which every pair integrates exactly (a zero error estimate: the steps grow to
// the controller's limit). A step size of 10 is set, so one step covers [0, 10].
using state1 = std::array<double, 1>;
using clock_dp5 = odestep::adaptive_rk<odestep::tables::dormand_prince54, state1>;
auto one = [](double, const state1&) { return state1{1.0}; };

struct sample {
    double t;
    double y;
};

}  // namespace

TEST_CASE("free-running events: two events in one step both fire, in time order, and record events are observed") {
    clock_dp5 engine;
    engine.set_step_size(10.0);
    auto at_2 = odestep::make_event<state1>([](double, const state1& y) { return y[0] - 2.0; },
                                            odestep::direction::rising, odestep::record);
    auto at_3 = odestep::make_event<state1>([](double, const state1& y) { return y[0] - 3.0; },
                                            odestep::direction::rising, odestep::record);
    std::vector<sample> seen;
    state1 y{0.0};
    const auto r = odestep::integrate_adaptive(engine, one, y, 0.0, 10.0, odestep::watch(at_3, at_2),
                                               [&](double t, const state1& s) {
                                                   seen.push_back({t, s[0]});
                                               });
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 1);
    CHECK(r.firings[0] == 1);
    CHECK(r.firings[1] == 1);
    REQUIRE(seen.size() == 4);  // t0, the two events in time order, the step's end
    CHECK(seen[0].t == 0.0);
    // g = y - 2 is zero at t = 2 on the exact solution; the extension of the step (exact for y = t but for
    // rounding: terms of size 10, a few ULPs of 10) crosses it within a few ULPs of 10 / |y'| = 10 of it
    const double ulps = 8.0 * std::numeric_limits<double>::epsilon() * 10.0;
    CHECK(std::abs(seen[1].t - 2.0) <= ulps);
    CHECK(std::abs(seen[1].y - 2.0) <= ulps);
    CHECK(std::abs(seen[2].t - 3.0) <= ulps);
    CHECK(seen[3].t == 10.0);
    CHECK(std::abs(seen[3].y - 10.0) <= ulps);
    // record leaves the run bit for bit: the same step as without events
    clock_dp5 plain;
    plain.set_step_size(10.0);
    state1 z{0.0};
    const auto p = odestep::integrate_adaptive(plain, one, z, 0.0, 10.0, [](double, const state1&) {});
    CHECK(p.steps == r.steps);
    CHECK(z[0] == y[0]);
}

TEST_CASE("free-running events: a terminal event on the first step stops there; an event zero at t0 does not fire") {
    clock_dp5 engine;
    engine.set_step_size(10.0);
    auto at_1 =
        odestep::make_event<state1>([](double t, const state1&) { return t - 1.0; }, odestep::direction::rising);
    // g = y is zero at t0: as on the grid (and CVODE; unlike SciPy, which reports t0), it does not fire
    auto at_0 = odestep::make_event<state1>([](double, const state1& y) { return y[0]; }, odestep::direction::either,
                                            odestep::record);
    std::vector<sample> seen;
    state1 y{0.0};
    const auto r = odestep::integrate_adaptive(engine, one, y, 0.0, 10.0, odestep::watch(at_0, at_1),
                                               [&](double t, const state1& s) {
                                                   seen.push_back({t, s[0]});
                                               });
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 1);
    CHECK(r.firings[0] == 0);
    CHECK(r.steps == 0);
    CHECK(r.t <= 1.0);  // g = t - 1: exactly zero at 1, a representable time: there or the time before
    CHECK(r.t >= std::nextafter(1.0, 0.0));
    CHECK(std::abs(y[0] - 1.0) <= 8.0 * std::numeric_limits<double>::epsilon() * 10.0);
    REQUIRE(seen.size() == 2);
    CHECK(seen[1].t == r.t);
    CHECK(seen[1].y == y[0]);
    // Called again from the stopped state: the root within the tolerance after the new t0 does not fire again.
    const auto again = odestep::integrate_adaptive(engine, one, y, r.t, 10.0, odestep::watch(at_0, at_1));
    CHECK(again.status == odestep::status::ok);
    CHECK(again.t == 10.0);
    CHECK(again.fired == 0);
}

TEST_CASE("free-running events: an action that changes only a parameter restarts the step sequence (FSAL honest)") {
    // y' = k, k = 1 until t = 1, then k = -1: y = t on [0, 1], y = 2 - t after; at t = 3, y = -1 exactly.
    // With a first step of 1 the event is at that step's end (g = t - 1 is zero there): without the restart,
    // DP 5(4)'s kept first stage (f at that point, with k = 1) would start the next step.
    for (const double step : {1.0, 10.0, 0.0}) {
        CAPTURE(step);
        double k = 1.0;
        auto f = [&k](double, const state1&) { return state1{k}; };
        auto turn = odestep::make_event<state1>([](double t, const state1&) { return t - 1.0; },
                                                odestep::direction::rising, [&k](double, state1&) { k = -1.0; });
        clock_dp5 engine;
        engine.set_step_size(step);
        state1 y{0.0};
        const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, 3.0, odestep::watch(turn));
        CHECK(r.status == odestep::status::ok);
        CHECK(r.fired == 1);
        CHECK(std::abs(y[0] + 1.0) <= 16.0 * std::numeric_limits<double>::epsilon());
    }
}

TEST_CASE("free-running events: integrate_times sees its times, record firings and the stop, in time order") {
    // SciPy's test_t_eval_early_event, and its times before the event: t - 7 terminal on [5, 9].
    auto early =
        odestep::make_event<state2>([](double t, const state2&) { return t - 7.0; }, odestep::direction::either);
    auto mark = odestep::make_event<state2>([](double t, const state2&) { return t - 6.25; },
                                            odestep::direction::rising, odestep::record);
    const std::array<double, 5> times{5.5, 6.0, 6.5, 7.5, 9.0};
    const auto tol = odestep::tolerances<state2>::uniform(1e-10, 1e-12);
    std::vector<firing> seen;
    dp5<double> engine(tol);
    state2 y{1.0 / 3.0, 2.0 / 9.0};
    const auto r = odestep::integrate_times(engine, rational, y, 5.0, times, odestep::watch(early, mark),
                                            [&](double t, const state2& s) {
                                                seen.push_back({0, t, s});
                                            });
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 0);
    REQUIRE(seen.size() == 5);  // 5.5, 6.0, the record at 6.25, 6.5, the stop at 7 (SciPy observes no stop)
    const std::array<double, 5> expected{5.5, 6.0, 6.25, 6.5, 7.0};
    for (std::size_t i = 0; i < 5; ++i) {
        CAPTURE(i);
        CHECK(std::abs(seen[i].t - expected[i]) <= 2.0 * std::numeric_limits<double>::epsilon() * expected[i]);
        CHECK(std::abs(seen[i].y[0] - rational_solution(seen[i].t)[0]) < 1e-9);
    }
    CHECK(seen[4].t == r.t);
    CHECK(seen[4].y[0] == y[0]);
    CHECK(seen[4].y[1] == y[1]);
    // Radau: the same times from the collocation polynomial
    std::vector<firing> seen_radau;
    radau<double> stiff(tol);
    state2 z{1.0 / 3.0, 2.0 / 9.0};
    const auto rr = odestep::integrate_times(stiff, rational, z, 5.0, times, odestep::watch(early, mark),
                                             [&](double t, const state2& s) {
                                                 seen_radau.push_back({0, t, s});
                                             });
    CHECK(rr.status == odestep::status::stopped_by_event);
    REQUIRE(seen_radau.size() == 5);
    for (std::size_t i = 0; i < 5; ++i)
        CHECK(std::abs(seen_radau[i].y[0] - rational_solution(seen_radau[i].t)[0]) < 1e-8);
    // Rodas4 and SDIRK4: the same times, the stop and the record from the cubic Hermite interpolant of their steps
    const auto hermite_times = [&](auto stiff_engine, const char* name) {
        CAPTURE(name);
        std::vector<firing> got;
        state2 u{1.0 / 3.0, 2.0 / 9.0};
        const auto rh = odestep::integrate_times(stiff_engine, rational, u, 5.0, times, odestep::watch(early, mark),
                                                 [&](double t, const state2& s) {
                                                     got.push_back({0, t, s});
                                                 });
        CHECK(rh.status == odestep::status::stopped_by_event);
        CHECK(rh.event == 0);
        REQUIRE(got.size() == 5);
        for (std::size_t i = 0; i < 5; ++i) {
            CAPTURE(i);
            CHECK(std::abs(got[i].t - expected[i]) <= 2.0 * std::numeric_limits<double>::epsilon() * expected[i]);
            // order 3 between steps taken at rtol 1e-10: measured 5.6e-13 (Rodas4) and 4.0e-12 (SDIRK4) at most
            CHECK(std::abs(got[i].y[0] - rational_solution(got[i].t)[0]) < 1e-10);
        }
        CHECK(got[4].t == rh.t);
        CHECK(got[4].y[0] == u[0]);
    };
    hermite_times(rodas<double>(tol), "Rodas4");
    hermite_times(sdirk<double>(tol), "SDIRK4");
}

namespace {

// Robertson's chemical kinetics (HNW II, Sec. IV.1), y1 falling through 0.5. The reference, 268.3247260155,
// is SciPy 1.10.1's, agreeing with its BDF and LSODA to 1.2e-8 s:
//   solve_ivp(f, (0, 1e5), [1, 0, 0], method="Radau", rtol=1e-12, atol=[1e-14, 1e-18, 1e-14], events=ev)
//   (ev = y[0] - 0.5, direction -1; BDF: 268.324726026893, LSODA: 268.324726023559)
using state3 = std::array<double, 3>;
state3 robertson(double, const state3& y) {
    return {-0.04 * y[0] + 1e4 * y[1] * y[2], 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1], 3e7 * y[1] * y[1]};
}

template <class Engine>
void check_robertson(const char* name) {
    CAPTURE(name);
    const double reference = 268.3247260155;
    const auto tol = odestep::tolerances<state3>::per_component({1e-9, 1e-9, 1e-9}, {1e-12, 1e-16, 1e-12});
    auto half =
        odestep::make_event<state3>([](double, const state3& y) { return y[0] - 0.5; }, odestep::direction::falling);
    Engine engine(tol);
    state3 y{1.0, 0.0, 0.0};
    const auto r = odestep::integrate_adaptive(engine, robertson, y, 0.0, 1e5, odestep::watch(half));
    CHECK(r.status == odestep::status::stopped_by_event);
    // y1' = -4.6e-4 there: a state error of 1e-9 relative (5e-10 in y1) moves the time by about 1e-6 s; the
    // check allows ten times that.
    CHECK(std::abs(r.t - reference) < 1e-5);
    CHECK(std::abs(y[0] - 0.5) < 1e-12);
    CHECK(std::abs(y[0] + y[1] + y[2] - 1.0) < 1e-9);  // mass conservation
}

}  // namespace

TEST_CASE("free-running events: Robertson's y1 crosses 0.5 at SciPy's time, with Radau, Rodas4 and SDIRK4") {
    check_robertson<odestep::radau5<state3>>("Radau IIA 5");
    check_robertson<odestep::rosenbrock_adaptive<odestep::tables::rodas4, state3>>("Rodas4");
    check_robertson<odestep::sdirk_adaptive<odestep::tables::sdirk4, state3>>("SDIRK4");
}

TEST_CASE("free-running events: bad input is refused before anything is observed; the work stays within its bound") {
    auto ground =
        odestep::make_event<state2>([](double, const state2& s) { return s[0]; }, odestep::direction::falling);
    std::size_t observed = 0;
    auto count = [&](double, const state2&) { ++observed; };
    const state2 y0{1.0, 0.0};
    auto fall = [](double, const state2& s) { return state2{s[1], -9.81}; };
    {
        dp5<double> engine;
        state2 y = y0;
        const auto r =
            odestep::integrate_adaptive(engine, fall, y, 0.0, 1.0, odestep::watch(ground.with_tolerance(-1.0)), count);
        CHECK(r.status == odestep::status::invalid_tolerance);
        const auto z = odestep::integrate_adaptive(engine, fall, y, 0.0, 1.0, odestep::watch(ground), count, 0);
        CHECK(z.status == odestep::status::invalid_setting);
        const auto n = odestep::integrate_adaptive(engine, fall, y, 0.0, std::nan(""), odestep::watch(ground), count);
        CHECK(n.status == odestep::status::invalid_time);
        auto nan_g =
            odestep::make_event<state2>([](double, const state2&) { return std::nan(""); }, odestep::direction::either);
        const auto g = odestep::integrate_adaptive(engine, fall, y, 0.0, 1.0, odestep::watch(nan_g), count);
        CHECK(g.status == odestep::status::non_finite_event);
        CHECK(observed == 0);
        CHECK(y == y0);
    }
    {
        // The cap: a run that needs more attempts ends with substep_limit at its last state
        auto never =
            odestep::make_event<state2>([](double t, const state2&) { return t - 1e9; }, odestep::direction::either);
        dp5<double> engine;
        state2 y = y0;
        const auto r = odestep::integrate_adaptive(engine, fall, y, 0.0, 1e6, odestep::watch(never), count, 3);
        CHECK(r.status == odestep::status::substep_limit);
        CHECK(r.steps == 3);
    }
    // The bound, counted: the ball with its bounces, until event_limit
    for (const std::size_t attempts : {std::size_t(5), std::size_t(40), std::size_t(100000)}) {
        CAPTURE(attempts);
        std::size_t calls = 0;
        auto counted = odestep_test::counted(fall, &calls);
        auto bounce =
            odestep::make_event<state2>([](double, const state2& s) { return s[0]; }, odestep::direction::falling,
                                        [](double, state2& s) { s[1] = -0.7 * s[1]; });
        const auto events = odestep::watch(bounce);
        dp5<double> engine;
        state2 y = y0;
        const auto r = odestep::integrate_adaptive(engine, counted, y, 0.0, 10.0, events, count, attempts);
        CHECK(r.status != odestep::status::ok);
        CHECK(calls <= odestep::max_rhs_evals_free_running<dp5<double>>(1, events.limits, attempts));
        std::size_t radau_calls = 0;
        auto radau_counted = odestep_test::counted(fall, &radau_calls);
        radau<double> stiff;
        state2 z = y0;
        (void)odestep::integrate_adaptive(stiff, radau_counted, z, 0.0, 10.0, events, count, attempts);
        CHECK(radau_calls <= odestep::max_rhs_evals_free_running<radau<double>>(1, events.limits, attempts));
    }
    // RK4's grid bound with two events and the default limits is 6572; the free-running one per attempt:
    static_assert(odestep::max_rhs_evals_free_running<dp5<double>>(2, {}, 1) == 3 + 1 * (6 + 3 + 0 + 8),
                  "DP 5(4): start 3, per attempt 6 stages, a restart's 3, no completion, 8 actions' headings");
}

TEST_CASE("free-running events: integrate_times across an action follows the trajectory the action left") {
    // y' = k, k = 1 until t = 1, then k = -1 (a parameter-only action): y = t, then 2 - t. The times before the
    // event come from the first step's extension, those after from the restarted steps.
    for (const double step : {10.0, 0.0}) {
        CAPTURE(step);
        double k = 1.0;
        auto f = [&k](double, const state1&) { return state1{k}; };
        auto turn = odestep::make_event<state1>([](double t, const state1&) { return t - 1.0; },
                                                odestep::direction::rising, [&k](double, state1&) { k = -1.0; });
        clock_dp5 engine;
        engine.set_step_size(step);
        const std::array<double, 4> times{0.5, 1.5, 2.5, 4.0};
        std::vector<sample> seen;
        state1 y{0.0};
        const auto r =
            odestep::integrate_times(engine, f, y, 0.0, times, odestep::watch(turn), [&](double t, const state1& s) {
                seen.push_back({t, s[0]});
            });
        CHECK(r.status == odestep::status::ok);
        CHECK(r.t == 4.0);
        CHECK(r.fired == 1);
        REQUIRE(seen.size() == 4);
        const std::array<double, 4> expected{0.5, 0.5, -0.5, -2.0};
        for (std::size_t i = 0; i < 4; ++i) {
            CAPTURE(i);
            CHECK(seen[i].t == times[i]);
            CHECK(std::abs(seen[i].y - expected[i]) <= 64.0 * std::numeric_limits<double>::epsilon());
        }
        CHECK(y[0] == seen[3].y);
    }
}

TEST_CASE("free-running events: on_interpolant locates on the Hermite cubic of the free-running step") {
    // Free fall from 10 m: the Hermite cubic is exact for the quadratic, so the impact is the closed form's
    // sqrt(2 h / g) to rounding, as with the step's own extension.
    using T = double;
    using state = std::array<T, 2>;
    auto f = [](T, const state& s) { return state{s[1], -9.81}; };
    auto ground = odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling);
    dp5<double> engine;
    state y{10.0, 0.0};
    const auto r =
        odestep::integrate_adaptive(engine, f, y, 0.0, 100.0, odestep::watch<odestep::on_interpolant<>>(ground));
    const double t_hit = std::sqrt(2.0 * 10.0 / 9.81);
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - t_hit) <= 1e-14);
    CHECK(y[0] >= 0.0);
    CHECK(y[0] <= 1e-13);
    // and the ball bounces on it until event_limit, never below the floor
    auto bounce = odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling,
                                             [](T, state& s) { s[1] = -0.7 * s[1]; });
    dp5<double> again;
    state z{1.0, 0.0};
    double lowest = 1.0;
    const auto b =
        odestep::integrate_adaptive(again, f, z, 0.0, 10.0, odestep::watch<odestep::on_interpolant<>>(bounce),
                                    [&](T, const state& s) { lowest = std::fmin(lowest, s[0]); });
    CHECK(b.status == odestep::status::event_limit);
    CHECK(b.t < zeno_time(1.0, 9.81, 0.7));
    CHECK(lowest >= -floor_tolerance<double>());
}

TEST_CASE("free-running events: the replaying stepper reads the step, and refuses to re-step from elsewhere") {
    // The contract the free-running loop relies on (detail::replaying_stepper): the engine's own stepper
    // gives the step's end once, then asks for a restart; a copy re-steps s after the step's start from its
    // extension, and a re-step from any other start (t or y) asks for the restart too.
    using state = std::array<double, 2>;
    using engine_type = dp5<double>;
    auto f = [](double, const state& s) { return state{s[1], -9.81}; };
    using replayed_type = odestep::detail::replayed_step<engine_type, decltype(f), state>;
    engine_type engine;
    engine.set_step_size(0.25);  // (free fall: a zero error estimate, the step is accepted)
    replayed_type replayed(engine, f);
    state y{1.0, 0.0};
    double t = 0.0;
    bool accepted = false;
    while (!accepted) REQUIRE(engine.attempt(f, t, y, 0.25, accepted, replayed.ext.sink()) == odestep::status::ok);
    REQUIRE(t == 0.25);
    replayed.begin(0.0, state{1.0, 0.0}, t, y);
    odestep::detail::replaying_stepper<replayed_type, state> own(replayed);
    state u{1.0, 0.0};
    CHECK(own.step(f, u, 0.0, 0.25) == odestep::status::ok);
    CHECK(u == y);
    auto copy = own;
    state w{1.0, 0.0};
    CHECK(copy.step(f, w, 0.0, 0.125) == odestep::status::ok);
    // free fall from 1 m: the extension is exact for the quadratic, to rounding
    CHECK(std::abs(w[0] - (1.0 - 9.81 * 0.125 * 0.125 / 2.0)) <= 1e-15);
    CHECK(std::abs(w[1] + 9.81 * 0.125) <= 1e-14);
    CHECK(!replayed.restart);
    state elsewhere{0.5, 0.0};
    CHECK(copy.step(f, elsewhere, 0.0, 0.125) != odestep::status::ok);
    CHECK(replayed.restart);
    replayed.restart = false;
    state later{1.0, 0.0};
    CHECK(copy.step(f, later, 0.125, 0.0625) != odestep::status::ok);
    CHECK(replayed.restart);
    replayed.restart = false;
    CHECK(own.step(f, u, 0.125, 0.125) != odestep::status::ok);  // the engine's stepper, a second time
    CHECK(replayed.restart);
}

TEST_CASE("free-running events: a record and a terminal event at one time: the stop hands back the state observed") {
    // y0' = 10 + 10 t, y0(0) = 0: y0 = 5 t (t + 2), zero at t = -2 (BS 3(2)'s steps and its Hermite extension are
    // exact for this quadratic but for rounding); y1' = 10 (y0 + y1 + 1 + t) only makes the steps short. The
    // record and the terminal event watch the same g = y0, so both fire at one location: the record's
    // observation is the event's state, and the stop hands back that same state (fuzz_free_events'
    // stopped-two-events-same-time: the record was read from the extension at t - t_s, the stop at the
    // location's own offset, which rounds to the same t; the two states differed in the last bits).
    auto f = [](double t, const state2& y) { return state2{10.0 + 10.0 * t, 10.0 * (y[0] + y[1] + 1.0 + t)}; };
    auto g = [](double, const state2& y) { return y[0]; };
    auto seen_at = odestep::make_event<state2>(g, odestep::direction::either, odestep::record);
    auto stop_at = odestep::make_event<state2>(g, odestep::direction::either, odestep::terminal);
    odestep::adaptive_rk<odestep::tables::bogacki_shampine32, state2> engine(
        odestep::tolerances<state2>::uniform(10.0, 10.0));
    state2 y{0.0, 0.0};
    double last_t = 0.0;
    state2 last{};
    std::size_t observed = 0;
    const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, -9.375, odestep::watch(seen_at, stop_at),
                                               [&](double t, const state2& s) {
                                                   last_t = t;
                                                   last = s;
                                                   ++observed;
                                               });
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.event == 1);
    CHECK(r.firings[0] == 1);
    // the root of 5 t (t + 2): -2, to the rounding of the steps (terms of size 20: a few ULPs of 20, over |y0'| = 10)
    CHECK(std::abs(r.t + 2.0) <= 64.0 * std::numeric_limits<double>::epsilon());
    CHECK(std::abs(y[0]) <= 64.0 * std::numeric_limits<double>::epsilon() * 20.0);
    CHECK(observed >= 2);
    CHECK(last_t == r.t);
    CHECK(last[0] == y[0]);
    CHECK(last[1] == y[1]);
}
