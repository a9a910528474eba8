// SPDX-License-Identifier: BSL-1.0
// odestep: events on the free-running loops: integrate_adaptive and integrate_times with watch(...), for the
// explicit pairs (adaptive_rk), Radau IIA 5 and the Rosenbrock pairs. Each accepted step is handed to the event
// engine (engine.hpp) through a stepper that replays it on the step's continuous extension, so detection,
// location, firing, arming after an action and the work bounds are the grid loop's own; an action that ran cuts
// the step at the event and restarts the engine's step sequence from there.
#ifndef ODESTEP_EVENTS_FREE_RUNNING_HPP
#define ODESTEP_EVENTS_FREE_RUNNING_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "../adaptive/adaptive_rk.hpp"
#include "../adaptive/dense.hpp"
#include "../adaptive/integrate_adaptive.hpp"
#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stiff/radau5.hpp"
#include "../stiff/rosenbrock_adaptive.hpp"
#include "../stiff/sdirk_adaptive.hpp"
#include "bounds.hpp"
#include "engine.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {

// The continuous extension of one accepted step of an engine: sink() is what attempt() is handed,
// begin() sees the step's ends, complete() makes the extension usable (at most rhs_evals_to_complete
// evaluations of f), at_offset(s) reads it s after the step's start (an offset, not a time: t_s + s rounds
// to t_s for s under half an ULP of t, and the state there must still be the one just after the start).
template <class Engine>
struct free_extension;

template <class Engine, class = void>
struct has_free_extension : std::false_type {};
template <class Engine>
struct has_free_extension<Engine, std::void_t<decltype(free_extension<Engine>::rhs_evals_to_complete)>>
    : std::true_type {};
// An engine the free-running loops with events drive: one with a free_extension.
template <class Engine>
inline constexpr bool has_free_extension_v = has_free_extension<Engine>::value;

// The cubic Hermite interpolant (hermite_cubic's polynomial, HNW I (6.7)) in powers of theta about the start:
//     u = y0 + theta (h f0 + theta ((3 d - 2 h f0 - h f1) + theta (h f0 + h f1 - 2 d))),  d = y1 - y0,
// so that just after the start it is y0 plus a term of the size of the motion there (theta h f0), not of the
// whole step's rounding (eps |d|): a ball bounced slowly on the floor in a long step stays above it.
template <class State>
void hermite_from_start(const State& y0, const State& f0, const State& y1, const State& f1, value_type_t<State> h,
                        value_type_t<State> theta, State& out) noexcept {
    using T = value_type_t<State>;
    for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
        const T d = y1[i] - y0[i];
        const T a = h * f0[i];
        const T b = h * f1[i];
        out[i] = y0[i] + theta * (a + theta * ((T(3) * d - T(2) * a - b) + theta * (a + b - T(2) * d)));
    }
}

// The explicit pairs: odestep::dense_step (DP 5(4)'s and DOP853's own extensions, cubic Hermite otherwise),
// read about the start. DOPRI5's and DOP853's form u = r1 + theta (r2 + (1 - theta)(r3 + theta R)),
// R = r4 + (1 - theta) p (p = r5, or DOP853's r5 + theta (r6 + (1 - theta)(r7 + theta r8))), with
// r2 + r3 = h k1, is the same polynomial as
//     u = r1 + theta (h k1 + theta ((1 - theta) R - r3)),
// whose first term is the step's own h k1 (kept here from the stages), not r2 + r3 rounded to eps |r2|.
template <class Method, class State>
struct free_extension<adaptive_rk<Method, State>> {
    using T = value_type_t<State>;
    using dense_type = dense_step<Method, State>;
    static constexpr std::size_t rhs_evals_to_complete = dense_type::rhs_evals_to_complete;
    static constexpr bool dopri5 = std::is_same_v<Method, tables::dormand_prince54>;
    static constexpr bool dop853 = std::is_same_v<Method, tables::dop853>;
    struct sink_type {
        free_extension* self;
        template <class Stages>
        void operator()(T t, const State& y, T h, const Stages& k, const State& y_new) const noexcept {
            self->dense(t, y, h, k, y_new);
            for (std::size_t i = 0; i < state_traits<State>::size; ++i) self->hk1[i] = h * k[0][i];
        }
    };
    dense_type dense;
    State hk1{};
    sink_type sink() noexcept { return sink_type{this}; }
    void begin(T, const State&, T, const State&) noexcept {}
    template <class System>
    status complete(System& f, adaptive_rk<Method, State>& engine) {
        return dense.complete(f, engine);
    }
    void at_offset(T s, State& out) const noexcept {
        const auto& piece = dense.piece();
        const T theta = s / piece.h;
        const T theta1 = T(1) - theta;
        const auto& r = piece.r;
        if constexpr (dopri5 || dop853) {
            for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
                T p = r[4][i];
                if constexpr (dop853) p = r[4][i] + theta * (r[5][i] + theta1 * (r[6][i] + theta * r[7][i]));
                const T big_r = r[3][i] + theta1 * p;
                out[i] = r[0][i] + theta * (hk1[i] + theta * (theta1 * big_r - r[2][i]));
            }
        } else {
            hermite_from_start(r[0], r[1], r[2], r[3], piece.h, theta, out);
        }
    }
};

// Radau IIA 5: the step's collocation polynomial, no evaluation. radau5_dense reads it about the step's end,
//     u(s) = y1 + s (q0 + (s - c2 + 1)(q1 + (s - c1 + 1) q2)),  s = (t - t1) / h in [-1, 0]
// (radau5.f's CONTR5), which passes through the start y0 = u(-1) only to rounding of size eps |y1|. The events
// read the same polynomial about the start (u(-1) = y0 exactly for the collocation polynomial, whose
// divided differences take Z = 0 at c = 0), so that it leaves y0 exactly as the steps' states do: a ball
// bounced on the floor (y0 = 0) is not put below it by that rounding, to be found there again at once.
//     u = y0 + sigma (q0 + (s - c2) q1 + (s (s + 1 - c1 - c2) + c1 c2) q2),  sigma = s + 1 = (t - t0) / h.
template <class State>
struct free_extension<radau5<State>> {
    using T = value_type_t<State>;
    static constexpr std::size_t rhs_evals_to_complete = 0;
    static constexpr auto tab = tables::radau_iia5::table<T>;
    struct sink_type {
        free_extension* self;
        void operator()(T, T step, const State&, const std::array<State, 3>& divided) const noexcept {
            self->h = step;
            self->q = divided;
        }
    };
    T h = T(1);
    State y0{};
    std::array<State, 3> q{};
    sink_type sink() noexcept { return sink_type{this}; }
    void begin(T, const State& y_s, T, const State&) noexcept { assign(y0, y_s); }
    template <class System>
    status complete(System&, radau5<State>&) noexcept {
        return status::ok;
    }
    // (sigma from the offset, not s + 1: near the start s + 1 cancels to a multiple of eps, and the state just
    // after a bounce would read y0 itself, on the floor)
    void at_offset(T offset, State& out) const noexcept {
        const T sigma = offset / h;
        const T s = sigma - T(1);
        const T a = s - tab.c[1];
        const T b = s * (s + T(1) - tab.c[0] - tab.c[1]) + tab.c[0] * tab.c[1];
        for (std::size_t i = 0; i < state_traits<State>::size; ++i)
            out[i] = y0[i] + sigma * (q[0][i] + a * q[1][i] + b * q[2][i]);
    }
};

// The Rosenbrock pairs publish no extension: cubic Hermite through the step's ends, f at both (two evaluations),
// read about the start (hermite_from_start).
template <class Method, class State>
struct free_extension<rosenbrock_adaptive<Method, State>> {
    using T = value_type_t<State>;
    static constexpr std::size_t rhs_evals_to_complete = 2;
    T t0 = T(0);
    T t1 = T(0);
    State y0{};
    State y1{};
    State f0{};
    State f1{};
    no_step_sink sink() const noexcept { return {}; }
    void begin(T t_s, const State& y_s, T t_e, const State& y_e) noexcept {
        t0 = t_s;
        t1 = t_e;
        assign(y0, y_s);
        assign(y1, y_e);
    }
    template <class System>
    status complete(System& f, rosenbrock_adaptive<Method, State>&) {
        evaluate(f, t0, static_cast<const State&>(y0), f0);
        evaluate(f, t1, static_cast<const State&>(y1), f1);
        return all_finite(f0) && all_finite(f1) ? status::ok : status::non_finite;
    }
    void at_offset(T s, State& out) const noexcept { hermite_from_start(y0, f0, y1, f1, t1 - t0, s / (t1 - t0), out); }
};

// The SDIRK pairs: cubic Hermite through the step's ends and the slopes the step already has (what sdirk_dense
// is given: the previous point's and the last stage's), read about the start: no evaluation of f.
template <class Method, class State>
struct free_extension<sdirk_adaptive<Method, State>> {
    using T = value_type_t<State>;
    static constexpr std::size_t rhs_evals_to_complete = 0;
    struct sink_type {
        free_extension* self;
        void operator()(const T&, const T& step, const State& y_old, const State& slope_old, const State& y_new,
                        const State& slope_new) const noexcept {
            self->h = step;
            assign(self->y0, y_old);
            assign(self->f0, slope_old);
            assign(self->y1, y_new);
            assign(self->f1, slope_new);
        }
    };
    T h = T(1);
    State y0{};
    State f0{};
    State y1{};
    State f1{};
    sink_type sink() noexcept { return sink_type{this}; }
    void begin(T, const State&, T, const State&) noexcept {}
    template <class System>
    status complete(System&, sdirk_adaptive<Method, State>&) noexcept {
        return status::ok;
    }
    void at_offset(T s, State& out) const noexcept { hermite_from_start(y0, f0, y1, f1, h, s / h, out); }
};

// One accepted step, as the replaying stepper reads it: its ends (exact), its extension inside (completed on
// first use), and what the event engine did with the stepper (calls, restart).
template <class Engine, class System, class State>
struct replayed_step {
    using T = value_type_t<State>;
    Engine& engine;
    System& f;
    free_extension<Engine> ext{};
    T t_s = T(0);
    T t_e = T(0);
    T h = T(0);
    State y_s{};
    State y_e{};
    bool completed = false;
    status completion = status::ok;
    std::size_t calls = 0;  // calls of the event engine's own stepper (not its copies) in this step
    bool restart = false;   // an action ran: the engine asked for the rest of the step from the event

    replayed_step(Engine& e, System& system) noexcept : engine(e), f(system) {}

    void begin(T start, const State& y_start, T end, const State& y_end) {
        t_s = start;
        t_e = end;
        h = end - start;
        assign(y_s, y_start);
        assign(y_e, y_end);
        completed = false;
        completion = status::ok;
        calls = 0;
        restart = false;
        ext.begin(start, y_start, end, y_end);
    }

    // The state s after the step's start (s in [0, h]): its ends exactly, else the extension; non_finite when
    // the extension cannot be completed or overflows between finite ends.
    status state_after(T s, State& out) {
        if (s == h) {
            assign(out, y_e);
            return status::ok;
        }
        if (s == T(0)) {
            assign(out, y_s);
            return status::ok;
        }
        if (!completed) {
            completion = ext.complete(f, engine);
            completed = true;
        }
        if (completion != status::ok) return completion;
        State u;
        ext.at_offset(s, u);
        if (!all_finite(u)) return status::non_finite;
        assign(out, u);
        return status::ok;
    }
    // The state at the time t inside the step.
    status state_at(T t, State& out) { return state_after(t == t_e ? h : t - t_s, out); }
};

// The stepper the event engine is given for one accepted step. The engine calls its own stepper once for the
// regular step (the step's end: y_e exactly) and once more only to take the rest of the step after an action
// (refused here: the loop restarts its engine from the event instead); it re-steps to s inside the step on
// copies (the probes and the location), which read the extension s after the step's start (its end exactly
// at s = h, as the engine's time_at reads it). No evaluation of f per step (rhs_evals_per_step = 0): the
// extension's completion is counted by the free-running bound.
template <class Replayed, class State>
class replaying_stepper {
public:
    using state_type = State;                ///< the state
    using value_type = value_type_t<State>;  ///< its scalar
    static constexpr std::size_t rhs_evals_per_step = 0;
    static constexpr bool self_starting = true;

    explicit replaying_stepper(Replayed& r) noexcept : r_(&r) {}
    replaying_stepper(const replaying_stepper& o) noexcept : r_(o.r_), copy_(true) {}
    replaying_stepper& operator=(const replaying_stepper& o) noexcept {
        r_ = o.r_;
        copy_ = true;
        return *this;
    }

    template <class System>
    status step(System&, State& y, value_type t, value_type s) {
        using T = value_type;
        if (!copy_) {
            if (r_->calls++ == 0) {
                assign(y, r_->y_e);
                return status::ok;
            }
            r_->restart = true;  // (the engine returns at the event, y the state its actions left)
            return status::stopped_by_event;
        }
        // A re-step from anywhere but the replayed step's start (the rest of a step after an action, were the
        // engine to take it on a copy) cannot be read from this extension: the same restart as above.
        if (!(t == r_->t_s) || !same_values(y, r_->y_s)) {
            r_->restart = true;
            return status::stopped_by_event;
        }
        if (r_->h > T(0) ? s > r_->h : s < r_->h) s = r_->h;
        return r_->state_after(s, y);
    }

private:
    Replayed* r_;
    bool copy_ = false;
};

// The cost the event bounds charge for a replayed step: none (the stepper reads the extension).
template <class T>
struct replay_cost {
    using value_type = T;
    static constexpr std::size_t rhs_evals_per_step = 0;
};

// The record events of a set (their firings are observed).
template <class Set>
struct record_flags;
template <class Finder, class... Events>
struct record_flags<event_set<Finder, Events...>> {
    static constexpr std::array<bool, sizeof...(Events)> value{
        std::is_same_v<std::remove_cv_t<decltype(Events::action)>, record_action>...};
};

// What integrate_adaptive with events observes: the start, each record firing (the event's state, as the
// location found it), every completed step's end (a step cut at an action's event ends there, with the state the
// action left), and the state where the run stopped unless it was the last one observed, time and state bit for
// bit (same_bits: a step that starts at an event can stop at an offset that rounds to the event's time, with a
// state the event's observation was not).
template <class Observer, class State>
struct step_output {
    using T = value_type_t<State>;
    Observer& observe;
    T last = T(0);
    State last_y{};
    status failure = status::ok;
    void see(T t, const State& y) {
        observe(t, y);
        last = t;
        assign(last_y, y);
    }
    void start(T t0, const State& y) { see(t0, y); }
    template <class Replayed>
    void record(T t, const State& y_event, Replayed&) {
        see(t, y_event);
    }
    template <class Replayed>
    void step_end(T t, const State& y, Replayed&) {
        see(t, y);
    }
    template <class Replayed>
    void stopped(T t, const State& y, bool acted, Replayed&) {
        if (acted || !(last == t) || !same_bits(last_y, y)) see(t, y);
    }
};

// What integrate_times with events observes: every time of `times` (inside a step from its extension, at a
// step's end its state), each record firing (after the times before it), and the state where the run stopped
// (a time equal to it gets that state), unless it was the last one observed (time and state).
template <class Observer, class State, class Times>
struct times_output {
    using T = value_type_t<State>;
    Observer& observe;
    const Times& times;
    bool forward;
    std::size_t next = 0;
    T last = T(0);
    State last_y{};
    bool any = false;
    status failure = status::ok;
    void see(T t, const State& y) {
        observe(t, y);
        last = t;
        assign(last_y, y);
        any = true;
    }
    bool before(T a, T b) const { return forward ? a < b : a > b; }
    void start(T t0, const State& y) {
        while (next < times.size() && times[next] == t0) see(times[next++], y);
    }
    // Every time before t inside the replayed step, from its extension.
    template <class Replayed>
    void flush(T t, Replayed& r) {
        State u;
        for (; failure == status::ok && next < times.size() && before(times[next], t); ++next) {
            failure = r.state_at(times[next], u);
            if (failure == status::ok) see(times[next], u);
        }
    }
    template <class Replayed>
    void record(T t, const State& y_event, Replayed& r) {
        flush(t, r);
        if (failure == status::ok) see(t, y_event);
    }
    template <class Replayed>
    void step_end(T t, const State& y, Replayed& r) {
        flush(t, r);
        while (failure == status::ok && next < times.size() && times[next] == t) see(times[next++], y);
    }
    template <class Replayed>
    void stopped(T t, const State& y, bool acted, Replayed& r) {
        flush(t, r);
        if (failure != status::ok) return;
        bool seen = false;
        while (next < times.size() && times[next] == t) {
            see(times[next++], y);
            seen = true;
        }
        if (!seen && (acted || !any || !(last == t) || !same_bits(last_y, y))) see(t, y);
    }
};

// The loop's checks: the engine's settings, the cap, the span, the event limits (their bounds, with the
// replayed step's cost).
template <class Engine, class Set, class T>
status check_free_running(const Engine& engine, const Set& set, T t0, T t1, step_count max_attempts) {
    status s = preflight(engine, t0, t1, max_attempts);
    if (s == status::ok) s = limits_status<replay_cost<T>, typename Set::finder, T>(Set::size, set.limits);
    return s;
}

// THE free-running loop with events, for every engine with a free_extension: attempts until t1 or the cap
// (max_attempts, every attempt counted, accepted or not, whether a step is cut or not); each accepted step
// from (t_s, y_s) to (t_e, y_e) replayed through the event engine on its extension. An action that ran cuts
// the step at its event: y is then the state the action left, the engine restarts there (restart(): its step
// size, controller memory and every carried derivative, FSAL stage or Jacobian, recomputed from the new
// state). The firings inside one step are capped by max_firings_per_step as on the grid; a step cut at an
// event passes what is left of that cap to the steps that start before the cut step's planned end (the
// window), so that firings accumulating in time (a Zeno ball) end with event_limit, as in one grid step.
template <class Engine, class System, class State, class Set, class Output>
event_integrate_result<value_type_t<State>, Set::size> free_running_events(Engine& engine, System& f, State& y,
                                                                           value_type_t<State> t0,
                                                                           value_type_t<State> t1, Set& set,
                                                                           Output& out, step_count max_attempts,
                                                                           status checked) {
    using T = value_type_t<State>;
    // Every evaluation of f counted (the attempts', the interpolant's, the engine's Hermite slopes and headings):
    // the engine's own counters give J, the factorizations, Newton iterations, accepted and rejected steps.
    const counts before = engine_counts(engine);
    evaluation_tally tally;
    auto counted = counting(f, tally);
    using counted_system = decltype(counted);
    using replayed_type = replayed_step<Engine, counted_system, State>;
    using stepper_type = replaying_stepper<replayed_type, State>;
    using engine_type = event_engine<State, 1, Set>;
    constexpr std::size_t E = Set::size;
    engine_type events;
    step_count advances = 0;  // steps handed to the event engine: E evaluations of g each, off its work count
    const auto finish = [&](status s, T t, step_count steps, std::size_t event) {
        event_integrate_result<T, E> r{s, t, steps, event, 0, {}};
        for (std::size_t i = 0; i < E; ++i) {
            r.firings[i] = events.memory[i].fired;
            r.fired += events.memory[i].fired;
        }
        r.counts = engine_work(engine, before, tally);
        r.counts.event_evals = (advances - events.work.failed_steps) * E + events.work.g;
        r.counts.firings = r.fired;
        return r;
    };
    if (checked != status::ok) return finish(checked, t0, 0, no_event);
    const std::array<State*, 1> y_refs{&y};
    const status started = events.begin(set, t0, y_refs);
    if (started != status::ok) return finish(started, t0, 0, no_event);
    out.start(t0, static_cast<const State&>(y));
    if (t0 == t1 && !all_finite(y)) return finish(status::non_finite, t0, 0, no_event);
    replayed_type replayed(engine, counted);
    stepper_type replay(replayed);
    const bool forward = !(t1 < t0);
    const std::size_t cap = set.limits.max_firings_per_step;
    bool window = false;  // a step in which an event fired, and its planned end: the cap covers them together
    T window_end = t0;
    std::size_t used = 0;
    constexpr std::array<bool, E> records = record_flags<std::remove_cv_t<Set>>::value;
    // A record firing is observed at the event's own state (the location's, as a stop at the same time hands
    // back), not read again from the extension at t_event - t_s, which can round to another offset.
    const auto sink = [&](std::size_t, std::size_t i, T t_event, const std::array<State*, 1>& y_event) {
        if (records[i]) out.record(t_event, static_cast<const State&>(*y_event[0]), replayed);
    };
    T t = t0;
    step_count steps = 0;
    for (step_count n = 0; n < max_attempts && t != t1; ++n) {
        const T t_s = t;
        const State y_s = y;
        bool accepted = false;
        status s = engine.attempt(counted, t, y, t1, accepted, replayed.ext.sink());
        if (s != status::ok) return finish(s, t, steps, no_event);
        if (!accepted) continue;
        replayed.begin(t_s, y_s, t, y);
        assign(y, y_s);
        if (window && !(forward ? t_s < window_end : t_s > window_end)) {
            window = false;
            used = 0;
        }
        set.limits.max_firings_per_step = cap - used;
        ++advances;
        const step_outcome<T> o = events.advance(replay, counted, set, y_refs, t_s, replayed.h, replayed.t_e, sink);
        set.limits.max_firings_per_step = cap;
        if (o.fired != 0) {
            if (!window) window_end = replayed.t_e;
            window = true;
            used += o.fired;
        }
        const bool cut = replayed.restart;
        if (out.failure != status::ok) return finish(out.failure, o.t, steps, no_event);
        if (o.code == status::stopped_by_event && !cut) {
            out.stopped(o.t, static_cast<const State&>(y), o.acted, replayed);
            if (out.failure != status::ok) return finish(out.failure, o.t, steps, no_event);
            return finish(status::stopped_by_event, o.t, steps, o.event);
        }
        if (o.code != status::ok && !cut) return finish(o.code, o.t, steps, o.event);
        // A completed step, or one cut at an action's event (o.t; an action at the step's end cuts nothing)
        t = o.t;
        ++steps;
        if (o.acted) {
            // The state (or what f reads) changed: nothing carried from before holds; the step size is kept as
            // the next attempt's guess (its error test judges it), so that events that accumulate in time
            // (a Zeno ball) meet the firing cap instead of an ever smaller estimate meeting step_too_small.
            const T size = engine.step_size();
            engine.restart();
            engine.set_step_size(size);
        }
        out.step_end(t, static_cast<const State&>(y), replayed);
        if (out.failure != status::ok) return finish(out.failure, t, steps, no_event);
    }
    if (t != t1) return finish(status::substep_limit, t, steps, no_event);
    return finish(status::ok, t1, steps, no_event);  // t1 itself: an empty run from -0.0 to +0.0 ends on +0.0
}

// A const set runs on a copy (as integrate's does): its g and actions are called as non-const.
template <class Engine, class System, class State, class Set, class Output>
auto free_running_on(Engine& engine, System& f, State& y, value_type_t<State> t0, value_type_t<State> t1, Set& set,
                     Output& out, step_count max_attempts) {
    const status checked = check_free_running(engine, set, t0, t1, max_attempts);
    if constexpr (std::is_const_v<Set>) {
        std::remove_const_t<Set> copy = set;
        return free_running_events(engine, f, y, t0, t1, copy, out, max_attempts, checked);
    } else {
        return free_running_events(engine, f, y, t0, t1, set, out, max_attempts, checked);
    }
}

template <class Engine, class System, class State, class Set, class Observer>
auto adaptive_with_events(Engine& engine, System& f, State& y, value_type_t<State> t0, value_type_t<State> t1, Set& set,
                          Observer& observe, step_count max_attempts) {
    step_output<Observer, State> out{observe};
    return free_running_on(engine, f, y, t0, t1, set, out, max_attempts);
}

template <class Engine, class System, class State, class Times, class Set, class Observer>
auto times_with_events(Engine& engine, System& f, State& y, value_type_t<State> t0, const Times& times, Set& set,
                       Observer& observe, step_count max_attempts) {
    using T = value_type_t<State>;
    using result = event_integrate_result<T, std::remove_cv_t<Set>::size>;
    T t1 = t0;
    const status s = check_times(engine, t0, times, max_attempts, t1);
    if (s != status::ok || times.size() == 0) return result{s, t0, 0, no_event, 0, {}};
    times_output<Observer, State, Times> out{observe, times, !(t1 < t0)};
    return free_running_on(engine, f, y, t0, t1, set, out, max_attempts);
}

}  // namespace detail

/// The most evaluations of f one free-running run with events can make, for `Engine` (adaptive_rk,
/// radau5, rosenbrock_adaptive, sdirk_adaptive), `events` events with these limits and at most `max_attempts` attempts:
///   A + M (P + A + X + B)
/// with A = 1 + Engine::rhs_evals_to_start (a start, and a restart after an action), P =
/// Engine::rhs_evals_per_attempt, X the extension's completion (dense_step::rhs_evals_to_complete; none for
/// Radau's polynomial and the SDIRK pairs' Hermite ends; 2 for the Rosenbrock pairs' Hermite ends) and B = max_rhs_evals_per_step of a step
/// that costs nothing to re-take (the location reads the extension; B counts f after each action, and with
/// on_interpolant the Hermite slopes). SIZE_MAX when it does not fit std::size_t.
template <class Engine, class Finder = default_root_finder>
constexpr std::size_t max_rhs_evals_free_running(std::size_t events, event_limits limits,
                                                 step_count max_attempts) noexcept {
    using detail::sat_add;
    using detail::sat_mul;
    using T = typename Engine::value_type;
    const std::size_t a = 1 + Engine::rhs_evals_to_start;
    const std::size_t per_step =
        sat_add(sat_add(Engine::rhs_evals_per_attempt, a),
                sat_add(detail::free_extension<Engine>::rhs_evals_to_complete,
                        max_rhs_evals_per_step<detail::replay_cost<T>, Finder, T>(events, limits)));
    const std::size_t m = max_attempts > static_cast<step_count>(detail::count_max)
                              ? detail::count_max
                              : static_cast<std::size_t>(max_attempts);
    return sat_add(a, sat_mul(m, per_step));
}

/// integrate_adaptive with events: the free-running run of `engine` (odestep::adaptive_rk, odestep::radau5,
/// odestep::rosenbrock_adaptive, odestep::sdirk_adaptive) from t0 to t1 (as integrate_adaptive without
/// events) watching `events` (odestep::watch(...)) as integrate does on the grid. Each accepted step is
/// scanned on its own continuous extension: Dormand-Prince 5(4)'s and DOP853's, cubic Hermite for the other
/// explicit pairs; Radau's collocation polynomial and the SDIRK pairs' cubic Hermite interpolant of the
/// step's ends and slopes (no evaluation of f); for the Rosenbrock pairs the cubic Hermite interpolant of the
/// step's ends (f at both, two evaluations, only for a step that probes or locates). A crossing is located
/// to adjacent times of that interpolant and the event's state is its value there. `terminal` stops the run (status::stopped_by_event, `event`, `t`, y the state there);
/// `record` leaves the run bit for bit as without the event, and the observer sees the event's state at its
/// time; a callable action cuts the step at the event: the observer sees the state it left there, and the
/// engine restarts from it (restart(): step size, controller and the kept first stage computed afresh).
/// Each event is armed after an action from the way g heads along f, as on the grid. The observer sees t0,
/// every step's end, every record firing and the state the run stopped at (unless just observed).
///
/// At most max_firings_per_step firings in a step and the steps that start before its planned end (a step
/// cut at an event counts as the whole of it): one more is status::event_limit, with the state before it.
/// Work: at most max_attempts attempts and max_rhs_evals_free_running evaluations of f. Statuses as
/// integrate_adaptive and integrate with events; `steps` counts the completed steps (a cut step counts).
template <class Engine, class System, class Set, class Observer,
          std::enable_if_t<detail::has_free_extension_v<Engine> && detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate_adaptive(Engine& engine, System&& f, typename Engine::state_type& y,
                                      detail::time_t_of<typename Engine::state_type> t0,
                                      detail::time_t_of<typename Engine::state_type> t1, Set&& events,
                                      Observer&& observe, step_count max_attempts = default_max_attempts) {
    return detail::adaptive_with_events(engine, f, y, t0, t1, events, observe, max_attempts);
}

/// integrate_adaptive with events, without an observer.
template <class Engine, class System, class Set,
          std::enable_if_t<detail::has_free_extension_v<Engine> && detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate_adaptive(Engine& engine, System&& f, typename Engine::state_type& y,
                                      detail::time_t_of<typename Engine::state_type> t0,
                                      detail::time_t_of<typename Engine::state_type> t1, Set&& events) {
    detail::no_observer none;
    return detail::adaptive_with_events(engine, f, y, t0, t1, events, none, default_max_attempts);
}

/// integrate_times with events: the free-running run to the last of `times` (as integrate_times), watching
/// `events` as integrate_adaptive with events does. The observer sees every time of `times` up to where the
/// run ends (from the step's extension inside a step, the step's own state at its end; after an action, the
/// trajectory the action left), every record firing at its time (after the times before it), and the state
/// the run stopped at (a time equal to it gets that state). Bounds and statuses as integrate_adaptive with
/// events; invalid_time for bad times as integrate_times; with no times the call does nothing and returns ok.
template <class Engine, class System, class Times, class Set, class Observer,
          std::enable_if_t<detail::has_free_extension_v<Engine> && detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate_times(Engine& engine, System&& f, typename Engine::state_type& y,
                                   detail::time_t_of<typename Engine::state_type> t0, const Times& times, Set&& events,
                                   Observer&& observe, step_count max_attempts = default_max_attempts) {
    return detail::times_with_events(engine, f, y, t0, times, events, observe, max_attempts);
}

}  // namespace odestep

#endif
