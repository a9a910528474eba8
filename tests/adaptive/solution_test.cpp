// SPDX-License-Identifier: BSL-1.0
// The solution object (adaptive/solution.hpp): the state anywhere in a free-running run's span from the
// stored interpolants, against closed forms (y' = -y: exp(-t); the oscillator: cos t, -sin t) within the
// interpolants' measured bounds (docs/adaptive.md, "Error bounds"), the same values as integrate_times, the
// capacity's limit, queries outside the span, no heap; and adaptive_sampler (times one at a time) against
// integrate_times bit for bit.
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "support/counting.hpp"
#if defined(ODESTEP_TEST_ALLOC_HOOKS)
#include "support/alloc_counter.hpp"
#endif

namespace {

using odestep::status;
using state1 = std::array<double, 1>;
using state2 = std::array<double, 2>;

struct decay {
    void operator()(double, const state1& y, state1& d) const noexcept { d[0] = -y[0]; }
};
// x' = v, v' = -x from (1, 0): x = cos t, v = -sin t.
struct oscillator {
    void operator()(double, const state2& y, state2& d) const noexcept {
        d[0] = y[1];
        d[1] = -y[0];
    }
};

template <std::size_t N>
bool same_bits(const std::array<double, N>& a, const std::array<double, N>& b) {
    for (std::size_t i = 0; i < N; ++i)
        if (!(a[i] == b[i]) && !(std::isnan(a[i]) && std::isnan(b[i]))) return false;
    return true;
}

constexpr std::size_t queries = 1000;

// The oscillator over [0, 10] at tol: the solution at 1000 times against cos t and -sin t, within bound * tol
// in the tolerance's scale (|error| / (1 + |exact|)), and the same values as integrate_times at those times.
template <class Method>
void oscillator_within(double tol, double bound) {
    constexpr std::size_t capacity = 2048;
    static odestep::solution<Method, state2, capacity> sol;  // static: about 100 kB for DOP853 (not the stack)
    const auto tols = odestep::tolerances<state2>::uniform(tol, tol);
    odestep::adaptive_rk<Method, state2> engine(tols);
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate_adaptive(engine, oscillator{}, y, 0.0, 10.0, sol);
    REQUIRE(r.status == status::ok);
    CHECK(sol.size() == r.steps);
    CHECK(sol.t_first() == 0.0);
    CHECK(sol.t_last() == 10.0);
    std::array<double, queries> times{};
    for (std::size_t i = 0; i < queries; ++i) times[i] = 10.0 * static_cast<double>(i + 1) / double(queries);
    std::vector<state2> sampled;  // integrate_times' values, the reference for "the same interpolant"
    sampled.reserve(queries);
    odestep::adaptive_rk<Method, state2> engine2(tols);
    state2 y2{1.0, 0.0};
    const auto q = odestep::integrate_times(engine2, oscillator{}, y2, 0.0, times,
                                            [&](double, const state2& u) { sampled.push_back(u); });
    REQUIRE(q.status == status::ok);
    CHECK(q.steps == r.steps);
    double worst = 0.0;
    std::size_t same = 0;
    for (std::size_t i = 0; i < queries; ++i) {
        state2 u{};
        REQUIRE(sol(times[i], u) == status::ok);
        const double t = times[i];
        const double e0 = std::fabs(u[0] - std::cos(t)) / (1.0 + std::fabs(std::cos(t)));
        const double e1 = std::fabs(u[1] + std::sin(t)) / (1.0 + std::fabs(std::sin(t)));
        worst = std::fmax(worst, std::fmax(e0, e1));
        same += same_bits(u, sampled[i]) ? 1 : 0;
    }
    MESSAGE("error / tol " << worst / tol << " at tol " << tol << ", " << r.steps << " steps");
    CHECK(worst <= bound * tol);
    CHECK(same == queries);
    // The span's ends: the run's own states, bit for bit.
    state2 u{};
    REQUIRE(sol(0.0, u) == status::ok);
    CHECK(same_bits(u, state2{1.0, 0.0}));
    REQUIRE(sol(10.0, u) == status::ok);
    CHECK(same_bits(u, y));
}

}  // namespace

TEST_CASE("solution: y' = -y, the state anywhere in the span within DP 5(4)'s interpolant bound") {
    static odestep::solution<odestep::tables::dormand_prince54, state1, 512> sol;
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state1> engine(
        odestep::tolerances<state1>::uniform(1e-8, 1e-8));
    state1 y{1.0};
    const auto r = odestep::integrate_adaptive(engine, decay{}, y, 0.0, 5.0, sol);
    REQUIRE(r.status == status::ok);
    double worst = 0.0;
    for (std::size_t i = 0; i <= queries; ++i) {
        const double t = 5.0 * static_cast<double>(i) / double(queries);
        state1 u{};
        REQUIRE(sol(t, u) == status::ok);
        worst = std::fmax(worst, std::fabs(u[0] - std::exp(-t)) / (1.0 + std::exp(-t)));
    }
    // 19 tol: DP 5(4)'s interpolant bound (measured 12.3 over DETEST, docs/adaptive.md).
    CHECK(worst <= 19 * 1e-8);
    CHECK(worst > 0.0);
}

TEST_CASE("solution: the oscillator, every interpolant within its bound, the same values as integrate_times") {
    // Bounds from docs/adaptive.md's table (1.5 times the largest ratio measured over DETEST at 1e-3 .. 1e-10):
    // DP 5(4) 19, DOP853 28, Hermite after BS 3(2) 27; after Cash-Karp the ratio grows as the tolerance
    // tightens (7200 over 1e-3 .. 1e-10): at 1e-6 it is at most 81, so 120.
    oscillator_within<odestep::tables::dormand_prince54>(1e-8, 19);
    oscillator_within<odestep::tables::dop853>(1e-10, 28);
    oscillator_within<odestep::tables::bogacki_shampine32>(1e-6, 27);
    oscillator_within<odestep::tables::cash_karp54>(1e-6, 120);
}

TEST_CASE("solution: full storage stops the run with storage_full, the state and the solution agree") {
    odestep::solution<odestep::tables::dormand_prince54, state2, 8> sol;
    odestep::adaptive_rk<odestep::tables::dormand_prince54, state2> engine(
        odestep::tolerances<state2>::uniform(1e-8, 1e-8));
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate_adaptive(engine, oscillator{}, y, 0.0, 10.0, sol);
    CHECK(r.status == status::storage_full);
    CHECK(r.steps == 8);
    CHECK(sol.size() == 8);
    CHECK(sol.full());
    CHECK(r.t > 0.0);
    CHECK(r.t < 10.0);
    CHECK(sol.t_last() == r.t);
    state2 u{};
    REQUIRE(sol(r.t, u) == status::ok);
    CHECK(same_bits(u, y));  // y is the last accepted state, and the solution ends there
    CHECK(std::fabs(y[0] - std::cos(r.t)) < 1e-7);
    CHECK(sol(r.t + 1e-3, u) == status::invalid_time);  // past what it holds
    // The run goes on from there into a second solution.
    static odestep::solution<odestep::tables::dormand_prince54, state2, 1024> rest;
    const double t_stop = r.t;
    const auto r2 = odestep::integrate_adaptive(engine, oscillator{}, y, t_stop, 10.0, rest);
    CHECK(r2.status == status::ok);
    CHECK(rest.t_first() == t_stop);
    CHECK(std::fabs(y[0] - std::cos(10.0)) < 1e-6);
}

TEST_CASE("solution: outside the span, NaN, before any run, and backwards: invalid_time, out untouched") {
    odestep::solution<odestep::tables::cash_karp54, state1, 256> sol;
    state1 u{42.0};
    CHECK(sol(0.0, u) == status::invalid_time);  // no run yet
    CHECK(u[0] == 42.0);
    odestep::adaptive_rk<odestep::tables::cash_karp54, state1> engine(odestep::tolerances<state1>::uniform(1e-8, 1e-8));
    state1 y{1.0};
    // Backwards from 0 to -2: y = exp(-t) grows to e^2.
    const auto r = odestep::integrate_adaptive(engine, decay{}, y, 0.0, -2.0, sol);
    REQUIRE(r.status == status::ok);
    CHECK(sol.t_first() == 0.0);
    CHECK(sol.t_last() == -2.0);
    for (const double t : {0.5, -2.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
        CHECK(sol(t, u) == status::invalid_time);
        CHECK(u[0] == 42.0);
    }
    REQUIRE(sol(-1.3, u) == status::ok);
    // Hermite after Cash-Karp: within its bound at 1e-8 (ratio below 1200 at 1e-9, docs/adaptive.md).
    CHECK(std::fabs(u[0] - std::exp(1.3)) / (1.0 + std::exp(1.3)) < 1200 * 1e-8);
    // Bad arguments: refused before anything, the solution as it was.
    const std::size_t held = sol.size();
    state1 z{1.0};
    CHECK(odestep::integrate_adaptive(engine, decay{}, z, 0.0, std::numeric_limits<double>::quiet_NaN(), sol).status ==
          status::invalid_time);
    CHECK(odestep::integrate_adaptive(engine, decay{}, z, 0.0, 1.0, sol, 0).status == status::invalid_setting);
    CHECK(sol.size() == held);
    CHECK(sol.t_last() == -2.0);
    sol.clear();
    CHECK(sol(-1.0, u) == status::invalid_time);
}

TEST_CASE("solution: NaN from f stops the run with non_finite, the solution ends at the last accepted step") {
    std::size_t calls = 0;
    auto f = odestep_test::counted(
        [](double t, const state1& y, state1& d) { d[0] = t > 1.5 ? std::numeric_limits<double>::quiet_NaN() : -y[0]; },
        &calls);
    odestep::solution<odestep::tables::dop853, state1, 256> sol;
    odestep::adaptive_rk<odestep::tables::dop853, state1> engine(odestep::tolerances<state1>::uniform(1e-8, 1e-8));
    state1 y{1.0};
    const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, 3.0, sol);
    CHECK(r.status == status::non_finite);
    CHECK(sol.t_last() <= r.t);
    CHECK(sol.t_last() <= 1.5);
    state1 u{};
    REQUIRE(sol(sol.t_last(), u) == status::ok);
    CHECK(std::fabs(u[0] - std::exp(-sol.t_last())) < 1e-7);
}

TEST_CASE("solution: evaluations within the published bound (DOP853: three more per step)") {
    using engine_t = odestep::adaptive_rk<odestep::tables::dop853, state2>;
    using dense_t = odestep::dense_step<odestep::tables::dop853, state2>;
    std::size_t calls = 0;
    odestep_test::counting<oscillator> f{oscillator{}, &calls};
    static odestep::solution<odestep::tables::dop853, state2, 512> sol;
    engine_t engine(odestep::tolerances<state2>::uniform(1e-9, 1e-9));
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate_adaptive(engine, f, y, 0.0, 10.0, sol);
    REQUIRE(r.status == status::ok);
    const std::size_t attempts = static_cast<std::size_t>(engine.accepted_steps() + engine.rejected_steps());
    // Without FSAL: f at t0, the first-step probe, 11 new stages per attempt, f at each accepted step's end
    // (the next first stage, or the last step's, for its interpolant) and 3 extra stages per accepted step.
    CHECK(calls == 2 + 11 * attempts + 4 * static_cast<std::size_t>(r.steps));
    CHECK(calls <=
          engine_t::rhs_evals_to_start + attempts * (engine_t::rhs_evals_per_attempt + dense_t::rhs_evals_to_complete));
}

namespace {

template <class M>
void sampler_as_integrate_times() {
    const auto tols = odestep::tolerances<state2>::uniform(1e-7, 1e-7);
    const std::array<double, 7> times{0.0, 0.25, 0.25, 1.0, 3.3, 7.0, 10.0};
    std::vector<state2> expected;
    odestep::adaptive_rk<M, state2> e1(tols);
    state2 y{1.0, 0.0};
    REQUIRE(odestep::integrate_times(e1, oscillator{}, y, 0.0, times, [&](double, const state2& u) {
                expected.push_back(u);
            }).status == status::ok);
    odestep::adaptive_rk<M, state2> e2(tols);
    odestep::adaptive_sampler<M, state2> sampler(e2, 0.0, state2{1.0, 0.0}, 10.0);
    for (std::size_t i = 0; i < times.size(); ++i) {
        state2 u{};
        REQUIRE(sampler.advance_to(oscillator{}, times[i], u) == status::ok);
        CHECK(same_bits(u, expected[i]));
        CHECK(std::fabs(u[0] - std::cos(times[i])) < 1e-4);
    }
    CHECK(sampler.steps() == e1.accepted_steps());
    CHECK(sampler.time() == 10.0);
    state2 u{7.0, 7.0};
    CHECK(sampler.advance_to(oscillator{}, 11.0, u) == status::invalid_time);  // past t1
    odestep::adaptive_sampler<M, state2> back(e2, 0.0, state2{1.0, 0.0}, 10.0);
    REQUIRE(back.advance_to(oscillator{}, 2.0, u) == status::ok);
    const state2 at2 = u;
    CHECK(back.advance_to(oscillator{}, 1.0, u) == status::invalid_time);  // going back
    CHECK(back.advance_to(oscillator{}, std::numeric_limits<double>::quiet_NaN(), u) == status::invalid_time);
    CHECK(same_bits(u, at2));
}

}  // namespace

TEST_CASE("adaptive_sampler: times one at a time, the same states as integrate_times, bit for bit") {
    sampler_as_integrate_times<odestep::tables::cash_karp54>();
    sampler_as_integrate_times<odestep::tables::dormand_prince54>();
    sampler_as_integrate_times<odestep::tables::dop853>();
    sampler_as_integrate_times<odestep::tables::fehlberg45>();
}

TEST_CASE("adaptive_sampler: the attempt cap per call, NaN from f, bad settings") {
    using M = odestep::tables::dormand_prince54;
    odestep::adaptive_rk<M, state2> e(odestep::tolerances<state2>::uniform(1e-9, 1e-9));
    odestep::adaptive_sampler<M, state2> s(e, 0.0, state2{1.0, 0.0}, 10.0, 3);
    state2 u{5.0, 5.0};
    CHECK(s.advance_to(oscillator{}, 10.0, u) == status::substep_limit);  // far more than 3 steps
    CHECK(same_bits(u, state2{5.0, 5.0}));
    const double reached = s.time();
    CHECK(reached > 0.0);
    for (int i = 0; i < 1000 && s.advance_to(oscillator{}, 10.0, u) == status::substep_limit; ++i) {
    }
    CHECK(s.time() == 10.0);
    CHECK(std::fabs(u[0] - std::cos(10.0)) < 1e-7);
    // NaN from f past t = 1: non_finite, y_out untouched, the run at its last accepted step.
    auto bad = [](double t, const state2& y, state2& d) {
        d[0] = t > 1.0 ? std::numeric_limits<double>::quiet_NaN() : y[1];
        d[1] = -y[0];
    };
    odestep::adaptive_sampler<M, state2> n(e, 0.0, state2{1.0, 0.0}, 10.0);
    state2 v{5.0, 5.0};
    CHECK(n.advance_to(bad, 2.0, v) == status::non_finite);
    CHECK(same_bits(v, state2{5.0, 5.0}));
    CHECK(n.time() <= 1.0);
    CHECK(std::fabs(n.state()[0] - std::cos(n.time())) < 1e-8);
    odestep::adaptive_rk<M, state2> wrong(odestep::tolerances<state2>::uniform(-1.0, 1e-9));
    odestep::adaptive_sampler<M, state2> w(wrong, 0.0, state2{1.0, 0.0}, 10.0);
    CHECK(w.advance_to(oscillator{}, 1.0, v) == status::invalid_tolerance);
}

#if defined(ODESTEP_TEST_ALLOC_HOOKS)
TEST_CASE("solution and adaptive_sampler: no heap allocation") {
    static odestep::solution<odestep::tables::dop853, state2, 256> sol;
    const std::size_t before = odestep_test::allocations();
    odestep::adaptive_rk<odestep::tables::dop853, state2> engine(odestep::tolerances<state2>::uniform(1e-8, 1e-8));
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate_adaptive(engine, oscillator{}, y, 0.0, 10.0, sol);
    state2 u{};
    double sum = 0.0;
    for (int i = 0; i <= 100; ++i) {
        if (sol(0.1 * i, u) == status::ok) sum += u[0];
    }
    odestep::adaptive_sampler<odestep::tables::dop853, state2> s(engine, 0.0, state2{1.0, 0.0}, 10.0);
    for (int i = 0; i <= 100; ++i) {
        if (s.advance_to(oscillator{}, 0.1 * i, u) == status::ok) sum += u[0];
    }
    const std::size_t after = odestep_test::allocations();
    CHECK(r.status == status::ok);
    CHECK(std::isfinite(sum));
    CHECK(after == before);
}
#endif
