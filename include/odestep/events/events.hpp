// odestep: events, the moments when a function of the state crosses zero (the top of a flight, a ball
// reaching the floor, coffee cooling to drinking temperature), located by re-stepping the integrator from the
// start of the step, acted on, and paid for with a bounded, published amount of work per step.
#ifndef ODESTEP_EVENTS_EVENTS_HPP
#define ODESTEP_EVENTS_EVENTS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../integrate.hpp"
#include "../roots/bracket.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"

namespace odestep {

/// Which sign changes of g count: rising (- to +), falling (+ to -) or either. Reaching exactly zero from
/// the side the direction starts on counts too; leaving zero does not.
enum class direction : unsigned char { rising, falling, either };

/// What an event's action returns: go on integrating, or stop the run at the event.
enum class event_result : unsigned char { proceed, stop };

/// The action of a terminal event: the run stops at the event, which is the default.
struct stop_action {};
/// The action of an event that is only counted and reported: the state is untouched and the run goes on.
struct record_action {};
inline constexpr stop_action terminal{};
inline constexpr record_action record{};

/// One event: g(t, y) -> T for a first-order state, or g(t, x, v) -> T for Newton's equations, the
/// direction that counts, and the action: `terminal`, `record`, or a callable
/// `action(T t, State& y)` / `action(T t, State& x, State& v)` that may change the state (a bounce, a
/// serving of cream) and returns `event_result` (or nothing, meaning proceed). A callable that takes one
/// more argument, `action(T t, State& y, direction crossed)`, is told which way the crossing went (rising
/// or falling), so that one `either` event can act both ways.
///
/// Settings, all optional (the defaults are what most problems need):
///   - tolerance: the width of the time bracket the event is located to. Zero (the default) means adjacent
///     times: half the spacing of T at the step's time, so that the bracket's ends are adjacent (or equal)
///     representable times, in float and double, tiny and huge t alike (within the root finder's cap of
///     re-steps, event_limits::max_iterations). A crossing located within the tolerance, or at least
///     4 eps (|t| + |dt|), after the event's last firing is that firing's own (an action that moved the
///     state but not g: it fires once), and one as close after the start (or a rearm) counts as a zero
///     there: it does not fire (so a run begun at a stopped_by_event state goes on).
///   - band: after firing, the event re-arms only once |g| > band has been seen at a step's end (a probe,
///     or the event's own location point): the dead band of a crossing. Zero by default (re-arms as soon as
///     g leaves zero).
///   - dead_time: the least time between two firings; zero by default.
///   - max_firings: after this many firings the event stays quiet; zero (the default) means no limit.
/// Negative or non-finite tolerance, band or dead_time is rejected with status::invalid_tolerance.
template <class State, class G, class Action = stop_action>
struct event {
    using state_type = State;
    using value_type = value_type_t<State>;

    G g;
    odestep::direction direction = odestep::direction::either;
    Action action;  // no default initializer: a capturing lambda has no default constructor (C++20)
    value_type tolerance = value_type(0);
    value_type band = value_type(0);
    value_type dead_time = value_type(0);
    std::size_t max_firings = 0;

    constexpr event with_tolerance(value_type v) const {
        event e = *this;
        e.tolerance = v;
        return e;
    }
    constexpr event with_band(value_type v) const {
        event e = *this;
        e.band = v;
        return e;
    }
    constexpr event with_dead_time(value_type v) const {
        event e = *this;
        e.dead_time = v;
        return e;
    }
    constexpr event with_max_firings(std::size_t n) const {
        event e = *this;
        e.max_firings = n;
        return e;
    }
};

/// make_event<State>(g, direction[, action]): an event on a State (std::array<T, N>); the action defaults
/// to `terminal`.
template <class State, class G, class Action = stop_action>
constexpr event<State, G, Action> make_event(G g, direction d, Action action = Action{}) {
    return event<State, G, Action>{g, d, action};
}

/// Settings of the event loop, the same for all its events; they bound the work of one step (see
/// max_rhs_evals_per_step). Limits whose bounds do not fit std::size_t (a huge probe count, cap or firing
/// limit) are refused with status::invalid_setting before anything is touched.
struct event_limits {
    /// Cap on the root finder's re-steps for one event location; zero means the finder's own worst case from
    /// dt down to 4 eps dt (Brent: 102 in double, 44 in float; bisection: 50 and 21). Smooth event
    /// functions need 4 to 10 to reach adjacent times; a location that would need more (a root of high
    /// order, or t much smaller than dt) stops at the cap with a wider bracket.
    std::size_t max_iterations = 0;
    /// Firings allowed inside one step; one more is reported as status::event_limit. It also caps the
    /// locations in one step, whether they fire or not (an event function that is not a pure function of
    /// (t, y), a sensor, can show a crossing that location does not find again): every call is bounded.
    std::size_t max_firings_per_step = 8;
    /// Interior probes per step: each is a re-step to k dt / (probes + 1), where g is evaluated too, so that
    /// a g that crosses zero twice inside one step is seen. Without probes such a pair is missed (g has the
    /// same sign at both ends of the step).
    std::size_t probes = 0;
};

/// The root finder used when none is named: Brent needed the fewest re-steps on the events of the examples
/// (as few as Anderson-Bjorck on smooth ones, and 7.8 against 12.8 on average after a bounce, where the
/// bracket starts next to the last root; see the README's event section for the measurement).
using default_root_finder = brent;

/// The events of one run, given together (each its own type: no type erasure, no heap), the loop's limits
/// and the root finder.
template <class Finder, class... Events>
struct event_set {
    static_assert(sizeof...(Events) > 0, "odestep: an event set needs at least one event");
    using event_set_tag = void;  ///< marks an event set for the driving loops (integrate's overloads)
    using finder = Finder;
    static constexpr std::size_t size = sizeof...(Events);

    std::tuple<Events...> events;
    event_limits limits{};

    constexpr event_set with_limits(event_limits l) const {
        event_set s = *this;
        s.limits = l;
        return s;
    }
};

/// watch(e1, e2, ...): the events of a run, in order of priority (events located at the same time fire in
/// this order). watch<odestep::itp>(...) picks another root finder.
template <class Finder = default_root_finder, class... Events>
constexpr event_set<Finder, Events...> watch(Events... e) {
    return event_set<Finder, Events...>{std::tuple<Events...>(e...), event_limits{}};
}

namespace detail {
// The root finder's cap: the user's, or else the finder's own worst case from a bracket of dt down to the
// default tolerance (at least 4 eps dt): enough for it always to converge.
template <class T, class Finder>
constexpr std::size_t event_iterations(event_limits limits) noexcept {
    return limits.max_iterations != 0 ? limits.max_iterations
                                      : Finder::worst_case_evaluations(T(1), T(4) * std::numeric_limits<T>::epsilon());
}

// The bounds' arithmetic saturates at SIZE_MAX instead of wrapping: a bound that does not fit std::size_t is
// SIZE_MAX, and limits with such a bound are refused (status::invalid_setting).
constexpr std::size_t count_max = std::numeric_limits<std::size_t>::max();
constexpr std::size_t sat_add(std::size_t a, std::size_t b) noexcept { return a > count_max - b ? count_max : a + b; }
constexpr std::size_t sat_mul(std::size_t a, std::size_t b) noexcept {
    return b != 0 && a > count_max / b ? count_max : a * b;
}
}  // namespace detail

/// The most right-hand-side evaluations (accelerations, for Newton's equations) one step with events can
/// cost, for a stepper whose own step costs at most Stepper::rhs_evals_per_step:
///   S [ (1 + F)(1 + P) + F E C ]
/// with F firings per step, P probes, E events and C root-finder iterations: the step and its probes, once
/// more after each location whose action ran (the rest of the step from the event), and at most C re-steps
/// for each event narrowed in each location (a step makes at most F locations, whether they fire or not).
/// With no event firing and no probes it is S: the step itself, nothing more. SIZE_MAX when the bound does
/// not fit std::size_t (such limits are refused with status::invalid_setting).
template <class Stepper, class Finder = default_root_finder,
          class T = typename std::remove_reference_t<Stepper>::value_type>
constexpr std::size_t max_rhs_evals_per_step(std::size_t events, event_limits limits = {}) noexcept {
    using detail::sat_add;
    using detail::sat_mul;
    const std::size_t s = std::remove_reference_t<Stepper>::rhs_evals_per_step;
    const std::size_t f = limits.max_firings_per_step;
    const std::size_t p = limits.probes;
    return sat_mul(s, sat_add(sat_mul(sat_add(1, f), sat_add(1, p)),
                              sat_mul(sat_mul(f, events), detail::event_iterations<T, Finder>(limits))));
}

/// The most evaluations of event functions one step can cost (all events together):
///   E (1 + F)(1 + P) + F E (C + E + 2).
/// With no event firing and no probes it is E: one per event, at the step's end. SIZE_MAX when it does not
/// fit std::size_t.
template <class T, class Finder = default_root_finder>
constexpr std::size_t max_g_evals_per_step(std::size_t events, event_limits limits = {}) noexcept {
    using detail::sat_add;
    using detail::sat_mul;
    const std::size_t f = limits.max_firings_per_step;
    const std::size_t p = limits.probes;
    const std::size_t c = detail::event_iterations<T, Finder>(limits);
    return sat_add(sat_mul(events, sat_mul(sat_add(1, f), sat_add(1, p))),
                   sat_mul(sat_mul(f, events), sat_add(c, sat_add(events, 2))));
}

/// The most right-hand-side evaluations one `event_stepper::tick` can cost: two steps' worth (a tick after
/// one that ended early first completes the rest of that tick's period, then takes its own; see
/// event_stepper). SIZE_MAX when it does not fit std::size_t.
template <class Stepper, class Finder = default_root_finder,
          class T = typename std::remove_reference_t<Stepper>::value_type>
constexpr std::size_t max_rhs_evals_per_tick(std::size_t events, event_limits limits = {}) noexcept {
    return detail::sat_mul(2, max_rhs_evals_per_step<Stepper, Finder, T>(events, limits));
}

/// The most event-function evaluations one `event_stepper::tick` can cost: two steps' worth.
template <class T, class Finder = default_root_finder>
constexpr std::size_t max_g_evals_per_tick(std::size_t events, event_limits limits = {}) noexcept {
    return detail::sat_mul(2, max_g_evals_per_step<T, Finder>(events, limits));
}

namespace detail {
// Limits are valid when the per-tick bounds (twice the per-step ones) fit std::size_t: then nothing in the
// loop's counting wraps either (probes + 1, the bounds themselves).
template <class Stepper, class Finder, class T>
constexpr status limits_status(std::size_t events, event_limits limits) noexcept {
    const bool fits = max_rhs_evals_per_tick<Stepper, Finder, T>(events, limits) < count_max &&
                      max_g_evals_per_tick<T, Finder>(events, limits) < count_max;
    return fits ? status::ok : status::invalid_setting;
}
}  // namespace detail

/// One firing: which event (its index in the set) and when.
template <class T>
struct event_firing {
    std::size_t event;
    T t;
};

/// What integrate with events reports. `status` is ok (t1 reached), stopped_by_event (`event` says which,
/// `t` when), event_limit, or an error; the state is always the one at `t`.
template <class T, std::size_t E>
struct event_integrate_result {
    odestep::status status;
    T t;
    step_count steps;                    ///< grid steps completed
    std::size_t event;                   ///< the terminal event, or no_event
    std::size_t fired;                   ///< firings in total
    std::array<std::size_t, E> firings;  ///< firings per event
};

/// What one tick of an event_stepper reports: the status (ok, stopped_by_event, event_limit, or an error),
/// the time of the state now (the tick's end unless the tick stopped early), and the firings inside the tick
/// (the first Capacity of them are listed; `fired` counts them all; entries past those are not written).
template <class T, std::size_t Capacity>
struct tick_result {
    odestep::status status;
    T t;
    std::size_t fired;
    std::size_t event;  ///< the terminal event, or no_event
    std::array<event_firing<T>, Capacity> firings;
};

namespace detail {

template <class S, class = void>
struct has_reset : std::false_type {};
template <class S>
struct has_reset<S, std::void_t<decltype(std::declval<S&>().reset())>> : std::true_type {};

template <class S>
constexpr void reset_if_any(S& s) noexcept {
    if constexpr (has_reset<S>::value) s.reset();
}

template <class T>
constexpr bool crosses(direction d, T before, T after) noexcept {
    switch (d) {
        case direction::falling: return before > T(0) && after <= T(0);
        case direction::rising: return before < T(0) && after >= T(0);
        case direction::either: break;
    }
    return (before > T(0) && after <= T(0)) || (before < T(0) && after >= T(0));
}

// What the loop remembers of each event between evaluation points.
template <class T>
struct event_memory {
    T g = T(0);     // g at the last evaluation point: crossings are measured from it
    T last = T(0);  // time of the last firing
    // The end of the last firing's bracket (or the time of start or rearm): a crossing located within the
    // event's tolerance after it is that firing's own crossing (or a zero at the start) and does not fire.
    T until = T(0);
    std::size_t fired = 0;
    bool armed = false;  // may fire: g has been seen away from zero (beyond the band, after the dead time)
};

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

    std::array<event_memory<T>, E> memory{};
    bool all_armed = false;  // every event is armed: kept by rearm and fire_all, read by the quiet step's test

    // Checks the settings and evaluates every g at the start. An event whose g is zero there is not armed.
    template <class Ptrs>
    status begin(set_type& set, T t0, const Ptrs& y) {
        if (!settings_valid(set)) return status::invalid_tolerance;
        values g{};
        if (!evaluate_all(set, t0, y, g)) return status::non_finite_event;
        for (std::size_t i = 0; i < E; ++i) memory[i] = event_memory<T>{g[i], t0, t0, 0, false};
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
        if (ODESTEP_UNLIKELY(s != status::ok)) return {s, t_s, 0, no_event};
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
        // One pass per restart: the first, and one after each location whose action ran.
        for (;;) {
            if (partial) {
                load(y, start);
                s = call_step(stepper, f, y, t_s, h, seq{});
                if (s != status::ok) return outcome(s, t_s, no_event);
                evaluate(set, t_end, y, g_end);
            }
            if (!finite_values(g_end)) return fail(start, t_s, status::non_finite_event);
            // Nothing crossed and no probes: remember the values and go on.
            if (pieces == 1 && !any_crossing(set, g_end)) {
                for (std::size_t i = 0; i < E; ++i) memory[i].g = g_end[i];
                rearm(set, t_end, g_end);
                if (partial) reset_if_any(stepper);
                return outcome(status::ok, t_end, no_event);
            }
            const bool forward = h > T(0);
            // Crossings this close after an event's last firing (or the start) are the same crossing.
            const T same_root = T(4) * std::numeric_limits<T>::epsilon() * (abs_value(t_s) + abs_value(h));
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
                    hi_state = start;
                    hi_refs = pointers(hi_state);
                    reset_if_any(scratch);
                    const status ps = call_step(scratch, f, hi_refs, t_s, hi, seq{});
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
                        locate(scratch, f, set, start, t_s, h, t_end, lo, lo_state, a, b, a_state, b_state, g_b);
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
                        store(y, a_state);
                        for (std::size_t i = 0; i < E; ++i) memory[i].g = g_cross[i];
                        rearm(set, t_star, g_cross);
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
    // (advance_rest decides then). With every event armed it is one product per event: g before times g now
    // is positive only when both are strictly on the same side of zero, which no direction counts as a
    // crossing (a product that underflows to zero only sends the step to the full test).
    // The products also prove every g finite (the memory's g are): their sum, of positive terms, is at most
    // the largest finite T only if every term is finite (an overflowed sum only sends the step on, too).
    ODESTEP_INLINE bool quiet(const set_type& set, const values& g) const {
        if (set.limits.probes != 0) return false;
        if (all_armed) {
            // (compile-time indices throughout, here and in remember: g then stays in registers)
            T sum = memory[0].g * g[0];
            bool same_side = sum > T(0);
            for_each(set, [&](auto index, const auto&) {
                constexpr std::size_t i = decltype(index)::value;
                if constexpr (i > 0) {
                    const T p = memory[i].g * g[i];
                    same_side = same_side && p > T(0);
                    sum += p;
                }
            });
            return same_side && sum <= std::numeric_limits<T>::max();
        }
        T sum = g[0];
        for_each(set, [&](auto index, const auto&) {
            constexpr std::size_t i = decltype(index)::value;
            if constexpr (i > 0) sum += g[i];
        });
        return finite_sum(sum) && !any_crossing(set, g);  // finite_sum proves every g finite
    }

    // The g values become the events' memory: crossings are measured from them next.
    ODESTEP_INLINE void remember(const set_type& set, const values& g) {
        for_each(set, [&](auto index, const auto&) {
            constexpr std::size_t i = decltype(index)::value;
            memory[i].g = g[i];
        });
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
    static bool same(const pack& a, const pack& b) {
        for (std::size_t k = 0; k < K; ++k)
            for (std::size_t n = 0; n < a[k].size(); ++n)
                if (!(a[k][n] == b[k][n])) return false;
        return true;
    }
    static bool all_finite_pack(const pack& p) {
        for (std::size_t k = 0; k < K; ++k)
            if (!finite_values(p[k])) return false;
        return true;
    }
    // detail::all_finite, which is always inlined (the steppers' hot paths), behind a call the compiler may
    // keep out of line: these are the event loop's rare paths, and at -Os one shared copy is the smaller
    // (inlined everywhere, the M4F float -Os event tick was 38 bytes larger).
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
    static bool evaluate_all(set_type& set, T t, const Ptrs& y, values& g) {
        evaluate(set, t, y, g);
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
    static T evaluate_one(set_type& set, std::size_t i, T t, const refs& y) {
        T value = T(0);
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
        all_armed = all;
    }

    // Narrows [a, b] (the crossings between lo = a and b) to the earliest one: every event crossed by b is
    // located on [lo, b] in turn, and b only moves earlier. Re-steps go from the step's start (on `trial`,
    // a copy of the stepper, reset before each), so the event state is the integrator's own. On return [a, b]
    // brackets the earliest crossing, a_state and b_state are the states there and g_b all g at b.
    template <class Stepper, class System>
    ODESTEP_INLINE status locate(Stepper& trial, System& f, set_type& set, const pack& start, T t_s, T h, T t_end, T lo,
                                 const pack& lo_state, T& a, T& b, pack& a_state, pack& b_state, values& g_b) {
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
            auto fn = [&, sign_h, side, c, t_s, h, t_end](T u) -> T {  // (the scalars by value: in registers)
                const T s_trial = sign_h * u;
                trial_state = start;
                reset_if_any(trial);
                const status st = call_step(trial, f, pointers(trial_state), t_s, s_trial, seq{});
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
    // (its last firing's bracket end, or the start or rearm) is that firing's own (an action that moved the
    // state but not g) or a zero at the start (a run begun at a stopped_by_event state): it does not fire.
    // acted: a callable action ran (and did not stop).
    template <class Sink>
    void fire_all(set_type& set, T t_star, T t_b, bool forward, T same_root, const refs& y_star, const values& g_b,
                  Sink& sink, std::size_t& fired_here, std::size_t& stop_index, bool& limited, bool& acted) {
        for_each(set, [&](auto index, auto& e) {
            using Ev = std::remove_reference_t<decltype(e)>;
            constexpr std::size_t i = decltype(index)::value;
            if (stop_index != no_event || limited) return;
            event_memory<T>& m = memory[i];
            if (!(m.armed && crosses(e.direction, m.g, g_b[i]))) return;
            const T tolerance = max_value(e.tolerance, same_root);
            if (forward ? !(t_star > m.until + tolerance) : !(t_star < m.until - tolerance)) return;
            if (fired_here >= set.limits.max_firings_per_step) {
                limited = true;
                return;
            }
            m.armed = false;
            all_armed = false;
            m.fired += 1;
            m.last = t_star;
            m.until = t_b;
            sink(fired_here, i, t_star);
            fired_here += 1;
            // The direction the crossing went: from below zero, rising; from above, falling.
            const direction crossed = m.g < T(0) ? direction::rising : direction::falling;
            if (call_action<State>(e.action, t_star, crossed, y_star, seq{}) == event_result::stop) {
                stop_index = i;
            } else if constexpr (!keeps_state_v<Ev>) {
                acted = true;
            }
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

template <class T, class Stepper, class System, class Set, class Observer, class State, class... More>
event_integrate_result<T, Set::size> drive_events(Stepper& stepper, System& f, Set& set, Observer& observe,
                                                  status planned, const grid_plan<T>& plan, State& y0, More&... ys) {
    require_self_starting<Stepper>();
    constexpr std::size_t K = 1 + sizeof...(More);
    using engine_type = event_engine<State, K, Set>;
    engine_type engine;
    const auto finish = [&](status s, T t, step_count steps, std::size_t event) {
        event_integrate_result<T, Set::size> r{s, t, steps, event, 0, {}};
        for (std::size_t i = 0; i < Set::size; ++i) {
            r.firings[i] = engine.memory[i].fired;
            r.fired += engine.memory[i].fired;
        }
        return r;
    };
    if (planned == status::ok) planned = fits_plan<Stepper>(plan);
    if (planned == status::ok)
        planned = limits_status<Stepper, typename Set::finder, value_type_t<State>>(Set::size, set.limits);
    if (planned != status::ok) return finish(planned, plan.clock.t0, 0, no_event);
    const std::array<State*, K> y{&y0, &ys...};
    const status started = engine.begin(set, plan.clock.t0, y);
    if (started != status::ok) return finish(started, plan.clock.t0, 0, no_event);
    no_sink sink;
    const run_outcome<T> r = run_grid(
        plan, [&](T t, T h, T next) { return engine.advance(stepper, f, set, y, t, h, next, sink); }, observe, y0,
        ys...);
    return finish(r.code, r.t, r.steps, r.event);
}

}  // namespace detail

/// Integrates y' = f(t, y) from t0 to t1 on the grid t0 + i dt, as `integrate` does, and watches the events
/// of `events` (odestep::watch(...)): each crossing inside a step is located by re-stepping from the step's
/// start, its action runs on the integrator's own state at that time, and the rest of the step is taken
/// from there, so the observer still sees the grid. A terminal event (or an action that returns
/// event_result::stop) ends the run: status::stopped_by_event, `event` says which, `t` when, and y is the
/// state then (the observer sees it too). The result also counts the firings, per event and in all.
///
/// After a callable action (which may change the state, or only a parameter the right-hand side reads) the
/// rest of the step is recomputed from the event, and the stepper is reset (its history, or a kept
/// acceleration, belongs to the old state). A `record` event leaves the trajectory exactly as it would be
/// without it. A terminal event at the start of a step (a root within the tolerance after a grid time) is
/// not observed a second time, unless an action changed the state there.
template <class Stepper, class System, class State, class Set, class Observer,
          std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, System&& f, State& y, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events,
                             Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive_events(stepper, f, events, observe, planned, plan, y);
}

/// integrate with events, without an observer.
template <class Stepper, class System, class State, class Set, std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, System&& f, State& y, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events) {
    detail::no_observer none;
    return integrate(stepper, f, y, t0, t1, dt, events, none);
}

/// Newton's equations with events: g(t, x, v), action(t, x, v), observe(t, x, v).
template <class Stepper, class Accel, class State, class Set, class Observer,
          std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, Accel&& a, State& x, State& v, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events,
                             Observer&& observe) {
    detail::grid_plan<value_type_t<State>> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::drive_events(stepper, a, events, observe, planned, plan, x, v);
}

template <class Stepper, class Accel, class State, class Set, std::enable_if_t<detail::is_event_set_v<Set>, int> = 0>
[[nodiscard]] auto integrate(Stepper&& stepper, Accel&& a, State& x, State& v, detail::time_t_of<State> t0,
                             detail::time_t_of<State> t1, detail::time_t_of<State> dt, Set&& events) {
    detail::no_observer none;
    return integrate(stepper, a, x, v, t0, t1, dt, events, none);
}

/// The event loop for a control loop, one `tick` per period of a timer: the clock is t0 + n dt on an
/// integer counter, and each tick reports the events that fired inside it and when.
///
/// The per-tick contract (docs/events.md):
///   - Every call that does not return an error is one period: ticks() goes up by one. A tick ends on its
///     grid time t0 + ticks() dt (status ok), or early, inside its period, where a terminal event (or an
///     action returning event_result::stop) fired (stopped_by_event) or the firing limit was reached
///     (event_limit); the state is then the integrator's own state at r.t.
///   - The call after one that ended early first completes the rest of that period (a partial step to its
///     grid time, events watched), then takes its own period: at most two steps per call, so one call per
///     timer interrupt stays in step with the timer whatever fires. (If that call ends early in the rest of
///     the earlier period, the state lags one more period; each later call gains one back.) reached() is the
///     last grid time the state reached.
///   - An error (non_finite, non_finite_event, a stepper's status, invalid_time once t0 + n dt overflows)
///     does not count: the state is the last good one, at r.t, and the next call tries again from there.
///   - At most max_rhs_evals_per_tick / max_g_evals_per_tick evaluations per call (two steps' worth).
///
///     odestep::event_stepper loop(odestep::rk4<state>{}, odestep::watch(ground));
///     if (loop.start(0.0, 1e-3, y) != odestep::status::ok) { ... }
///     for (;;) { auto r = loop.tick(f, y); if (r.fired) { ... r.firings[0].t ... } }
///
/// If the caller changes the state between ticks, `rearm(y)` re-reads the events' functions (and resets
/// the stepper's history); otherwise crossings are measured from the last tick's values.
template <class Stepper, class Set, std::size_t Capacity = 8>
class event_stepper {
public:
    using stepper_type = Stepper;
    using state_type = typename Stepper::state_type;
    using value_type = value_type_t<state_type>;
    using set_type = Set;
    static constexpr std::size_t capacity = Capacity;
    static constexpr std::size_t arity =
        detail::event_arity<state_type, std::tuple_element_t<0, decltype(Set::events)>>();

    constexpr event_stepper(Stepper stepper, Set events) : stepper_(stepper), set_(events) {
        detail::require_self_starting<Stepper>();
    }

    /// Starts the clock at t0 with ticks of dt and reads every event function on the initial state. An event
    /// whose function is zero there (or whose root lies within its tolerance after t0) does not fire at t0.
    /// Limits whose work bounds do not fit std::size_t: status::invalid_setting, nothing touched.
    template <class... States>
    [[nodiscard]] status start(value_type t0, value_type dt, const States&... y) {
        static_assert(sizeof...(States) == arity, "odestep: start(t0, dt, y) (Newtonian: start(t0, dt, x, v))");
        const detail::grid_clock<value_type> clock{t0, dt};
        const status checked = clock.check();
        if (checked != status::ok) return checked;
        const status limited = limits_ok();
        if (limited != status::ok) return limited;
        const std::array<const state_type*, arity> ptrs{&y...};
        const status s = engine_.begin(set_, t0, ptrs);
        if (s != status::ok) return s;
        detail::reset_if_any(stepper_);
        clock_ = clock;
        n_ = 0;
        lag_ = 0;
        t_now_ = clock_.time(0);  // t0 + 0 dt, as every grid time
        clock_state_ = clock_state::on_grid;
        return status::ok;
    }

    /// Re-reads every event function at the current time, after the caller changed the state, and resets
    /// the stepper's history. Firing counts are kept, and with them max_firings and the dead time: an event
    /// that has used up its firings stays quiet. An event whose root lies within its tolerance after the
    /// current time does not fire (call rearm at a stopped_by_event state and go on). On a failure
    /// (non_finite_event, invalid_tolerance, invalid_setting) nothing changes.
    template <class... States>
    [[nodiscard]] status rearm(const States&... y) {
        static_assert(sizeof...(States) == arity, "odestep: rearm(y) (Newtonian: rearm(x, v))");
        if (clock_state_ == clock_state::idle) return status::invalid_time;
        const status limited = limits_ok();
        if (limited != status::ok) return limited;
        const std::array<const state_type*, arity> ptrs{&y...};
        const status s = engine_.reread(set_, time(), ptrs);
        if (s != status::ok) return s;
        detail::reset_if_any(stepper_);
        return status::ok;
    }

    /// One tick: one period of the timer, to the grid time t0 + (ticks() + 1) dt (see the class comment).
    /// Before `start`: status::invalid_time, nothing touched.
    // (Always inlined: the caller's frame then holds the quiet tick's few values, and the rare paths' frames,
    // rest and catch_up, are the only other ones on the stack.)
    template <class System, class... States>
    [[nodiscard]] ODESTEP_INLINE tick_result<value_type, Capacity> tick(System&& f, States&... y) {
        static_assert(sizeof...(States) == arity, "odestep: tick(f, y) (Newtonian: tick(a, x, v))");
        const std::array<state_type*, arity> ptrs{&y...};
        if (ODESTEP_UNLIKELY(clock_state_ != clock_state::on_grid)) return catch_up(f, ptrs);
        tick_result<T, Capacity> r;  // firings past `fired` stay unwritten: clearing them cost most of a quiet tick
        r.status = status::ok;
        r.t = t_now_;
        r.fired = 0;
        r.event = no_event;
        // The time of the state (t_now_) is the last tick's end; the tick's end is converted from the counter
        // after the step (on the grid nothing is kept across the step's call).
        typename engine_type::pack start;
        r.status = engine_type::step(stepper_, f, ptrs, t_now_, clock_.dt, start);
        if (ODESTEP_UNLIKELY(r.status != status::ok)) return r;  // y untouched, at t_now_
        const T t_end = grid_time();
        typename engine_type::values g;
        if (ODESTEP_UNLIKELY(!detail::is_finite(t_end) || !engine_.settle(set_, ptrs, t_end, g)))
            return rest(f, ptrs, start, g, t_end);
        ++n_;
        t_now_ = t_end;
        r.t = t_end;
        return r;
    }

    /// The time of the state: t0 + reached() dt, or the time a tick stopped at.
    constexpr value_type time() const noexcept { return t_now_; }
    /// Periods counted: the calls of tick since start that did not return an error.
    constexpr std::uint64_t ticks() const noexcept { return n_ + lag_; }
    /// The last grid time the state reached is t0 + reached() dt: ticks(), or one less after a tick that
    /// ended early (more only while catching up after early ends in a row).
    constexpr std::uint64_t reached() const noexcept { return n_; }
    /// Firings of event i since start.
    constexpr std::size_t firings(std::size_t i) const noexcept { return engine_.memory[i].fired; }
    /// The stepper, as the loop keeps it.
    Stepper& stepper() noexcept { return stepper_; }
    /// The events and their limits (changed limits are checked by the next rearm).
    Set& events() noexcept { return set_; }

private:
    using T = value_type;
    using engine_type = detail::event_engine<state_type, arity, Set>;
    using ptrs_type = std::array<state_type*, arity>;

    // The end of the step being taken, t0 + (n+1) dt, from the counter.
    value_type grid_time() const noexcept { return clock_.time(n_ + 1); }

    status limits_ok() const noexcept {
        return detail::limits_status<Stepper, typename Set::finder, value_type>(Set::size, set_.limits);
    }

    static constexpr bool is_error(status s) noexcept {
        return !(s == status::ok || s == status::stopped_by_event || s == status::event_limit);
    }

    // The quiet tick's step needs more than settle: a crossing (or probes, or a NaN from g), or a grid time
    // that overflowed (then the step is undone: status::invalid_time, nothing else changes).
    template <class System>
    ODESTEP_EVENTS_NOINLINE tick_result<T, Capacity> rest(System& f, const ptrs_type& ptrs,
                                                          typename engine_type::pack& start,
                                                          const typename engine_type::values& g, T t_end) {
        tick_result<T, Capacity> r;
        r.status = status::ok;
        r.t = t_now_;
        r.fired = 0;
        r.event = no_event;
        if (!detail::is_finite(t_end)) {
            for (std::size_t k = 0; k < arity; ++k) *ptrs[k] = start[k];
            detail::reset_if_any(stepper_);
            r.status = status::invalid_time;
            return r;
        }
        const std::uint64_t target = n_ + 1;
        finish_piece(f, ptrs, start, g, t_now_, clock_.dt, t_end, r);
        account(r, target);
        return r;
    }

    // A tick off the quiet path: before start, or after a tick that ended early (or failed inside its
    // period). Up to two pieces, each to the next grid time: the rest of an earlier period, then this one's.
    template <class System>
    ODESTEP_EVENTS_NOINLINE tick_result<T, Capacity> catch_up(System& f, const ptrs_type& ptrs) {
        tick_result<T, Capacity> r;
        r.status = status::ok;
        r.t = t_now_;
        r.fired = 0;
        r.event = no_event;
        if (clock_state_ == clock_state::idle) {
            r.status = status::invalid_time;
            return r;
        }
        const std::uint64_t target = n_ + lag_ + 1;  // this call's period ends at t0 + target dt
        for (int piece = 0; piece < 2 && r.status == status::ok && n_ < target; ++piece) {
            const T t_end = grid_time();
            if (!detail::is_finite(t_end)) {
                r.status = status::invalid_time;
                break;
            }
            // On the grid a step is dt (as in the quiet tick: a multistep history expects it); off it, back to
            // the grid time.
            const T h = off_grid_ ? t_end - t_now_ : clock_.dt;
            if (h == T(0)) {  // an earlier tick stopped on this grid time
                ++n_;
                off_grid_ = false;
                continue;
            }
            const bool partial = off_grid_;
            typename engine_type::pack start;
            const status s = engine_type::step(stepper_, f, ptrs, t_now_, h, start);
            if (s != status::ok) {
                r.status = s;
                break;
            }
            typename engine_type::values g;
            if (engine_.settle(set_, ptrs, t_end, g)) {
                ++n_;
                t_now_ = t_end;
                off_grid_ = false;
            } else {
                finish_piece(f, ptrs, start, g, t_now_, h, t_end, r);
            }
            // A partial step (from where a tick stopped back to the grid) does not fit a multistep history.
            if (partial) detail::reset_if_any(stepper_);
        }
        r.t = t_now_;
        account(r, target);
        return r;
    }

    // The rest of one piece after settle returned false: the engine's advance_rest, its firings appended to
    // r's list, and the clock moved to where the piece ended.
    template <class System>
    void finish_piece(System& f, const ptrs_type& ptrs, typename engine_type::pack& start,
                      const typename engine_type::values& g, T t_start, T h, T t_end, tick_result<T, Capacity>& r) {
        const std::size_t offset = r.fired;
        auto sink = [&r, offset](std::size_t k, std::size_t i, T t) {
            if (offset + k < Capacity) r.firings[offset + k] = event_firing<T>{i, t};
        };
        const detail::step_outcome<T> a =
            engine_.advance_rest(stepper_, f, set_, ptrs, start, g, t_start, h, t_end, sink);
        r.status = a.code;
        r.fired += a.fired;
        r.event = a.event;
        r.t = a.t;
        t_now_ = a.t;
        if (a.code == status::ok) {
            ++n_;
            off_grid_ = false;
        } else if (!(a.t == t_start)) {
            off_grid_ = true;
        }
    }

    // After a tick that left the quiet path: the call counts one period unless it returned an error.
    void account(const tick_result<T, Capacity>& r, std::uint64_t target) noexcept {
        const std::uint64_t counted = is_error(r.status) ? target - 1 : target;
        lag_ = counted > n_ ? counted - n_ : 0;
        clock_state_ = lag_ == 0 && !off_grid_ ? clock_state::on_grid : clock_state::behind;
    }

    // idle: before start; on_grid: the state is at t0 + n dt and no period is owed; behind: the state is off
    // the grid (a tick stopped inside its period) or periods are owed (lag_).
    enum class clock_state : unsigned char { idle, on_grid, behind };

    Stepper stepper_;
    Set set_;
    engine_type engine_{};
    detail::grid_clock<value_type> clock_{};
    value_type t_now_ = value_type(0);  // the time of the state: t0 + n dt, or where a tick stopped
    std::uint64_t n_ = 0;    // the last grid time reached; 64 bits on every target (a 32-bit count of 1 kHz ticks
                             // wraps after 49.7 days)
    std::uint64_t lag_ = 0;  // periods counted beyond n_ (after ticks that ended early)
    clock_state clock_state_ = clock_state::idle;
    bool off_grid_ = false;  // the state is between t0 + n dt and t0 + (n+1) dt
};

/// make_event_stepper(stepper, watch(...)) with the default capacity; make_event_stepper<16>(...) lists up
/// to 16 firings per tick.
template <std::size_t Capacity = 8, class Stepper, class Set>
constexpr event_stepper<Stepper, Set, Capacity> make_event_stepper(Stepper stepper, Set events) {
    return event_stepper<Stepper, Set, Capacity>(stepper, events);
}

}  // namespace odestep

#endif
