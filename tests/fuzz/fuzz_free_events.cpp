// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the free-running loops with events (events/free_running.hpp), integrate_adaptive and
// integrate_times with watch(...), on the explicit pairs (Dormand-Prince 5(4) in double and float, DOP853,
// Bogacki-Shampine 3(2)) and Radau IIA 5, with Brent and, for one pair, ITP and bisection. Drawn: the right-hand
// side (fuzz_support.hpp's script), tolerances, a first step size, the span or four output times, the cap on
// attempts, and three events as fuzz_events draws them (an action that proceeds, bounces, stops or jumps; a
// record; a terminal event; directions, settings and limits). Checks (issue 24 item 3, as docs/events.md and
// docs/adaptive.md promise them): one status of the enum; a rejected argument or setting, or an event function
// not finite at t0, leaves nothing evaluated, observed or touched, and the engine runs afterwards bit for bit as
// its copy from before the call (the twin); at most max_rhs_evals_free_running evaluations of f; observer times
// finite, monotone, inside [t0, t1] (integrate_adaptive: (t0, y0) first, before any evaluation); an ok run ends
// on t1 bit for bit with the last observed state, finite; f not called after it gave NaN or Inf (the explicit
// pairs); a stopped run's y and r.t are its last observation; the firings per event add up, and the callable
// event's firings are its action's calls, at most its max_firings, at least its dead time apart; every action
// runs at a time inside the step after the last observation; the missed-crossing property on the accepted
// steps (integrate_adaptive observes every step's end, and record firings inside steps, which the check tells
// apart by the evaluations of f between observations): when the callable event's g has opposite strict signs,
// in its direction, at two consecutive step ends, its action ran between them (pure g, default settings,
// after the first step, as in fuzz_events; not over an interval that starts at an action's event, which may
// carry the rest of the fired crossing). Not at two consecutive observations: g may cross and cross back
// inside one step, unseen at its ends, with a record firing observed in between
// (seed-crossing-and-back-inside-one-step).
#include <odestep/adaptive.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <tuple>
#include <type_traits>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

template <class T>
using state = std::array<T, 2>;

template <class T>
double d(T v) {
    return static_cast<double>(v);
}

template <class S>
bool same_scalar_bits(S a, S b) {
    return std::memcmp(&a, &b, sizeof(S)) == 0;
}

// Every event-function evaluation, every call of the drawn action and the time of the last one.
template <class T>
struct counter {
    unsigned total = 0;
    unsigned actions = 0;
    bool pure = false;  // no drawn glitch (the twins' runs)
    bool action_outside = false;
    T window_start = T(0);  // the last observation's time
    T t1 = T(0);
    bool forward = true;
    // the callable event's rules: at most max_firings calls (0: no limit), two calls at least dead_time apart
    std::size_t max_firings = 0;
    T dead_time = T(0);
    T last_action = T(0);
};

bool impure() {
    static const bool on = std::getenv("ODESTEP_FUZZ_PURE_EVENTS") == nullptr;
    return on;
}

// g(t, y): y_k - c, t - c or y_0 y_1 - c, with one drawn value at one drawn evaluation (as in fuzz_events).
template <class T>
struct g_function {
    counter<T>* count;
    unsigned kind = 0;
    std::size_t k = 0;
    T c = T(0);
    unsigned poison_at = 0;
    T poison = T(0);

    void read(reader& in) {
        kind = static_cast<unsigned>(in.index(3));
        k = in.index(2);
        c = in.number<T>();
        if (in.index(4) == 0) {
            poison_at = 1U + in.u16() % 256U;
            poison = in.number<T>();
        }
        ODESTEP_FUZZ_TRACE("g: kind %u, k %zu, c %.17g, poison %.17g at %u\n", kind, k, d(c), d(poison), poison_at);
    }
    T operator()(T t, const state<T>& y) const {
        ++count->total;
        if (impure() && !count->pure && count->total == poison_at) return poison;
        switch (kind) {
            case 0: return y[k] - c;
            case 1: return t - c;
            default: return y[0] * y[1] - c;
        }
    }
};

// proceed, a bounce (y_k times -r, r in [0, 1)), stop (after y_k = r when r is not zero), a jump (y_k = r).
template <class T>
struct action {
    counter<T>* count;
    unsigned mode = 0;
    std::size_t k = 0;
    T r = T(0);

    void read(reader& in) {
        mode = static_cast<unsigned>(in.index(4));
        k = in.index(2);
        r = in.number<T>();
        if (!std::isfinite(r)) r = T(0);
        if (mode == 1) r = r < T(0) ? -r - std::floor(-r) : r - std::floor(r);
        ODESTEP_FUZZ_TRACE("action: mode %u, k %zu, r %.17g\n", mode, k, d(r));
    }
    odestep::event_result operator()(T t, state<T>& y) const {
        ODESTEP_FUZZ_CHECK(count->max_firings == 0 || count->actions < count->max_firings,
                           "an event fired more often than its max_firings");
        ODESTEP_FUZZ_CHECK(count->actions == 0 || !(std::fabs(t - count->last_action) < count->dead_time),
                           "an event fired again within its dead time");
        count->last_action = t;
        ++count->actions;
        const bool inside = count->forward ? (count->window_start <= t && t <= count->t1)
                                           : (count->window_start >= t && t >= count->t1);
        if (!inside) count->action_outside = true;
        switch (mode) {
            case 0: return odestep::event_result::proceed;
            case 1: y[k] = -r * y[k]; return odestep::event_result::proceed;
            case 2:
                if (r != T(0)) y[k] = r;
                return odestep::event_result::stop;
            default: y[k] = r; return odestep::event_result::proceed;
        }
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
    return e;
}

odestep::direction draw_direction(reader& in) {
    switch (in.index(3)) {
        case 0: return odestep::direction::rising;
        case 1: return odestep::direction::falling;
        default: return odestep::direction::either;
    }
}

template <class T>
odestep::tolerances<state<T>> draw_tolerances(reader& in) {
    const T relative = in.number<T>();
    const T absolute = in.number<T>();
    return odestep::tolerances<state<T>>::uniform(relative, absolute);
}

// The observer: fuzz_adaptive's free_check with events (an observation may repeat a time: an event's), and the
// missed-crossing watch of the callable event.
template <class T, class G>
struct observer {
    using S = state<T>;
    script<T, 2>* f;
    counter<T>* count;
    T t0;
    T t1;
    S initial;
    const T* times = nullptr;  // integrate_times: the times asked for (observed among event observations)
    S last{};
    T last_t = T(0);
    std::uint64_t observed = 0;
    // the missed-crossing watch, on the step ends (issue 24: g at two consecutive step ends; a record
    // firing's observation lies inside a step, and g may cross and cross back between step ends unseen). The
    // last observation waits until the next one tells whether it was a step's end (or t0): after a step's
    // end, the next step's attempts evaluate f more than record_evals times (every engine here: at least two
    // stages an attempt, DOP853 eleven); after a record firing's observation, the rest of its step evaluates f
    // at most record_evals times (the extension's completion, if a later location reads it first, and the
    // heading after the one action that cuts the step).
    unsigned record_evals = 1;
    bool watch = false;
    G g{nullptr};
    counter<T> own{};
    odestep::direction dir = odestep::direction::either;
    struct point {
        T g;
        unsigned actions;   // the action's calls up to it
        bool after_action;  // (a step end) an action ran in the step that ended here
    };
    bool pending = false;  // the last observation, not yet known to be a step end
    point last_point{};
    std::uint64_t ends = 0;  // the step ends known (t0 the first)
    point end{};             // the last one

    bool along(T a, T b) const { return t1 < t0 ? a >= b : a <= b; }

    void operator()(T t, const S& y) {
        ODESTEP_FUZZ_TRACE("observe #%llu t=%.17g y=(%.17g, %.17g) (evaluations %u, actions %u)\n",
                           static_cast<unsigned long long>(observed), d(t), d(y[0]), d(y[1]), f->since, count->actions);
        ODESTEP_FUZZ_CHECK(std::isfinite(t), "an observer time that is not finite");
        if (observed == 0 && times == nullptr) {
            ODESTEP_FUZZ_CHECK(t == t0 && same_bits(y, initial), "the first observation is not (t0, y0)");
            ODESTEP_FUZZ_CHECK(f->evaluations == 0, "an evaluation before the first observation");
        }
        if (observed > 0) ODESTEP_FUZZ_CHECK(along(last_t, t), "observer times not monotone");
        ODESTEP_FUZZ_CHECK(along(t0, t) && along(t, t1), "an observer time outside [t0, t1]");
        ODESTEP_FUZZ_CHECK(finite(y) || (t == t0 && same_bits(y, initial)), "an observed state not finite");
        if (watch && times == nullptr) {
            settle(f->since > record_evals);
            last_point = point{g(t, y), count->actions, false};
            pending = true;
        }
        f->mark();
        last = y;
        last_t = t;
        count->window_start = t;
        ++observed;
    }

    // The last observation is a step's end (at_end) or not: if it is, the interval from the step end before
    // it is checked. Not checked: the first step, and an interval that starts at an action's event (a crossing
    // located to adjacent times of T may be fired at the left one, before g changes sign: the interval from
    // the event carries that crossing's rest; found in float at t = 10, where g fell by 1.2 in one ULP, and
    // in double with g at -1e-16 at the event).
    void settle(bool at_end) {
        if (!pending || !at_end) return;
        pending = false;
        point p = last_point;
        if (ends > 0) {
            p.after_action = p.actions != end.actions;
            const bool falls = end.g > T(0) && p.g < T(0);
            const bool rises = end.g < T(0) && p.g > T(0);
            const bool crossed = dir == odestep::direction::falling  ? falls
                                 : dir == odestep::direction::rising ? rises
                                                                     : falls || rises;
            ODESTEP_FUZZ_CHECK(!(ends >= 2 && crossed && !end.after_action) || p.after_action,
                               "g crossed between two step ends and its event did not fire");
        }
        end = p;
        ++ends;
    }
};

// The twin: the engine after a call that changed nothing, and its copy from before it, each run the same clean
// program (the drawn f without its drawn values and budget, pure event functions, 0 to 1 from a finite
// state); results and states agree bit for bit.
template <class Engine, class Set, class T>
void twins(const Engine& after, const Engine& before, const Set& set, const script<T, 2>& f, counter<T>& count,
           const state<T>& y0) {
    const counter<T> saved = count;
    count.pure = true;
    count.max_firings = 0;  // (two runs' firings on one counter: the rules are checked in the run itself)
    count.dead_time = T(0);
    count.window_start = T(0);
    count.t1 = T(1);
    count.forward = true;
    const state<T> start = finite(y0) ? y0 : state<T>{T(1), T(0)};
    const auto go = [&](const Engine& from, state<T>& y) {
        Engine engine = from;
        Set events = set;
        script<T, 2> c = f;
        c.poison_count = 0;
        c.budget = std::numeric_limits<unsigned>::max();
        auto rhs = [&c](T t, const state<T>& x) { return c(t, x); };
        // (64 attempts: a drawn f can need millions of steps over [0, 1], and the twin asks only for the same bits)
        return odestep::integrate_adaptive(
            engine, rhs, y, T(0), T(1), events, [](T, const state<T>&) {}, 64);
    };
    state<T> ya = start;
    state<T> yb = start;
    const auto a = go(after, ya);
    const auto b = go(before, yb);
    ODESTEP_FUZZ_CHECK(a.status == b.status && same_scalar_bits(a.t, b.t) && a.steps == b.steps && a.fired == b.fired &&
                           a.firings == b.firings && same_bits(ya, yb),
                       "an engine after a failed call does not run as its copy from before the call");
    count = saved;
}

template <class Engine, class Finder>
void run(reader& in) {
    using T = typename Engine::value_type;
    using S = state<T>;
    script<T, 2> f;
    f.read(in);
    const auto tol = draw_tolerances<T>(in);
    Engine engine(tol);
    if (in.flag()) engine.set_step_size(in.number<T>());
    ODESTEP_FUZZ_TRACE("tolerances: relative %.17g, absolute %.17g; first step %.17g\n", d(tol.rtol[0]), d(tol.atol[0]),
                       d(engine.step_size()));
    counter<T> count;
    g_function<T> g1{&count}, g2{&count}, g3{&count};
    g1.read(in);
    g2.read(in);
    g3.read(in);
    action<T> act{&count};
    act.read(in);
    const auto e1 = with_settings(in, odestep::make_event<S>(g1, draw_direction(in), act));
    ODESTEP_FUZZ_TRACE("event 1: direction %d, tolerance %.17g, band %.17g, dead time %.17g, max_firings %zu\n",
                       static_cast<int>(e1.direction), d(e1.tolerance), d(e1.band), d(e1.dead_time), e1.max_firings);
    count.max_firings = e1.max_firings;
    count.dead_time = e1.dead_time;
    const auto e2 = with_settings(in, odestep::make_event<S>(g2, draw_direction(in), odestep::record));
    const auto e3 = with_settings(in, odestep::make_event<S>(g3, draw_direction(in), odestep::terminal));
    ODESTEP_FUZZ_TRACE("events 2, 3: directions %d %d, tolerances %.17g %.17g, bands %.17g %.17g\n",
                       static_cast<int>(e2.direction), static_cast<int>(e3.direction), d(e2.tolerance), d(e3.tolerance),
                       d(e2.band), d(e3.band));
    auto set = odestep::watch<Finder>(e1, e2, e3);
    using Set = decltype(set);
    constexpr std::size_t E = Set::size;
    odestep::event_limits limits;
    if (in.flag()) {
        limits.max_iterations = in.index(9);
        limits.max_firings_per_step = in.index(10);
        limits.probes = in.index(4);
    }
    set = set.with_limits(limits);
    ODESTEP_FUZZ_TRACE("limits: max_iterations %zu, max_firings_per_step %zu, probes %zu\n", limits.max_iterations,
                       limits.max_firings_per_step, limits.probes);
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const bool sample = in.flag();
    std::array<T, 4> times{};
    T t1;
    if (sample) {
        T t = t0;
        for (auto& ti : times) {
            t = in.flag() ? in.number<T>() : t + in.number<T>();
            ti = t;
        }
        t1 = times[times.size() - 1];
    } else {
        t1 = in.flag() ? in.number<T>() : t0 + in.number<T>();
    }
    const odestep::step_count max_attempts = in.byte() % 200;
    ODESTEP_FUZZ_TRACE("%s: t0 %.17g t1 %.17g y0 (%.17g, %.17g), max_attempts %llu\n",
                       sample ? "integrate_times" : "integrate_adaptive", d(t0), d(t1), d(y[0]), d(y[1]),
                       static_cast<unsigned long long>(max_attempts));
    const S initial = y;
    count.window_start = t0;
    count.t1 = t1;
    count.forward = !(t1 < t0);
    observer<T, g_function<T>> check{&f, &count, t0, t1, y};
    if (sample) check.times = times.data();
    // The missed-crossing watch: the callable event with a pure g and the default settings.
    check.watch = (g1.poison_at == 0 || !impure()) && e1.band == T(0) && e1.dead_time == T(0) && e1.max_firings == 0 &&
                  e1.tolerance == T(0);
    check.g = g1;
    check.record_evals = 1U + static_cast<unsigned>(odestep::detail::free_extension<Engine>::rhs_evals_to_complete);
    check.g.count = &check.own;
    check.dir = e1.direction;
    const Engine twin = engine;
    const Set twin_set = set;
    bool gave_non_finite = false;
    unsigned after_non_finite = 0;
    auto rhs = [&](T t, const S& x) {
        if (gave_non_finite) ++after_non_finite;
        const S out = f(t, x);
        if (!finite(out)) gave_non_finite = true;
        return out;
    };
    const auto r = sample ? odestep::integrate_times(engine, rhs, y, t0, times, set, check, max_attempts)
                          : odestep::integrate_adaptive(engine, rhs, y, t0, t1, set, check, max_attempts);
    ODESTEP_FUZZ_TRACE(
        "result %s t=%.17g y=(%.17g, %.17g) steps=%llu fired %zu (event %zu) evaluations %u actions %u\n",
        odestep::to_string(r.status), d(r.t), d(y[0]), d(y[1]), static_cast<unsigned long long>(r.steps), r.fired,
        r.event, f.evaluations, count.actions);
    ODESTEP_FUZZ_CHECK(valid(r.status), "a status outside the enum");
    // (The explicit pairs' promise, docs/adaptive.md; Radau retries a Newton iteration that met NaN with h halved.)
    if constexpr (!std::is_same_v<Engine, odestep::radau5<S>>)
        ODESTEP_FUZZ_CHECK(after_non_finite == 0, "f called again after it gave NaN or Inf");
    const std::size_t bound = odestep::max_rhs_evals_free_running<Engine, Finder>(E, set.limits, max_attempts);
    ODESTEP_FUZZ_CHECK(f.evaluations <= bound, "more evaluations than max_rhs_evals_free_running");
    // non_finite_event before any observation is a refusal at t0 for integrate_adaptive (it observes t0 first);
    // integrate_times observes only its times, so there it can follow steps (rehearsal finding, now a seed).
    if (rejects_argument(r.status) ||
        (!sample && r.status == odestep::status::non_finite_event && check.observed == 0)) {
        ODESTEP_FUZZ_CHECK(f.evaluations == 0 && check.observed == 0 && r.steps == 0 && count.actions == 0,
                           "a rejected argument, and yet something was evaluated, observed or fired");
        ODESTEP_FUZZ_CHECK(same_bits(y, initial) && same_scalar(r.t, t0), "a rejected argument, and y or t moved");
        twins(engine, twin, twin_set, f, count, initial);
        return;
    }
    ODESTEP_FUZZ_CHECK(r.status != odestep::status::stopped_by_event || r.event < E, "stopped by no event");
    std::size_t fired = 0;
    for (std::size_t i = 0; i < E; ++i) fired += r.firings[i];
    ODESTEP_FUZZ_CHECK(fired == r.fired, "the firings per event do not add up to the firings");
    ODESTEP_FUZZ_CHECK(r.firings[0] == count.actions, "the firings of an event are not the calls of its action");
    ODESTEP_FUZZ_CHECK(!count.action_outside, "an action ran outside the step after the last observation");
    ODESTEP_FUZZ_CHECK(std::isfinite(r.t) && (finite(y) || same_bits(y, initial)),
                       "a run that left a time or a state not finite");
    if (r.status == odestep::status::ok) {
        check.settle(true);  // (its last observation is its last step's end)
        ODESTEP_FUZZ_CHECK(same_scalar_bits(r.t, t1), "an ok run that did not end on t1 bit for bit");
        ODESTEP_FUZZ_CHECK(finite(y), "an ok run with a state not finite");
        if (!sample)
            ODESTEP_FUZZ_CHECK(check.observed > 0 && same_bits(y, check.last), "ok, and y is not the last observed");
        return;
    }
    // (regression-free-stopped-record-and-stop-same-time: a record and a terminal event of one g at one time)
    if (r.status == odestep::status::stopped_by_event) {
        ODESTEP_FUZZ_CHECK(check.observed > 0 && r.t == check.last_t && same_bits(y, check.last),
                           "a stopped run whose y and r.t are not its last observation");
        return;
    }
}

template <class T>
using dp5 = odestep::adaptive_rk<odestep::tables::dormand_prince54, state<T>>;

template <class Engine, class Finder>
struct entry {
    using engine = Engine;
    using finder = Finder;
};

using engines =
    list<entry<dp5<double>, odestep::default_root_finder>, entry<dp5<float>, odestep::default_root_finder>,
         entry<odestep::adaptive_rk<odestep::tables::dop853, state<double>>, odestep::default_root_finder>,
         entry<odestep::adaptive_rk<odestep::tables::bogacki_shampine32, state<double>>, odestep::itp>,
         entry<odestep::radau5<state<double>>, odestep::default_root_finder>, entry<dp5<double>, odestep::bisection>>;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    const std::size_t which = in.index(engines::size);
    ODESTEP_FUZZ_TRACE("engine %zu (0 dp5, 1 dp5 float, 2 dop853, 3 bs32 itp, 4 radau5, 5 dp5 bisection)\n", which);
    dispatch(which, engines{}, [&](auto e) {
        using E = typename decltype(e)::t;
        run<typename E::engine, typename E::finder>(in);
    });
    return 0;
}
