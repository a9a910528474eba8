// SPDX-License-Identifier: BSL-1.0
// The event loop: a pebble thrown straight up at v0 = 50 m/s against quadratic drag (terminal speed 30 m/s,
// g = 9.8; examples/pebble.cpp), state (y, v) as std::array<double, 2>, RK4 at dt = 0.01, watched by two
// events: the apex (v falls through 0) and the ground (y falls through 0), both `odestep::record`, so the
// run goes on through them and the stepped stretch is in steady state. Three variants:
//   odestep  odestep::make_event_stepper(rk4, watch(apex, ground)), one tick(f, y) per step, as a control
//            loop uses it (the tick's report is read: a firing is noted with its time);
//   plain    odestep::rk4 step alone, no events: the event loop's overhead is odestep - plain;
//   hand     the hand-written RK4 step and the check a careful engineer writes: v and y before the step
//            against v and y after it, a sign change noted at the step's end (no location);
//   hand_checked  the same loop with the guarantees of odestep's quiet tick: the checked RK4 step
//            (bench::hand::rk4_checked: a NaN or Inf leaves y as it was), each g evaluated at the step's end,
//            tested finite (else the state before the step is restored and an error returned, as odestep's
//            non_finite_event) and against its value at the last step's end in its direction, then kept.
//            The reference for the quiet tick's own cost (it locates nothing either).
// Neither Boost.Odeint nor GSL odeiv2 locates events: no variant of theirs.
//
// Measured stretches: `pebble_events`, 1000 steps from the throw (t = 0 to 10 s: the apex at 3.15 s and the
// ground at 7.08 s fire in 2 of the 1000 ticks), and `pebble_events_quiet`, the first 300 steps (before the
// apex: no tick fires), which gives the per-tick cost of the loop when nothing fires. Besides, the ticks in
// which something fires are measured alone: Callgrind dumps "odestep@quiet" (the tick before the apex),
// "odestep@apex" and "odestep@ground" (count mode), and the right-hand-side and event-function evaluations
// of those ticks are counted in a separate run whose f and g count their calls (EVENT lines, check mode).
//
// Checks (besides the harness's: every variant against the closed form at the stretch's end): odestep's
// state equals plain's bit for bit (record events leave the trajectory alone); the apex and ground times
// from odestep's tick reports against the closed forms; the hand loop sees each event in the same tick;
// a tick in which nothing fires evaluates f 4 times (the RK4 step) and each g once.
#include <cinttypes>

#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<double, 2>;

constexpr double gravity = 9.8, vt = 30.0, v0 = 50.0;
constexpr double dt = 0.01;
constexpr int steps_full = 1000;  // t = 10 s: past the apex and the ground
constexpr int steps_quiet = 300;  // t = 3 s: before the apex, nothing fires

constexpr auto rhs = [](double, const State& y, State& d) { bench::pebble<double>(y, d); };
constexpr auto height = [](double, const State& y) { return y[0]; };
constexpr auto speed = [](double, const State& y) { return y[1]; };

auto make_loop() {
    // y = 0 at the throw: the ground event is not armed there; it arms once y > 0 has been seen.
    return odestep::make_event_stepper(
        odestep::rk4<State>{},
        odestep::watch(odestep::make_event<State>(speed, odestep::direction::falling, odestep::record),
                       odestep::make_event<State>(height, odestep::direction::falling, odestep::record)));
}
auto odestep_loop = make_loop();

/// What a variant noticed: firings per event (0 apex, 1 ground) and the time of the last one.
struct firing_log {
    std::uint32_t count[2];
    double t[2];
};
firing_log odestep_log, hand_log, hand_checked_log;
double hand_g[2];  // hand_checked: g of the apex and the ground at the last step's end

void start_odestep(const State& y0, double t0) {
    if (odestep_loop.start(t0, dt, y0) != odestep::status::ok) {
        std::fprintf(stderr, "bench: pebble_events: event_stepper start failed\n");
        std::exit(2);
    }
    odestep_log = {};
}
void start_hand(const State&, double) { hand_log = {}; }
void start_hand_checked(const State& y0, double t0) {
    hand_checked_log = {};
    hand_g[0] = speed(t0, y0);
    hand_g[1] = height(t0, y0);
}

// The closed form. Up (v > 0): v = vt tan(phi0 - t / tau), y = vt tau ln(cos(phi0 - t / tau) / cos phi0) with
// tau = vt / g, phi0 = atan(v0 / vt); apex at t_a = tau phi0, y_max = vt tau ln(1 / cos phi0). Down:
// v = -vt tanh(s), y = y_max - vt tau ln cosh(s), s = (t - t_a) / tau; ground at s = acosh(exp(y_max / (vt tau))).
constexpr long double tau_l = static_cast<long double>(vt) / static_cast<long double>(gravity);
long double phi0() { return std::atan(static_cast<long double>(v0) / static_cast<long double>(vt)); }
long double t_apex_exact() { return tau_l * phi0(); }
long double y_max_exact() { return static_cast<long double>(vt) * tau_l * -std::log(std::cos(phi0())); }
long double t_ground_exact() {
    return t_apex_exact() + tau_l * std::acosh(std::exp(y_max_exact() / (static_cast<long double>(vt) * tau_l)));
}
State pebble_exact(long double t) {
    const long double ta = t_apex_exact(), V = vt;
    if (t <= ta) {
        const long double a = phi0() - t / tau_l;
        return {static_cast<double>(V * tau_l * std::log(std::cos(a) / std::cos(phi0()))),
                static_cast<double>(V * std::tan(a))};
    }
    const long double s = (t - ta) / tau_l;
    return {static_cast<double>(y_max_exact() - V * tau_l * std::log(std::cosh(s))),
            static_cast<double>(-V * std::tanh(s))};
}
}  // namespace

BENCH_STEP int bench_step_pebble_events_odestep(State& y, State&, double, double) {
    const auto r = odestep_loop.tick(rhs, y);
    if (r.fired != 0) {
        for (std::size_t k = 0; k < r.fired && k < r.firings.size(); ++k) {
            const std::size_t e = r.firings[k].event;
            odestep_log.count[e] += 1;
            odestep_log.t[e] = r.firings[k].t;
        }
    }
    return static_cast<int>(r.status);
}
BENCH_STEP int bench_step_pebble_events_plain(State& y, State&, double t, double h) {
    return static_cast<int>(odestep::rk4<State>{}.step(rhs, y, t, h));
}
BENCH_STEP int bench_step_pebble_events_hand(State& y, State&, double t, double h) {
    const double y_before = y[0], v_before = y[1];
    bench::hand::rk4(rhs, y, t, h);
    if (v_before > 0 && y[1] <= 0) {  // apex
        hand_log.count[0] += 1;
        hand_log.t[0] = t + h;
    }
    if (y_before > 0 && y[0] <= 0) {  // ground
        hand_log.count[1] += 1;
        hand_log.t[1] = t + h;
    }
    return 0;
}

BENCH_STEP int bench_step_pebble_events_hand_checked(State& y, State&, double t, double h) {
    const State before = y;
    if (bench::hand::rk4_checked(rhs, y, t, h) != bench::hand::ok) return bench::hand::non_finite;
    const double t_end = t + h;
    const std::array<double, 2> g{speed(t_end, y), height(t_end, y)};
    if (!bench::hand::finite_state(g[0] + g[1], g)) {
        y = before;
        return 2;  // an event function NaN or Inf
    }
    if (hand_g[0] > 0 && g[0] <= 0) {  // apex (falling)
        hand_checked_log.count[0] += 1;
        hand_checked_log.t[0] = t_end;
    }
    if (hand_g[1] > 0 && g[1] <= 0) {  // ground (falling)
        hand_checked_log.count[1] += 1;
        hand_checked_log.t[1] = t_end;
    }
    hand_g[0] = g[0];
    hand_g[1] = g[1];
    return 0;
}

namespace {
const std::vector<bench::variant<State>>& variants() {
    static const std::vector<bench::variant<State>> vs{
        {"odestep", "odestep::event_stepper tick: rk4 + apex and ground events (record)",
         bench_step_pebble_events_odestep, true, start_odestep},
        {"plain", "odestep::rk4 step alone, no events (the tick's step without the event loop)",
         bench_step_pebble_events_plain, true},
        {"hand", "hand-written RK4 loop + sign test of v and y against their values before the step",
         bench_step_pebble_events_hand, true, start_hand},
        {"hand_checked",
         "hand-written checked RK4 + the events' g at the step's end, tested finite and against their last values",
         bench_step_pebble_events_hand_checked, true, start_hand_checked}};
    return vs;
}

bench::problem<State> stretch(const char* name, int steps) {
    return {name, State{0.0, v0}, 0.0, dt, steps,
            pebble_exact(static_cast<long double>(steps) * static_cast<long double>(dt)),
            // Round-off: the hand loop's arithmetic may differ from odestep's by a few ulps per step
            // (measured: none, with GCC 12 at every -O).
            1e-12,
            // RK4 at dt = 0.01 against the closed form: 2.8e-11 relative at t = 3 s, 3.8e-10 at t = 10 s (the
            // step over the apex, where the drag's second derivative jumps, is of lower order). Kutta's
            // third-order method misses by 1.1e-8 and 7.2e-9, the midpoint method by 3e-6 and 7e-6.
            2e-9, false};
}

// The evaluations of one tick, counted by a separate event stepper whose f and g count their calls (the
// same arithmetic as the benchmark's, so the same trajectory and the same event times).
std::uint64_t n_f = 0, n_g = 0;
struct tick_cost {
    int tick = -1;  // index of the tick (0 is the first)
    std::uint64_t f = 0, g = 0;
    double t = -1;  // the located time
};

struct counted_run {
    tick_cost quiet_max, apex, ground;  // quiet_max: the most evaluations of any tick that fired nothing
    tick_cost quiet_before_apex;
    int quiet_ticks = 0;
    bool ok = true;
};

counted_run count_evaluations(int steps) {
    constexpr auto f = [](double t, const State& y, State& d) {
        ++n_f;
        rhs(t, y, d);
    };
    constexpr auto g_speed = [](double t, const State& y) {
        ++n_g;
        return speed(t, y);
    };
    constexpr auto g_height = [](double t, const State& y) {
        ++n_g;
        return height(t, y);
    };
    auto loop = odestep::make_event_stepper(
        odestep::rk4<State>{},
        odestep::watch(odestep::make_event<State>(g_speed, odestep::direction::falling, odestep::record),
                       odestep::make_event<State>(g_height, odestep::direction::falling, odestep::record)));
    counted_run out;
    State y{0.0, v0};
    out.ok = loop.start(0.0, dt, y) == odestep::status::ok;
    tick_cost previous;
    for (int i = 0; i < steps && out.ok; ++i) {
        n_f = n_g = 0;
        const auto r = loop.tick(f, y);
        out.ok = r.status == odestep::status::ok;
        const tick_cost c{i, n_f, n_g, -1};
        if (r.fired == 0) {
            ++out.quiet_ticks;
            if (c.f > out.quiet_max.f || c.g > out.quiet_max.g) out.quiet_max = c;
            previous = c;
            continue;
        }
        for (std::size_t k = 0; k < r.fired && k < r.firings.size(); ++k) {
            tick_cost& slot = r.firings[k].event == 0 ? out.apex : out.ground;
            if (slot.tick >= 0) out.ok = false;  // each fires once
            slot = c;
            slot.t = r.firings[k].t;
            if (r.firings[k].event == 0) out.quiet_before_apex = previous;
        }
    }
    return out;
}

int extra_checks(const bench::problem<State>& p, const counted_run& cr) {
    const auto& vs = variants();
    int failures = 0;
    auto report = [&](const char* key, bool ok, const char* text) {
        if (!ok) ++failures;
        std::printf("CHECK\t%s\t%s\t%s\t%s\n", p.name, key, ok ? "ok" : "FAIL", text);
    };
    char text[256];

    // odestep's state equals plain's bit for bit.
    State y_odestep = p.y0, y_plain = p.y0, y_hand = p.y0, err{};
    bench::start_run(vs[0], p);
    const int bad0 = bench::run_steps(vs[0], p, y_odestep, err, p.check_steps);
    const firing_log seen = odestep_log;
    bench::start_run(vs[1], p);
    const int bad1 = bench::run_steps(vs[1], p, y_plain, err, p.check_steps);
    bench::start_run(vs[2], p);
    bench::run_steps(vs[2], p, y_hand, err, p.check_steps);
    State y_hand_checked = p.y0;
    bench::start_run(vs[3], p);
    const int bad3 = bench::run_steps(vs[3], p, y_hand_checked, err, p.check_steps);
    const bool bits = std::memcmp(y_odestep.data(), y_plain.data(), sizeof(State)) == 0;
    std::snprintf(text, sizeof text,
                  "bit-identical to odestep after %d steps: %s (record events leave the trajectory alone)",
                  p.check_steps, bits ? "yes" : "no");
    report("plain", bad0 == 0 && bad1 == 0 && bits, text);

    // Event times from the tick reports against the closed forms.
    // Measured: 8.1e-13 (apex) and 1.5e-10 (ground) relative; a check at the step's end, without location,
    // is off by up to dt / t = 3e-3.
    const double tol_apex = 1e-9, tol_ground = 1e-9;
    const double ta = static_cast<double>(t_apex_exact()), tg = static_cast<double>(t_ground_exact());
    const double ea = std::fabs(seen.t[0] - ta) / ta, eg = std::fabs(seen.t[1] - tg) / tg;
    std::snprintf(text, sizeof text, "apex t=%.15f fired %u (closed form %.15f, rel. error %.2e, tol %.0e)", seen.t[0],
                  seen.count[0], ta, ea, tol_apex);
    report("odestep", seen.count[0] == 1 && ea <= tol_apex, text);
    // The ground: RK4 over the apex's step is of lower order (the drag's second derivative jumps at v = 0),
    // and the error it leaves carries on to the ground.
    std::snprintf(text, sizeof text, "ground t=%.15f fired %u (closed form %.15f, rel. error %.2e, tol %.0e)",
                  seen.t[1], seen.count[1], tg, eg, tol_ground);
    report("odestep", seen.count[1] == 1 && eg <= tol_ground, text);

    // The hand loops see each event in the tick in which odestep locates it.
    bool same_ticks = bad3 == 0;
    for (int e = 0; e < 2; ++e)
        same_ticks = same_ticks && hand_log.count[e] == 1 && seen.t[e] > hand_log.t[e] - dt &&
                     seen.t[e] <= hand_log.t[e] && hand_checked_log.count[e] == 1 &&
                     hand_checked_log.t[e] == hand_log.t[e];
    std::snprintf(text, sizeof text,
                  "apex seen at the end of the step to t=%.2f, ground to t=%.2f: the ticks odestep locates them in",
                  hand_log.t[0], hand_log.t[1]);
    report("hand", same_ticks, text);

    // The counted run: the same event times, and the published cost of a tick that fires nothing.
    const bool same_times = cr.apex.t == seen.t[0] && cr.ground.t == seen.t[1];
    std::snprintf(text, sizeof text,
                  "ticks firing nothing (%d of %d): at most %" PRIu64 " f and %" PRIu64
                  " g evaluations (target: 4, the RK4 step, and 1 per event); event times as counted run: %s",
                  cr.quiet_ticks, p.check_steps, cr.quiet_max.f, cr.quiet_max.g, same_times ? "same" : "differ");
    report("odestep", cr.ok && same_times && cr.quiet_max.f == 4 && cr.quiet_max.g == 2, text);
    return failures;
}
}  // namespace

int main(int argc, char** argv) {
    const bench::problem<State> full = stretch("pebble_events", steps_full);
    const bench::problem<State> quiet = stretch("pebble_events_quiet", steps_quiet);
    const auto& vs = variants();
    const char* mode = argc > 1 ? argv[1] : "check";

    if (std::strcmp(mode, "check") == 0) {
        int failures = bench::main<State>(argc, argv, full, vs) != 0;
        const counted_run cr = count_evaluations(steps_full);
        failures += extra_checks(full, cr);
        for (const auto& v : vs)
            std::printf("VARIANT\t%s\t%s\t%s\t%s\n", quiet.name, v.key, v.same_method ? "same" : "other",
                        v.description);
        failures += bench::check(quiet, vs);
        // The evaluations of single ticks: EVENT case tick index what-fires f g re-steps, where re-steps are
        // the f evaluations beyond the step's own, in steps.
        auto event_line = [&](const char* kind, const tick_cost& c, const char* fires) {
            constexpr std::uint64_t per_step = odestep::rk4<State>::rhs_evals_per_step;
            std::printf("EVENT\t%s\t%s\t%d\t%s\t%" PRIu64 "\t%" PRIu64 "\t%" PRIu64 "\n", full.name, kind, c.tick,
                        fires, c.f, c.g, (c.f - per_step) / per_step);
        };
        event_line("quiet", cr.quiet_before_apex, "nothing");
        event_line("apex", cr.apex, "apex (record)");
        event_line("ground", cr.ground, "ground (record)");
        return failures == 0 ? 0 : 1;
    }
    if (std::strcmp(mode, "count") == 0) {
        const int n = argc > 2 ? std::atoi(argv[2]) : steps_full;
        if (bench::main<State>(argc, argv, full, vs) != 0) return 1;
        if (bench::count(quiet, vs, steps_quiet) != 0) return 1;
        // Single ticks of odestep's event stepper: the tick before the apex, the apex's, the ground's.
        const counted_run cr = count_evaluations(n);
        const std::pair<const char*, int> ticks[] = {{"odestep@quiet", cr.quiet_before_apex.tick},
                                                     {"odestep@apex", cr.apex.tick},
                                                     {"odestep@ground", cr.ground.tick}};
        for (const auto& [name, index] : ticks) {
            if (index < 0) continue;
            State y = full.y0, err{};
            bench::start_run(vs[0], full);
            int bad = bench::run_steps(vs[0], full, y, err, index);
            CALLGRIND_ZERO_STATS;
            bad |= vs[0].step(y, err, full.t0 + static_cast<double>(index) * full.dt, full.dt);
            char dump[128];
            std::snprintf(dump, sizeof dump, "%s %s 1", full.name, name);
            CALLGRIND_DUMP_STATS_AT(dump);
            if (bad) return 1;
        }
        return 0;
    }
    if (std::strcmp(mode, "time") == 0) {
        if (bench::main<State>(argc, argv, full, vs) != 0) return 1;
        return bench::time(quiet, vs, argc > 2 ? std::atoi(argv[2]) : 21, argc > 3 ? std::atof(argv[3]) : 2.0);
    }
    return bench::main<State>(argc, argv, full, vs);
}
