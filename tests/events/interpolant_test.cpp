// SPDX-License-Identifier: BSL-1.0
// Events located on the step's interpolant (watch<odestep::on_interpolant<>>): the cubic Hermite interpolant
// through the step's ends and f there. Expected values: closed forms (free fall, where Hermite is exact, and
// the harmonic oscillator, where the interpolant's leading error term is known), the re-stepping mode of the
// same run, and the counts of f calls the interpolant must cost (two per step that locates).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

namespace {

using state2 = std::array<double, 2>;

constexpr double gravity = 9.8;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double pi = 3.141592653589793238462643383279502884;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

using interpolant = odestep::on_interpolant<>;

struct free_fall {  // (y, v)' = (v, -g); calls counted, NaN from call number nan_at on (0: never)
    std::size_t* calls = nullptr;
    std::size_t nan_at = 0;
    state2 operator()(double, const state2& s) const {
        const std::size_t n = calls ? ++*calls : 0;
        if (nan_at != 0 && n >= nan_at) return {nan, nan};
        return {s[1], -gravity};
    }
};

struct oscillator {  // (x, v)' = (v, -x): x = cos t, v = -sin t from (1, 0)
    std::size_t* calls = nullptr;
    state2 operator()(double, const state2& s) const {
        if (calls) ++*calls;
        return {s[1], -s[0]};
    }
};

auto height = [](double, const state2& s) { return s[0]; };
auto half = [](double, const state2& s) { return s[0] - 0.5; };  // cos t = 1/2 at t = pi/3, 5 pi/3, 7 pi/3, ...

bool same_bits(const state2& a, const state2& b) { return std::memcmp(a.data(), b.data(), sizeof(a)) == 0; }

// The terminal crossing of cos t through 1/2 (falling, at pi/3), stepped at dt, located one way or the other.
template <class Stepper, class Finder>
double oscillator_event_time(double dt) {
    state2 s{1.0, 0.0};
    const auto ev = odestep::make_event<state2>(half, odestep::direction::falling);
    const auto r = odestep::integrate(Stepper{}, oscillator{}, s, 0.0, 1.5, dt, odestep::watch<Finder>(ev));
    REQUIRE(r.status == odestep::status::stopped_by_event);
    return r.t;
}

}  // namespace

TEST_CASE("events on the interpolant: a falling body meets the ground at sqrt(2 h / g) to a few ULPs") {
    // y = h - g t^2 / 2 is a quadratic: RK4 is exact for it (to rounding) and so is the cubic Hermite
    // interpolant (it reproduces every cubic), so the located time is the closed form to the bracket's width.
    const double h = 10.0;
    const double t_hit = std::sqrt(2.0 * h / gravity);
    state2 s{h, 0.0};
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    const auto r =
        odestep::integrate(odestep::rk4<state2>{}, free_fall{}, s, 0.0, 10.0, 0.1, odestep::watch<interpolant>(ground));
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - t_hit) <= 64 * eps * t_hit);
    CHECK(s[0] > 0.0);  // the state before the crossing (the finder's a side), as re-stepping gives
    CHECK(s[0] < 64 * eps * gravity * t_hit * t_hit);
    CHECK(s[1] == doctest::Approx(-gravity * t_hit).epsilon(1e-13));  // the impact speed, closed form
}

TEST_CASE("events on the interpolant: a bouncing ball's impacts and a Newtonian bounce match the closed forms") {
    // Dropped from 1 at rest, e = 0.7: t_1 = sqrt(2 h / g), t_{k+1} = t_k + 2 e^k v_1 / g (exact data and an
    // exact interpolant: the continuation from each interpolated state stays on the closed form).
    const double e = 0.7, h0 = 1.0;
    const double v1 = std::sqrt(2 * gravity * h0);
    std::array<double, 16> impacts{};
    std::size_t n = 0;
    auto bounce = [&](double t, state2& s) {
        if (n < impacts.size()) impacts[n] = t;
        ++n;
        s[1] = -e * s[1];
    };
    state2 s{h0, 0.0};
    const auto floor = odestep::make_event<state2>(height, odestep::direction::falling, bounce);
    const auto r =
        odestep::integrate(odestep::rk4<state2>{}, free_fall{}, s, 0.0, 2.3, 0.01, odestep::watch<interpolant>(floor));
    // To 2.3 s: six impacts (t_7 = 2.312), before the flights get shorter than a step.
    REQUIRE(r.status == odestep::status::ok);
    CHECK(s[0] >= 0.0);  // never below the floor
    REQUIRE(n == 6);
    double t_k = std::sqrt(2 * h0 / gravity);
    for (std::size_t k = 0; k < 6; ++k) {
        CHECK(std::abs(impacts[k] - t_k) <= 1e-12);
        t_k += 2.0 * std::pow(e, static_cast<double>(k + 1)) * v1 / gravity;
    }
    // Newton's form: velocity Verlet (exact for constant gravity), Hermite on x with v and on v with a.
    using vec = std::array<double, 1>;
    auto a = [](double, const vec&) { return vec{-gravity}; };
    auto ground = [](double, const vec& x, const vec&) { return x[0]; };
    vec x{10.0};
    vec v{5.0};
    auto elastic = [](double, vec&, vec& vel) { vel[0] = -vel[0]; };
    const auto q = odestep::integrate(
        odestep::velocity_verlet<vec>{}, a, x, v, 0.0, 3.0, 0.1,
        odestep::watch<interpolant>(odestep::make_event<vec>(ground, odestep::direction::falling, elastic)));
    REQUIRE(q.status == odestep::status::ok);
    // After the bounce at t_hit the ball retraces its fall (the same closed form as events_test.cpp's).
    const double t_hit = (5.0 + std::sqrt(25.0 + 2.0 * gravity * 10.0)) / gravity;
    const double u = 3.0 - t_hit;
    const double v_hit = 5.0 - gravity * t_hit;
    CHECK(x[0] == doctest::Approx(-v_hit * u - gravity * u * u / 2).epsilon(1e-12));
}

TEST_CASE("events on the interpolant: the located time's error is the interpolant's, O(dt^4), observed order 4") {
    // cos t falls through 1/2 at t* = pi/3. The step sizes put t* in the middle of a step (theta = 1/2):
    // dt = t* / 3.5 and t* / 7.5. There the Hermite interpolant of x = cos t is short by
    //   x''''(t*) theta^2 (1 - theta)^2 dt^4 / 4! = cos(t*) dt^4 / 384 = dt^4 / 768
    // (the remainder of Hermite interpolation; HNW I, II.6), so it reaches 1/2 earlier by
    //   dt^4 / (768 |x'(t*)|) = dt^4 / (768 sin(pi/3)),
    // the next term being O(dt^6) (the dt^5 one is odd about the middle of the step). DOP853 (order 8) makes
    // the step's ends exact to ~1e-12, so the located time's error is the interpolant's alone.
    const double t_star = pi / 3.0;
    const double dt[2] = {t_star / 3.5, t_star / 7.5};
    double error[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
        CAPTURE(dt[k]);
        error[k] = oscillator_event_time<odestep::dop853<state2>, interpolant>(dt[k]) - t_star;
        const double predicted = -std::pow(dt[k], 4) / (768.0 * std::sin(t_star));
        CHECK(std::abs(error[k] / predicted - 1.0) < 0.01);  // measured: 0.15% and 0.03%
        // Re-stepping finds the stepper's own crossing: DOP853's error, 1e-11 at most here.
        CHECK(std::abs(oscillator_event_time<odestep::dop853<state2>, odestep::brent>(dt[k]) - t_star) < 1e-10);
    }
    const double order = std::log(error[0] / error[1]) / std::log(dt[0] / dt[1]);
    CHECK(std::abs(order - 4.0) < 0.02);  // measured: 3.998
    // RK4: both modes share the step's ends, and differ by the interpolant's error, at most
    // max|x''''| theta^2 (1 - theta)^2 dt^4 / 4! / |x'(t*)| <= dt^4 / (384 sin(pi/3)) (plus RK4's own error
    // inside the step, O(dt^5): measured 3.7e-6 and 3.7e-7 against bounds of 2.4e-5 and 1.1e-6).
    for (double h : dt) {
        CAPTURE(h);
        const double t_interp = oscillator_event_time<odestep::rk4<state2>, interpolant>(h);
        const double t_restep = oscillator_event_time<odestep::rk4<state2>, odestep::brent>(h);
        CHECK(std::abs(t_interp - t_restep) <= std::pow(h, 4) / (384.0 * std::sin(t_star)));
    }
}

TEST_CASE("events on the interpolant: two f calls per step that locates, none per iteration; record keeps the run") {
    // cos t = 1/2 at pi/3, 5 pi/3 and 7 pi/3 in [0, 10]: three steps with a crossing, each one location of
    // the record event. RK4: 4 calls per step, and on the interpolant 2 more (f at the step's two ends) in
    // each of those three steps; re-stepping costs 4 per re-step instead.
    const auto ev = odestep::make_event<state2>(half, odestep::direction::either, odestep::record);
    std::size_t calls_interp = 0, calls_restep = 0, calls_plain = 0;
    state2 y_interp{1.0, 0.0}, y_restep{1.0, 0.0}, y_plain{1.0, 0.0};
    const auto ri = odestep::integrate(odestep::rk4<state2>{}, oscillator{&calls_interp}, y_interp, 0.0, 10.0, 0.1,
                                       odestep::watch<interpolant>(ev));
    const auto rr = odestep::integrate(odestep::rk4<state2>{}, oscillator{&calls_restep}, y_restep, 0.0, 10.0, 0.1,
                                       odestep::watch(ev));
    const auto rp = odestep::integrate(odestep::rk4<state2>{}, oscillator{&calls_plain}, y_plain, 0.0, 10.0, 0.1);
    REQUIRE(ri.status == odestep::status::ok);
    REQUIRE(rr.status == odestep::status::ok);
    REQUIRE(rp.status == odestep::status::ok);
    CHECK(ri.fired == 3);
    CHECK(rr.fired == 3);
    CHECK(calls_plain == 400);
    CHECK(calls_interp == 400 + 3 * 2);
    CHECK(calls_restep >= 400 + 3 * 4 * 3);  // at least three re-steps per location (measured: 4 to 6)
    CHECK(calls_interp < calls_restep);
    CHECK(same_bits(y_interp, y_plain));  // record: the trajectory is the plain run's, bit for bit
    CHECK(same_bits(y_restep, y_plain));
}

TEST_CASE("events on the interpolant: the published bounds are smaller and hold for every tick") {
    using rk4 = odestep::rk4<state2>;
    constexpr odestep::event_limits limits{};  // F = 8, P = 0, C = Brent's 102 in double
    // (1 + F)(S + 2) + F = 9 * 6 + 8 against S [(1 + F) + F E C] + F = 4 (9 + 8 * 2 * 102) + 8
    static_assert(odestep::max_rhs_evals_per_step<rk4, interpolant>(2, limits) == 62);
    static_assert(odestep::max_rhs_evals_per_step<rk4>(2, limits) == 6572);
    static_assert(odestep::max_rhs_evals_per_step<rk4, interpolant>(2, {0, 0, 0}) == 4);   // no location: the step
    static_assert(odestep::max_rhs_evals_per_step<rk4, interpolant>(1, {0, 2, 3}) == 20);  // 3 (4 + 2) + 2
    static_assert(odestep::max_g_evals_per_step<double, interpolant>(2, limits) ==
                  odestep::max_g_evals_per_step<double>(2, limits));
    // A bouncing ball under the per-tick loop, with probes: every tick within the published bound.
    std::size_t calls = 0;
    auto bounce = [](double, state2& s) { s[1] = -0.7 * s[1]; };
    const odestep::event_limits probing{0, 8, 2};
    auto loop = odestep::make_event_stepper(
        rk4{}, odestep::watch<interpolant>(odestep::make_event<state2>(height, odestep::direction::falling, bounce))
                   .with_limits(probing));
    state2 s{1.0, 0.0};
    REQUIRE(loop.start(0.0, 0.01, s) == odestep::status::ok);
    const std::size_t bound = odestep::max_rhs_evals_per_tick<rk4, interpolant>(1, probing);
    CHECK(bound == 2 * (9 * 6 + 8));
    std::size_t worst = 0, fired = 0;
    free_fall f{&calls};
    for (int k = 0; k < 300; ++k) {
        calls = 0;
        const auto r = loop.tick(f, s);
        fired += r.fired;
        worst = calls > worst ? calls : worst;
        if (r.status == odestep::status::event_limit) break;
        REQUIRE(r.status == odestep::status::ok);
    }
    CHECK(fired >= 8);
    CHECK(worst <= bound);
    CHECK(worst >= 4 + 2);  // a tick that located paid for the slopes
}

TEST_CASE("events on the interpolant: NaN from f at the slopes is non_finite with the last good state") {
    // Free fall from 10 at rest, dt = 0.1: the ground (t = 1.4286) is in the 15th step; its 4 calls are the
    // 57th to 60th, the slopes the 61st (f at the step's start) and 62nd (at its end).
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    state2 before{10.0, 0.0};  // the state at t = 1.4, 14 plain steps
    {
        odestep::rk4<state2> rk;
        free_fall f{};
        for (int i = 0; i < 14; ++i) REQUIRE(rk.step(f, before, 0.1 * i, 0.1) == odestep::status::ok);
    }
    for (std::size_t nan_at : {std::size_t(61), std::size_t(62)}) {
        CAPTURE(nan_at);
        std::size_t calls = 0;
        state2 s{10.0, 0.0};
        const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{&calls, nan_at}, s, 0.0, 10.0, 0.1,
                                          odestep::watch<interpolant>(ground));
        CHECK(r.status == odestep::status::non_finite);
        CHECK(r.t == odestep::detail::grid_clock<double>{0.0, 0.1}.time(14));
        CHECK(same_bits(s, before));
        CHECK(calls == 62);  // both slopes, then nothing more
        // The per-tick loop: the tick does not count, the state is the one before it.
        calls = 0;
        state2 y{10.0, 0.0};
        auto loop = odestep::make_event_stepper(odestep::rk4<state2>{}, odestep::watch<interpolant>(ground));
        REQUIRE(loop.start(0.0, 0.1, y) == odestep::status::ok);
        free_fall f{&calls, nan_at};
        for (int i = 0; i < 14; ++i) REQUIRE(loop.tick(f, y).status == odestep::status::ok);
        const auto t = loop.tick(f, y);
        CHECK(t.status == odestep::status::non_finite);
        CHECK(loop.ticks() == 14);
        CHECK(same_bits(y, before));
    }
    // Bad settings are refused before anything is evaluated, as in re-stepping mode.
    std::size_t calls = 0;
    state2 s{10.0, 0.0};
    const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{&calls}, s, 0.0, 1.0, 0.1,
                                      odestep::watch<interpolant>(ground.with_tolerance(-1.0)));
    CHECK(r.status == odestep::status::invalid_tolerance);
    CHECK(calls == 0);
}

TEST_CASE("event_stepper: a change of the probes takes effect at rearm, and the quiet tick then probes") {
    // (Issue 18: the quiet tick reads the probes through the all-armed flag that rearm keeps.) y' = 1 from 0
    // with dt = 1, g = (y - 1.3)(y - 1.7): two roots inside the second tick, g > 0 at both its ends, so only
    // a probe (at 1.5, where g = -0.04) sees them.
    using state1 = std::array<double, 1>;
    auto clock = [](double, const state1&) { return state1{1.0}; };
    auto two_roots = [](double, const state1& y) { return (y[0] - 1.3) * (y[0] - 1.7); };
    for (bool probing : {false, true}) {
        CAPTURE(probing);
        auto loop = odestep::make_event_stepper(
            odestep::rk4<state1>{},
            odestep::watch(odestep::make_event<state1>(two_roots, odestep::direction::either, odestep::record)));
        state1 y{0.0};
        REQUIRE(loop.start(0.0, 1.0, y) == odestep::status::ok);
        REQUIRE(loop.tick(clock, y).status == odestep::status::ok);
        if (probing) {
            loop.events().limits.probes = 1;
            REQUIRE(loop.rearm(y) == odestep::status::ok);
        }
        const auto r = loop.tick(clock, y);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.fired == (probing ? 2u : 0u));
        if (probing && r.fired == 2) {  // RK4 is exact for y' = 1: the roots 1.3 and 1.7 to the bracket's width
            CHECK(std::abs(r.firings[0].t - 1.3) <= 1e-14);
            CHECK(std::abs(r.firings[1].t - 1.7) <= 1e-14);
        }
    }
}

TEST_CASE("events on the interpolant: located_on_interpolant() picks the mode apart from the finder") {
    const auto ground = odestep::make_event<state2>(height, odestep::direction::falling);
    // The type: the same set as the finder-slot spelling, for the default finder and for ITP; idempotent.
    using brent_set = decltype(odestep::watch<interpolant>(ground));
    using itp_set = decltype(odestep::watch<odestep::on_interpolant<odestep::itp>>(ground));
    static_assert(std::is_same_v<decltype(odestep::watch(ground).located_on_interpolant()), brent_set>);
    static_assert(std::is_same_v<decltype(odestep::watch<odestep::itp>(ground).located_on_interpolant()), itp_set>);
    static_assert(std::is_same_v<decltype(odestep::watch<interpolant>(ground).located_on_interpolant()), brent_set>);
    // The limits carry over, and the run is the on_interpolant run (free fall: the closed form's time).
    odestep::event_limits limits;
    limits.max_firings_per_step = 3;
    const auto set = odestep::watch<odestep::itp>(ground).with_limits(limits).located_on_interpolant();
    CHECK(set.limits.max_firings_per_step == 3);
    const double h = 10.0;
    const double t_hit = std::sqrt(2.0 * h / gravity);
    state2 s{h, 0.0};
    const auto r = odestep::integrate(odestep::rk4<state2>{}, free_fall{}, s, 0.0, 10.0, 0.1, set);
    REQUIRE(r.status == odestep::status::stopped_by_event);
    CHECK(std::abs(r.t - t_hit) <= 64 * eps * t_hit);
}
