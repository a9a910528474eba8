// SPDX-License-Identifier: BSL-1.0
// odestep::counts in every result: each count against an independent counter, a wrapper around f, J or g that
// increments its own variable on every call (or the observer's calls, for accepted steps), for each loop kind.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace {

using S2 = std::array<double, 2>;
using S1 = std::array<double, 1>;
using odestep::step_count;

// f (or a, or g) with every call counted in `calls`, and J's calls in `jacobians` when it carries one: the
// independent counters the results are compared with.
template <class F>
struct counted_fn {
    F f;
    step_count* calls;
    template <class... A>
    auto operator()(A&&... a) const -> decltype(f(a...)) {
        ++*calls;
        return f(a...);
    }
};
template <class F>
counted_fn<F> count_calls(F f, step_count* calls) {
    return counted_fn<F>{f, calls};
}

// The harmonic oscillator y'' = -y as a first-order system.
const auto sho = [](double, const S2& y) { return S2{y[1], -y[0]}; };

// A stiff linear system y' = A y, A = [[-50, 1], [0, -1]], and its Jacobian A.
const auto stiff_f = [](double, const S2& y) { return S2{-50.0 * y[0] + y[1], -y[1]}; };
const auto stiff_j = [](double, const S2&, odestep::jacobian_t<S2>& m) {
    m[0] = S2{-50.0, 1.0};
    m[1] = S2{0.0, -1.0};
};

TEST_CASE("counts: the fixed-grid loop with RK4 reports f's calls and its steps (evaluations derived)") {
    step_count calls = 0;
    auto f = count_calls(sho, &calls);
    S2 y{1.0, 0.0};
    const auto r = odestep::integrate(odestep::rk4<S2>{}, f, y, 0.0, 1.0, 0.03);  // 34 steps, the last shortened
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.counts.rhs_evals == calls);
    CHECK(calls == 4 * 34);  // RK4: four stages per step
    CHECK(r.counts.accepted_steps == r.steps);
    CHECK(r.counts.rejected_steps == 0);
    CHECK(r.counts.jacobian_evals == 0);
    CHECK(r.counts.factorizations == 0);
    CHECK(r.counts.event_evals == 0);
    CHECK(r.counts.firings == 0);
}

TEST_CASE("counts: a step that fails (NaN from f) still counts the evaluations it made") {
    step_count calls = 0;
    auto f = count_calls(
        [&](double t, const S2& y) {
            return t > 0.5 ? S2{std::numeric_limits<double>::quiet_NaN(), 0.0} : S2{y[1], -y[0]};
        },
        &calls);
    S2 y{1.0, 0.0};
    const auto r = odestep::integrate(odestep::rk4<S2>{}, f, y, 0.0, 1.0, 0.1);
    REQUIRE(r.status == odestep::status::non_finite);
    CHECK(r.counts.rhs_evals == calls);
    CHECK(r.counts.accepted_steps == r.steps);
}

TEST_CASE("counts: steppers whose evaluations vary are counted call by call (Verlet, Adams, unchecked)") {
    SUBCASE("velocity Verlet keeps its acceleration: one evaluation a step after the first") {
        step_count calls = 0;
        auto a = count_calls([](double, const S1& x) { return S1{-x[0]}; }, &calls);
        S1 x{1.0};
        S1 v{0.0};
        const auto r = odestep::integrate_n_steps(odestep::velocity_verlet<S1>{}, a, x, v, 0.0, 0.01, 100);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == calls);
        CHECK(r.counts.accepted_steps == 100);
    }
    SUBCASE("Adams-Bashforth 4 starts with RK4") {
        step_count calls = 0;
        auto f = count_calls(sho, &calls);
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate_n_steps(odestep::adams_bashforth4<S2>{}, f, y, 0.0, 0.01, 50);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == calls);
    }
}

TEST_CASE("counts: a fixed-step implicit stepper reports f, its own Jacobian's calls and a factorization a step") {
    step_count f_calls = 0;
    step_count j_calls = 0;
    auto sys = odestep::with_jacobian(count_calls(stiff_f, &f_calls), count_calls(stiff_j, &j_calls));
    S2 y{1.0, 1.0};
    const auto r = odestep::integrate(odestep::radau_iia5<S2>{}, sys, y, 0.0, 1.0, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.counts.rhs_evals == f_calls);
    CHECK(r.counts.jacobian_evals == j_calls);
    CHECK(j_calls == 10);                  // one Jacobian per step (jacobians_per_step)
    CHECK(r.counts.factorizations == 10);  // one factorization per step
    // Radau IIA 5 with the system's Jacobian evaluates f only in its Newton iterations, at its three stages
    CHECK(r.counts.newton_iterations * 3 == f_calls);
    CHECK(r.counts.newton_iterations >= 10);  // at least one a step
}

// y' = -y^3 (nonlinear: Newton takes a varying number of iterations) and its Jacobian -3 y^2.
const auto cubic_f = [](double, const S1& y) { return S1{-y[0] * y[0] * y[0]}; };
const auto cubic_j = [](double, const S1& y, odestep::jacobian_t<S1>& m) { m[0] = S1{-3.0 * y[0] * y[0]}; };

TEST_CASE("counts: the fixed-step implicit steppers report their Newton iterations in every loop") {
    step_count f_calls = 0;
    step_count j_calls = 0;
    auto sys = odestep::with_jacobian(count_calls(cubic_f, &f_calls), count_calls(cubic_j, &j_calls));
    SUBCASE("backward Euler with the system's Jacobian: each iteration is f's one call (newton<10>)") {
        S1 y{1.0};
        const auto r = odestep::integrate(odestep::backward_euler<S1>{}, sys, y, 0.0, 1.0, 0.1);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.newton_iterations == f_calls);
        CHECK(r.counts.newton_iterations > r.steps);  // nonlinear: more than one iteration in some step
        CHECK(r.counts.jacobian_evals == j_calls);
    }
    SUBCASE("fixed_newton<3>: exactly three iterations a step, in integrate_n_steps") {
        S1 y{1.0};
        const auto r =
            odestep::integrate_n_steps(odestep::backward_euler<S1, odestep::fixed_newton<3>>{}, sys, y, 0.0, 0.1, 10);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.newton_iterations == 30);
        CHECK(f_calls == 30);
    }
    SUBCASE("Radau IIA 5, fixed_newton<4>, difference Jacobian: 4 iterations a step of 3 evaluations each") {
        step_count calls = 0;
        auto f = count_calls(stiff_f, &calls);
        S2 y{1.0, 1.0};
        const auto r =
            odestep::integrate_n_steps(odestep::radau_iia5<S2, odestep::fixed_newton<4>>{}, f, y, 0.0, 0.1, 10);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.newton_iterations == 40);
        CHECK(calls == 10 * (4 * 3 + 2 + 1));  // the iterations' 3 a time, and the difference Jacobian's N + 1
        CHECK(r.counts.rhs_evals == calls);
    }
    SUBCASE("integrate with events (re-stepping), and the per-tick loop: f's calls are all iterations") {
        // y = 1 / sqrt(1 + 2t) crosses 0.5 at t = 1.5: a record event re-steps through the crossing
        auto g = [](double, const S1& y) { return y[0] - 0.5; };
        auto events = odestep::watch(odestep::make_event<S1>(g, odestep::direction::falling, odestep::record));
        S1 y{1.0};
        const auto r = odestep::integrate(odestep::backward_euler<S1>{}, sys, y, 0.0, 2.0, 0.1, events);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(r.fired == 1);
        CHECK(r.counts.newton_iterations == f_calls);
        CHECK(r.counts.newton_iterations > r.steps);  // the location's re-steps iterate too
        f_calls = 0;
        auto loop = odestep::make_event_stepper(odestep::backward_euler<S1>{}, events);
        S1 u{1.0};
        REQUIRE(loop.start(0.0, 0.1, u) == odestep::status::ok);
        for (int k = 0; k < 20; ++k) REQUIRE(loop.tick(sys, u).status == odestep::status::ok);
        REQUIRE(loop.firings(0) == 1);
        CHECK(loop.counts().newton_iterations == f_calls);
    }
    SUBCASE("a step called directly, on a system no loop counts, compiles and runs (the counter is the loop's)") {
        S1 y{1.0};
        const odestep::backward_euler<S1> stepper;
        REQUIRE(stepper.step(sys, y, 0.0, 0.1) == odestep::status::ok);
        CHECK(f_calls >= 1);
    }
}

// A falling ball, y = (height, velocity), bouncing on the floor with restitution 0.9.
const auto ball = [](double, const S2& y) { return S2{y[1], -9.81}; };

TEST_CASE("counts: integrate with events reports f, g and the firings (re-stepping and on the interpolant)") {
    const auto bounce = [](double, S2& y) { y[1] = -0.9 * y[1]; };
    SUBCASE("re-stepping with RK4 (f derived from the step calls)") {
        step_count f_calls = 0;
        step_count g_calls = 0;
        auto f = count_calls(ball, &f_calls);
        auto g = count_calls([](double, const S2& y) { return y[0]; }, &g_calls);
        auto events = odestep::watch(odestep::make_event<S2>(g, odestep::direction::falling, bounce));
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate(odestep::rk4<S2>{}, f, y, 0.0, 2.0, 0.01, events);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(r.fired >= 2);  // lands at 0.45 s, and again at 1.26 s
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.event_evals == g_calls);
        CHECK(r.counts.firings == r.fired);
        CHECK(r.counts.accepted_steps == r.steps);
    }
    SUBCASE("on the interpolant, with probes and a record event") {
        step_count f_calls = 0;
        step_count g_calls = 0;
        step_count h_calls = 0;
        auto f = count_calls(ball, &f_calls);
        auto g = count_calls([](double, const S2& y) { return y[0]; }, &g_calls);
        auto apex = count_calls([](double, const S2& y) { return y[1]; }, &h_calls);
        odestep::event_limits limits;
        limits.probes = 2;
        auto events = odestep::watch<odestep::on_interpolant<>>(
                          odestep::make_event<S2>(g, odestep::direction::falling, bounce),
                          odestep::make_event<S2>(apex, odestep::direction::falling, odestep::record))
                          .with_limits(limits);
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate(odestep::rk4<S2>{}, f, y, 0.0, 2.0, 0.01, events);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(r.firings[0] >= 2);
        REQUIRE(r.firings[1] >= 1);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.event_evals == g_calls + h_calls);
        CHECK(r.counts.firings == r.fired);
    }
    SUBCASE("a Newtonian stepper (Verlet, f counted call by call) stopped by a terminal event") {
        step_count a_calls = 0;
        step_count g_calls = 0;
        auto a = count_calls([](double, const S1&) { return S1{-9.81}; }, &a_calls);
        auto g = count_calls([](double, const S1& x, const S1&) { return x[0]; }, &g_calls);
        auto events = odestep::watch(odestep::make_event<S1>(g, odestep::direction::falling));
        S1 x{1.0};
        S1 v{0.0};
        const auto r = odestep::integrate(odestep::velocity_verlet<S1>{}, a, x, v, 0.0, 2.0, 0.01, events);
        REQUIRE(r.status == odestep::status::stopped_by_event);
        CHECK(r.counts.rhs_evals == a_calls);
        CHECK(r.counts.event_evals == g_calls);
        CHECK(r.counts.firings == 1);
    }
}

TEST_CASE("counts: the per-tick event loop counts since start, the quiet ticks' work derived") {
    const auto bounce = [](double, S2& y) { y[1] = -0.9 * y[1]; };
    SUBCASE("RK4, a bounce, a terminal event that stops inside a tick, then catching up") {
        step_count f_calls = 0;
        step_count g_calls = 0;
        step_count h_calls = 0;
        auto f = count_calls(ball, &f_calls);
        auto g = count_calls([](double, const S2& y) { return y[0]; }, &g_calls);
        // terminal when the ball first passes 0.5 m on the way up after the bounce
        auto up = count_calls([](double, const S2& y) { return y[0] - 0.5; }, &h_calls);
        auto loop = odestep::make_event_stepper(
            odestep::rk4<S2>{}, odestep::watch(odestep::make_event<S2>(g, odestep::direction::falling, bounce),
                                               odestep::make_event<S2>(up, odestep::direction::rising)));
        S2 y{1.0, 0.0};
        REQUIRE(loop.start(0.0, 0.01, y) == odestep::status::ok);
        std::size_t stops = 0;
        for (int k = 0; k < 150; ++k) {
            const auto r = loop.tick(f, y);
            REQUIRE((r.status == odestep::status::ok || r.status == odestep::status::stopped_by_event));
            if (r.status == odestep::status::stopped_by_event) ++stops;
        }
        REQUIRE(stops == 2);  // rising through 0.5 m after each of the first two landings (0.45 s, 1.26 s)
        const odestep::counts c = loop.counts();
        CHECK(c.rhs_evals == f_calls);
        CHECK(c.event_evals == g_calls + h_calls);
        CHECK(c.firings == loop.firings(0) + loop.firings(1));
        CHECK(c.firings >= 2);
        CHECK(c.accepted_steps == loop.reached());
        // a second start counts afresh
        f_calls = g_calls = h_calls = 0;
        REQUIRE(loop.start(0.0, 0.01, y) == odestep::status::ok);
        for (int k = 0; k < 10; ++k) REQUIRE(loop.tick(f, y).status == odestep::status::ok);
        CHECK(loop.counts().rhs_evals == f_calls);
        CHECK(loop.counts().event_evals == g_calls + h_calls);
        // a tick whose step fails (NaN from f) still made its evaluations
        bool poisoned = true;
        auto bad = count_calls(
            [&](double t, const S2& u) {
                return poisoned ? S2{std::numeric_limits<double>::quiet_NaN(), 0.0} : ball(t, u);
            },
            &f_calls);
        CHECK(loop.tick(bad, y).status == odestep::status::non_finite);
        poisoned = false;
        CHECK(loop.tick(bad, y).status == odestep::status::ok);
        CHECK(loop.counts().rhs_evals == f_calls);
        CHECK(loop.counts().event_evals == g_calls + h_calls);
    }
    SUBCASE("velocity Verlet (f counted call by call), and a tick whose step fails") {
        step_count a_calls = 0;
        step_count g_calls = 0;
        bool poisoned = false;
        auto a = count_calls(
            [&](double, const S1&) { return S1{poisoned ? std::numeric_limits<double>::quiet_NaN() : -9.81}; },
            &a_calls);
        auto g = count_calls([](double, const S1& x, const S1&) { return x[0]; }, &g_calls);
        auto loop = odestep::make_event_stepper(
            odestep::velocity_verlet<S1>{},
            odestep::watch(odestep::make_event<S1>(g, odestep::direction::falling, odestep::record)));
        S1 x{1.0};
        S1 v{0.0};
        REQUIRE(loop.start(0.0, 0.01, x, v) == odestep::status::ok);
        for (int k = 0; k < 60; ++k) REQUIRE(loop.tick(a, x, v).status == odestep::status::ok);
        poisoned = true;
        CHECK(loop.tick(a, x, v).status == odestep::status::non_finite);
        const odestep::counts c = loop.counts();
        CHECK(c.rhs_evals == a_calls);
        CHECK(c.event_evals == g_calls);
        CHECK(c.firings == 1);  // lands at 0.4515 s
        CHECK(c.accepted_steps == 60);
    }
}

TEST_CASE("counts: the free-running loops with events report f, g, J and the firings") {
    const auto bounce = [](double, S2& y) { y[1] = -0.9 * y[1]; };
    step_count observed = 0;
    const auto observe = [&](double, const S2&) { ++observed; };
    SUBCASE("integrate_adaptive, Dormand-Prince 5(4), a bounce and a record event") {
        step_count f_calls = 0;
        step_count g_calls = 0;
        step_count h_calls = 0;
        auto f = count_calls(ball, &f_calls);
        auto g = count_calls([](double, const S2& y) { return y[0]; }, &g_calls);
        auto apex = count_calls([](double, const S2& y) { return y[1]; }, &h_calls);
        odestep::adaptive_rk<odestep::tables::dormand_prince54, S2> engine(
            odestep::tolerances<S2>::uniform(1e-8, 1e-8));
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate_adaptive(
            engine, f, y, 0.0, 2.0,
            odestep::watch(odestep::make_event<S2>(g, odestep::direction::falling, bounce),
                           odestep::make_event<S2>(apex, odestep::direction::falling, odestep::record)),
            observe);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(r.firings[0] >= 2);  // lands at 0.45 s, and again at 1.26 s
        REQUIRE(r.firings[1] >= 1);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.event_evals == g_calls + h_calls);
        CHECK(r.counts.firings == r.fired);
        CHECK(r.counts.accepted_steps == r.steps);
    }
    SUBCASE("integrate_adaptive, Radau 5(4) (f, J and factorizations), a terminal event") {
        step_count f_calls = 0;
        step_count j_calls = 0;
        step_count g_calls = 0;
        auto f = count_calls(stiff_f, &f_calls);
        auto jac = count_calls(stiff_j, &j_calls);
        auto g = count_calls([](double, const S2& y) { return y[1] - 0.5; }, &g_calls);  // y2 = e^-t: t = ln 2
        odestep::radau5<S2> engine(odestep::tolerances<S2>::uniform(1e-8, 1e-8));
        S2 y{1.0, 1.0};
        const auto r = odestep::integrate_adaptive(
            engine, odestep::with_jacobian(f, jac), y, 0.0, 5.0,
            odestep::watch(odestep::make_event<S2>(g, odestep::direction::falling, odestep::terminal)), observe);
        REQUIRE(r.status == odestep::status::stopped_by_event);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.jacobian_evals == j_calls);
        CHECK(r.counts.event_evals == g_calls);
        CHECK(r.counts.factorizations >= 2);  // a real and a complex one per decomposition, at least one
        CHECK(r.counts.firings == 1);
    }
}

TEST_CASE("counts: the free-running adaptive loops report f, accepted and rejected steps") {
    step_count observed = 0;
    const auto observe = [&](double, const S2&) { ++observed; };
    SUBCASE("integrate_adaptive, Dormand-Prince 5(4)") {
        step_count calls = 0;
        auto f = count_calls(sho, &calls);
        odestep::adaptive_rk<odestep::tables::dormand_prince54, S2> engine(
            odestep::tolerances<S2>::uniform(1e-8, 1e-8));
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, 10.0, observe);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == calls);
        CHECK(r.counts.accepted_steps == observed - 1);  // the observer: the start, then every accepted step
        CHECK(r.counts.accepted_steps == r.steps);
        CHECK(r.counts.rejected_steps == engine.rejected_steps());  // the engine's first run
        // a second run on the same engine reports its own work only
        observed = 0;
        calls = 0;
        const auto again = odestep::integrate_adaptive(engine, f, y, 10.0, 12.0, observe);
        REQUIRE(again.status == odestep::status::ok);
        CHECK(again.counts.rhs_evals == calls);
        CHECK(again.counts.accepted_steps == observed - 1);
    }
    SUBCASE("integrate_times, DOP853 (its interpolant's extra evaluations)") {
        step_count calls = 0;
        auto f = count_calls(sho, &calls);
        odestep::adaptive_rk<odestep::tables::dop853, S2> engine(odestep::tolerances<S2>::uniform(1e-8, 1e-8));
        S2 y{1.0, 0.0};
        const std::array<double, 5> times{0.5, 1.0, 2.5, 4.0, 7.0};
        const auto r = odestep::integrate_times(engine, f, y, 0.0, times, observe);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == calls);
        CHECK(r.counts.accepted_steps == r.steps);
    }
    SUBCASE("integrate_adaptive into a solution, Cash-Karp (no first-same-as-last)") {
        step_count calls = 0;
        auto f = count_calls(sho, &calls);
        odestep::adaptive_rk<odestep::tables::cash_karp54, S2> engine(odestep::tolerances<S2>::uniform(1e-6, 1e-6));
        odestep::solution<odestep::tables::cash_karp54, S2, 200> sol;
        S2 y{1.0, 0.0};
        const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, 5.0, sol);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == calls);
        CHECK(r.counts.accepted_steps == sol.size());
    }
}

TEST_CASE("counts: adaptive_sampler reports its run's work over its advance_to calls") {
    step_count calls = 0;
    auto f = count_calls(sho, &calls);
    using M = odestep::tables::dop853;  // its interpolant costs three more evaluations a step it is used in
    const odestep::adaptive_rk<M, S2> engine(odestep::tolerances<S2>::uniform(1e-8, 1e-8));
    odestep::adaptive_sampler<M, S2> sampler(engine, 0.0, S2{1.0, 0.0}, 10.0);
    CHECK(sampler.counts().rhs_evals == 0);  // nothing evaluated before advance_to
    S2 y{};
    for (const double t : {0.5, 1.0, 2.5, 4.0, 7.0, 10.0}) REQUIRE(sampler.advance_to(f, t, y) == odestep::status::ok);
    const odestep::counts c = sampler.counts();
    CHECK(c.rhs_evals == calls);
    CHECK(c.accepted_steps == sampler.steps());
    // the same steps as integrate_adaptive over [0, 10] (the class's promise): its accepted and rejected steps
    step_count observed = 0;
    odestep::adaptive_rk<M, S2> twin(odestep::tolerances<S2>::uniform(1e-8, 1e-8));
    S2 z{1.0, 0.0};
    const auto r = odestep::integrate_adaptive(twin, sho, z, 0.0, 10.0, [&](double, const S2&) { ++observed; });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(c.accepted_steps == observed - 1);
    CHECK(c.rejected_steps == r.counts.rejected_steps);
    // asking again for t = 10, the run's own state, evaluates nothing
    const step_count before = calls;
    REQUIRE(sampler.advance_to(f, 10.0, y) == odestep::status::ok);
    CHECK(sampler.counts().rhs_evals == calls);
    CHECK(calls == before);
}

TEST_CASE("counts: the stiff engines report f, J, factorizations and Newton iterations") {
    step_count observed = 0;
    const auto observe = [&](double, const S2&) { ++observed; };
    SUBCASE("radau5 with its own Jacobian") {
        step_count f_calls = 0;
        step_count j_calls = 0;
        auto sys = odestep::with_jacobian(count_calls(stiff_f, &f_calls), count_calls(stiff_j, &j_calls));
        odestep::radau5<S2> engine(odestep::tolerances<S2>::uniform(1e-6, 1e-6));
        S2 y{1.0, 1.0};
        const auto r = odestep::integrate_adaptive(engine, sys, y, 0.0, 5.0, observe);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.jacobian_evals == j_calls);
        CHECK(r.counts.accepted_steps == observed - 1);
        CHECK(r.counts.factorizations == 2 * engine.decompositions());  // a real and a complex LU each
        CHECK(r.counts.newton_iterations == engine.newton_iterations());
        CHECK(r.counts.newton_iterations >= r.counts.accepted_steps);  // at least one per accepted step
    }
    SUBCASE("SDIRK4 with its own Jacobian (its factorizations were reported as 0)") {
        step_count f_calls = 0;
        step_count j_calls = 0;
        auto sys = odestep::with_jacobian(count_calls(stiff_f, &f_calls), count_calls(stiff_j, &j_calls));
        odestep::sdirk_adaptive<odestep::tables::sdirk4, S2> engine(odestep::tolerances<S2>::uniform(1e-6, 1e-6));
        S2 y{1.0, 1.0};
        const auto r = odestep::integrate_adaptive(engine, sys, y, 0.0, 5.0, observe);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.jacobian_evals == j_calls);
        CHECK(r.counts.accepted_steps == observed - 1);
        CHECK(r.counts.factorizations == engine.decompositions());
        CHECK(r.counts.factorizations >= j_calls);  // every new Jacobian is factorized
        CHECK(r.counts.newton_iterations == engine.newton_iterations());
        CHECK(r.counts.newton_iterations <= f_calls);  // each iteration one evaluation of f
        CHECK(r.counts.newton_iterations >= r.counts.accepted_steps);
    }
    SUBCASE("Rodas4 with its own Jacobian: one Jacobian and one factorization per step tried") {
        step_count f_calls = 0;
        step_count j_calls = 0;
        auto sys = odestep::with_jacobian(count_calls(stiff_f, &f_calls), count_calls(stiff_j, &j_calls));
        odestep::rosenbrock_adaptive<odestep::tables::rodas4, S2> engine(odestep::tolerances<S2>::uniform(1e-6, 1e-6));
        S2 y{1.0, 1.0};
        const auto r = odestep::integrate_adaptive(engine, sys, y, 0.0, 5.0, observe);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.jacobian_evals == j_calls);
        CHECK(r.counts.factorizations == j_calls);
        CHECK(j_calls == r.counts.accepted_steps + r.counts.rejected_steps);
        CHECK(r.counts.accepted_steps == observed - 1);
    }
    SUBCASE("radau5_substeps on a fixed grid: the engine's steps inside the grid's") {
        step_count f_calls = 0;
        auto f = count_calls(stiff_f, &f_calls);
        odestep::radau5_substeps<S2> stepper;
        stepper.engine().set_tolerance(odestep::tolerances<S2>::uniform(1e-6, 1e-6));
        S2 y{1.0, 1.0};
        const auto r = odestep::integrate(stepper, f, y, 0.0, 2.0, 0.5);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.counts.rhs_evals == f_calls);
        CHECK(r.counts.accepted_steps == stepper.engine().accepted_steps());
        CHECK(r.counts.accepted_steps >= r.steps);
        CHECK(r.counts.jacobian_evals == stepper.engine().jacobian_evaluations());
    }
}

}  // namespace
