// SPDX-License-Identifier: BSL-1.0
// Host only (ten steppers, two location modes: 290 kB of Cortex-M4 code at -O1). Issue 24 item 3: after a tick that
// fails (an error status, the state handed back as it was), the per-tick loop goes on bit for bit as its copy taken
// before that tick (its twin), for every stepper with a memory (a multistep history, a kept acceleration) that the loop
// accepts. The failures are those that come after the stepper has stepped: g not finite at the step's end, at a probe,
// and inside a location; and, for comparison, the step's own non_finite. Expected values: the twin's ticks, an
// independent computation (a loop that never saw the failed call); each loop runs y' = -y (x'' = -x), where a history
// that was reset or advanced changes the next state. The evaluations of f in the ticks after the failure are compared
// too (a kept acceleration that was dropped is evaluated again, with the same value).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace {

using state = std::array<double, 2>;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

bool same_bits(const state& a, const state& b) { return std::memcmp(a.data(), b.data(), sizeof(state)) == 0; }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// The glitches of one scenario, switched on for the failing tick only: g is Inf at times strictly inside
// (lo, hi); f returns NaN while nan_f.
struct glitch {
    double lo = 0.0;
    double hi = 0.0;
    bool nan_f = false;
};

// g = 1 before t_c and -1 from t_c on (t_c = Inf: never), Inf inside the glitch's window: a crossing at t_c,
// and a g that is not finite where the window says. K: g(t, y) or g(t, x, v).
template <std::size_t K>
struct g_of_t {
    const glitch* w;
    double t_c;
    double value(double t) const {
        if (w->lo < t && t < w->hi) return inf;
        return t < t_c ? 1.0 : -1.0;
    }
    template <std::size_t L = K, std::enable_if_t<L == 1, int> = 0>
    double operator()(double t, const state&) const {
        return value(t);
    }
    template <std::size_t L = K, std::enable_if_t<L == 2, int> = 0>
    double operator()(double t, const state&, const state&) const {
        return value(t);
    }
};

// y' = -y and x'' = -x (a force of position alone, a(t, x)), counting their calls; NaN while the glitch says so.
struct decay {
    const glitch* w;
    std::uint64_t* calls;
    state value(const state& y) const {
        ++*calls;
        if (w->nan_f) return {nan, nan};
        return {-y[0], -y[1]};
    }
    state operator()(double, const state& y) const { return value(y); }
};

enum class failure { g_at_end, g_at_probe, g_in_location, f_in_step };

constexpr double dt = 0.125;

// Starts the loop at 0, ticks `warm` times (the history fills), copies it (the twin), makes the failing tick
// with the glitch, then ticks both three times without it: status, time, state and evaluations of f agree bit
// for bit. The failing tick spans [t_f, t_f + dt], t_f = warm dt (exact in binary).
template <class Stepper, class Finder, std::size_t K>
void check_twin(failure kind, int warm) {
    glitch w;
    std::uint64_t calls = 0;
    const double t_f = warm * dt;
    const double t_e = t_f + dt;
    // The location case: a crossing at a third of the failing step, g Inf inside the step (at the re-steps) but
    // finite at both of its ends. Otherwise no crossing before the end of the test.
    const double t_c = kind == failure::g_in_location ? t_f + dt / 3.0 : inf;
    auto set = odestep::watch<Finder>(odestep::make_event<state>(g_of_t<K>{&w, t_c}, odestep::direction::either));
    if (kind == failure::g_at_probe) {
        odestep::event_limits limits;
        limits.probes = 1;
        set = set.with_limits(limits);
    }
    auto loop = odestep::make_event_stepper(Stepper{}, set);
    std::array<state, K> y{};
    for (auto& s : y) s = state{1.0, 0.5};
    const auto tick = [](auto& l, auto& f, std::array<state, K>& s) {
        if constexpr (K == 1) {
            return l.tick(f, s[0]);
        } else {
            return l.tick(f, s[0], s[1]);
        }
    };
    decay f{&w, &calls};
    if constexpr (K == 1) {
        REQUIRE(loop.start(0.0, dt, y[0]) == odestep::status::ok);
    } else {
        REQUIRE(loop.start(0.0, dt, y[0], y[1]) == odestep::status::ok);
    }
    for (int i = 0; i < warm; ++i) REQUIRE(tick(loop, f, y).status == odestep::status::ok);
    const auto twin = loop;
    const std::array<state, K> before = y;
    switch (kind) {
        case failure::g_at_end: w = glitch{t_f, t_e + dt, false}; break;  // Inf at t_e, finite at t_f
        case failure::g_at_probe:                                         // Inf at the probe, t_f + dt / 2 only
        case failure::g_in_location: w = glitch{t_f, t_e, false}; break;  // Inf strictly inside the step
        case failure::f_in_step: w = glitch{0.0, 0.0, true}; break;
    }
    const auto failed = tick(loop, f, y);
    const odestep::status expected =
        kind == failure::f_in_step ? odestep::status::non_finite : odestep::status::non_finite_event;
    REQUIRE(failed.status == expected);
    CHECK(failed.fired == 0);
    CHECK(same_bits(failed.t, t_f));
    for (std::size_t k = 0; k < K; ++k) CHECK(same_bits(y[k], before[k]));
    CHECK(loop.ticks() == twin.ticks());
    w = glitch{};
    // Three ticks of each loop on the same state objects (the Newtonian steppers' kept values are tied to the
    // state object, as in a control loop), each from the state before the failed tick.
    struct record {
        odestep::status status;
        double t;
        std::size_t fired;
        std::uint64_t calls;
        std::array<state, K> y;
    };
    const auto run = [&](auto& l) {
        std::array<record, 3> out{};
        y = before;
        for (auto& o : out) {
            const std::uint64_t c0 = calls;
            const auto r = tick(l, f, y);
            o = record{r.status, r.t, r.fired, calls - c0, y};
        }
        return out;
    };
    auto other = twin;
    const auto a = run(loop);
    const auto b = run(other);
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        CHECK(a[i].status == b[i].status);
        CHECK(same_bits(a[i].t, b[i].t));
        CHECK(a[i].fired == b[i].fired);
        CHECK(a[i].calls == b[i].calls);
        for (std::size_t k = 0; k < K; ++k) CHECK(same_bits(a[i].y[k], b[i].y[k]));
    }
    CHECK(loop.ticks() == other.ticks());
    CHECK(loop.reached() == other.reached());
    CHECK(loop.firings(0) == other.firings(0));
}

template <class Stepper, std::size_t K>
void check_all_failures(const char* name) {
    const std::string stepper = name;
    CAPTURE(stepper);
    for (const failure kind : {failure::g_at_end, failure::g_at_probe, failure::g_in_location, failure::f_in_step}) {
        CAPTURE(static_cast<int>(kind));
        for (const int warm : {1, 6}) {  // the failing tick while a history starts (1), and with it full (6)
            CAPTURE(warm);
            check_twin<Stepper, odestep::default_root_finder, K>(kind, warm);
            check_twin<Stepper, odestep::on_interpolant<>, K>(kind, warm);
        }
    }
}

}  // namespace

TEST_CASE("failed tick: a multistep loop goes on as its copy from before the tick (Adams, ABM)") {
    check_all_failures<odestep::adams_bashforth2<state>, 1>("adams_bashforth2");
    check_all_failures<odestep::adams_bashforth2<state, odestep::midpoint<state>>, 1>(
        "adams_bashforth2 (midpoint starter)");
    check_all_failures<odestep::adams_bashforth4<state>, 1>("adams_bashforth4");
    check_all_failures<odestep::adams_bashforth_moulton4<state>, 1>("adams_bashforth_moulton4");
}

TEST_CASE("failed tick: a Newtonian loop with a history or a kept acceleration goes on as its copy") {
    check_all_failures<odestep::beeman<state>, 2>("beeman");
    check_all_failures<odestep::predictor_corrector<state>, 2>("predictor_corrector");
    check_all_failures<odestep::half_step<state>, 2>("half_step");
    check_all_failures<odestep::leapfrog_position_form<state>, 2>("leapfrog_position_form");
    check_all_failures<odestep::velocity_verlet<state>, 2>("velocity_verlet");
}

TEST_CASE("failed tick: a loop over a stepper without memory goes on as its copy (RK4)") {
    check_all_failures<odestep::rk4<state>, 1>("rk4");
}

namespace {
// A stepper of the user's with reset() and no memory(), whose object counts its own step calls (as the C API's
// adapter counts evaluations): the roll-back cannot know what its copy would undo, so it resets it, and the
// count keeps the failed step.
struct counting_rk4 : odestep::rk4<state> {
    std::uint64_t steps = 0;
    int resets = 0;
    template <class System>
    odestep::status step(System&& f, state& y, double t, double h) {
        ++steps;
        return odestep::rk4<state>::step(f, y, t, h);
    }
    void reset() noexcept { ++resets; }
};
}  // namespace

TEST_CASE("failed tick: a stepper without memory() is reset after the roll-back, and its own counts count the step") {
    glitch w;
    std::uint64_t calls = 0;
    auto loop = odestep::make_event_stepper(
        counting_rk4{}, odestep::watch(odestep::make_event<state>(g_of_t<1>{&w, inf}, odestep::direction::either)));
    state y{1.0, 0.5};
    decay f{&w, &calls};
    REQUIRE(loop.start(0.0, dt, y) == odestep::status::ok);
    const int resets_at_start = loop.stepper().resets;  // (start resets the stepper)
    for (int i = 0; i < 3; ++i) REQUIRE(loop.tick(f, y).status == odestep::status::ok);
    w = glitch{3 * dt, 5 * dt, false};  // g Inf at the end of the fourth tick
    CHECK(loop.tick(f, y).status == odestep::status::non_finite_event);
    CHECK(loop.stepper().steps == 4);  // three ticks and the failed one: one step call each
    CHECK(loop.stepper().resets == resets_at_start + 1);
}
