// SPDX-License-Identifier: BSL-1.0
// odestep: the per-tick event loop, event_stepper: one tick per period of a timer, on the grid clock, with the
// per-tick contract (docs/events.md).
#ifndef ODESTEP_EVENTS_STEPPER_HPP
#define ODESTEP_EVENTS_STEPPER_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>

#include "../counts.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "arming.hpp"
#include "bounds.hpp"
#include "engine.hpp"
#include "event.hpp"

/// The per-tick event loop's quiet tick (event_stepper::tick with an explicit or Newtonian stepper) inlines
/// every call in it, the step's and the right-hand side's included (GCC's and Clang's flatten), as the loop
/// written out by hand does. Define it empty to keep the step a call (less flash, more instructions).
#ifndef ODESTEP_EVENTS_TICK_FLATTEN
#if defined(__GNUC__) || defined(__clang__)
#define ODESTEP_EVENTS_TICK_FLATTEN [[gnu::flatten]] inline
#else
#define ODESTEP_EVENTS_TICK_FLATTEN inline
#endif
#endif

namespace odestep {

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
///     does not count: the state is the last good one, at r.t, and the next call tries again from there. One
///     that hands back the tick's own start with nothing fired leaves the loop as it was before the call, the
///     stepper's memory (a history, a kept acceleration) included; the error-controlled substeps keep their
///     adapted step size and counts (docs/events.md).
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
    using stepper_type = Stepper;                      ///< the stepper it drives
    using state_type = typename Stepper::state_type;   ///< the stepper's state
    using value_type = value_type_t<state_type>;       ///< T
    using set_type = Set;                              ///< the event set
    static constexpr std::size_t capacity = Capacity;  ///< firings listed per tick (all are counted)
    /// 1 for y' = f(t, y) (g(t, y)), 2 for Newton's equations (g(t, x, v)).
    static constexpr std::size_t arity =
        detail::event_arity<state_type, std::tuple_element_t<0, decltype(Set::events)>>();

    /// The loop over a stepper and an event set; `start` begins it.
    constexpr event_stepper(Stepper stepper, Set events) : stepper_(stepper), set_(events) {
        detail::require_self_starting<Stepper>();
    }

    /// Starts the clock at t0 with ticks of dt and reads every event function on the initial state. An event
    /// whose function is zero there (or whose root lies within its tolerance after t0) does not fire at t0.
    /// Before anything is evaluated (detail::preflight): t0 and dt as the grid clock checks them, the stepper's
    /// settings (settings_status()), then limits whose work bounds do not fit std::size_t
    /// (status::invalid_setting); on any of them nothing is touched.
    template <class... States>
    [[nodiscard]] status start(value_type t0, value_type dt, const States&... y) {
        static_assert(sizeof...(States) == arity, "odestep: start(t0, dt, y) (Newtonian: start(t0, dt, x, v))");
        const detail::grid_clock<value_type> clock{t0, dt};
        const status checked = detail::preflight(stepper_, t0, dt);
        if (checked != status::ok) return checked;
        const status limited = limits_ok();
        if (limited != status::ok) return limited;
        const std::array<const state_type*, arity> ptrs{&y...};
        const auto work_before = engine_.work;
        const status s = engine_.begin(set_, t0, ptrs);
        if (s != status::ok) {
            engine_.work = work_before;  // (begin evaluated g: the counts stay those of the last start)
            return s;
        }
        // The counts start afresh, with the start's evaluations of g.
        engine_.work = {};
        engine_.work.g = Set::size;
        work_ = {};
        tally_ = {};
        detail::reset_if_any(stepper_);
        clock_ = clock;
        n_ = 0;
        lag_ = 0;
        t_now_ = clock_.time(0);  // t0 + 0 dt, as every grid time
        // Every grid time the 64-bit counter can reach is finite when the last one is (t0 + n dt, rounded, is
        // monotonic in n): then the quiet tick needs no test of its grid time. Otherwise (a dt or t0 near the
        // top of T's range) every tick takes catch_up, which tests it before the step.
        unbounded_clock_ = !detail::is_finite(clock_.time(std::numeric_limits<std::uint64_t>::max()));
        off_grid_ = false;
        settle_clock();
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
        settle_clock();  // (the events' arming may have changed)
        return status::ok;
    }

    /// One tick: one period of the timer, to the grid time t0 + (ticks() + 1) dt (see the class comment).
    /// Before `start`: status::invalid_time, nothing touched.
    // (Always inlined: the caller's frame then holds the quiet tick's few values, and the rare paths' frames,
    // rest and catch_up, are the only other ones on the stack.)
    template <class System, class... States>
    [[nodiscard]] ODESTEP_INLINE tick_result<value_type, Capacity> tick(System&& f, States&... y) {
        static_assert(sizeof...(States) == arity, "odestep: tick(f, y) (Newtonian: tick(a, x, v))");
        if constexpr (detail::exact_rhs_evals_v<Stepper>) {
            return tick_flat(f, y...);  // f's evaluations derived from the step calls (see counts())
        } else {
            auto counted = detail::counting(f, tally_);
            return tick_on(counted, y...);
        }
    }

    /// What the loop did since start (odestep::counts): evaluations of f and of every g (the start's too),
    /// the Jacobians and factorizations of an implicit stepper, the grid times reached (accepted_steps, as
    /// reached()) and the firings. Kept as the loop goes, off the quiet tick's path: a quiet tick counts
    /// nothing (its work is derived), so a caller who wants one tick's counts subtracts two readings.
    odestep::counts counts() const noexcept {
        const auto& w = engine_.work;
        const std::uint64_t quiet = n_ - work_.off_reached;  // quiet ticks that reached their grid time
        const std::uint64_t calls = quiet + work_.quiet_failed + work_.rested + work_.off_steps + w.steps;
        odestep::counts c;
        using S = std::remove_cv_t<Stepper>;
        detail::add_implicit_work<S>(c, calls, tally_, tally_.jacobian != 0);
        c.rhs_evals = detail::exact_rhs_evals_v<S> ? calls * static_cast<std::uint64_t>(S::rhs_evals_per_step) + w.rhs
                                                   : tally_.rhs;
        c.event_evals = (quiet + work_.rested + work_.off_settles) * Set::size + w.g;
        c.accepted_steps = n_;
        for (std::size_t i = 0; i < Set::size; ++i) c.firings += engine_.memory[i].fired;
        return c;
    }

    /// The time of the state: t0 + reached() dt, or the time a tick stopped at.
    constexpr value_type time() const noexcept { return off_grid_ ? t_now_ : clock_.time(n_); }
    /// Periods counted: the calls of tick since start that did not return an error.
    constexpr std::uint64_t ticks() const noexcept { return n_ + lag_; }
    /// The last grid time the state reached is t0 + reached() dt: ticks(), or one less after a tick that
    /// ended early (more only while catching up after early ends in a row).
    constexpr std::uint64_t reached() const noexcept { return n_; }
    /// Firings of event i since start.
    constexpr std::size_t firings(std::size_t i) const noexcept { return engine_.memory[i].fired; }
    /// The stepper, as the loop keeps it.
    Stepper& stepper() noexcept { return stepper_; }
    /// The stepper, read only.
    const Stepper& stepper() const noexcept { return stepper_; }
    /// The events and their limits (changed limits are checked by the next rearm, and a change of the probes
    /// takes effect there).
    Set& events() noexcept { return set_; }
    /// The events, read only.
    const Set& events() const noexcept { return set_; }

private:
    using T = value_type;
    using engine_type = detail::event_engine<state_type, arity, Set>;
    using ptrs_type = std::array<state_type*, arity>;
    using memory_type = detail::stepper_memory<Stepper>;  // the stepper's memory from before a step

    // The quiet tick with every call in it inlined (the step, f, every g), as the loop written out by hand:
    // GCC at -O2 otherwise calls the step out of line, and the values around the call cost the tick a frame
    // and copies. For the steppers whose every step makes rhs_evals_per_step evaluations (the explicit and
    // Newtonian ones); an implicit stepper's Newton iteration stays the stepper's own calls. The rare paths
    // (rest, catch_up) stay out of line (ODESTEP_EVENTS_NOINLINE).
    template <class System, class... States>
    [[nodiscard]] ODESTEP_EVENTS_TICK_FLATTEN tick_result<value_type, Capacity> tick_flat(System& f, States&... y) {
        return tick_on(f, y...);
    }

    template <class System, class... States>
    [[nodiscard]] ODESTEP_INLINE tick_result<value_type, Capacity> tick_on(System& f, States&... y) {
        const std::array<state_type*, arity> ptrs{&y...};
        if (ODESTEP_UNLIKELY(clock_state_ != clock_state::on_grid)) return catch_up(f, ptrs);
        tick_result<T, Capacity> r;  // firings past `fired` stay unwritten: clearing them cost most of a quiet tick
        r.fired = 0;
        r.event = no_event;
        // On the grid the times are the counter's, t0 + n dt, converted where they are used (nothing stores
        // them: a step and events that do not read t, and a caller who does not read r.t, convert nothing).
        const T t_s = clock_.time(n_);
        typename engine_type::pack start;
        const memory_type before(stepper_);  // (a stepper without memory keeps nothing here)
        r.status = engine_type::step(stepper_, f, ptrs, t_s, clock_.dt, start);
        if (ODESTEP_UNLIKELY(r.status != status::ok)) {
            ++work_.quiet_failed;
            r.t = t_s;
            return r;  // y untouched, at t_s
        }
        const T t_end = grid_time();  // finite: an unbounded clock never takes this path (see start)
        typename engine_type::values g;
        if (ODESTEP_UNLIKELY(!engine_.settle_armed(set_, ptrs, t_end, g))) return rest(f, ptrs, start, before, g);
        ++n_;
        r.t = t_end;
        return r;
    }

    // The end of the step being taken, t0 + (n+1) dt, from the counter.
    value_type grid_time() const noexcept { return clock_.time(n_ + 1); }

    status limits_ok() const noexcept {
        return detail::limits_status<Stepper, typename Set::finder, value_type>(Set::size, set_.limits);
    }

    static constexpr bool is_error(status s) noexcept {
        return !(s == status::ok || s == status::stopped_by_event || s == status::event_limit);
    }

    // The quiet tick's step needs more than settle: a crossing (or probes, or a NaN from g).
    template <class System>
    // (ptrs, the state before the step and g by value: the quiet tick then keeps them in registers where
    // they fit and builds the arguments on this path only, instead of copying the state to its frame.)
    ODESTEP_EVENTS_NOINLINE tick_result<T, Capacity> rest(System& f, const ptrs_type ptrs,
                                                          typename engine_type::pack start, const memory_type& before,
                                                          const typename engine_type::values g) {
        ++work_.rested;
        const T t_end = grid_time();  // (converted again here: the quiet tick keeps nothing for this path)
        tick_result<T, Capacity> r;
        r.status = status::ok;
        r.t = time();
        r.fired = 0;
        r.event = no_event;
        const std::uint64_t target = n_ + 1;
        finish_piece(f, ptrs, start, before, g, time(), clock_.dt, t_end, r);
        account(r, target);
        return r;
    }

    // A tick off the quiet path: before start, after a tick that ended early (or failed inside its period),
    // or every tick of an unbounded clock (its grid time is tested here). Up to two pieces, each to the next grid time: the rest of an earlier period, then this one's.
    template <class System>
    ODESTEP_EVENTS_NOINLINE tick_result<T, Capacity> catch_up(System& f, const ptrs_type ptrs) {
        tick_result<T, Capacity> r;
        r.status = status::ok;
        r.t = time();
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
                ++work_.off_reached;
                off_grid_ = false;
                continue;
            }
            const bool partial = off_grid_;
            typename engine_type::pack start;
            const memory_type before(stepper_);
            const status s = engine_type::step(stepper_, f, ptrs, time(), h, start);
            ++work_.off_steps;
            if (s != status::ok) {
                r.status = s;
                break;
            }
            typename engine_type::values g;
            ++work_.off_settles;
            if (engine_.settle(set_, ptrs, t_end, g)) {
                ++n_;
                ++work_.off_reached;
                t_now_ = t_end;
                off_grid_ = false;
            } else {
                finish_piece(f, ptrs, start, before, g, time(), h, t_end, r);
            }
            // A partial step (from where a tick stopped back to the grid) does not fit a multistep history.
            if (partial) detail::reset_if_any(stepper_);
        }
        r.t = time();
        account(r, target);
        return r;
    }

    // The rest of one piece after settle returned false: the engine's advance_rest, its firings appended to
    // r's list, and the clock moved to where the piece ended.
    template <class System>
    ODESTEP_INLINE void finish_piece(System& f, const ptrs_type& ptrs, typename engine_type::pack& start,
                                     const memory_type& before, const typename engine_type::values& g, T t_start, T h,
                                     T t_end, tick_result<T, Capacity>& r) {
        const std::size_t offset = r.fired;
        auto sink = [&r, offset](std::size_t k, std::size_t i, T t) {
            if (offset + k < Capacity) r.firings[offset + k] = event_firing<T>{i, t};
        };
        const detail::step_outcome<T> a =
            engine_.advance_rest(stepper_, before, f, set_, ptrs, start, g, t_start, h, t_end, sink);
        r.status = a.code;
        r.fired += a.fired;
        r.event = a.event;
        r.t = a.t;
        t_now_ = a.t;
        if (a.code == status::ok) {
            ++n_;
            ++work_.off_reached;
            off_grid_ = false;
        } else if (!(a.t == t_start)) {
            off_grid_ = true;
        }
    }

    // After a tick that left the quiet path: the call counts one period unless it returned an error.
    void account(const tick_result<T, Capacity>& r, std::uint64_t target) noexcept {
        const std::uint64_t counted = is_error(r.status) ? target - 1 : target;
        lag_ = counted > n_ ? counted - n_ : 0;
        settle_clock();
    }

    // The quiet tick's path (on_grid) or the general one (behind), after anything that moved the clock or
    // may have changed the events' arming.
    void settle_clock() noexcept {
        const bool quiet_path = lag_ == 0 && !off_grid_ && !unbounded_clock_ && engine_.all_armed;
        clock_state_ = quiet_path ? clock_state::on_grid : clock_state::behind;
    }

    // idle: before start; on_grid: the state is at t0 + n dt, no period is owed, and every event is armed
    // with no probes (the engine's all_armed: the quiet test is then one product per event); behind: the
    // state is off the grid (a tick stopped inside its period), periods are owed (lag_), the clock is
    // unbounded, or an event is not armed (catch_up's step then takes the engine's full quiet test).
    enum class clock_state : unsigned char { idle, on_grid, behind };

    Stepper stepper_;
    Set set_;
    engine_type engine_{};
    detail::grid_clock<value_type> clock_{};
    value_type t_now_ = value_type(0);  // the time of the state off the grid, where a tick stopped (on it: time())
    std::uint64_t n_ = 0;    // the last grid time reached; 64 bits on every target (a 32-bit count of 1 kHz ticks
                             // wraps after 49.7 days)
    std::uint64_t lag_ = 0;  // periods counted beyond n_ (after ticks that ended early)
    clock_state clock_state_ = clock_state::idle;
    bool off_grid_ = false;         // the state is between t0 + n dt and t0 + (n+1) dt
    bool unbounded_clock_ = false;  // some grid time the counter can reach is not finite: every tick in catch_up
    // The work since start off the quiet tick's path, counted where it is done (counts() derives the quiet
    // ticks' work from n_): quiet ticks whose step failed, quiet ticks that went on in rest, catch_up's step
    // calls and settles, and the grid times reached off the quiet path.
    struct tick_work {
        std::uint64_t quiet_failed = 0;
        std::uint64_t rested = 0;
        std::uint64_t off_steps = 0;
        std::uint64_t off_settles = 0;
        std::uint64_t off_reached = 0;
    };
    tick_work work_{};
    detail::evaluation_tally tally_{};  // f and J, counted call by call for a stepper without exact_rhs_evals
};

/// make_event_stepper(stepper, watch(...)) with the default capacity; make_event_stepper<16>(...) lists up
/// to 16 firings per tick.
template <std::size_t Capacity = 8, class Stepper, class Set>
constexpr event_stepper<Stepper, Set, Capacity> make_event_stepper(Stepper stepper, Set events) {
    return event_stepper<Stepper, Set, Capacity>(stepper, events);
}

}  // namespace odestep

#endif
