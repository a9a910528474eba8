// SPDX-License-Identifier: BSL-1.0
// Issue 24, the regression: the README's bouncing ball must never pass the floor, and a Zeno run (a ball
// that comes to rest, a relay that chatters) ends with event_limit before its accumulation point, or at the
// user's latch, never ok with the state on the wrong side. And the missed-crossing property: when g of an
// armed event has opposite signs, in its direction, at two consecutive step ends, an event fired between them.
//
// Expected values are closed forms. The ball dropped from h at rest under gravity g with restitution e first
// lands at t_1 = sqrt(2 h / g); flight k after it lasts 2 e^k v_1 / g (v_1 = g t_1), so the impacts accumulate
// at the Zeno time t_Z = t_1 (1 + 2 e / (1 - e)) (2.5586 s for h = 1, g = 9.81, e = 0.7). RK4 is exact for
// constant acceleration (and the Hermite interpolant for a quadratic trajectory), so the states the run
// computes are the closed form's up to rounding.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace {

using restep = odestep::brent;
using interpolant = odestep::on_interpolant<>;

// The Zeno time of the ball dropped from h with restitution e (closed form above), in double.
double zeno_time(double h, double gravity, double e) {
    const double t1 = std::sqrt(2.0 * h / gravity);
    return t1 * (1.0 + 2.0 * e / (1.0 - e));
}

// How far below the floor a height computed by the run may be and still be the floor: the heights are sums of
// terms no larger than the drop height h (the event state y*, s v and g s^2 / 2 with |v| <= v_1 and s <= dt,
// v_1 dt <= h here), each rounded once per RK4 stage combination (at most eight roundings of terms of size h):
// 16 eps h.
template <class T>
T floor_tolerance(T h) {
    return T(16) * std::numeric_limits<T>::epsilon() * h;
}

struct ball_outcome {
    odestep::status status;
    double t;
    double final_height;
    double lowest_observed;
    std::size_t fired;
    std::size_t bounces;  // actions actually called
};

// The README's ball: RK4, make_event<state>(s[0], falling, s[1] = -e s[1]), dropped from 1 m under 9.81,
// run as integrate(rk4, f, y, 0, t1, dt, watch(ground)), with an observer.
template <class T, class Finder>
ball_outcome readme_ball(T dt, T e, T t_end) {
    using state = std::array<T, 2>;
    const T gravity = T(9.81);
    auto f = [gravity](T, const state& s) { return state{s[1], -gravity}; };
    std::size_t bounces = 0;
    auto ground = odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling,
                                             [&bounces, e](T, state& s) {
                                                 ++bounces;
                                                 s[1] = -e * s[1];
                                             });
    T lowest = T(1);
    auto observe = [&lowest](T, const state& s) { lowest = s[0] < lowest ? s[0] : lowest; };
    state y{T(1), T(0)};
    const auto r =
        odestep::integrate(odestep::rk4<state>{}, f, y, T(0), t_end, dt, odestep::watch<Finder>(ground), observe);
    return {r.status, static_cast<double>(r.t), static_cast<double>(y[0]), static_cast<double>(lowest), r.fired,
            bounces};
}

template <class T, class Finder>
void check_readme_ball(const char* mode) {
    const double t_zeno = zeno_time(1.0, 9.81, 0.7);
    CHECK(std::abs(t_zeno - 2.5586) < 1e-4);  // the figure
    const double tolerance = static_cast<double>(floor_tolerance(T(1)));
    for (const double dt : {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}) {
        CAPTURE(mode);
        CAPTURE(sizeof(T));
        CAPTURE(dt);
        const ball_outcome o = readme_ball<T, Finder>(static_cast<T>(dt), T(0.7), T(10));
        CHECK(o.lowest_observed >= -tolerance);
        CHECK(o.final_height >= -tolerance);
        // The impacts accumulate inside one step before t_Z: more than max_firings_per_step of them.
        CHECK(o.status == odestep::status::event_limit);
        CHECK(o.t < t_zeno);
        CHECK(o.fired == o.bounces);
    }
}

}  // namespace

TEST_CASE("zeno: the README's ball never passes the floor and stops with event_limit before t_Z (issue 24)") {
    check_readme_ball<double, restep>("re-stepping");
    check_readme_ball<double, interpolant>("on_interpolant");
    check_readme_ball<float, restep>("re-stepping");
    check_readme_ball<float, interpolant>("on_interpolant");
}

TEST_CASE("zeno: the restitution sweep 0.1 ... 0.95 never passes the floor and stops before each t_Z") {
    for (const double e : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
        const double t_zeno = zeno_time(1.0, 9.81, e);
        for (const double dt : {0.1, 0.01}) {
            CAPTURE(e);
            CAPTURE(dt);
            const ball_outcome a = readme_ball<double, restep>(dt, e, 40.0);
            const ball_outcome b = readme_ball<double, interpolant>(dt, e, 40.0);
            const ball_outcome c = readme_ball<float, restep>(static_cast<float>(dt), static_cast<float>(e), 40.0f);
            const ball_outcome d =
                readme_ball<float, interpolant>(static_cast<float>(dt), static_cast<float>(e), 40.0f);
            for (const ball_outcome& o : {a, b}) {
                CHECK(o.lowest_observed >= -floor_tolerance(1.0));
                CHECK(o.status == odestep::status::event_limit);
                CHECK(o.t < t_zeno);
            }
            for (const ball_outcome& o : {c, d}) {
                CHECK(o.lowest_observed >= -static_cast<double>(floor_tolerance(1.0f)));
                CHECK(o.status == odestep::status::event_limit);
                // float's t carries its own rounding: t_Z to float's relative spacing at 40 s
                CHECK(o.t < t_zeno + 40.0 * static_cast<double>(std::numeric_limits<float>::epsilon()));
            }
        }
    }
}

namespace {

// The ball with a latch: an impact too slow to bounce visibly (rebound speed under 0.1 m/s) lays it still.
template <class T, class Finder>
void check_latched_ball(T dt) {
    using state = std::array<T, 2>;
    const T gravity = T(9.81);
    const T e = T(0.7);
    bool resting = false;
    auto f = [&resting, gravity](T, const state& s) { return resting ? state{T(0), T(0)} : state{s[1], -gravity}; };
    std::size_t bounces = 0;
    auto bounce = [&](T, state& s) {
        ++bounces;
        if (-s[1] * e < T(0.1)) {
            resting = true;
            s = {T(0), T(0)};
        } else {
            s[1] = -e * s[1];
        }
    };
    T lowest = T(1);
    auto observe = [&lowest](T, const state& s) { lowest = s[0] < lowest ? s[0] : lowest; };
    state y{T(1), T(0)};
    const auto ground =
        odestep::make_event<state>([](T, const state& s) { return s[0]; }, odestep::direction::falling, bounce);
    const auto r =
        odestep::integrate(odestep::rk4<state>{}, f, y, T(0), T(10), dt, odestep::watch<Finder>(ground), observe);
    CAPTURE(sizeof(T));
    CAPTURE(static_cast<double>(dt));
    CHECK(r.status == odestep::status::ok);
    CHECK(resting);
    CHECK(y[0] == T(0));
    CHECK(lowest >= -floor_tolerance(T(1)));
    // Impact k has speed e^(k-1) v_1; the latch takes the first with e^k v_1 < 0.1:
    // k = ceil(ln(0.1 / v_1) / ln e) = 11 with v_1 = sqrt(2 * 9.81)
    const double v1 = std::sqrt(2 * 9.81);
    const auto k = static_cast<std::size_t>(std::ceil(std::log(0.1 / v1) / std::log(0.7)));
    CHECK(k == 11);
    CHECK(r.fired == k);
    CHECK(bounces == k);
}

}  // namespace

TEST_CASE("zeno: the ball with a latch comes to rest on the floor at the closed-form impact, every dt and mode") {
    for (const double dt : {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}) {
        check_latched_ball<double, restep>(dt);
        check_latched_ball<double, interpolant>(dt);
        check_latched_ball<float, restep>(static_cast<float>(dt));
        check_latched_ball<float, interpolant>(static_cast<float>(dt));
    }
}

namespace {

// A chattering relay: the twisting controller x'' = -a sx - b sv (a > b > 0), sx and sv the relay outputs,
// switched by the events x = 0 and v = 0 (either way) to the sign of the side the state goes to. From
// (x0, 0) the amplitude shrinks by q = (a - b) / (a + b) every half cycle, and a half cycle from amplitude X
// lasts sqrt(2 X) (1 / sqrt(a - b) + sqrt(a - b) / (a + b)) (the fall to 0 at a - b, then the stop at a + b),
// so the switchings accumulate at t_Z = T(x0) / (1 - sqrt(q)): 4.4614 s for a = 2, b = 1, x0 = 1.
// The wrong side: a relay output opposite to the sign of what it switches on.
template <class T, class Finder>
void check_relay(T dt) {
    using state = std::array<T, 2>;
    const double a = 2.0, b = 1.0, x0 = 1.0;
    const double q = (a - b) / (a + b);
    const double half = std::sqrt(2 * x0) * (1 / std::sqrt(a - b) + std::sqrt(a - b) / (a + b));
    const double t_zeno = half / (1 - std::sqrt(q));
    CHECK(std::abs(t_zeno - 4.4614) < 1e-4);
    T sx = T(1);
    T sv = T(-1);  // v leaves 0 downwards: x'' = -a + b < 0
    auto f = [&](T, const state& s) { return state{s[1], -T(a) * sx - T(b) * sv}; };
    const auto on_x = odestep::make_event<state>(
        [](T, const state& s) { return s[0]; }, odestep::direction::either,
        [&](T, state&, odestep::direction crossed) { sx = crossed == odestep::direction::rising ? T(1) : T(-1); });
    const auto on_v = odestep::make_event<state>(
        [](T, const state& s) { return s[1]; }, odestep::direction::either,
        [&](T, state&, odestep::direction crossed) { sv = crossed == odestep::direction::rising ? T(1) : T(-1); });
    // x and v are bounded by x0 and sqrt(2 (a - b) x0): rounding of terms that size
    const T tolerance = floor_tolerance(T(2));
    bool wrong_side = false;
    auto observe = [&](T, const state& s) {
        wrong_side = wrong_side || s[0] * sx < -tolerance || s[1] * sv < -tolerance;
    };
    state y{T(x0), T(0)};
    const auto r =
        odestep::integrate(odestep::rk4<state>{}, f, y, T(0), T(10), dt, odestep::watch<Finder>(on_x, on_v), observe);
    CAPTURE(sizeof(T));
    CAPTURE(static_cast<double>(dt));
    CHECK_FALSE(wrong_side);
    CHECK(r.status == odestep::status::event_limit);
    CHECK(static_cast<double>(r.t) < t_zeno);
}

}  // namespace

TEST_CASE("zeno: a chattering relay ends with event_limit before its accumulation point, never on the wrong side") {
    for (const double dt : {0.1, 0.01, 0.001}) {
        check_relay<double, restep>(dt);
        check_relay<double, interpolant>(dt);
        check_relay<float, restep>(static_cast<float>(dt));
        check_relay<float, interpolant>(static_cast<float>(dt));
    }
}

namespace {

// The missed-crossing property on one run: the observer's (t, g) at every step end and the firings' times;
// whenever g has opposite strict signs, in the event's direction, at two consecutive step ends, a firing lies
// between them (the events here have no band, dead time or firing limit, so an event is armed wherever its g
// is not zero at a step end). Every firing lies inside a step, and the firings counted are the actions called.
struct trace {
    std::vector<double> t;
    std::vector<double> g;
    std::vector<double> fired_at;
};

bool crossed(odestep::direction d, double before, double after) {
    const bool falls = before > 0 && after < 0;
    const bool rises = before < 0 && after > 0;
    return d == odestep::direction::falling ? falls : d == odestep::direction::rising ? rises : falls || rises;
}

void check_property(const trace& tr, odestep::direction d) {
    std::size_t misses = 0;
    std::size_t next = 0;  // the first firing not before the current step
    for (std::size_t k = 0; k + 1 < tr.t.size(); ++k) {
        while (next < tr.fired_at.size() && tr.fired_at[next] <= tr.t[k]) ++next;
        const bool fired_inside = next < tr.fired_at.size() && tr.fired_at[next] <= tr.t[k + 1];
        if (crossed(d, tr.g[k], tr.g[k + 1]) && !fired_inside) ++misses;
    }
    CHECK(misses == 0);
}

template <class Stepper, class Finder>
void property_run(double dt) {
    using state = std::array<double, 2>;
    // (1) the ball (falling, a bounce): never below the floor is the property's strongest form here
    {
        auto f = [](double, const state& s) { return state{s[1], -9.81}; };
        trace tr;
        auto height = [](double, const state& s) { return s[0]; };
        auto ground = odestep::make_event<state>(height, odestep::direction::falling, [&](double t, state& s) {
            tr.fired_at.push_back(t);
            s[1] = -0.7 * s[1];
        });
        auto observe = [&](double t, const state& s) {
            tr.t.push_back(t);
            tr.g.push_back(s[0]);
        };
        state y{1.0, 0.0};
        const auto r = odestep::integrate(Stepper{}, f, y, 0.0, 10.0, dt, odestep::watch<Finder>(ground), observe);
        CHECK(r.fired == tr.fired_at.size());
        // never below the floor (Euler's ball gains energy each step and keeps bouncing: not every run is Zeno)
        for (const double above : tr.g) CHECK(above >= -floor_tolerance(1.0));
        check_property(tr, odestep::direction::falling);
    }
    // (2) the oscillator x = cos t through 0.3, either way, with an action that only notes the time
    {
        auto f = [](double, const state& s) { return state{s[1], -s[0]}; };
        trace tr;
        auto level = [](double, const state& s) { return s[0] - 0.3; };
        auto ev = odestep::make_event<state>(level, odestep::direction::either,
                                             [&](double t, state&) { tr.fired_at.push_back(t); });
        auto observe = [&](double t, const state& s) {
            tr.t.push_back(t);
            tr.g.push_back(s[0] - 0.3);
        };
        state y{1.0, 0.0};
        const auto r = odestep::integrate(Stepper{}, f, y, 0.0, 20.0, dt, odestep::watch<Finder>(ev), observe);
        CHECK(r.status == odestep::status::ok);
        CHECK(r.fired == tr.fired_at.size());
        check_property(tr, odestep::direction::either);
        // cos t = 0.3 at acos(0.3) + 2 pi k and 2 pi - acos(0.3) + 2 pi k: six roots in [0, 20] (the seventh is
        // at 20.116)
        CHECK(tr.fired_at.size() == 6);
    }
}

}  // namespace

TEST_CASE("zeno: opposite signs of an armed g at consecutive step ends always mean a firing between them") {
    using state = std::array<double, 2>;
    for (const double dt : {0.1, 0.01}) {
        CAPTURE(dt);
        property_run<odestep::euler<state>, restep>(dt);
        property_run<odestep::euler<state>, interpolant>(dt);
        property_run<odestep::midpoint<state>, restep>(dt);
        property_run<odestep::midpoint<state>, interpolant>(dt);
        property_run<odestep::rk4<state>, restep>(dt);
        property_run<odestep::rk4<state>, interpolant>(dt);
        property_run<odestep::dop853<state>, restep>(dt);
        property_run<odestep::dop853<state>, interpolant>(dt);
        property_run<odestep::adams_bashforth_moulton4<state>, restep>(dt);
        property_run<odestep::adams_bashforth_moulton4<state>, interpolant>(dt);
    }
}
