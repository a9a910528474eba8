// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the C API (include/odestep/odestep.h, src/), double, as C firmware calls it: the single steps
// (plain, with error estimates, Newtonian, velocity Verlet's caller-kept form) in sequences of up to 6 calls on
// one stepper, and the two loops, with every method, a state size n from 0 to ODESTEP_C_MAX_STATES + 1, null
// pointers where the header allows none, a stepper used before odestep_stepper_init_d, and a right-hand side
// drawn as fuzz_support.hpp's script (padded to the library's maximum size). Checked against the header's
// promises: one status of the enum; after a rejected argument (invalid_time, invalid_step, wrong_direction,
// too_many_steps, step_mismatch, invalid_setting) nothing evaluated and y, x, v, acc and error untouched; after
// non_finite the state unchanged; no ok step from f's NaN or Inf; no step over odestep_method_info_d's
// rhs_evals_per_step; a loop's observer at t0 first, then monotone finite times, ending on t1 when ok; a failed
// loop's state the last one observed, at run.t. Built with src/*.cpp (scripts/fuzz.sh).
// The first byte chooses: even, the above; odd, the per-tick event loops (odestep_event_loop_*_d and
// odestep_newton_event_loop_*_d, issue 24 item 3) with one to ODESTEP_C_MAX_EVENTS events (and 0 and one more,
// refused) whose functions, directions (one out of range), actions (none: terminal; proceed, a bounce, stop, a
// jump), settings and limits are drawn, a start, up to 32 ticks and rearms after the caller changed the state.
// Checked: one status of the enum; a refused start touched nothing and evaluated no f, and the loop then
// refuses ticks (ODESTEP_INVALID_TIME) without evaluating or touching; every tick within the published bound
// of evaluations, ODESTEP_C_TICK_FIRINGS firings listed inside the tick, y at tick.t and the loop's time
// tick.t; a failed tick that fired nothing and ran no action leaves y as it was; each event's firings are the
// calls of its action; the loop's counts are the f and g evaluations the callbacks counted and the firings the
// ticks reported.
#include <odestep/odestep.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

constexpr std::size_t M = ODESTEP_C_MAX_STATES;
using buffer = std::array<double, M>;
using f_script = script<double, M>;

const odestep_method_d* const methods[] = {&odestep_euler_d,
                                           &odestep_euler_richardson_d,
                                           &odestep_heun_d,
                                           &odestep_rk4_d,
                                           &odestep_bs32_d,
                                           &odestep_dp54_d,
                                           &odestep_dop853_d,
                                           &odestep_ab4_d,
                                           &odestep_abm4_d,
                                           &odestep_euler_cromer_d,
                                           &odestep_velocity_verlet_d,
                                           &odestep_forest_ruth_d};

bool valid_c(odestep_status s) { return std::strcmp(odestep_status_name(s), "unknown") != 0; }

bool rejects(odestep_status s) {
    return s == ODESTEP_INVALID_TIME || s == ODESTEP_INVALID_STEP || s == ODESTEP_WRONG_DIRECTION ||
           s == ODESTEP_TOO_MANY_STEPS || s == ODESTEP_STEP_MISMATCH || s == ODESTEP_INVALID_SETTING ||
           s == ODESTEP_INVALID_TOLERANCE;
}

// The script's f over the first n components (the rest zero), as the C callbacks see it. The script's own
// note of values that were not finite covers all M components; the library sees only n of them, so the
// callback notes its own (into the script's counters, which the checks read).
struct context {
    f_script* f;
    std::size_t n;
};
void rhs(double t, const double* y, double* dydt, void* ctx) {
    auto* c = static_cast<context*>(ctx);
    buffer in{};
    for (std::size_t i = 0; i < c->n; ++i) in[i] = y[i];
    const bool before = c->f->non_finite_since;
    const buffer out = (*c->f)(t, in);
    c->f->non_finite_since = before;
    for (std::size_t i = 0; i < c->n; ++i) {
        dydt[i] = out[i];
        if (!std::isfinite(out[i])) c->f->non_finite_since = true;
    }
}
void accel(double t, const double* x, double* a, void* ctx) { rhs(t, x, a, ctx); }

bool same(const buffer& a, const buffer& b) { return std::memcmp(a.data(), b.data(), sizeof(a)) == 0; }
bool finite_n(const double* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(p[i])) return false;
    return true;
}
buffer draw_state(reader& in, std::size_t n) {
    buffer b{};
    for (std::size_t i = 0; i < n && i < M; ++i) b[i] = in.number<double>();
    return b;
}

// The observer of both loops: what it saw, checked as it goes.
struct watch {
    f_script* f;
    std::size_t n;
    double t0;
    double dt;
    std::size_t bound;
    std::uint64_t observed = 0;
    double last_t = 0;
    buffer last_x{};
    buffer last_v{};

    void see(double t, const double* x, const double* v) {
        ODESTEP_FUZZ_CHECK(std::isfinite(t), "an observer time that is not finite");
        if (observed == 0) {
            ODESTEP_FUZZ_CHECK(t == t0 && f->since == 0, "the first observation is not at t0 before any evaluation");
        } else {
            ODESTEP_FUZZ_CHECK(dt > 0 ? t >= last_t : t <= last_t, "observer times not monotone");
            ODESTEP_FUZZ_CHECK(f->since <= bound, "a step made more evaluations than its published bound");
            ODESTEP_FUZZ_CHECK(!f->non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
            ODESTEP_FUZZ_CHECK(finite_n(x, n) && (v == nullptr || finite_n(v, n)), "an observed state not finite");
        }
        f->mark();
        last_t = t;
        last_x = buffer{};
        last_v = buffer{};
        for (std::size_t i = 0; i < n; ++i) {
            last_x[i] = x[i];
            if (v != nullptr) last_v[i] = v[i];
        }
        ++observed;
    }
};
void observe_first(double t, const double* y, void* ctx) { static_cast<watch*>(ctx)->see(t, y, nullptr); }
void observe_newton(double t, const double* x, const double* v, void* ctx) { static_cast<watch*>(ctx)->see(t, x, v); }

// ---- the event loops ----

// What every event's callbacks count.
struct event_counts {
    std::uint64_t g = 0;
    std::array<std::uint64_t, ODESTEP_C_MAX_EVENTS> actions{};
};

// One event: g = y_k - c (x_k or v_k for Newton's equations) or t - c; the action: none (terminal), proceed,
// a bounce (y_k times -r, r in [0, 1)), stop, or a jump (y_k = r).
struct event_context {
    event_counts* counts;
    std::size_t index;
    std::size_t n;
    unsigned kind;
    std::size_t k;
    double c;
    unsigned mode;
    double r;
};
double component(const event_context& e, const double* x, const double* v) {
    const std::size_t k = e.k % (2 * (e.n == 0 ? 1 : e.n));
    if (e.n == 0) return 0.0;
    return k < e.n ? x[k] : (v != nullptr ? v[k - e.n] : x[k - e.n]);
}
double event_g(double t, const double* y, void* ctx) {
    auto* e = static_cast<event_context*>(ctx);
    ++e->counts->g;
    return e->kind == 0 ? component(*e, y, nullptr) - e->c : t - e->c;
}
double newton_event_g(double t, const double* x, const double* v, void* ctx) {
    auto* e = static_cast<event_context*>(ctx);
    ++e->counts->g;
    return e->kind == 0 ? component(*e, x, v) - e->c : t - e->c;
}
odestep_event_result event_action(double, double* y, void* ctx) {
    auto* e = static_cast<event_context*>(ctx);
    ++e->counts->actions[e->index];
    if (e->n == 0) return ODESTEP_PROCEED;
    double& target = y[e->k % e->n];
    switch (e->mode) {
        case 0: return ODESTEP_PROCEED;
        case 1: target = -e->r * target; return ODESTEP_PROCEED;
        case 2: return ODESTEP_STOP;
        default: target = e->r; return ODESTEP_PROCEED;
    }
}
odestep_event_result newton_event_action(double t, double* x, double*, void* ctx) { return event_action(t, x, ctx); }

// One loop: first-order (odestep_event_loop_*_d) or Newtonian (odestep_newton_event_loop_*_d), behind one face.
struct c_loop {
    bool newtonian;
    odestep_event_loop_d first;
    odestep_newton_event_loop_d second;
    odestep_system_d* system;
    odestep_newton_d* newton;

    odestep_status tick(double* x, double* v, odestep_tick_d* t) {
        return newtonian ? odestep_newton_event_loop_tick_d(&second, newton, x, v, t)
                         : odestep_event_loop_tick_d(&first, system, x, t);
    }
    odestep_status rearm(const double* x, const double* v) {
        return newtonian ? odestep_newton_event_loop_rearm_d(&second, x, v) : odestep_event_loop_rearm_d(&first, x);
    }
    double time() const {
        return newtonian ? odestep_newton_event_loop_time_d(&second) : odestep_event_loop_time_d(&first);
    }
    std::size_t firings(std::size_t i) const {
        return newtonian ? odestep_newton_event_loop_firings_d(&second, i) : odestep_event_loop_firings_d(&first, i);
    }
    odestep_status counts(odestep_counts* c) const {
        return newtonian ? odestep_newton_event_loop_counts_d(&second, c) : odestep_event_loop_counts_d(&first, c);
    }
};

void run_event_loop(reader& in) {
    f_script f;
    f.read(in);
    const odestep_method_d* method = methods[in.index(sizeof(methods) / sizeof(methods[0]))];
    odestep_method_info info{};
    ODESTEP_FUZZ_CHECK(odestep_method_info_d(method, &info) == ODESTEP_OK, "method_info refused a method");
    const std::size_t n = in.index(M + 2);  // 0 and M + 1 are refused
    context ctx{&f, n};
    odestep_system_d system{rhs, &ctx, n};
    odestep_newton_d newton{accel, &ctx, n};
    const bool newtonian = info.newtonian != 0 && in.flag();
    const std::size_t count = in.index(ODESTEP_C_MAX_EVENTS + 2);  // 0 and one more are refused
    event_counts counted;
    std::array<event_context, ODESTEP_C_MAX_EVENTS + 1> contexts{};
    std::array<odestep_event_d, ODESTEP_C_MAX_EVENTS + 1> events{};
    std::array<odestep_newton_event_d, ODESTEP_C_MAX_EVENTS + 1> newton_events{};
    std::array<bool, ODESTEP_C_MAX_EVENTS + 1> has_action{};
    for (std::size_t i = 0; i < count; ++i) {
        event_context& e = contexts[i];
        e.counts = &counted;
        e.index = i < ODESTEP_C_MAX_EVENTS ? i : 0;
        e.n = n;
        e.kind = static_cast<unsigned>(in.index(2));
        e.k = in.index(2 * M);
        e.c = in.number<double>();
        const unsigned choice = static_cast<unsigned>(in.index(5));  // 0: terminal
        e.mode = choice == 0 ? 0U : choice - 1U;
        e.r = in.number<double>();
        if (!std::isfinite(e.r)) e.r = 0.0;
        if (e.mode == 1) e.r = e.r < 0.0 ? -e.r - std::floor(-e.r) : e.r - std::floor(e.r);
        has_action[i] = choice != 0;
        const bool null_g = in.byte() == 255;
        const odestep_direction direction = static_cast<odestep_direction>(in.index(4));  // 3: out of range
        odestep_event_d& ev = events[i];
        ev.g = null_g ? nullptr : event_g;
        ev.direction = direction;
        ev.action = has_action[i] ? event_action : nullptr;
        ev.ctx = &e;
        if (in.index(4) == 0) {
            ev.tolerance = in.number<double>();
            ev.band = in.number<double>();
            ev.dead_time = in.number<double>();
            ev.max_firings = in.byte() % 4;
        }
        odestep_newton_event_d& nv = newton_events[i];
        nv.g = null_g ? nullptr : newton_event_g;
        nv.direction = direction;
        nv.action = has_action[i] ? newton_event_action : nullptr;
        nv.ctx = &e;
        nv.tolerance = ev.tolerance;
        nv.band = ev.band;
        nv.dead_time = ev.dead_time;
        nv.max_firings = ev.max_firings;
        ODESTEP_FUZZ_TRACE("event %zu: kind %u k %zu c %.17g action %u r %.17g direction %d%s\n", i, e.kind, e.k, e.c,
                           choice, e.r, static_cast<int>(direction), null_g ? " (null g)" : "");
    }
    odestep_event_limits limits{};
    const bool with_limits = in.flag();
    if (with_limits) {
        limits.max_iterations = in.index(9);
        limits.max_firings_per_step = in.index(10);
        limits.probes = in.index(4);
    }
    buffer x = draw_state(in, n);
    buffer v = draw_state(in, n);
    const double t0 = in.number<double>();
    const double dt = in.number<double>();
    c_loop loop{newtonian, {}, {}, &system, &newton};
    std::memset(&loop.first, 0, sizeof(loop.first));
    std::memset(&loop.second, 0, sizeof(loop.second));
    const bool tick_first = in.flag();
    if (tick_first) {  // a tick before start
        const buffer x0 = x;
        odestep_tick_d t{};
        const odestep_status s = loop.tick(x.data(), v.data(), &t);
        ODESTEP_FUZZ_CHECK(s == ODESTEP_INVALID_TIME && f.evaluations == 0 && same(x, x0),
                           "a tick before start was not invalid_time, or evaluated or touched");
    }
    const buffer x0 = x;
    const buffer v0 = v;
    const odestep_event_limits* limits_arg = with_limits ? &limits : nullptr;
    const odestep_status started =
        newtonian ? odestep_newton_event_loop_start_d(&loop.second, method, newton_events.data(), count, limits_arg,
                                                      &newton, x.data(), v.data(), t0, dt)
                  : odestep_event_loop_start_d(&loop.first, method, events.data(), count, limits_arg, &system, x.data(),
                                               t0, dt);
    ODESTEP_FUZZ_TRACE("start (%s, n %zu, %zu events, t0 %.17g, dt %.17g): %s\n",
                       newtonian ? "Newtonian" : "first order", n, count, t0, dt, odestep_status_name(started));
    ODESTEP_FUZZ_CHECK(valid_c(started), "start: a status outside the enum");
    ODESTEP_FUZZ_CHECK(f.evaluations == 0 && same(x, x0) && same(v, v0), "start evaluated f or touched the state");
    if (started != ODESTEP_OK) {
        odestep_tick_d t{};
        const odestep_status s = loop.tick(x.data(), v.data(), &t);
        ODESTEP_FUZZ_CHECK(s == ODESTEP_INVALID_TIME && f.evaluations == 0 && same(x, x0) && same(v, v0),
                           "a tick after a failed start was not invalid_time, or evaluated or touched");
        return;
    }
    ODESTEP_FUZZ_CHECK(count >= 1 && count <= ODESTEP_C_MAX_EVENTS && n >= 1 && n <= M, "a start that should fail");
    ODESTEP_FUZZ_CHECK(loop.time() == t0, "start: the loop's time is not t0");
    std::uint64_t fired_total = 0;
    for (int i = 0, ticks = 1 + static_cast<int>(in.index(32)); i < ticks; ++i) {
        if (in.index(8) == 0) {  // the caller changes the state, and rearms
            x[in.index(n)] = in.number<double>();
            if (!finite_n(x.data(), n)) x = buffer{};
            const std::uint64_t before = f.evaluations;
            const odestep_status s = loop.rearm(x.data(), v.data());
            ODESTEP_FUZZ_CHECK(valid_c(s), "rearm: a status outside the enum");
            ODESTEP_FUZZ_CHECK(f.evaluations == before, "rearm evaluated f");
        }
        const buffer xb = x;
        const buffer vb = v;
        const double t_before = loop.time();
        const event_counts counted_before = counted;
        f.mark();
        odestep_tick_d t{};
        const odestep_status s = loop.tick(x.data(), v.data(), &t);
        ODESTEP_FUZZ_TRACE("tick %d: %s t=%.17g fired %zu (evaluations %u)\n", i, odestep_status_name(s), t.t, t.fired,
                           f.since);
        ODESTEP_FUZZ_CHECK(valid_c(s), "tick: a status outside the enum");
        ODESTEP_FUZZ_CHECK(t.t == loop.time() || (std::isnan(t.t) && std::isnan(loop.time())),
                           "tick.t is not the loop's time");
        const bool error = !(s == ODESTEP_OK || s == ODESTEP_STOPPED_BY_EVENT || s == ODESTEP_EVENT_LIMIT);
        fired_total += t.fired;
        if (!error) {
            const std::size_t listed = t.fired < ODESTEP_C_TICK_FIRINGS ? t.fired : ODESTEP_C_TICK_FIRINGS;
            for (std::size_t k = 0; k < listed; ++k) {
                ODESTEP_FUZZ_CHECK(t.firings[k].event < count, "a firing of no event");
                ODESTEP_FUZZ_CHECK(dt > 0 ? (t_before <= t.firings[k].t && t.firings[k].t <= t.t)
                                          : (t_before >= t.firings[k].t && t.firings[k].t >= t.t),
                                   "a firing outside its tick");
            }
            ODESTEP_FUZZ_CHECK(s != ODESTEP_STOPPED_BY_EVENT || t.event < count, "stopped by no event");
            ODESTEP_FUZZ_CHECK(finite_n(x.data(), n) && (!newtonian || finite_n(v.data(), n)),
                               "a tick that was not an error left a state not finite");
        } else {
            bool acted = false;
            for (std::size_t e = 0; e < count; ++e) acted = acted || counted.actions[e] != counted_before.actions[e];
            // As fuzz_events asks it: nothing fired, no action, no probe and no location (g read once per event,
            // at the step's end). (A location that fired nothing can leave the state at t_s + s for an s that
            // t_s + s does not resolve: then the tick ends at t_s with that state, the last good one.)
            if (t.t == t_before && t.fired == 0 && !acted && limits.probes == 0 &&
                counted.g - counted_before.g <= count)
                ODESTEP_FUZZ_CHECK(same(x, xb) && same(v, vb), "a failed tick that changed the state");
        }
        for (std::size_t e = 0; e < count; ++e)
            if (has_action[e])
                ODESTEP_FUZZ_CHECK(loop.firings(e) == counted.actions[e],
                                   "the firings of an event are not the calls of its action");
        odestep_counts c{};
        ODESTEP_FUZZ_CHECK(loop.counts(&c) == ODESTEP_OK, "counts refused after a start");
        ODESTEP_FUZZ_CHECK(c.rhs_evals == f.evaluations, "counts: rhs_evals is not the evaluations f counted");
        ODESTEP_FUZZ_CHECK(c.event_evals == counted.g, "counts: event_evals is not the evaluations of g counted");
        std::uint64_t per_event = 0;
        for (std::size_t e = 0; e < count; ++e) per_event += loop.firings(e);
        ODESTEP_FUZZ_CHECK(c.firings == per_event, "counts: firings are not the sum of the events' firings");
        ODESTEP_FUZZ_CHECK(c.firings == fired_total, "counts: firings are not the firings the ticks reported");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    if (in.byte() % 2 == 1) {
        run_event_loop(in);
        return 0;
    }
    f_script f;
    f.read(in);
    const odestep_method_d* method = methods[in.index(sizeof(methods) / sizeof(methods[0]))];
    odestep_method_info info{};
    ODESTEP_FUZZ_CHECK(odestep_method_info_d(method, &info) == ODESTEP_OK, "method_info refused a method");
    const std::size_t n = in.index(M + 2);  // 0 and M + 1 are refused
    context ctx{&f, n};
    const bool null_f = in.byte() == 255;
    odestep_system_d system{null_f ? nullptr : rhs, &ctx, n};
    odestep_newton_d newton{null_f ? nullptr : accel, &ctx, n};
    odestep_stepper_d stepper;
    std::memset(&stepper, 0, sizeof(stepper));
    if (in.byte() != 255) ODESTEP_FUZZ_CHECK(odestep_stepper_init_d(&stepper, method) == ODESTEP_OK, "init refused");
    buffer x = draw_state(in, n);
    buffer v = draw_state(in, n);
    const std::size_t evals_bound = info.rhs_evals_per_step;

    if (in.flag()) {  // a loop
        const double t0 = in.number<double>();
        const double dt = in.number<double>();
        const double t1 = in.index(2) == 0 ? in.number<double>() : t0 + double(in.byte() % 64) * dt;
        watch w{&f, n, t0, dt, evals_bound};
        odestep_run_d run{-1.0, 77, {}};
        const buffer x0 = x;
        const buffer v0 = v;
        const odestep_status s =
            info.newtonian != 0 && in.flag()
                ? odestep_integrate_newton_d(&stepper, &newton, x.data(), v.data(), t0, t1, dt, observe_newton, &w,
                                             &run)
                : odestep_integrate_d(&stepper, &system, x.data(), t0, t1, dt, observe_first, &w, &run);
        ODESTEP_FUZZ_CHECK(valid_c(s), "a status outside the enum");
        if (rejects(s) && w.observed == 0) {
            ODESTEP_FUZZ_CHECK(f.evaluations == 0 && same(x, x0) && same(v, v0),
                               "a rejected argument touched something");
            return 0;
        }
        ODESTEP_FUZZ_CHECK(!rejects(s), "an argument rejected after the loop had begun");
        ODESTEP_FUZZ_CHECK(w.observed > 0 && run.steps + 1 == w.observed, "run.steps does not match the observations");
        ODESTEP_FUZZ_CHECK(run.t == w.last_t, "run.t is not the time of the last observation");
        ODESTEP_FUZZ_CHECK(run.counts.rhs_evals == static_cast<std::uint64_t>(f.evaluations),
                           "run.counts.rhs_evals differs from the evaluations f counted");
        ODESTEP_FUZZ_CHECK(run.counts.accepted_steps == run.steps, "run.counts.accepted_steps is not run.steps");
        buffer xn{};
        for (std::size_t i = 0; i < n; ++i) xn[i] = x[i];
        ODESTEP_FUZZ_CHECK(same(xn, w.last_x), "the loop's state is not the last one observed");
        if (s == ODESTEP_OK) ODESTEP_FUZZ_CHECK(run.t == t1, "an ok loop that did not end on t1");
        return 0;
    }

    // A sequence of single steps on one stepper.
    buffer acc{};
    bool acc_ready = false;
    double t = in.number<double>();
    const unsigned calls = 1 + in.byte() % 6;
    for (unsigned k = 0; k < calls; ++k) {
        const double dt = in.number<double>();
        const unsigned form = in.byte() % 4;
        if (in.flag()) t = in.number<double>();  // or continue from the last step's end
        buffer err{};
        buffer err2{};
        if (form == 3 && info.newtonian != 0 && !acc_ready && n >= 1 && n <= M) {  // the caller's first a(t, x)
            accel(t, x.data(), acc.data(), &ctx);
            acc_ready = true;
        }
        const buffer x0 = x;
        const buffer v0 = v;
        const buffer acc0 = acc;
        f.mark();
        odestep_status s;
        switch (form) {
            case 0: s = odestep_step_d(&stepper, &system, x.data(), t, dt); break;
            case 1: {
                double* const e1 = in.flag() ? err.data() : nullptr;  // one read per statement (fuzz_support.hpp)
                double* const e2 = in.flag() ? err2.data() : nullptr;
                s = odestep_step_error_d(&stepper, &system, x.data(), t, dt, e1, e2);
                break;
            }
            case 2: s = odestep_step_newton_d(&stepper, &newton, x.data(), v.data(), t, dt); break;
            default:
                s = odestep_step_newton_kept_d(&stepper, &newton, x.data(), v.data(), in.flag() ? acc.data() : nullptr,
                                               t, dt);
                break;
        }
        ODESTEP_FUZZ_TRACE("call %u form %u t=%.17g dt=%.17g: %s (%u evaluations)\n", k, form, t, dt,
                           odestep_status_name(s), f.since);
        ODESTEP_FUZZ_CHECK(valid_c(s), "a status outside the enum");
        ODESTEP_FUZZ_CHECK(f.since <= evals_bound, "a step made more evaluations than its published bound");
        if (s == ODESTEP_OK) {
            ODESTEP_FUZZ_CHECK(!f.non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
            t = t + dt;
            continue;
        }
        if (rejects(s)) ODESTEP_FUZZ_CHECK(f.since == 0, "a rejected argument, and yet f was evaluated");
        ODESTEP_FUZZ_CHECK(same(x, x0) && same(v, v0) && same(acc, acc0) && same(err, buffer{}) && same(err2, buffer{}),
                           "a failed step touched the state, the acceleration or the error");
    }
    return 0;
}
