// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the event loops through the public API only, integrate(..., watch(...)) and
// make_event_stepper(...).start / tick / rearm, first-order (RK4, the midpoint rule, Dormand-Prince, ABM4) and
// Newtonian (velocity Verlet, Euler-Richardson). One to three events whose functions, directions, actions
// (proceed, a bounce, a stop, a jump; record; terminal), settings and limits are drawn from the input, as
// are the right-hand side and the times. Checks: one status of the enum; a rejected argument or setting
// leaves nothing evaluated, observed or touched; per grid step at most max_rhs_evals_per_step
// right-hand-side and max_g_evals_per_step event-function evaluations, per tick max_rhs_evals_per_tick and
// max_g_evals_per_tick; no ok step from a right-hand side that returned NaN or Inf; observer times on the
// grid (or t1, or the time of the terminal event that ends the run), monotone; a run or tick that failed at
// the time of its last good state leaves that state bit for bit, and one that stopped inside a step stops
// there with a finite state; every tick that is not an error counts one period (ticks() + 1), an error
// none; an ok tick ends on the grid time it reached, t0 + reached() dt, which is finite (defect 5 of issue
// 20: once t0 + n dt overflows, a tick is invalid_time); a stopped one inside its own period. Issue 24: both
// location modes (re-stepping, and on_interpolant: the selector byte's value / 6 is odd); an ok run ends on t1
// bit for bit with finite states (the empty-run rule: ok never hands back a NaN); a stopped run's y and r.t
// are its last observation; the firings of the event with the callable action equal the action's calls; every
// firing a tick lists lies inside the tick. Issue 24 item 3 (the wide sweep, below): float as well as double;
// every root finder of roots/bracket.hpp; more stepper classes (implicit RK, the error-controlled substeps,
// Adams with the midpoint starter, Beeman, the predictor-corrector, the position-form leapfrog); and the twin:
// after a call that failed (a run, a tick or a rearm with an error status that left the state as it was), the
// stepper and the event loop go on bit for bit like copies taken before the call, on the same clean right-hand
// side (no drawn NaN, no budget) and pure event functions.
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

// The same bits (an ok run ends on t1 itself: -0.0 and +0.0 differ here).
template <class S>
bool same_scalar_bits(S a, S b) {
    return std::memcmp(&a, &b, sizeof(S)) == 0;
}

template <class T>
using vec2 = std::array<T, 2>;

// A value for the traces (printf's %g takes a double; float code states the promotion).
template <class T>
double d(T v) {
    return static_cast<double>(v);
}

// Counts every event-function evaluation of the run, and every call of the drawn action (the only thing
// that changes the state besides a step). pure: no drawn glitch (the twins' runs).
struct g_counter {
    unsigned total = 0;
    unsigned since = 0;
    unsigned actions = 0;
    bool pure = false;
    // The callable event's own rules (issue 24 item 3): at most max_firings calls (0: no limit), and two calls
    // at least dead_time apart (the engine's test, |t - last| < dead_time, in T: the last call's time is kept in
    // double, which holds a float exactly).
    std::size_t max_firings = 0;
    double dead_time = 0.0;
    double last_action = 0.0;
};

// An event function may return one drawn value at one drawn evaluation, so that it is not a function of
// (t, y) alone (a sensor, a counter): every call must still return within its bound (issue 19, defect 1).
// ODESTEP_FUZZ_PURE_EVENTS=1 in the environment turns that off.
bool impure() {
    static const bool on = std::getenv("ODESTEP_FUZZ_PURE_EVENTS") == nullptr;
    return on;
}

// g(t, y) (K = 1) or g(t, x, v) (K = 2): y_k - c, t - c, or y_0 y_1 - c (x_k, v_k for Newton's
// equations); impure: with one drawn value (NaN, Inf, ...) returned at a drawn evaluation.
template <class T, std::size_t K>
struct g_function {
    using v2 = vec2<T>;
    g_counter* count;
    unsigned kind = 0;
    std::size_t k = 0;
    T c = T(0);
    unsigned poison_at = 0;
    T poison = T(0);

    void read(reader& in) {
        kind = static_cast<unsigned>(in.index(3));
        k = in.index(4);
        c = in.number<T>();
        if (in.index(4) == 0) {
            poison_at = 1U + in.u16() % 256U;
            poison = in.number<T>();
        }
        ODESTEP_FUZZ_TRACE("g: kind %u (0: y_k - c, 1: t - c, 2: y0 y1 - c), k %zu, c %.17g, poison %.17g at %u\n",
                           kind, k, d(c), d(poison), poison_at);
    }
    T value(T t, const v2& a, const v2& b) const {
        ++count->total;
        ++count->since;
        if (impure() && !count->pure && count->total == poison_at) return poison;
        const T component = k < 2 ? a[k] : b[k - 2];
        switch (kind) {
            case 0: return component - c;
            case 1: return t - c;
            default: return a[0] * a[1] - c;
        }
    }
    template <std::size_t L = K, std::enable_if_t<L == 1, int> = 0>
    T operator()(T t, const v2& y) const {
        return value(t, y, y);
    }
    template <std::size_t L = K, std::enable_if_t<L == 2, int> = 0>
    T operator()(T t, const v2& x, const v2& v) const {
        return value(t, x, v);
    }
};

// An action: proceed without a change, a bounce (component k times -r, r in [0, 1]), stop (after a jump of
// component k to r when r is not zero: issue 24's B), or a jump of component k to a finite value. K states, as
// g_function.
template <class T, std::size_t K>
struct action {
    using v2 = vec2<T>;
    g_counter* count;
    unsigned mode = 0;
    std::size_t k = 0;
    T r = T(0);

    void read(reader& in) {
        mode = static_cast<unsigned>(in.index(4));
        k = in.index(2);
        r = in.number<T>();
        if (!std::isfinite(r)) r = T(0);
        if (mode == 1) r = r < T(0) ? -r - std::floor(-r) : r - std::floor(r);  // in [0, 1)
        ODESTEP_FUZZ_TRACE("action: mode %u (0 proceed, 1 bounce, 2 stop (a jump if r), 3 jump), k %zu, r %.17g\n",
                           mode, k, d(r));
    }
    odestep::event_result apply(T t, v2& y) const {
        ODESTEP_FUZZ_CHECK(count->max_firings == 0 || count->actions < count->max_firings,
                           "an event fired more often than its max_firings");
        ODESTEP_FUZZ_CHECK(count->actions == 0 ||
                               !(std::fabs(t - static_cast<T>(count->last_action)) < static_cast<T>(count->dead_time)),
                           "an event fired again within its dead time");
        count->last_action = static_cast<double>(t);
        ++count->actions;
        switch (mode) {
            case 0: return odestep::event_result::proceed;
            case 1: y[k] = -r * y[k]; return odestep::event_result::proceed;
            case 2:
                if (r != T(0)) y[k] = r;
                return odestep::event_result::stop;
            default: y[k] = r; return odestep::event_result::proceed;
        }
    }
    template <std::size_t L = K, std::enable_if_t<L == 1, int> = 0>
    odestep::event_result operator()(T t, v2& y) const {
        return apply(t, y);
    }
    template <std::size_t L = K, std::enable_if_t<L == 2, int> = 0>
    odestep::event_result operator()(T t, v2& x, v2&) const {
        return apply(t, x);
    }
};

template <class Event>
Event with_settings(reader& in, Event e) {
    using T = decltype(e.tolerance);
    if (in.index(4) == 0) {
        e = e.with_tolerance(in.number<T>());
        e = e.with_band(in.number<T>());
        e = e.with_dead_time(in.number<T>());
        e = e.with_max_firings(in.byte() % 4);
    }
    ODESTEP_FUZZ_TRACE("event: direction %d, tolerance %.17g, band %.17g, dead time %.17g, max firings %zu\n",
                       static_cast<int>(e.direction), d(e.tolerance), d(e.band), d(e.dead_time), e.max_firings);
    return e;
}

odestep::direction draw_direction(reader& in) {
    switch (in.index(3)) {
        case 0: return odestep::direction::rising;
        case 1: return odestep::direction::falling;
        default: return odestep::direction::either;
    }
}

odestep::event_limits draw_limits(reader& in) {
    odestep::event_limits limits;
    if (in.flag()) {
        limits.max_iterations = in.index(9);
        limits.max_firings_per_step = in.index(10);
        limits.probes = in.index(4);
    }
    return limits;
}

// The right-hand side or the force, with the script's counters.
template <class T>
struct system_of {
    script<T, 2>* s;
    vec2<T> operator()(T t, const vec2<T>& y) const { return (*s)(t, y); }
};

// The twins' right-hand side: the drawn one without its drawn values and its budget (a function of (t, y)).
template <class T>
script<T, 2> clean(const script<T, 2>& f) {
    script<T, 2> c = f;
    c.poison_count = 0;
    c.budget = std::numeric_limits<unsigned>::max();
    c.evaluations = 0;
    c.mark();
    return c;
}

// A call that failed: an error status (not ok, stopped_by_event or event_limit).
bool failure(odestep::status s) {
    return !(s == odestep::status::ok || s == odestep::status::stopped_by_event || s == odestep::status::event_limit);
}

// Every event of the set fired at most its max_firings times (0: no limit); firings(i) reads event i's count.
template <class Set, class Firings>
bool within_max_firings(const Set& set, Firings firings) {
    std::size_t i = 0;
    bool ok = true;
    std::apply([&](const auto&... e) { ((ok = ok && (e.max_firings == 0 || firings(i) <= e.max_firings), ++i), ...); },
               set.events);
    return ok;
}

// The missed-crossing property (issue 24) for the event with the callable action: when its g has opposite
// strict signs, in its direction, at two consecutive observations, its action ran between them. Checked only
// where the event is armed wherever g is not zero: a pure g (no drawn poison) and the default settings (no
// band, dead time, firing limit or tolerance), and not over the first step: a root within the time resolution
// of t0 (4 eps (|t0| + |dt|)) is taken for a zero at the start by design (a run begun at a stopped_by_event
// state goes on), and a g steep enough can put one there from far away. g is read on a copy with a counter
// of its own.
template <class T, std::size_t K>
struct crossing_watch {
    bool on = false;
    g_function<T, K> g{nullptr};
    g_counter own;
    odestep::direction dir = odestep::direction::either;
    unsigned seen = 0;
    T last = T(0);
    unsigned actions_last = 0;

    template <class Event>
    void arm(const Event& e) {
        g = e.g;
        g.count = &own;
        dir = e.direction;
        on = (g.poison_at == 0 || !impure()) && e.band == T(0) && e.dead_time == T(0) && e.max_firings == 0 &&
             e.tolerance == T(0);
    }
    template <class... S>
    void see(T t, unsigned actions, const S&... s) {
        if (!on) return;
        const T now = g(t, s...);
        ODESTEP_FUZZ_TRACE("crossing watch: g %.17g at t %.17g (actions %u)\n", d(now), d(t), actions);
        const bool falls = last > T(0) && now < T(0);
        const bool rises = last < T(0) && now > T(0);
        const bool crossed = dir == odestep::direction::falling  ? falls
                             : dir == odestep::direction::rising ? rises
                                                                 : falls || rises;
        ODESTEP_FUZZ_CHECK(!(seen >= 2 && crossed) || actions != actions_last,
                           "g crossed between two observations and its event did not fire");
        ++seen;
        last = now;
        actions_last = actions;
    }
};

// The observer of integrate with events: loop_check, and the event functions' evaluations per grid step; a copy
// of the stepper as it was at the last observation (the twin of a run that fails in the step after it).
template <class T, std::size_t K, class Stepper>
struct event_observer {
    loop_check<T, vec2<T>, K, script<T, 2>>* loop;
    g_counter* g;
    std::size_t g_bound;
    crossing_watch<T, K>* crossing;
    const Stepper* live;
    Stepper at_last{};
    unsigned actions_then = 0;  // the action calls up to the last observation
    template <class... S>
    void operator()(T t, const S&... s) {
        ODESTEP_FUZZ_CHECK(loop->observed == 0 || g->since <= g_bound,
                           "a step evaluated the event functions more often than max_g_evals_per_step");
        g->since = 0;
        at_last = *live;
        actions_then = g->actions;
        crossing->see(t, g->actions, s...);
        (*loop)(t, s...);
    }
};

// adaptive_substeps and the stiff substep forms keep their engine's memory (the adapted step size, the first
// stage f gave at the interval's start) and its counts after a failed call, by design (docs/events.md, "A failed
// call and the stepper's memory"): a later call is a valid one to the same tolerances, not its twin's. Their failed
// calls are checked for the state only. Every other stepper's memory (a multistep history, a kept acceleration)
// is put back by the event engine when a failed step is rolled back to its start.
template <class S, class = void>
struct keeps_memory_on_failure : std::false_type {};
template <class S>
struct keeps_memory_on_failure<S, std::void_t<typename S::engine_type>> : std::true_type {};

// The integrate twin: a stepper after a failed run, and its twin (its copy from before a refused run, or from
// the last observation of a run whose next step failed and left that observation's state), each run the same
// clean program (the clean right-hand side, pure event functions, four steps of dt from t_start on from the same
// finite state; a multistep history then goes on from where the twin's left off); the results and states must
// agree bit for bit. The counters are put back afterwards.
template <class T, class Stepper, std::size_t K, class Set>
void integrate_twins(const Stepper& after, const Stepper& before, const Set& set, const script<T, 2>& f, g_counter& g,
                     const std::array<vec2<T>, K>& y0, T t_start, T dt) {
    const g_counter saved = g;
    g.pure = true;
    g.max_firings = 0;  // (two loops' firings on one counter: the rules are checked in the run itself)
    g.dead_time = 0.0;
    std::array<vec2<T>, K> start = y0;
    for (auto& s : start)
        if (!finite(s)) s = vec2<T>{T(1), T(0)};
    const auto go = [&](const Stepper& from, std::array<vec2<T>, K>& y) {
        Stepper stepper = from;
        Set events = set;
        script<T, 2> c = clean(f);
        system_of<T> sys{&c};
        const T t_end = t_start + T(4) * dt;
        if constexpr (K == 1) {
            return odestep::integrate(stepper, sys, y[0], t_start, t_end, dt, events);
        } else {
            return odestep::integrate(stepper, sys, y[0], y[1], t_start, t_end, dt, events);
        }
    };
    std::array<vec2<T>, K> ya = start;
    std::array<vec2<T>, K> yb = start;
    const auto a = go(after, ya);
    const auto b = go(before, yb);
    ODESTEP_FUZZ_TRACE("integrate twins: %s t=%.17g and %s t=%.17g\n", odestep::to_string(a.status), d(a.t),
                       odestep::to_string(b.status), d(b.t));
    bool same = a.status == b.status && same_scalar_bits(a.t, b.t) && a.steps == b.steps && a.fired == b.fired &&
                a.event == b.event && a.firings == b.firings;
    for (std::size_t k = 0; k < K; ++k) same = same && same_bits(ya[k], yb[k]);
    ODESTEP_FUZZ_CHECK(same, "a stepper after a failed run does not run as its copy from before the run");
    g = saved;
}

template <class T, class Stepper, std::size_t K, class Set>
void run_integrate(reader& in, Stepper& stepper, Set& set, script<T, 2>& f, g_counter& g, std::array<vec2<T>, K>& y) {
    using v2 = vec2<T>;
    const T t0 = in.number<T>();
    const T dt = in.number<T>();
    const T t1 = draw_t1(in, t0, dt);
    constexpr std::size_t E = Set::size;
    using finder = typename Set::finder;
    const std::size_t bound = odestep::max_rhs_evals_per_step<Stepper, finder>(E, set.limits);
    const std::size_t g_bound = odestep::max_g_evals_per_step<T, finder>(E, set.limits);
    loop_check<T, v2, K, script<T, 2>> check{&f, bound, t0, dt, t1, true, y};
    crossing_watch<T, K> crossing;
    crossing.arm(std::get<0>(set.events));
    event_observer<T, K, Stepper> observe{&check, &g, g_bound, &crossing, &stepper};
    system_of<T> sys{&f};
    const Stepper twin = stepper;
    const Set twin_set = set;
    const std::array<v2, K> y0 = y;
    const auto r = [&] {
        if constexpr (K == 1) {
            return odestep::integrate(stepper, sys, y[0], t0, t1, dt, set, observe);
        } else {
            return odestep::integrate(stepper, sys, y[0], y[1], t0, t1, dt, set, observe);
        }
    }();
    ODESTEP_FUZZ_CHECK(check.observed == 0 || g.since <= g_bound,
                       "the last step evaluated the event functions more often than max_g_evals_per_step");
    ODESTEP_FUZZ_CHECK(r.status != odestep::status::stopped_by_event || r.event < E, "stopped by no event");
    std::size_t fired = 0;
    for (std::size_t i = 0; i < E; ++i) fired += r.firings[i];
    ODESTEP_FUZZ_CHECK(fired == r.fired, "the firings per event do not add up to the firings");
    ODESTEP_FUZZ_CHECK(within_max_firings(set, [&](std::size_t i) { return r.firings[i]; }),
                       "an event fired more often than its max_firings");
    const bool quiet_failure = r.status != odestep::status::ok && check.observed > 0 && r.t == check.last_t &&
                               r.fired == 0 && g.actions == observe.actions_then && set.limits.probes == 0 &&
                               g.since <= E;  // as in run_ticks
    if (quiet_failure)
        for (std::size_t k = 0; k < K; ++k)
            ODESTEP_FUZZ_CHECK(same_bits(y[k], check.last[k]), "a failed run whose state is not the last one observed");
    // Issue 24: the firings of the event with the callable action (e1) are its calls; a stopped run's state and
    // time are its last observation (B: also after a stopping action that changed the state at a step's start);
    // an ok run ends on t1 bit for bit (A: -0.0 to +0.0 ends on +0.0), with finite states (the empty-run rule).
    if (!rejects_argument(r.status)) {
        ODESTEP_FUZZ_CHECK(r.firings[0] == g.actions, "the firings of an event are not the calls of its action");
        if (r.status == odestep::status::stopped_by_event) {
            ODESTEP_FUZZ_CHECK(check.observed > 0 && r.t == check.last_t, "a stopped run not at its last observation");
            for (std::size_t k = 0; k < K; ++k)
                ODESTEP_FUZZ_CHECK(same_bits(y[k], check.last[k]),
                                   "a stopped run whose state is not the last observed");
        }
        if (r.status == odestep::status::ok) {
            ODESTEP_FUZZ_CHECK(same_scalar_bits(r.t, t1), "an ok run that did not end on t1 bit for bit");
            for (std::size_t k = 0; k < K; ++k) ODESTEP_FUZZ_CHECK(finite(y[k]), "an ok run with a state not finite");
        }
    }
    check.finish(r, y, false, 0);
    if (failure(r.status) && check.observed == 0) {
        integrate_twins<T>(stepper, twin, twin_set, f, g, y0, T(0), T(0.125));  // refused: as before the call
    } else if (failure(r.status) && quiet_failure && !keeps_memory_on_failure<Stepper>::value) {
        // (a stepper that keeps its engine's memory by design is checked for its state alone, as in run_ticks)
        integrate_twins<T>(stepper, observe.at_last, twin_set, f, g, y, r.t, dt);  // as at the last observation
    }
}

// The tick twin: a loop after a failed call (tick or rearm) that left the state as it was, and its copy from
// before the call, each tick twice from the same state on the clean right-hand side with pure event functions;
// results, states and the loops' clocks and firing counts must agree bit for bit. The counters are put back.
template <class T, class Loop, std::size_t K>
void tick_twins(const Loop& after, const Loop& before, const script<T, 2>& f, g_counter& g,
                const std::array<vec2<T>, K>& y) {
    constexpr std::size_t E = Loop::set_type::size;
    const g_counter saved = g;
    g.pure = true;
    g.max_firings = 0;  // (two loops' firings on one counter: the rules are checked in the run itself)
    g.dead_time = 0.0;
    Loop a = after;
    Loop b = before;
    std::array<vec2<T>, K> ya = y;
    std::array<vec2<T>, K> yb = y;
    script<T, 2> fa = clean(f);
    script<T, 2> fb = clean(f);
    system_of<T> sa{&fa};
    system_of<T> sb{&fb};
    for (int i = 0; i < 2; ++i) {
        const auto ra = std::apply([&](auto&... s) { return a.tick(sa, s...); }, ya);
        const auto rb = std::apply([&](auto&... s) { return b.tick(sb, s...); }, yb);
        ODESTEP_FUZZ_TRACE("tick twins: %s t=%.17g and %s t=%.17g\n", odestep::to_string(ra.status), d(ra.t),
                           odestep::to_string(rb.status), d(rb.t));
        bool same = ra.status == rb.status && same_scalar_bits(ra.t, rb.t) && ra.fired == rb.fired &&
                    ra.event == rb.event && a.ticks() == b.ticks() && a.reached() == b.reached() &&
                    same_scalar_bits(a.time(), b.time());
        const std::size_t listed = ra.fired < ra.firings.size() ? ra.fired : ra.firings.size();
        for (std::size_t k = 0; k < listed && same; ++k)
            same = ra.firings[k].event == rb.firings[k].event && same_scalar_bits(ra.firings[k].t, rb.firings[k].t);
        for (std::size_t e = 0; e < E; ++e) same = same && a.firings(e) == b.firings(e);
        for (std::size_t k = 0; k < K; ++k) same = same && same_bits(ya[k], yb[k]);
        ODESTEP_FUZZ_CHECK(same, "an event loop after a failed call does not tick as its copy from before the call");
    }
    g = saved;
}

template <class T, class Stepper, std::size_t K, class Set>
void run_ticks(reader& in, Stepper& stepper, Set& set, script<T, 2>& f, g_counter& g, std::array<vec2<T>, K>& y) {
    using v2 = vec2<T>;
    constexpr std::size_t E = Set::size;
    using finder = typename Set::finder;
    const std::size_t bound = odestep::max_rhs_evals_per_tick<Stepper, finder>(E, set.limits);
    const std::size_t g_bound = odestep::max_g_evals_per_tick<T, finder>(E, set.limits);
    auto loop = odestep::make_event_stepper(stepper, set);
    system_of<T> sys{&f};
    const auto tick = [&] { return std::apply([&](auto&... s) { return loop.tick(sys, s...); }, y); };
    const auto unchanged = [&](const std::array<v2, K>& before) {
        for (std::size_t k = 0; k < K; ++k)
            if (!same_bits(before[k], y[k])) return false;
        return true;
    };
    if (in.flag()) {  // a tick before start
        const std::array<v2, K> before = y;
        const auto r = tick();
        ODESTEP_FUZZ_CHECK(r.status == odestep::status::invalid_time, "a tick before start was not invalid_time");
        ODESTEP_FUZZ_CHECK(f.evaluations == 0 && unchanged(before), "a tick before start evaluated or touched");
    }
    const T t0 = in.number<T>();
    const T dt = in.number<T>();
    ODESTEP_FUZZ_TRACE("start(t0 %.17g, dt %.17g)\n", d(t0), d(dt));
    const odestep::status started = std::apply([&](const auto&... s) { return loop.start(t0, dt, s...); }, y);
    ODESTEP_FUZZ_CHECK(valid(started), "start: a status outside the enum");
    ODESTEP_FUZZ_CHECK(f.evaluations == 0, "start evaluated the right-hand side");
    if (started != odestep::status::ok) {
        const std::array<v2, K> before = y;
        const auto r = tick();
        ODESTEP_FUZZ_CHECK(r.status == odestep::status::invalid_time,
                           "a tick after a failed start was not invalid_time");
        ODESTEP_FUZZ_CHECK(f.evaluations == 0 && unchanged(before), "a tick after a failed start evaluated or touched");
        return;
    }
    ODESTEP_FUZZ_CHECK(loop.time() == t0 && loop.ticks() == 0, "start: not at t0");
    for (int i = 0, ticks = 1 + static_cast<int>(in.index(32)); i < ticks; ++i) {
        if (in.index(8) == 0) {  // the caller changes the state, and rearms
            y[0][in.index(2)] = in.number<T>();
            if (!finite(y[0])) y[0] = v2{};
            f.mark();
            const auto twin = loop;
            const odestep::status s = std::apply([&](const auto&... st) { return loop.rearm(st...); }, y);
            ODESTEP_FUZZ_CHECK(valid(s), "rearm: a status outside the enum");
            ODESTEP_FUZZ_CHECK(f.since == 0, "rearm evaluated the right-hand side");
            if (s != odestep::status::ok && !keeps_memory_on_failure<Stepper>::value)
                tick_twins<T>(loop, twin, f, g, y);  // "on a failure nothing changes"
        }
        const std::array<v2, K> before = y;
        const auto twin = loop;
        const T t_before = loop.time();
        const std::uint64_t n_before = loop.ticks();
        const std::uint64_t reached_before = loop.reached();
        const T grid_end = t0 + static_cast<T>(n_before + 1) * dt;
        const unsigned actions_before = g.actions;
        f.mark();
        g.since = 0;
        const auto r = tick();
        ODESTEP_FUZZ_TRACE("tick %llu: %s t=%.17g fired %zu (evaluations %u, g %u)\n",
                           static_cast<unsigned long long>(n_before), odestep::to_string(r.status), d(r.t), r.fired,
                           f.since, g.since);
        ODESTEP_FUZZ_CHECK(valid(r.status), "tick: a status outside the enum");
        ODESTEP_FUZZ_CHECK(f.since <= bound, "a tick made more evaluations than max_rhs_evals_per_tick");
        ODESTEP_FUZZ_CHECK(g.since <= g_bound, "a tick evaluated the event functions more than max_g_evals_per_tick");
        const bool error = failure(r.status);
        ODESTEP_FUZZ_CHECK(loop.ticks() == n_before + (error ? 0U : 1U),
                           "a tick that was not an error did not count one period (or an error counted one)");
        ODESTEP_FUZZ_CHECK(r.t == loop.time(), "tick: r.t is not the loop's time");
        ODESTEP_FUZZ_CHECK(loop.firings(0) == g.actions, "the firings of an event are not the calls of its action");
        ODESTEP_FUZZ_CHECK(within_max_firings(set, [&](std::size_t e) { return loop.firings(e); }),
                           "an event fired more often than its max_firings");
        if (!error) {
            const std::size_t listed = r.fired < r.firings.size() ? r.fired : r.firings.size();
            const bool fwd = dt > T(0);
            for (std::size_t k = 0; k < listed; ++k)
                ODESTEP_FUZZ_CHECK(fwd ? (t_before <= r.firings[k].t && r.firings[k].t <= r.t)
                                       : (t_before >= r.firings[k].t && r.firings[k].t >= r.t),
                                   "a firing outside its tick");
        }
        ODESTEP_FUZZ_CHECK(r.status != odestep::status::stopped_by_event || r.event < E, "stopped by no event");
        const bool forward = dt > T(0);
        const auto along = [forward](T a, T b) { return forward ? a <= b : a >= b; };
        if (r.status == odestep::status::ok) {
            ODESTEP_FUZZ_CHECK(!f.non_finite_since, "a tick whose right-hand side returned NaN or Inf was ok");
            ODESTEP_FUZZ_CHECK(r.t == t0 + static_cast<T>(loop.reached()) * dt && loop.reached() <= loop.ticks(),
                               "an ok tick not on the grid time it reached, t0 + reached() dt");
            ODESTEP_FUZZ_CHECK(std::isfinite(r.t), "an ok tick whose time is not finite");
            for (const auto& s : y) ODESTEP_FUZZ_CHECK(finite(s), "an ok tick left a state that is not finite");
        } else if (r.t == t_before && loop.reached() == reached_before && r.fired == 0 && g.actions == actions_before &&
                   set.limits.probes == 0 && g.since <= E) {
            // Nothing fired, no action ran, no probe, no location (g read only at the step's end), no step
            // completed (a tick completes an earlier one that ended early: with dt under the ULP of t, that step
            // moves the state and reached() but not the time): the tick stopped at its start, with the state
            // before it. (A firing, a probe or a location that fired
            // nothing, as after an impure g's glitch, can leave the state at t_s + s for an s that t_s + s does
            // not resolve, where dt is far below the ULP of t: then only finiteness is asked.) Such a failed
            // tick is one the loop never saw: it goes on as its copy from before the tick (the twin).
            ODESTEP_FUZZ_CHECK(unchanged(before), "a failed tick whose state is not the one before it");
            if (error && !keeps_memory_on_failure<Stepper>::value) tick_twins<T>(loop, twin, f, g, y);
        } else if (r.t == t_before) {
            bool all_finite = true;
            for (const auto& s : y) all_finite = all_finite && finite(s);
            ODESTEP_FUZZ_CHECK(unchanged(before) || all_finite, "a stopped tick left a state that is not finite");
        } else {
            ODESTEP_FUZZ_CHECK(std::isfinite(r.t) && along(t_before, r.t) && along(r.t, grid_end),
                               "a tick stopped outside its step");
            for (const auto& s : y) ODESTEP_FUZZ_CHECK(finite(s), "a stopped tick left a state that is not finite");
        }
    }
}

template <class T, class Stepper, std::size_t K, class Set>
void run_set(reader& in, Stepper& stepper, Set set, script<T, 2>& f, g_counter& g) {
    std::array<vec2<T>, K> y{};
    for (auto& s : y) s = vec2<T>{in.number<T>(), in.number<T>()};
    set = set.with_limits(draw_limits(in));
    ODESTEP_FUZZ_TRACE("%zu events; limits: iterations %zu, firings per step %zu, probes %zu; y0 (%.17g, %.17g)\n",
                       Set::size, set.limits.max_iterations, set.limits.max_firings_per_step, set.limits.probes,
                       d(y[0][0]), d(y[0][1]));
    if (in.flag()) {
        run_integrate<T>(in, stepper, set, f, g, y);
    } else {
        run_ticks<T>(in, stepper, set, f, g, y);
    }
}

// The drawn program: f, three event functions, the action, three events; then (All) one, two or three of them
// watched, or (the wide sweep, to bound the build) all three.
template <class Stepper, class Finder, bool All>
void run(reader& in) {
    using T = odestep::value_type_t<typename Stepper::state_type>;
    constexpr std::size_t K = Stepper::system == odestep::system_form::first_order ? 1 : 2;
    script<T, 2> f;
    f.read(in);
    g_counter g;
    Stepper stepper;
    g_function<T, K> g1{&g}, g2{&g}, g3{&g};
    g1.read(in);
    g2.read(in);
    g3.read(in);
    action<T, K> act{&g};
    act.read(in);
    const auto e1 = with_settings(in, odestep::make_event<vec2<T>>(g1, draw_direction(in), act));
    g.max_firings = e1.max_firings;
    g.dead_time = static_cast<double>(e1.dead_time);
    const auto e2 = with_settings(in, odestep::make_event<vec2<T>>(g2, draw_direction(in), odestep::record));
    const auto e3 = with_settings(in, odestep::make_event<vec2<T>>(g3, draw_direction(in), odestep::terminal));
    const std::size_t watched = in.index(3);
    if constexpr (All) {
        switch (watched) {
            case 0: run_set<T, Stepper, K>(in, stepper, odestep::watch<Finder>(e1), f, g); break;
            case 1: run_set<T, Stepper, K>(in, stepper, odestep::watch<Finder>(e1, e2), f, g); break;
            default: run_set<T, Stepper, K>(in, stepper, odestep::watch<Finder>(e1, e2, e3), f, g); break;
        }
    } else {
        run_set<T, Stepper, K>(in, stepper, odestep::watch<Finder>(e1, e2, e3), f, g);
    }
}

using v2 = vec2<double>;
using f2 = vec2<float>;

// The first selector's steppers (double, Brent; every event set size).
using steppers =
    list<odestep::rk4<v2>, odestep::midpoint<v2>, odestep::dormand_prince54<v2>, odestep::adams_bashforth_moulton4<v2>,
         odestep::velocity_verlet<v2>, odestep::newtonian_euler_richardson<v2>>;

// The wide sweep: a stepper, a root finder, float or double, either location mode. The first selector's six
// steppers in float; in double the stepper classes they leave out (implicit RK with Newton, the error-controlled
// substeps of a pair, Adams with the midpoint starter, Beeman's and the predictor-corrector's history, the
// position-form leapfrog); each with one of the four finders other than Brent (Brent: the first selector), so
// that every finder meets a first-order and a Newtonian stepper and float and double. One entry is one compiled
// pair of loops (the build's cost): the other aliases of these classes (the explicit RK tables, the splitting
// tables) run the same code with other coefficients.
template <class Stepper, class Finder>
struct entry {
    using stepper = Stepper;
    using finder = Finder;
};
using odestep::anderson_bjorck;
using odestep::bisection;
using odestep::illinois;
using odestep::itp;
using wide = list<
    // float
    entry<odestep::rk4<f2>, illinois>, entry<odestep::midpoint<f2>, itp>,
    entry<odestep::dormand_prince54<f2>, bisection>, entry<odestep::adams_bashforth_moulton4<f2>, anderson_bjorck>,
    entry<odestep::velocity_verlet<f2>, itp>, entry<odestep::newtonian_euler_richardson<f2>, bisection>,
    // double
    entry<odestep::backward_euler<v2>, illinois>, entry<odestep::dormand_prince54_substeps<v2>, anderson_bjorck>,
    entry<odestep::adams_bashforth2<v2, odestep::midpoint<v2>>, bisection>, entry<odestep::beeman<v2>, illinois>,
    entry<odestep::predictor_corrector<v2>, itp>, entry<odestep::leapfrog_position_form<v2>, anderson_bjorck>>;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    // The selector: below 12, the stepper of `steppers` (value % 6) and the location mode ((value / 6) odd: on
    // the interpolant), so that the inputs written before the wide sweep keep their meaning; from 12 on, the
    // wide sweep: the next byte picks the entry, the one after it the location mode (odd: on the interpolant).
    const std::uint8_t selector = in.byte();
    if (selector < 2 * steppers::size) {
        const bool on_interpolant = (selector / steppers::size) % 2 == 1;
        dispatch(selector % steppers::size, steppers{}, [&](auto s) {
            using S = typename decltype(s)::t;
            if (on_interpolant) {
                run<S, odestep::on_interpolant<>, true>(in);
            } else {
                run<S, odestep::default_root_finder, true>(in);
            }
        });
        return 0;
    }
    const std::size_t which = in.index(wide::size);
    const bool on_interpolant = in.flag();
    dispatch(which, wide{}, [&](auto e) {
        using E = typename decltype(e)::t;
        if (on_interpolant) {
            run<typename E::stepper, odestep::on_interpolant<typename E::finder>, false>(in);
        } else {
            run<typename E::stepper, typename E::finder, false>(in);
        }
    });
    return 0;
}
