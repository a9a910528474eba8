// SPDX-License-Identifier: BSL-1.0
// odestep: the event engine, one step with events as named phases: the quiet step (step and settle), and, when
// settle cannot prove the step quiet, the scan (advance_rest): passes over the step piece by piece (probe), each
// crossing located (location.hpp), its events fired in rounds (fire_rounds, fire_all), and the step's result
// committed to the events' memory (commit) or, after an action, the rest of the step taken again from the event
// (restart).
#ifndef ODESTEP_EVENTS_ENGINE_HPP
#define ODESTEP_EVENTS_ENGINE_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "arming.hpp"
#include "bounds.hpp"
#include "engine_base.hpp"
#include "event.hpp"
#include "location.hpp"

namespace odestep {

namespace detail {

// Runs an action: `terminal` stops, `record` proceeds, a callable is called as action(t, y...) or, if it takes
// one more argument, action(t, y..., crossed), crossed being the direction the crossing went (rising or
// falling: for `either` events, one g with two behaviours, as Julia's affect! and affect_neg!).
template <class State, class Action, class T, std::size_t... I>
constexpr event_result call_action(Action& action, T t, direction crossed, const std::array<State*, sizeof...(I)>& y,
                                   std::index_sequence<I...>) {
    if constexpr (std::is_same_v<Action, stop_action>) {
        (void)action, (void)t, (void)y, (void)crossed;
        return event_result::stop;
    } else if constexpr (std::is_same_v<Action, record_action>) {
        (void)action, (void)t, (void)y, (void)crossed;
        return event_result::proceed;
    } else if constexpr (std::is_invocable_v<Action&, T, decltype(*y[I])..., direction>) {
        using R = std::invoke_result_t<Action&, T, decltype(*y[I])..., direction>;
        if constexpr (std::is_void_v<R>) {
            action(t, *y[I]..., crossed);
            return event_result::proceed;
        } else {
            static_assert(std::is_same_v<R, event_result>,
                          "odestep: an event action returns odestep::event_result or nothing");
            return action(t, *y[I]..., crossed);
        }
    } else {
        static_assert(std::is_invocable_v<Action&, T, decltype(*y[I])...>,
                      "odestep: an event action must be `terminal`, `record`, or callable as "
                      "action(T t, State& y) or action(T t, State& y, direction crossed) (Newtonian: "
                      "action(T t, State& x, State& v[, direction crossed]))");
        (void)crossed;
        using R = std::invoke_result_t<Action&, T, decltype(*y[I])...>;
        if constexpr (std::is_void_v<R>) {
            action(t, *y[I]...);
            return event_result::proceed;
        } else {
            static_assert(std::is_same_v<R, event_result>,
                          "odestep: an event action returns odestep::event_result or nothing");
            return action(t, *y[I]...);
        }
    }
}
// What a step changes in a stepper besides the state: nothing, or, for a stepper that publishes it as memory()
// (the library's Adams methods, Beeman, the predictor-corrector, half-step, the position-form leapfrog, the
// first-same-as-last splittings), its history or kept acceleration. It is kept from before the step, so that a
// step the engine rolls back to its start (a failure seen after the stepper stepped: g not finite at the step's
// end, at a probe or in a location) leaves the stepper as it was, and the next call goes on as if the failed one
// had not happened. A stepper without memory() keeps nothing and pays nothing; one that has reset() (a user's
// stepper) is reset after a roll-back, as after any step that does not end where the stepper expects. (The C
// API's adapters publish memory(): src/capi_events_impl.hpp.)
template <class S, class = void>
struct has_step_memory : std::false_type {};
template <class S>
struct has_step_memory<S, std::void_t<decltype(std::declval<S&>().restore_memory(std::declval<const S&>().memory()))>>
    : std::true_type {};

template <class Stepper, bool = has_step_memory<Stepper>::value>
class stepper_memory {
public:
    ODESTEP_INLINE explicit stepper_memory(const Stepper& s) : kept_(s.memory()) {}
    // true: the stepper is as before the step
    bool restore(Stepper& s) const {
        s.restore_memory(kept_);
        return true;
    }

private:
    decltype(std::declval<const Stepper&>().memory()) kept_;
};
template <class Stepper>
class stepper_memory<Stepper, false> {
public:
    ODESTEP_INLINE explicit constexpr stepper_memory(const Stepper&) noexcept {}
    constexpr bool restore(Stepper&) const noexcept { return false; }
};

// The event loop's state and its one step with events; integrate with events and event_stepper both use it.
// K is the number of state objects (1: y; 2: x and v).
template <class State, std::size_t K, class Set>
class event_engine;

template <class State, std::size_t K, class Finder, class... Events>
class event_engine<State, K, event_set<Finder, Events...>>
    : public event_location<State, K, event_set<Finder, Events...>> {
    using base = event_location<State, K, event_set<Finder, Events...>>;

public:
    using base::all_armed;
    using base::E;
    using base::interpolates;
    using base::memory;
    using base::work;
    using typename base::pack;
    using typename base::refs;
    using typename base::set_type;
    using typename base::slopes;
    using typename base::T;
    using typename base::values;

    // Checks the settings and evaluates every g at the start. An event whose g is zero there is not armed.
    template <class Ptrs>
    status begin(set_type& set, T t0, const Ptrs& y) {
        if (!settings_valid(set)) return status::invalid_tolerance;
        values g{};
        if (!evaluate_all(set, t0, y, g)) return status::non_finite_event;
        for (std::size_t i = 0; i < E; ++i) memory[i] = event_memory<T>{g[i], t0, t0, 0, false, true};
        rearm(set, t0, g);
        return status::ok;
    }

    // After the caller changed the state: every g read again at t, and every event disarmed and then armed
    // by the usual rule, so a crossing is measured from the new values and the firing counts, max_firings
    // and the dead time still hold. On a failure nothing is changed.
    template <class Ptrs>
    status reread(set_type& set, T t, const Ptrs& y) {
        if (!settings_valid(set)) return status::invalid_tolerance;
        values g{};
        if (!evaluate_all(set, t, y, g)) return status::non_finite_event;
        for (std::size_t i = 0; i < E; ++i) {
            memory[i].g = g[i];
            memory[i].until = t;
            memory[i].armed = false;
        }
        rearm(set, t, g);
        return status::ok;
    }

    // One step of h from (t_s, y) to t_end (t_end = t_s + h, with t_end from the caller's counter), with
    // every event it contains located, fired and acted on; the result's t is the time of y. sink(k, i, t) is
    // told the k-th firing inside the step (k from 0): event i at t; sink(k, i, t, y), if it takes it, also the
    // event's state there (before the event's own action).
    template <class Stepper, class System, class Sink>
    step_outcome<T> advance(Stepper& stepper, System& f, set_type& set, refs y, T t_s, T h, T t_end, Sink sink) {
        pack start;
        const stepper_memory<Stepper> before(stepper);
        const status s = step(stepper, f, y, t_s, h, start);
        if (ODESTEP_UNLIKELY(s != status::ok)) {
            ++work.failed_steps;
            return {s, t_s, 0, no_event};
        }
        values g;
        if (ODESTEP_UNLIKELY(!settle(set, y, t_end, g)))
            return advance_rest(stepper, before, f, set, y, start, g, t_s, h, t_end, sink);
        return {status::ok, t_end, 0, no_event};
    }

    // advance in three parts. The first two, inlined into the caller, are the step with nothing in it: step
    // takes the step, keeping y's state before it in start (the rollback, and the start of the re-steps that
    // locate an event); y is untouched if it fails. settle evaluates every g once at the step's end (into g)
    // and proves, with one test, that nothing happened: then the events' memory is updated and the answer
    // is true. Otherwise (a crossing, probes, a NaN or Inf from g, or a test that cannot tell) it is false,
    // and advance_rest, out of line, takes over from there: its buffers and registers cost a quiet step
    // nothing.
    template <class Stepper, class System>
    ODESTEP_INLINE static status step(Stepper& stepper, System& f, const refs& y, T t_s, T h, pack& start) {
        load(y, start);
        return call_step(stepper, f, y, t_s, h, seq{});
    }

    ODESTEP_INLINE bool settle(set_type& set, const refs& y, T t_end, values& g) {
        evaluate(set, t_end, y, g);
        if (ODESTEP_UNLIKELY(!quiet(set, g))) return false;
        remember(set, g);
        if (!all_armed) {
            const values copy = g;  // (rearm's reference to a copy: g itself can stay in registers)
            rearm(set, t_end, copy);
        }
        return true;
    }

    // settle when the caller knows every event armed and no probes (all_armed): the quiet test is then one
    // product per event, and nothing needs arming after it. The caller keeps all_armed in view (event_stepper
    // takes this path only while it holds).
    ODESTEP_INLINE bool settle_armed(set_type& set, const refs& y, T t_end, values& g) {
        evaluate(set, t_end, y, g);
        if (ODESTEP_UNLIKELY(!same_sides(g, events_seq{}))) return false;
        remember(set, g);
        return true;
    }

    // The rest of advance, after settle returned false (start, g and before as step and settle left them):
    // every crossing inside the step located, fired and acted on; after a callable action, the rest of the step
    // again from the event. Any outcome but ok leaves y somewhere other than the regular step's end. Rolled
    // back to the step's start (nothing committed, no action run), the stepper gets its memory from before the
    // step back (before): it fits y there. Anywhere else the stepper is reset (its history, or a kept
    // acceleration, belongs to another state).
    template <class Stepper, class System, class Sink>
    ODESTEP_EVENTS_NOINLINE step_outcome<T> advance_rest(Stepper& stepper, const stepper_memory<Stepper>& before,
                                                         System& f, set_type& set, refs y, pack& start, values g_end,
                                                         T t_s, T h, T t_end, Sink sink) {
        bool at_start = false;
        const step_outcome<T> o = scan(stepper, f, set, y, start, g_end, t_s, h, t_end, sink, at_start);
        if (o.code != status::ok) {
            if (!(at_start && before.restore(stepper))) reset_if_any(stepper);
        }
        return o;
    }

private:
    using base::all_finite_pack;
    using base::any_crossing;
    using base::evaluate;
    using base::evaluate_all;
    using base::finite_values;
    using base::for_each;
    using base::hermite_ends;
    using base::load;
    using base::locate;
    using base::pointers;
    using base::state_at;
    using base::store;
    using base::time_at;
    using typename base::events_seq;
    using typename base::seq;

    // What a step's scan carries from phase to phase: the pass (from t_s, with the state start, to t_end),
    // the firings so far, and the states of the scan: lo_state at lo (also the state before an action, once
    // lo is no longer needed), hi_state at a probe, a_state and b_state at the ends of a location's bracket.
    struct scan_state {
        scan_state(refs y_end, pack& pass_start, T t_start, T length, T t_step_end)
            : y(y_end), start(pass_start), t_s(t_start), h(length), t_end(t_step_end), step_h(length) {}
        refs y;
        pack& start;
        T t_s;
        T h;             // the pass's length (the rest of the step after an action)
        const T t_end;   // the step's end, from the caller's counter
        const T step_h;  // the step's length
        std::size_t fired_here = 0;
        std::size_t located = 0;  // locations in this step, firing or not: at most max_firings_per_step
        bool partial = false;     // the pass began at an event
        bool acted = false;       // a callable action ran in this step
        bool moved = false;       // the events' memory was committed past the step's start (lo moved)
        // The step's outcome, once a phase ends it (with fired_here and acted).
        status code = status::ok;
        T t_out = T(0);
        std::size_t event = no_event;
        pack lo_state;
        pack hi_state;
        pack a_state;
        pack b_state;
        slopes d;  // (on the interpolant) the pass's slopes, computed when it first probes or locates

        T at(T u) const noexcept { return time_at(t_s, u, h, t_end); }
        // Ends the step: always false (the phases return `end(...)` for "the scan stops here").
        bool end(status ended_with, T t, std::size_t which) noexcept {
            code = ended_with;
            t_out = t;
            event = which;
            return false;
        }
        // Ends the step back at the last good state, at t_good.
        bool fail(const pack& good, T t_good, status failure) {
            store(y, good);
            return end(failure, t_good, no_event);
        }
    };
    // How a location ends: the scan goes on from b, or the step restarts from the event, or the step ends.
    enum class after_location : unsigned char { scan_on, restart, end };

    // The scan: one pass per restart (the first, and one after each location whose action ran).
    // at_start: the step ended with y its own start, at t_s, the events' memory as before it (nothing
    // committed, nothing fired).
    template <class Stepper, class System, class Sink>
    step_outcome<T> scan(Stepper& stepper, System& f, set_type& set, refs y, pack& start, values g_end, T t_s, T h,
                         T t_end, Sink& sink, bool& at_start) {
        scan_state c(y, start, t_s, h, t_end);
        while (pass(stepper, f, set, c, g_end, sink)) {
            if (c.h == T(0)) {  // the event was at the step's end
                c.end(status::ok, t_end, no_event);
                break;
            }
            c.partial = true;
        }
        step_outcome<T> o{c.code, c.t_out, c.fired_here, c.event};
        o.acted = c.acted;
        // A stop at an offset that rounds to t_s (under half an ULP of it) with a state other than the start's:
        // a state the observation at t_s was not, to be observed as after an action.
        if (c.code == status::stopped_by_event && !c.acted && c.t_out == t_s) {
            for (std::size_t k = 0; k < K; ++k) o.acted = o.acted || !same_bits(start[k], *y[k]);
        }
        at_start = !c.partial && !c.moved && c.fired_here == 0 && !c.acted && c.t_out == t_s;
        return o;
    }

    // One pass over (t_s, t_end]: true when an action restarted it (c.t_s the event's time, c.h the rest of
    // the step), false when the step is over (c.code, c.t_out, c.event).
    template <class Stepper, class System, class Sink>
    bool pass(Stepper& stepper, System& f, set_type& set, scan_state& c, values& g_end, Sink& sink) {
        if constexpr (interpolates) c.d.ready = false;
        // Crossings this close after an event's last firing (or the start) are the same crossing.
        const T same_root = T(4) * std::numeric_limits<T>::epsilon() * (abs_value(c.t_s) + abs_value(c.h));
        if (c.partial && !rest_of_step(stepper, f, set, c, g_end)) return false;
        if (!finite_values(g_end)) return c.fail(c.start, c.t_s, status::non_finite_event);
        const std::size_t pieces = set.limits.probes + 1;  // (the limits are checked: no wrap)
        // Nothing crossed and no probes: remember the values and go on.
        if (pieces == 1 && !any_crossing(set, g_end)) {
            commit(set, c.t_end, g_end);
            return finish_pass(stepper, c);
        }
        // Scan (0, h] piece by piece (the pieces end at the probes and at h). lo is where the events' memory
        // was last updated; lo_state the state there.
        T lo = T(0);
        c.lo_state = c.start;
        // The probes and the location's re-steps go from the step's start on a copy of the stepper, reset
        // before each (its history, if any, belongs to the regular steps).
        Stepper scratch = stepper;
        for (std::size_t k = 1; k <= pieces; ++k) {
            T hi = c.h;
            refs hi_refs = c.y;  // the state at hi: y at the step's end, hi_state at a probe
            values g_hi = g_end;
            if (k < pieces) {
                hi = c.h * static_cast<T>(k) / static_cast<T>(pieces);
                hi_refs = pointers(c.hi_state);
                if (!probe(scratch, f, set, c, lo, hi, g_hi)) return false;
            }
            // Every firing inside (lo, hi], one location at a time.
            while (any_crossing(set, g_hi)) {
                const after_location next =
                    fire_next(stepper, scratch, f, set, c, lo, hi, hi_refs, g_hi, same_root, sink);
                if (next == after_location::end) return false;
                if (next == after_location::restart) return true;
            }
            if (!(lo == hi)) {  // (a location that ended at hi left the memory with the values read there)
                lo = hi;
                c.moved = true;
                load(hi_refs, c.lo_state);
                commit(set, c.at(hi), g_hi);
            }
        }
        return finish_pass(stepper, c);
    }

    // A pass after an action: the rest of the step from the event (start, t_s) to t_end, and every g there.
    template <class Stepper, class System>
    bool rest_of_step(Stepper& stepper, System& f, set_type& set, scan_state& c, values& g_end) {
        load(c.y, c.start);
        const status s = call_step(stepper, f, c.y, c.t_s, c.h, seq{});
        ++work.steps;
        if (s != status::ok) return c.end(s, c.t_s, no_event);
        evaluate(set, c.t_end, c.y, g_end);
        work.g += E;
        return true;
    }

    // A probe: the state at hi (hi_state) and every g there. NaN or Inf ends the step at lo.
    template <class Stepper, class System>
    bool probe(Stepper& scratch, System& f, set_type& set, scan_state& c, T lo, T hi, values& g_hi) {
        const status ps = state_at(scratch, f, c.start, c.y, c.d, c.t_s, hi, c.h, c.t_end, c.hi_state);
        if (ps != status::ok) return c.fail(c.lo_state, c.at(lo), ps);
        if (!evaluate_all(set, c.at(hi), pointers(c.hi_state), g_hi))
            return c.fail(c.lo_state, c.at(lo), status::non_finite_event);
        return true;
    }

    // One location in (lo, hi]: the earliest crossing located (locate: [a, b] with b - a within tolerance), its
    // events fired (fire_rounds), and then the rest of the step restarted from the event if an action ran
    // (restart), or else the step's own result kept up to b (lo moves to b). A step makes at most
    // max_firings_per_step locations, whether they fire or not: with an event function that is not a pure
    // function of (t, y) (a sensor), a crossing seen at hi can vanish when location reads g again, and without
    // this count the scan would start over for ever.
    template <class Stepper, class System, class Sink>
    after_location fire_next(Stepper& stepper, Stepper& scratch, System& f, set_type& set, scan_state& c, T& lo, T hi,
                             const refs& hi_refs, const values& g_hi, T same_root, Sink& sink) {
        if (c.located >= set.limits.max_firings_per_step)
            return ended(c.fail(c.lo_state, c.at(lo), status::event_limit));
        ++c.located;
        T a = lo;
        T b = hi;
        load(hi_refs, c.b_state);
        values g_b = g_hi;
        const status ls = locate(scratch, f, set, c.start, c.y, c.d, c.t_s, c.h, c.t_end, lo, c.lo_state, a, b,
                                 c.a_state, c.b_state, g_b);
        if (ls != status::ok) return ended(c.fail(c.lo_state, c.at(lo), ls));
        const T t_star = c.at(a);
        const T t_b = c.at(b);
        // Every g at the event's state, so that the state before an action (the roll-back target if the
        // action fails) is one where every g is finite. At lo they are the memory's.
        values g_cross = g_b;
        if constexpr (!actions_keep_state) {
            if (a == lo) {
                for (std::size_t i = 0; i < E; ++i) g_cross[i] = memory[i].g;
            } else if (!evaluate_all(set, t_star, pointers(c.a_state), g_cross)) {
                return ended(c.fail(c.lo_state, c.at(lo), status::non_finite_event));
            }
        }
        bool acted_here = false;
        const values g_before = g_cross;  // every g at t* before the actions (headings compares)
        if (!fire_rounds(set, c, t_star, t_b, same_root, g_b, g_cross, sink, acted_here)) return after_location::end;
        if (acted_here) {
            return restart(stepper, f, set, c, t_star, t_b, g_before, g_cross) ? after_location::restart
                                                                               : after_location::end;
        }
        // No action ran (record events only, or nothing fired): the step's own result stands; the scan goes
        // on from b.
        lo = b;
        c.moved = true;
        c.lo_state = c.b_state;
        commit(set, t_b, g_b);
        return after_location::scan_on;
    }
    static constexpr after_location ended(bool) noexcept { return after_location::end; }

    // The firings of one location, at t* with the integrator's state there (a_state), in rounds: each round
    // (fire_all) fires, in the order given, every armed event that has crossed. From here on lo_state is
    // free: it holds the state before each round of actions. An action may move the state across (or onto)
    // another event's zero: that event fires too, at the same time, in the next round. Each round fires at
    // least one event, and each event fires once in a location: at most E rounds. False when the step ends
    // (a stop, the firing limit, a NaN or Inf); acted_here: a callable ran, and g_cross is every g after it.
    template <class Sink>
    bool fire_rounds(set_type& set, scan_state& c, T t_star, T t_b, T same_root, const values& g_b, values& g_cross,
                     Sink& sink, bool& acted_here) {
        values after = g_b;  // the values the crossings are measured to
        for (;;) {
            if constexpr (!actions_keep_state) c.lo_state = c.a_state;
            std::size_t stop_index = no_event;
            bool limited = false;
            bool acted_now = false;
            fire_all(set, t_star, t_b, c.step_h > T(0), same_root, pointers(c.a_state), after, sink, c.fired_here,
                     stop_index, limited, acted_now);
            c.acted = c.acted || acted_now;
            if constexpr (!actions_keep_state) {
                if (!all_finite_pack(c.a_state)) return c.fail(c.lo_state, t_star, status::non_finite);
            }
            if (stop_index != no_event || limited) {
                store(c.y, c.a_state);
                return c.end(limited ? status::event_limit : status::stopped_by_event, t_star, stop_index);
            }
            if constexpr (actions_keep_state) {
                return true;
            } else {
                if (!acted_now) return true;
                acted_here = true;
                if (!evaluate_all(set, t_star, pointers(c.a_state), g_cross))
                    return c.fail(c.lo_state, t_star, status::non_finite_event);
                after = g_cross;
                if (!any_crossing(set, g_cross)) return true;
            }
        }
    }

    // After an action at t* (a_state the state the actions left, g_cross every g there; it may have changed
    // the state, or only a parameter the right-hand side reads): each event armed from what the state does
    // next (headings), the state handed back, and the pass restarted from the event (t_s = t*, h the rest of
    // the step). False when the step ends: f not finite after the action (as when the rest of the step's first
    // stage meets it: non_finite at the event, with the state the action left).
    template <class Stepper, class System>
    bool restart(Stepper& stepper, System& f, set_type& set, scan_state& c, T t_star, T t_b, const values& g_before,
                 const values& g_cross) {
        values g_next = g_cross;
        if (!headings(f, set, t_star, t_b, c.step_h, c.a_state, g_before, g_next)) {
            store(c.y, c.a_state);
            return c.end(status::non_finite, t_star, no_event);
        }
        store(c.y, c.a_state);
        commit(set, t_star, g_next);
        reset_if_any(stepper);  // a history or a kept acceleration belongs to the old state
        c.t_s = t_star;
        c.h = c.t_end - t_star;
        return true;
    }

    // The pass reached the step's end. A pass that began at an event took a partial step: a history built on
    // it would not fit the next regular step, so a multistep method starts afresh.
    template <class Stepper>
    static bool finish_pass(Stepper& stepper, scan_state& c) {
        if (c.partial) reset_if_any(stepper);
        return c.end(status::ok, c.t_end, no_event);
    }

    // The values g at t become the events' memory (crossings are measured from them next), and the events
    // that may fire again are armed.
    void commit(const set_type& set, T t, const values& g) {
        for (std::size_t i = 0; i < E; ++i) memory[i].g = g[i];
        rearm(set, t, g);
    }

    // record and terminal leave the state alone: with only those, a firing never restarts the step, and the
    // state before the actions needs no copy.
    template <class Ev>
    static constexpr bool keeps_state_v = std::is_same_v<std::remove_cv_t<decltype(Ev::action)>, record_action> ||
                                          std::is_same_v<std::remove_cv_t<decltype(Ev::action)>, stop_action>;
    static constexpr bool actions_keep_state = (keeps_state_v<Events> && ...);

    // The quiet step's test: true only if every g is finite and no event crossed; false when it cannot tell
    // (advance_rest decides then). With every event armed and no probes (all_armed) it is one product per
    // event: g before times g now is positive only when both are strictly on the same side of zero, which no
    // direction counts as a crossing (a product that underflows to zero only sends the step to the full
    // test); and one finiteness test of the plain sum of the g (finite_sum: an overflowed sum only sends the
    // step on, too), the test the steps make of a state (where g reads the state's components, the compiler
    // may find it already made).
    ODESTEP_INLINE bool quiet(const set_type& set, const values& g) const {
        if (all_armed) return same_sides(g, events_seq{});
        if (set.limits.probes != 0) return false;
        return finite_sum(sum_of(g, events_seq{})) && !any_crossing(set, g);  // finite_sum proves every g finite
    }

    // (Folds over compile-time indices, not for_each's lambdas, here and in remember: at -Os GCC left each
    // lambda a call with its closure built on the stack, on the quiet tick's path.
    // g then stays in registers.)
    template <std::size_t... I>
    ODESTEP_INLINE bool same_sides(const values& g, std::index_sequence<I...>) const {
        return ((memory[I].g * g[I] > T(0)) && ...) && finite_sum(sum_of(g, events_seq{}));
    }
    template <std::size_t... I>
    ODESTEP_INLINE static T sum_of(const values& g, std::index_sequence<I...>) {
        T sum = g[0];
        ((I > 0 ? (void)(sum += g[I]) : (void)0), ...);
        return sum;
    }

    // The g values become the events' memory: crossings are measured from them next.
    ODESTEP_INLINE void remember(const set_type&, const values& g) { remember_each(g, events_seq{}); }
    template <std::size_t... I>
    ODESTEP_INLINE void remember_each(const values& g, std::index_sequence<I...>) {
        ((memory[I].g = g[I]), ...);
    }

    static constexpr bool valid_setting(T v) noexcept { return is_finite(v) && !(v < T(0)); }

    static bool settings_valid(const set_type& set) {
        bool ok = true;
        for_each(set, [&](auto, const auto& e) {
            ok = ok && valid_setting(e.tolerance) && valid_setting(e.band) && valid_setting(e.dead_time);
        });
        return ok;
    }

    // Arms the events that may fire again: g seen beyond the band, the dead time over, firings left.
    void rearm(const set_type& set, T t, const values& g) {
        bool all = true;
        for_each(set, [&](auto index, const auto& e) {
            constexpr std::size_t i = decltype(index)::value;
            event_memory<T>& m = memory[i];
            if (!m.armed) {
                const bool quiet_now = e.max_firings != 0 && m.fired >= e.max_firings;
                const bool rested = m.fired == 0 || !(abs_value(t - m.last) < e.dead_time);
                if (!quiet_now && rested && abs_value(g[i]) > e.band) m.armed = true;
            }
            all = all && m.armed;
        });
        all_armed = all && set.limits.probes == 0;
    }

    // What the state does next after the actions at t* (y the state after them, g every g there): for each
    // event, the sign of g(t* + d, y + d y') - g(t*, y), the change of g along the tangent (one evaluation of
    // f; d = sqrt(eps) h, the forward difference's step that balances truncation against rounding), which is
    // the sign of dg/dt along f wherever that is not zero (exact for a g linear in y, such as a height). The sign before the event is the wrong guide
    // (OrdinaryDiffEq.jl #469: a bounce turns a downcrossing into an upcrossing), and so is g a little later
    // (a bounce's next landing can come sooner than any representable time after t*). Then:
    //   - an event that fired at this location (bracket end t_b) is `through` when g heads the way its
    //     crossing went (a dose on a time event) and not when the action turned it back (a bounce): see
    //     fire_all;
    //   - an event left at g exactly zero (a bounce located exactly on the floor) is measured from the side
    //     it heads to (g becomes the least normal T of that sign: a subnormal would be zero under flush-to-zero), so that rearm arms it at once and a
    //     second landing in the same step is seen; without it, it would wait for |g| > 0 at a step's end.
    // A change that is zero, NaN or Inf (the extrapolation is no state of the run) tells nothing: the event
    // keeps the rules it had without this. False if f itself is NaN or Inf at (t*, y): as from a step, the
    // caller rolls back (the rest of the step would start with that very evaluation).
    template <class System>
    ODESTEP_EVENTS_NOINLINE bool headings(System& f, set_type& set, T t_star, T t_b, T h, const pack& y,
                                          const values& g_before, values& g) {
        pack slope;
        work.rhs += 1;
        if constexpr (K == 1) {
            odestep::detail::evaluate(f, t_star, y[0], slope[0]);
        } else {
            slope[0] = y[1];
            slope[1] = acceleration(f, t_star, y[0], y[1]);
        }
        if (!all_finite_pack(slope)) return false;
        const T d = std::sqrt(std::numeric_limits<T>::epsilon()) * h;
        pack ahead;
        for (std::size_t k = 0; k < K; ++k)
            for (std::size_t n = 0; n < y[k].size(); ++n) ahead[k][n] = y[k][n] + d * slope[k][n];
        values g_ahead;
        evaluate(set, t_star + d, pointers(ahead), g_ahead);
        work.g += E;
        for (std::size_t i = 0; i < E; ++i) {
            event_memory<T>& m = memory[i];
            // (m.g is still the value before the crossing: it went from m.g's side to the other)
            const bool fired_here = m.fired != 0 && m.last == t_star && m.until == t_b;
            // An action that moved g back, farther to the side before the crossing than it was at t*, made
            // any later crossing a new one, even inside this firing's bracket (which the finder's cap can
            // leave wide): not through, whatever g does next.
            const bool moved_back =
                fired_here && (m.g < T(0) ? g[i] < g_before[i] && g[i] < T(0) : g[i] > g_before[i] && g[i] > T(0));
            if (moved_back) m.through = false;
            const T change = g_ahead[i] - g[i];
            if (!is_finite(change) || change == T(0)) continue;
            if (fired_here && !moved_back) m.through = m.g < T(0) ? change > T(0) : change < T(0);
            if (g[i] == T(0)) g[i] = change > T(0) ? std::numeric_limits<T>::min() : -std::numeric_limits<T>::min();
        }
        return true;
    }

    // Fires, in order, the armed events that have crossed by b (g_b), at t* on the state y_star; t_b is the
    // time of b, the end of the bracket. A crossing located within the event's tolerance after its `until`
    // (its last firing's bracket end, or the start or rearm), with its bracket ending within twice that, is
    // that firing's own (an action that moved the state but not g) or a zero at the start (a run begun at a
    // stopped_by_event state): it does not fire, unless the firing's action turned g back (through).
    // acted: a callable action ran (whether it stopped the run or not).
    template <class Sink>
    void fire_all(set_type& set, T t_star, T t_b, bool forward, T same_root, const refs& y_star, const values& g_b,
                  Sink& sink, std::size_t& fired_here, std::size_t& stop_index, bool& limited, bool& acted) {
        for_each(set, [&](auto index, auto& e) {
            using Ev = std::remove_reference_t<decltype(e)>;
            constexpr std::size_t i = decltype(index)::value;
            if (stop_index != no_event || limited) return;
            event_memory<T>& m = memory[i];
            if (!(m.armed && crosses(e.direction, m.g, g_b[i]))) return;
            // The same crossing as the last firing (or a zero at the start): located within the window after
            // until, its whole bracket too (a bracket the finder's cap left wide may hold a later root: it fires).
            const T window = max_value(e.tolerance, same_root);
            const bool same = forward ? !(t_star > m.until + window) && !(t_b > m.until + T(2) * window)
                                      : !(t_star < m.until - window) && !(t_b < m.until - T(2) * window);
            if (m.through && same) return;
            if (fired_here >= set.limits.max_firings_per_step) {
                limited = true;
                return;
            }
            m.armed = false;
            all_armed = false;
            m.fired += 1;
            m.last = t_star;
            m.until = t_b;
            m.through = true;  // (set_headings decides after an action)
            if constexpr (std::is_invocable_v<Sink&, std::size_t, std::size_t, T, const refs&>) {
                sink(fired_here, i, t_star, y_star);  // (the free-running loops observe a record at its state)
            } else {
                sink(fired_here, i, t_star);
            }
            fired_here += 1;
            // The direction the crossing went: from below zero, rising; from above, falling.
            const direction crossed = m.g < T(0) ? direction::rising : direction::falling;
            // acted: a callable ran, whether it stops the run or not (a stopping action may have changed the
            // state too: the run then hands back, and the observer sees, the state it left)
            if constexpr (!keeps_state_v<Ev>) acted = true;
            if (call_action<State>(e.action, t_star, crossed, y_star, seq{}) == event_result::stop) stop_index = i;
        });
    }
};

struct no_sink {
    template <class T>
    constexpr void operator()(std::size_t, std::size_t, T) const noexcept {}
};

// How many state objects an event set's functions take: g(t, y) is 1, g(t, x, v) is 2.
template <class State, class Event>
constexpr std::size_t event_arity() noexcept {
    using T = value_type_t<State>;
    if constexpr (std::is_invocable_v<decltype(std::declval<Event&>().g)&, T, const State&>) {
        return 1;
    } else {
        static_assert(std::is_invocable_v<decltype(std::declval<Event&>().g)&, T, const State&, const State&>,
                      "odestep: an event function must be callable as g(T t, const State& y) (Newtonian: "
                      "g(T t, const State& x, const State& v)) and return T");
        return 2;
    }
}

template <class Stepper>
constexpr void require_self_starting() noexcept {
    static_assert(std::remove_reference_t<Stepper>::self_starting,
                  "odestep: events need a stepper whose state at a step's end is the state at that time; a "
                  "staggered method (Boris: v half a step behind) cannot be re-stepped to an event");
}

}  // namespace detail

}  // namespace odestep

#endif
