// SPDX-License-Identifier: BSL-1.0
// odestep: the event loop's first phase, the description of an event and its settings: the direction, the action,
// the tolerance, band, dead time and firing limit of each event, the loop's limits, the set of events of a run
// (watch), and what a run or a tick with events reports.
#ifndef ODESTEP_EVENTS_EVENT_HPP
#define ODESTEP_EVENTS_EVENT_HPP

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include "../counts.hpp"
#include "../detail/grid_clock.hpp"
#include "../roots/bracket.hpp"
#include "../state.hpp"
#include "../status.hpp"

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
    using state_type = State;                ///< the state the event watches
    using value_type = value_type_t<State>;  ///< T

    G g;                                                        ///< g(t, y) (Newtonian: g(t, x, v))
    odestep::direction direction = odestep::direction::either;  ///< which crossings fire
    /// terminal, record, or a callable; no default initializer: a capturing lambda has no default
    /// constructor (C++20)
    Action action;
    value_type tolerance = value_type(0);  ///< the located bracket's width in time; 0: adjacent times
    value_type band = value_type(0);       ///< re-arm only once |g| > band has been seen
    value_type dead_time = value_type(0);  ///< the least time between two firings
    std::size_t max_firings = 0;           ///< quiet for good after this many firings; 0: no limit

    /// A copy with this tolerance.
    constexpr event with_tolerance(value_type v) const {
        event e = *this;
        e.tolerance = v;
        return e;
    }
    /// A copy with this band.
    constexpr event with_band(value_type v) const {
        event e = *this;
        e.band = v;
        return e;
    }
    /// A copy with this dead time.
    constexpr event with_dead_time(value_type v) const {
        event e = *this;
        e.dead_time = v;
        return e;
    }
    /// A copy with this firing limit.
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

/// The location policy that finds an event's root on the step's interpolant instead of re-stepping:
/// watch<odestep::on_interpolant<>>(...) (Brent), or on_interpolant<odestep::itp> for another finder. The
/// interpolant is the cubic Hermite one through the step's ends and their slopes (hermite_cubic, order 3),
/// for every stepper: f at the step's start and end, two evaluations (two accelerations, Newtonian) per
/// pass of a step that has a crossing or probes, none per iteration of the finder and none in a quiet
/// step. The event's state is then the interpolant's value, with its error (O(dt^4) locally) instead of
/// the stepper's: see docs/events.md for the trade-off, and max_rhs_evals_per_step for the smaller bound.
template <class Finder = brent>
struct on_interpolant {
    using root_finder = Finder;                           ///< the bracketing finder that narrows the root
    static constexpr bool locates_on_interpolant = true;  ///< the event engine's switch
    /// The finder's own worst case (see bracket.hpp).
    template <class T>
    static constexpr std::size_t worst_case_evaluations(T width, T tol) noexcept {
        return Finder::worst_case_evaluations(width, tol);
    }
    /// The finder's narrow (see bracket.hpp).
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(F&& f, T a, T fa, T b, T fb, T tol,
                                                                         std::size_t cap) {
        return Finder::narrow(f, a, fa, b, fb, tol, cap);
    }
};

namespace detail {
// True when the event set's Finder locates on the interpolant (on_interpolant<...>).
template <class Finder, class = void>
struct locates_on_interpolant : std::false_type {};
template <class Finder>
struct locates_on_interpolant<Finder, std::void_t<decltype(Finder::locates_on_interpolant)>>
    : std::bool_constant<Finder::locates_on_interpolant> {};
template <class Finder>
inline constexpr bool locates_on_interpolant_v = locates_on_interpolant<Finder>::value;
// The bracketing finder inside a location policy: Finder itself, or F of on_interpolant<F>.
template <class Finder, bool = locates_on_interpolant_v<Finder>>
struct bracketing_finder {
    using type = Finder;
};
template <class Finder>
struct bracketing_finder<Finder, true> {
    using type = typename Finder::root_finder;
};
template <class Finder>
using bracketing_finder_t = typename bracketing_finder<Finder>::type;
}  // namespace detail

/// The events of one run, given together (each its own type: no type erasure, no heap), the loop's limits
/// and the root finder.
template <class Finder, class... Events>
struct event_set {
    static_assert(sizeof...(Events) > 0, "odestep: an event set needs at least one event");
    using event_set_tag = void;  ///< marks an event set for the driving loops (integrate's overloads)
    using finder = Finder;       ///< the bracketing root finder (Brent by default)
    static constexpr std::size_t size = sizeof...(Events);  ///< how many events

    std::tuple<Events...> events;  ///< the events, in order of priority
    event_limits limits{};         ///< the loop's limits, shared by its events

    /// A copy with these limits.
    constexpr event_set with_limits(event_limits l) const {
        event_set s = *this;
        s.limits = l;
        return s;
    }
    /// A copy located on the step's interpolant (odestep::on_interpolant) with the same root finder: the
    /// location mode chosen apart from the finder, `watch<odestep::itp>(g).located_on_interpolant()` being
    /// `watch<odestep::on_interpolant<odestep::itp>>(g)`. Already on the interpolant: the same set.
    constexpr auto located_on_interpolant() const {
        using located = event_set<on_interpolant<detail::bracketing_finder_t<Finder>>, Events...>;
        return located{events, limits};
    }
};

/// watch(e1, e2, ...): the events of a run, in order of priority (events located at the same time fire in
/// this order). watch<odestep::itp>(...) picks another root finder.
template <class Finder = default_root_finder, class... Events>
constexpr event_set<Finder, Events...> watch(Events... e) {
    return event_set<Finder, Events...>{std::tuple<Events...>(e...), event_limits{}};
}

/// One firing: which event (its index in the set) and when.
template <class T>
struct event_firing {
    std::size_t event;  ///< the event's index in its set
    T t;                ///< the time it fired at
};

/// What integrate with events reports. `status` is ok (t1 reached), stopped_by_event (`event` says which,
/// `t` when), event_limit, or an error; the state is always the one at `t`.
template <class T, std::size_t E>
struct event_integrate_result {
    odestep::status status;              ///< ok, stopped_by_event, event_limit or an error
    T t;                                 ///< the time of the state
    step_count steps;                    ///< grid steps completed
    std::size_t event;                   ///< the terminal event, or no_event
    std::size_t fired;                   ///< firings in total
    std::array<std::size_t, E> firings;  ///< firings per event
    odestep::counts counts{};            ///< evaluations (of f and g), steps and firings of the call
};

/// What one tick of an event_stepper reports: the status (ok, stopped_by_event, event_limit, or an error),
/// the time of the state now (the tick's end unless the tick stopped early), and the firings inside the tick
/// (the first Capacity of them are listed; `fired` counts them all; entries past those are not written).
template <class T, std::size_t Capacity>
struct tick_result {
    odestep::status status;                         ///< ok, stopped_by_event, event_limit or an error
    T t;                                            ///< the time of the state now
    std::size_t fired;                              ///< firings inside the tick, all counted
    std::size_t event;                              ///< the terminal event, or no_event
    std::array<event_firing<T>, Capacity> firings;  ///< the first Capacity firings of the tick
};

}  // namespace odestep

#endif
