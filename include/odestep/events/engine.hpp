// SPDX-License-Identifier: BSL-1.0
// odestep: the event engine, one step with events as named phases: the quiet step (step and settle), the scan of the
// step piece by piece (probes), the location of the earliest crossing by re-stepping (locate), the firing of
// the cascade (fire_all), and the restart of the rest of the step after an action (scan's passes).
#ifndef ODESTEP_EVENTS_ENGINE_HPP
#define ODESTEP_EVENTS_ENGINE_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../detail/hermite.hpp"
#include "../detail/ops.hpp"
#include "../integrate.hpp"
#include "../roots/bracket.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "arming.hpp"
#include "bounds.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {

template <class State, class G, class T, class Ptrs, std::size_t... I>
constexpr T call_g(G& g, T t, const Ptrs& y, std::index_sequence<I...>) {
    return static_cast<T>(g(t, static_cast<const State&>(*y[I])...));
}

template <class S, class System, class State, class T, std::size_t... I>
constexpr status call_step(S& stepper, System& f, const std::array<State*, sizeof...(I)>& y, T t, T h,
                           std::index_sequence<I...>) {
    return stepper.step(f, *y[I]..., t, h);
}

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

// The event loop's state and its one step with events; integrate with events and event_stepper both use it.
// K is the number of state objects (1: y; 2: x and v).
template <class State, std::size_t K, class Set>
class event_engine;

template <class State, std::size_t K, class Finder, class... Events>
class event_engine<State, K, event_set<Finder, Events...>> {
public:
    using T = value_type_t<State>;
    using set_type = event_set<Finder, Events...>;
    static constexpr std::size_t E = sizeof...(Events);
    using pack = std::array<State, K>;
    using refs = std::array<State*, K>;
    using values = std::array<T, E>;

    // Located on the interpolant (on_interpolant): the Hermite slopes at a pass's two ends.
    static constexpr bool interpolates = locates_on_interpolant_v<Finder>;
    struct hermite_slopes {
        pack d0;             // the derivative at the pass's start (Newtonian: v and a)
        pack d1;             // and at its end
        bool ready = false;  // computed in this pass
    };
    struct no_slopes {};  // (re-stepping: nothing, and nothing on the stack)
    using slopes = std::conditional_t<interpolates, hermite_slopes, no_slopes>;

    std::array<event_memory<T>, E> memory{};
    // Every event is armed and the set has no probes: the quiet step's test is then one product per event.
    // Kept by rearm (which reads the probes: a change of set.limits.probes takes effect at the next rearm)
    // and fire_all; read by the quiet step's test.
    bool all_armed = false;
    // The work done off the quiet path, counted where it is done (the loops derive the quiet step's: one step
    // call and E evaluations of g): step calls that failed in advance, re-step calls (location, probes, the
    // rest of a step after an action), evaluations of f made directly (Hermite slopes, headings), and
    // evaluations of g (the start's, and every one off the quiet path).
    struct rest_work {
        step_count failed_steps = 0;
        step_count steps = 0;
        step_count rhs = 0;
        step_count g = 0;
    };
    rest_work work{};

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
    // told the k-th firing inside the step (k from 0): event i at t.
    template <class Stepper, class System, class Sink>
    step_outcome<T> advance(Stepper& stepper, System& f, set_type& set, refs y, T t_s, T h, T t_end, Sink sink) {
        pack start;
        const status s = step(stepper, f, y, t_s, h, start);
        if (ODESTEP_UNLIKELY(s != status::ok)) {
            ++work.failed_steps;
            return {s, t_s, 0, no_event};
        }
        values g;
        if (ODESTEP_UNLIKELY(!settle(set, y, t_end, g)))
            return advance_rest(stepper, f, set, y, start, g, t_s, h, t_end, sink);
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

    // The rest of advance, after settle returned false (start and g as step and settle left them): every
    // crossing inside the step located, fired and acted on; after a callable action, the rest of the step
    // again from the event. Any outcome but ok leaves y somewhere other than the regular step's end: the
    // stepper is reset then (its history, or a kept acceleration, belongs to that step).
    template <class Stepper, class System, class Sink>
    ODESTEP_EVENTS_NOINLINE step_outcome<T> advance_rest(Stepper& stepper, System& f, set_type& set, refs y,
                                                         pack& start, values g_end, T t_s, T h, T t_end, Sink sink) {
        const step_outcome<T> o = scan(stepper, f, set, y, start, g_end, t_s, h, t_end, sink);
        if (o.code != status::ok) reset_if_any(stepper);
        return o;
    }

private:
    // The time of the point s into a step from t_s (s in [0, h]): t_s + s, except that the step's end is
    // t_end itself (from the caller's counter, which t_s + h can miss by an ULP: the step's end is then read
    // at one time by the quiet test and at another by the location, and a crossing between the two is seen
    // and not found), and no time lies past t_end.
    static T time_at(T t_s, T s, T h, T t_end) noexcept {
        if (s == h) return t_end;
        const T t = t_s + s;
        return (h > T(0) ? t > t_end : t < t_end) ? t_end : t;
    }

    template <class Stepper, class System, class Sink>
    step_outcome<T> scan(Stepper& stepper, System& f, set_type& set, refs y, pack& start, values g_end, T t_s, T h,
                         T t_end, Sink& sink) {
        status s = status::ok;
        std::size_t fired_here = 0;
        std::size_t located = 0;  // locations in this step, firing or not: at most max_firings_per_step
        bool partial = false;
        bool acted = false;
        const std::size_t pieces = set.limits.probes + 1;  // (the limits are checked: no wrap)
        const auto at = [&](T u) { return time_at(t_s, u, h, t_end); };
        const auto outcome = [&](status code, T t, std::size_t event) {
            step_outcome<T> o{code, t, fired_here, event};
            o.acted = acted;
            return o;
        };
        // Back to the last good state, at t_good.
        const auto fail = [&](const pack& good, T t_good, status code) {
            store(y, good);
            return outcome(code, t_good, no_event);
        };
        // The states of the scan: lo_state at lo (also the state before an action, once lo is no longer
        // needed), hi_state at a probe, a_state and b_state at the ends of a location's bracket.
        pack lo_state;
        pack hi_state;
        pack a_state;
        pack b_state;
        slopes d;  // (on the interpolant) the pass's slopes, computed when it first probes or locates
        // One pass per restart: the first, and one after each location whose action ran.
        const bool forward = h > T(0);
        const T step_h = h;  // (h becomes the rest of the step after an action)
        for (;;) {
            if constexpr (interpolates) d.ready = false;
            // Crossings this close after an event's last firing (or the start) are the same crossing.
            const T same_root = T(4) * std::numeric_limits<T>::epsilon() * (abs_value(t_s) + abs_value(h));
            if (partial) {
                load(y, start);
                s = call_step(stepper, f, y, t_s, h, seq{});
                ++work.steps;
                if (s != status::ok) return outcome(s, t_s, no_event);
                evaluate(set, t_end, y, g_end);
                work.g += E;
            }
            if (!finite_values(g_end)) return fail(start, t_s, status::non_finite_event);
            // Nothing crossed and no probes: remember the values and go on.
            if (pieces == 1 && !any_crossing(set, g_end)) {
                for (std::size_t i = 0; i < E; ++i) memory[i].g = g_end[i];
                rearm(set, t_end, g_end);
                if (partial) reset_if_any(stepper);
                return outcome(status::ok, t_end, no_event);
            }
            // Scan (0, h] piece by piece (the pieces end at the probes and at h). lo is where the events'
            // memory was last updated; lo_state the state there.
            T lo = T(0);
            lo_state = start;
            bool restarted = false;
            // The probes and the location's re-steps go from the step's start on a copy of the stepper, reset
            // before each (its history, if any, belongs to the regular steps).
            Stepper scratch = stepper;
            for (std::size_t k = 1; k <= pieces && !restarted; ++k) {
                T hi = h;
                refs hi_refs = y;  // the state at hi: y at the step's end, hi_state at a probe
                values g_hi = g_end;
                if (k < pieces) {
                    hi = h * static_cast<T>(k) / static_cast<T>(pieces);
                    hi_refs = pointers(hi_state);
                    const status ps = state_at(scratch, f, start, y, d, t_s, hi, h, t_end, hi_state);
                    if (ps != status::ok) return fail(lo_state, at(lo), ps);
                    if (!evaluate_all(set, at(hi), hi_refs, g_hi))
                        return fail(lo_state, at(lo), status::non_finite_event);
                }
                // Every firing inside (lo, hi]. Each pass of this loop is one location, and a step makes at
                // most max_firings_per_step of them, whether they fire or not: with an event function that is
                // not a pure function of (t, y) (a sensor), a crossing seen at hi can vanish when location
                // reads g again, and without this count the loop would start over for ever.
                for (;;) {
                    if (!any_crossing(set, g_hi)) break;
                    if (located >= set.limits.max_firings_per_step) return fail(lo_state, at(lo), status::event_limit);
                    ++located;
                    // Locate the earliest crossing: [a, b] with b - a within tolerance.
                    T a = lo;
                    T b = hi;
                    load(hi_refs, b_state);
                    values g_b = g_hi;
                    const status ls =
                        locate(scratch, f, set, start, y, d, t_s, h, t_end, lo, lo_state, a, b, a_state, b_state, g_b);
                    if (ls != status::ok) return fail(lo_state, at(lo), ls);
                    const T t_star = at(a);
                    const T t_b = at(b);
                    // Every g at the event's state, so that the state before an action (the roll-back target
                    // if the action fails) is one where every g is finite. At lo they are the memory's.
                    values g_cross = g_b;
                    if constexpr (!actions_keep_state) {
                        if (a == lo) {
                            for (std::size_t i = 0; i < E; ++i) g_cross[i] = memory[i].g;
                        } else if (!evaluate_all(set, t_star, pointers(a_state), g_cross)) {
                            return fail(lo_state, at(lo), status::non_finite_event);
                        }
                    }
                    // Fire, in the order given, every event that has crossed by b, at t* with the integrator's
                    // state there. From here on lo_state is free: it holds the state before each round of
                    // actions. An action may move the state across (or onto) another event's zero: that event
                    // fires too, at the same time, after it. Each round fires at least one event, and each
                    // event fires once in a location: at most E rounds.
                    bool acted_here = false;
                    values after = g_b;  // the values the crossings are measured to
                    for (;;) {
                        if constexpr (!actions_keep_state) lo_state = a_state;
                        std::size_t stop_index = no_event;
                        bool limited = false;
                        bool acted_now = false;
                        fire_all(set, t_star, t_b, forward, same_root, pointers(a_state), after, sink, fired_here,
                                 stop_index, limited, acted_now);
                        acted = acted || acted_now;
                        if constexpr (!actions_keep_state) {
                            if (!all_finite_pack(a_state)) return fail(lo_state, t_star, status::non_finite);
                        }
                        if (stop_index != no_event || limited) {
                            store(y, a_state);
                            return outcome(limited ? status::event_limit : status::stopped_by_event, t_star,
                                           stop_index);
                        }
                        if constexpr (actions_keep_state) {
                            break;
                        } else {
                            if (!acted_now) break;
                            acted_here = true;
                            if (!evaluate_all(set, t_star, pointers(a_state), g_cross))
                                return fail(lo_state, t_star, status::non_finite_event);
                            after = g_cross;
                            if (!any_crossing(set, g_cross)) break;
                        }
                    }
                    if (acted_here) {
                        // An action ran (it may have changed the state, or only a parameter the right-hand
                        // side reads): the rest of the step starts again from the event.
                        // Each event is armed from what the state does next (see headings).
                        values g_next = g_cross;
                        if (!headings(f, set, t_star, t_b, step_h, a_state, g_next)) {
                            // f not finite after the action: as when the rest of the step's first stage meets
                            // it, non_finite at the event with the state the action left
                            store(y, a_state);
                            return outcome(status::non_finite, t_star, no_event);
                        }
                        store(y, a_state);
                        for (std::size_t i = 0; i < E; ++i) memory[i].g = g_next[i];
                        rearm(set, t_star, g_next);
                        reset_if_any(stepper);  // a history or a kept acceleration belongs to the old state
                        t_s = t_star;
                        h = t_end - t_star;
                        restarted = true;
                        break;
                    }
                    // No action ran (record events only, or nothing fired): the step's own result stands; go
                    // on scanning from b.
                    lo = b;
                    lo_state = b_state;
                    for (std::size_t i = 0; i < E; ++i) memory[i].g = g_b[i];
                    rearm(set, t_b, g_b);
                }
                if (restarted) break;
                if (!(lo == hi)) {  // (a location that ended at hi left the memory with the values read there)
                    lo = hi;
                    load(hi_refs, lo_state);
                    for (std::size_t i = 0; i < E; ++i) memory[i].g = g_hi[i];
                    rearm(set, at(hi), g_hi);
                }
            }
            if (!restarted) {
                // A pass that began at an event took a partial step: a history built on it would not fit
                // the next regular step, so a multistep method starts afresh.
                if (partial) reset_if_any(stepper);
                return outcome(status::ok, t_end, no_event);
            }
            if (h == T(0)) return outcome(status::ok, t_end, no_event);  // the event was at the step's end
            partial = true;
        }
    }

    using seq = std::make_index_sequence<K>;
    using events_seq = std::index_sequence_for<Events...>;

    // record and terminal leave the state alone: with only those, a firing never restarts the step, and the
    // state before the actions needs no copy.
    template <class Ev>
    static constexpr bool keeps_state_v = std::is_same_v<std::remove_cv_t<decltype(Ev::action)>, record_action> ||
                                          std::is_same_v<std::remove_cv_t<decltype(Ev::action)>, stop_action>;
    static constexpr bool actions_keep_state = (keeps_state_v<Events> && ...);

    // The quiet step's test: true only if every g is finite and no event crossed; false when it cannot tell
    // (advance_rest decides then). With every event armed and no probes (all_armed) it is one product per event: g before times g now
    // is positive only when both are strictly on the same side of zero, which no direction counts as a
    // crossing (a product that underflows to zero only sends the step to the full test).
    // The products also prove every g finite (the memory's g are): their sum, of positive terms, is at most
    // the largest finite T only if every term is finite (an overflowed sum only sends the step on, too).
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
        const values p{(memory[I].g * g[I])...};
        bool same_side = p[0] > T(0);
        T sum = p[0];
        ((I > 0 ? (void)(same_side = same_side && p[I] > T(0), sum += p[I]) : (void)0), ...);
        return same_side && sum <= std::numeric_limits<T>::max();
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

    ODESTEP_INLINE static void load(const refs& y, pack& p) {
        for (std::size_t k = 0; k < K; ++k) p[k] = *y[k];
    }
    static void store(const refs& y, const pack& p) {
        for (std::size_t k = 0; k < K; ++k) *y[k] = p[k];
    }
    static refs pointers(pack& p) {
        refs r;
        for (std::size_t k = 0; k < K; ++k) r[k] = &p[k];
        return r;
    }
    static bool all_finite_pack(const pack& p) {
        for (std::size_t k = 0; k < K; ++k)
            if (!finite_values(p[k])) return false;
        return true;
    }
    // detail::all_finite, which is always inlined (the steppers' hot paths), behind a call the compiler may
    // keep out of line: these are the event loop's rare paths, and at -Os one shared copy is the smaller
    // (inlined everywhere, the M4F float -Os event tick is larger).
    template <class A>
    static bool finite_values(const A& a) noexcept {
        return all_finite(a);
    }

    static constexpr bool valid_setting(T v) noexcept { return is_finite(v) && !(v < T(0)); }

    static bool settings_valid(const set_type& set) {
        bool ok = true;
        for_each(set, [&](auto, const auto& e) {
            ok = ok && valid_setting(e.tolerance) && valid_setting(e.band) && valid_setting(e.dead_time);
        });
        return ok;
    }

    template <class Set, class Fn, std::size_t... I>
    ODESTEP_INLINE static void for_each_impl(Set& set, Fn&& fn, std::index_sequence<I...>) {
        (fn(std::integral_constant<std::size_t, I>{}, std::get<I>(set.events)), ...);
    }
    template <class Set, class Fn>
    ODESTEP_INLINE static void for_each(Set& set, Fn&& fn) {
        for_each_impl(set, fn, events_seq{});
    }

    template <class Ev>
    static void check_event_type() {
        static_assert(std::is_same_v<typename Ev::state_type, State>,
                      "odestep: an event's State (make_event<State>) must be the integrated state type");
    }

    // g_i(t, y) for every event, unchecked.
    template <class Ptrs>
    ODESTEP_INLINE static void evaluate(set_type& set, T t, const Ptrs& y, values& g) {
        for_each(set, [&](auto index, auto& e) {
            using Ev = std::remove_reference_t<decltype(e)>;
            check_event_type<Ev>();
            constexpr std::size_t i = decltype(index)::value;
            g[i] = call_g<State>(e.g, t, y, seq{});
        });
    }

    // g_i(t, y) for every event; false if one is NaN or Inf.
    template <class Ptrs>
    bool evaluate_all(set_type& set, T t, const Ptrs& y, values& g) {
        evaluate(set, t, y, g);
        work.g += E;
        return finite_values(g);
    }

    // fn(event) for event i, a run-time index: the one place that turns an index into an event's type.
    template <class Set, class Fn>
    static void visit(Set& set, std::size_t i, Fn&& fn) {
        for_each(set, [&](auto index, auto& e) {
            if (decltype(index)::value == i) fn(e);
        });
    }

    // g of event i at (t, y).
    T evaluate_one(set_type& set, std::size_t i, T t, const refs& y) {
        T value = T(0);
        work.g += 1;
        visit(set, i, [&](auto& e) { value = call_g<State>(e.g, t, y, seq{}); });
        return value;
    }

    static direction direction_of(const set_type& set, std::size_t i) {
        direction d = direction::either;
        visit(set, i, [&](const auto& e) { d = e.direction; });
        return d;
    }

    // Event i (a run-time index) has crossed zero in its direction between its memory and g_now.
    bool crossed(const set_type& set, std::size_t i, T g_now) const {
        return memory[i].armed && crosses(direction_of(set, i), memory[i].g, g_now);
    }

    // Any event crossed (compile-time indices, each event's own direction).
    bool any_crossing(const set_type& set, const values& g) const {
        bool any = false;
        for_each(set, [&](auto index, const auto& e) {
            constexpr std::size_t i = decltype(index)::value;
            any = any || (memory[i].armed && crosses(e.direction, memory[i].g, g[i]));
        });
        return any;
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
    ODESTEP_EVENTS_NOINLINE bool headings(System& f, set_type& set, T t_star, T t_b, T h, const pack& y, values& g) {
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
            const T change = g_ahead[i] - g[i];
            if (!is_finite(change) || change == T(0)) continue;
            event_memory<T>& m = memory[i];
            // (m.g is still the value before the crossing: it went from m.g's side to the other)
            if (m.fired != 0 && m.last == t_star && m.until == t_b)
                m.through = m.g < T(0) ? change > T(0) : change < T(0);
            if (g[i] == T(0)) g[i] = change > T(0) ? std::numeric_limits<T>::min() : -std::numeric_limits<T>::min();
        }
        return true;
    }

    // The state s into the pass from (t_s, start) to (t_end, y_end), into out: by re-stepping (the stepper's
    // own state there: `trial`, a copy of the stepper, reset first, steps s from start), or on the
    // interpolant (Hermite from start, y_end and the slopes d, which the first call of a pass computes: f at
    // both ends; NaN or Inf there is non_finite, and the caller rolls back to the pass's start).
    template <class Stepper, class System>
    ODESTEP_INLINE status state_at(Stepper& trial, System& f, const pack& start, const refs& y_end, slopes& d, T t_s,
                                   T s, T h, T t_end, pack& out) {
        if constexpr (interpolates) {
            (void)trial;
            if (ODESTEP_UNLIKELY(!d.ready)) {
                const status sl = hermite_ends(f, start, y_end, t_s, t_end, d);
                if (sl != status::ok) return sl;
            }
            interpolate(start, y_end, d, s, h, out);
            // finite ends and slopes can still give an overflowing cubic (h f near the largest T)
            return all_finite_pack(out) ? status::ok : status::non_finite;
        } else {
            (void)d, (void)y_end, (void)h, (void)t_end;
            return restep(trial, f, start, t_s, s, out);
        }
    }
    // The stepper's own state s after (t_s, start): trial, a copy of the stepper, reset, steps s.
    template <class Stepper, class System>
    ODESTEP_INLINE status restep(Stepper& trial, System& f, const pack& start, T t_s, T s, pack& out) {
        out = start;
        reset_if_any(trial);
        ++work.steps;
        return call_step(trial, f, pointers(out), t_s, s, seq{});
    }
    // The Hermite interpolant at s into the pass of h (the slopes d ready).
    ODESTEP_INLINE static void interpolate(const pack& start, const refs& y_end, const slopes& d, T s, T h, pack& out) {
        if constexpr (interpolates) {
            const T theta = s / h;
            for (std::size_t k = 0; k < K; ++k) hermite_cubic(start[k], d.d0[k], *y_end[k], d.d1[k], h, theta, out[k]);
        } else {
            (void)start, (void)y_end, (void)d, (void)s, (void)h, (void)out;
        }
    }

    // The slopes at the pass's ends: f(t, y) (Newtonian: x' = v and v' = a(t, x, v)), two evaluations. Kept
    // out of line: the rare path of the rare path.
    template <class System>
    ODESTEP_EVENTS_NOINLINE status hermite_ends(System& f, const pack& start, const refs& y_end, T t_s, T t_end,
                                                slopes& d) {
        work.rhs += 2;
        if constexpr (K == 1) {
            odestep::detail::evaluate(f, t_s, start[0], d.d0[0]);
            odestep::detail::evaluate(f, t_end, static_cast<const State&>(*y_end[0]), d.d1[0]);
        } else {
            d.d0[0] = start[1];
            d.d0[1] = acceleration(f, t_s, start[0], start[1]);
            d.d1[0] = *y_end[1];
            d.d1[1] =
                acceleration(f, t_end, static_cast<const State&>(*y_end[0]), static_cast<const State&>(*y_end[1]));
        }
        if (!all_finite_pack(d.d0) || !all_finite_pack(d.d1)) return status::non_finite;
        d.ready = true;
        return status::ok;
    }

    // Narrows [a, b] (the crossings between lo = a and b) to the earliest one: every event crossed by b is
    // located on [lo, b] in turn, and b only moves earlier. Re-steps go from the step's start (on `trial`,
    // a copy of the stepper, reset before each), so the event state is the integrator's own. On return [a, b]
    // brackets the earliest crossing, a_state and b_state are the states there and g_b all g at b.
    template <class Stepper, class System>
    ODESTEP_INLINE status locate(Stepper& trial, System& f, set_type& set, const pack& start, const refs& y_end,
                                 slopes& d, T t_s, T h, T t_end, T lo, const pack& lo_state, T& a, T& b, pack& a_state,
                                 pack& b_state, values& g_b) {
        // Half the spacing of T at the step's times: a bracket that narrow, in s, has ends whose times are
        // adjacent or equal (each end rounds by at most half a spacing). (The spacing below the larger time,
        // which is the smaller one at a power of two, and never below the least subnormal.)
        const T larger = max_value(abs_value(t_s), abs_value(t_end));
        const T default_tolerance =
            max_value((larger - std::nextafter(larger, T(0))) / T(2), std::numeric_limits<T>::denorm_min());
        const std::size_t cap = event_iterations<T, Finder>(set.limits);
        // The trial states live in h-scaled units of time: s in (0, h] (or [h, 0) integrating backwards).
        // The finders want a < b, so they work on u = s / sign(h).
        const T sign_h = h < T(0) ? T(-1) : T(1);
        pack trial_state;
        status failure = status::ok;
        // a starts at lo: a_state is the state there until an event's bracket moves it (so that it holds a
        // state on every path, which arm-none-eabi-g++'s -Wmaybe-uninitialized could not see).
        a_state = lo_state;
        for (std::size_t c = 0; c < E; ++c) {
            if (!crossed(set, c, g_b[c])) continue;
            const T side = memory[c].g > T(0) ? T(-1) : T(1);  // f = side * g is negative before the crossing
            const T fb = side * g_b[c];
            if (fb == T(0)) {  // exactly zero at b: the root is b itself
                a = b;
                a_state = b_state;
                continue;
            }
            T tolerance = T(0);
            visit(set, c, [&](const auto& e) { tolerance = e.tolerance; });
            tolerance = max_value(tolerance, default_tolerance);
            // The bracket's ends move as the finder narrows it: a_state (from lo_state) and b_state follow.
            a_state = lo_state;
            if constexpr (interpolates) {
                if (!d.ready) {
                    const status sl = hermite_ends(f, start, y_end, t_s, t_end, d);
                    if (sl != status::ok) return sl;
                }
            }
            auto fn = [&, sign_h, side, c, t_s, h, t_end](T u) -> T {  // (the scalars by value: in registers)
                const T s_trial = sign_h * u;
                status st = status::ok;
                if constexpr (interpolates) {  // (each branch captures only what it reads)
                    interpolate(start, y_end, d, s_trial, h, trial_state);
                    if (!all_finite_pack(trial_state)) st = status::non_finite;  // (see state_at)
                } else {
                    st = restep(trial, f, start, t_s, s_trial, trial_state);
                }
                if (st != status::ok) {
                    failure = st;
                    return std::numeric_limits<T>::quiet_NaN();
                }
                const T value = side * evaluate_one(set, c, time_at(t_s, s_trial, h, t_end), pointers(trial_state));
                if (!is_finite(value)) {
                    failure = status::non_finite_event;
                } else if (value < T(0)) {
                    a_state = trial_state;
                } else {
                    b_state = trial_state;
                }
                return value;
            };
            const root_bracket<T> r =
                Finder::narrow(fn, sign_h * lo, side * memory[c].g, sign_h * b, fb, tolerance, cap);
            if (r.failed) return failure != status::ok ? failure : status::non_finite_event;
            a = sign_h * r.a;
            b = sign_h * r.b;
            if (r.fb == T(0)) {  // g exactly zero at b: the event is at that time, with the state there
                a = b;
                a_state = b_state;
            }
            if (!evaluate_all(set, time_at(t_s, b, h, t_end), pointers(b_state), g_b)) return status::non_finite_event;
        }
        return status::ok;
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
            sink(fired_here, i, t_star);
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
