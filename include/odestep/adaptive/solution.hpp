// SPDX-License-Identifier: BSL-1.0
// odestep: the solution of a free-running adaptive run as an object (SciPy's dense_output, Julia's sol(t)):
// every accepted step's interpolant in caller-provided, fixed-capacity storage, asked for the state at any time
// of the span; and integrate_times with the output times given one at a time (adaptive_sampler).
#ifndef ODESTEP_ADAPTIVE_SOLUTION_HPP
#define ODESTEP_ADAPTIVE_SOLUTION_HPP

#include <array>
#include <cstddef>

#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../integrate.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "adaptive_rk.hpp"
#include "dense.hpp"
#include "integrate_adaptive.hpp"

namespace odestep {

/// \brief The solution of one free-running adaptive run, y(t) anywhere in its span, in fixed storage.
///
/// Filled by `integrate_adaptive(engine, f, y, t0, t1, sol)`: every accepted step's interpolant (the
/// odestep::dense_step of the pair: Dormand-Prince 5(4)'s continuous extension of order 4, DOP853's of order 7,
/// cubic Hermite, order 3, for the other pairs), at most Capacity steps, held in the object itself: no heap,
/// sizeof grows with Capacity (per step 2 + 5 N (DP 5(4)), 2 + 8 N (DOP853) or 2 + 4 N scalars), so a large
/// one belongs in static or caller-owned storage rather than on a small stack. When it is full the run stops
/// with status::storage_full, y the last accepted state at r.t, and the solution holds [t0, r.t].
///
/// `sol(t, out)` writes the state at t: ok for t in the span [t_first(), t_last()] (either direction); the
/// state at the span's start and end is the run's own, bit for bit, and between them the interpolant's, as
/// integrate_times computes it (the same values). A time outside the span, or NaN: status::invalid_time and
/// out untouched (non_finite where the interpolant overflows, as integrate_times reports it).
template <class Method, class State, std::size_t Capacity>
class solution {
    static_assert(Capacity >= 1, "odestep: a solution needs room for at least one step");

public:
    using state_type = State;                                       ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;                         ///< its scalar T
    using method_type = Method;                                     ///< the pair's table tag
    using piece_type = detail::dense_piece<Method, State>;          ///< one step's interpolant
    using solution_tag = void;                                      ///< marks a solution for the loops' overloads
    static constexpr std::size_t capacity = Capacity;               ///< the most steps it holds
    static constexpr int order = dense_step<Method, State>::order;  ///< the interpolant's order

private:
    using T = value_type;

public:
    /// Steps held.
    std::size_t size() const noexcept { return size_; }
    /// No room for another step.
    bool full() const noexcept { return size_ == Capacity; }
    /// The span's start: the run's t0 (0 before any run).
    T t_first() const noexcept { return t_first_; }
    /// The span's end: the end of the last step held (t_first() when none is).
    T t_last() const noexcept { return t_last_; }
    /// Step i's interpolant (i < size()): its start, size and coefficients.
    const piece_type& piece(std::size_t i) const noexcept { return pieces_[i]; }

    /// The state at t into out: ok inside the span; status::invalid_time (out untouched) outside it, for a
    /// NaN or infinite t, and before any run; status::non_finite (out untouched) where the interpolant
    /// overflows between the ends of finite steps (huge states).
    status operator()(T t, State& out) const noexcept {
        if (!started_ || !detail::is_finite(t)) return status::invalid_time;
        const bool forward = !(t_last_ < t_first_);
        const auto before = [forward](T a, T b) { return forward ? a < b : a > b; };
        if (before(t, t_first_) || before(t_last_, t)) return status::invalid_time;
        if (t == t_last_) {
            detail::assign(out, y_last_);
            return status::ok;
        }
        // The last step whose start is not after t (steps are contiguous: each starts where the last ended).
        std::size_t lo = 0;
        std::size_t hi = size_;
        while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            (before(t, pieces_[mid].t0) ? hi : lo) = mid;
        }
        const piece_type& p = pieces_[lo];
        State u;
        p.at_theta((t - p.t0) / p.h, u);
        // The interpolant of finite steps can still overflow between their ends (huge states).
        if (!detail::all_finite(u)) return status::non_finite;
        detail::assign(out, u);
        return status::ok;
    }

    /// Forgets every step (the next run starts afresh).
    void clear() noexcept {
        size_ = 0;
        started_ = false;
    }

    /// The run's start: no step yet, the span [t0, t0] holding y0. (Called by the loops.)
    void start(T t0, const State& y0) noexcept {
        size_ = 0;
        started_ = true;
        t_first_ = t0;
        t_last_ = t0;
        detail::assign(y_last_, y0);
    }
    /// One more accepted step ending at (t_end, y_end); the caller has checked full(). (Called by the loops.)
    void push(const piece_type& p, T t_end, const State& y_end) noexcept {
        pieces_[size_++] = p;
        t_last_ = t_end;
        detail::assign(y_last_, y_end);
    }

private:
    std::array<piece_type, Capacity> pieces_{};
    std::size_t size_ = 0;
    bool started_ = false;
    T t_first_ = T(0);
    T t_last_ = T(0);
    State y_last_{};
};

/// Integrates y' = f(t, y) from t0 to exactly t1 with the engine's free-running steps (the same steps as
/// integrate_adaptive without a solution) and stores every accepted step's interpolant in `sol`, which is
/// restarted at (t0, y) first. Each step's interpolant is completed as it is accepted: for DOP853 three more
/// evaluations of f per step, for a pair without first-same-as-last f at the step's end (the next step's
/// first stage, so only the last step's costs one); none for DP 5(4). Hence at most
/// adaptive_rk::rhs_evals_to_start + max_attempts * (adaptive_rk::rhs_evals_per_attempt +
/// dense_step::rhs_evals_to_complete) evaluations. The result's `steps` counts the accepted steps.
///
/// Statuses as integrate_adaptive (bad arguments: nothing evaluated and sol untouched), and
/// status::storage_full when sol has no room for the next step, with y the last accepted state at r.t and
/// sol holding [t0, r.t]. If completing a step's interpolant fails (non_finite: f gave NaN or Inf at its end
/// or its extra stages), y is that step's end, at r.t, and sol ends at the step's start.
template <class Method, class State, std::size_t Capacity, class System>
[[nodiscard]] integrate_result<value_type_t<State>> integrate_adaptive(adaptive_rk<Method, State>& engine, System&& f,
                                                                       State& y, detail::time_t_of<State> t0,
                                                                       detail::time_t_of<State> t1,
                                                                       solution<Method, State, Capacity>& sol,
                                                                       step_count max_attempts = default_max_attempts) {
    using T = value_type_t<State>;
    status s = detail::preflight(engine, t0, t1, max_attempts);
    if (s != status::ok) return {s, t0, 0, {}};
    sol.start(t0, y);
    if (t0 == t1 && !detail::all_finite(y)) return {status::non_finite, t0, 0, {}};  // an empty run, as integrate()
    const counts before = detail::engine_counts(engine);
    detail::evaluation_tally tally;
    auto counted = detail::counting(f, tally);
    const auto done = [&](status code, T t_end, step_count steps) {
        return integrate_result<T>{code, t_end, steps, detail::engine_work(engine, before, tally)};
    };
    dense_step<Method, State> dense;
    T t = t0;
    step_count accepted = 0;
    for (step_count n = 0; n < max_attempts && t != t1; ++n) {
        if (sol.full()) return done(status::storage_full, t, accepted);
        bool ok = false;
        s = engine.attempt(counted, t, y, t1, ok, dense);
        if (s != status::ok) return done(s, t, accepted);
        if (!ok) continue;
        ++accepted;
        s = dense.complete(counted, engine);
        if (s != status::ok) return done(s, t, accepted);
        sol.push(dense.piece(), t, y);
    }
    if (t != t1) return done(status::substep_limit, t, accepted);
    return done(status::ok, t, accepted);
}

/// \brief integrate_times with the output times given one at a time: `advance_to(f, t_out, y_out)` runs the
/// engine's free-running steps over [t0, t1] as far as t_out needs and writes the state there.
///
/// The steps are those integrate_adaptive takes over [t0, t1] (the output times never shorten them) and the
/// states those integrate_times gives for the same times, bit for bit: between a step's ends the pair's
/// interpolant (odestep::dense_step), at a step's end the step's own state. Each t_out must be finite, in
/// [t0, t1] and not before the previous one along the run (status::invalid_time otherwise, nothing done). One
/// call makes at most max_attempts() attempts (status::substep_limit past it, the run kept at its last
/// accepted step: a later call goes on from there). A failure (non_finite, step_too_small) leaves y_out
/// untouched and the run at its last accepted step; the engine's settings are checked on every call
/// (invalid_tolerance, invalid_setting, nothing done). No heap: the engine, the run's state and one step's
/// interpolant are held in the object.
template <class Method, class State>
class adaptive_sampler {
public:
    using state_type = State;                        ///< the state
    using value_type = value_type_t<State>;          ///< its scalar T
    using engine_type = adaptive_rk<Method, State>;  ///< the error-controlled engine

private:
    using T = value_type;

public:
    /// A run of (a copy of) `engine` over [t0, t1] from y0; nothing is evaluated until advance_to.
    /// Non-finite t0 or t1: every advance_to returns status::invalid_time.
    adaptive_sampler(const engine_type& engine, T t0, const State& y0, T t1,
                     step_count max_attempts = default_max_attempts) noexcept
        : engine_(engine),
          start_(detail::engine_counts(engine)),
          t0_(t0),
          t1_(t1),
          t_(t0),
          last_out_(t0),
          y_(y0),
          max_attempts_(max_attempts) {}

    /// The state at t_out into y_out (see the class).
    template <class System>
    [[nodiscard]] status advance_to(System&& f, T t_out, State& y_out) {
        status s = detail::preflight(engine_, t0_, t1_, max_attempts_);
        if (s != status::ok) return s;
        if (!detail::is_finite(t_out)) return status::invalid_time;
        const bool forward = !(t1_ < t0_);
        const auto before = [forward](T a, T b) { return forward ? a < b : a > b; };
        if (before(t_out, last_out_) || before(t1_, t_out)) return status::invalid_time;
        last_out_ = t_out;
        auto counted = detail::counting(f, tally_);
        for (step_count n = 0;; ++n) {
            if (t_out == t_) {  // the run's own state: t0, or a step's end
                // Only y0 can be non-finite here (a step's end always is finite): as integrate()'s empty run.
                if (!detail::all_finite(y_)) return status::non_finite;
                detail::assign(y_out, y_);
                return status::ok;
            }
            if (has_step_ && !before(t_out, dense_.t_start()) && before(t_out, t_)) {
                s = dense_.complete(counted, engine_);
                if (s != status::ok) return s;
                State u;
                dense_.at(t_out, u);
                // The interpolant of a finite step can still overflow between its ends (huge states).
                if (!detail::all_finite(u)) return status::non_finite;
                detail::assign(y_out, u);
                return status::ok;
            }
            if (n == max_attempts_) return status::substep_limit;
            bool accepted = false;
            s = engine_.attempt(counted, t_, y_, t1_, accepted, dense_);
            if (s != status::ok) return s;
            if (accepted) {
                has_step_ = true;
                ++steps_;
            }
        }
    }

    /// The run's time: the end of its last accepted step (t0 before the first).
    T time() const noexcept { return t_; }
    /// The run's state at time().
    const State& state() const noexcept { return y_; }
    /// Accepted steps so far.
    step_count steps() const noexcept { return steps_; }
    /// The cap on attempts per call.
    step_count max_attempts() const noexcept { return max_attempts_; }
    /// The engine (its settings, step size and counts).
    const engine_type& engine() const noexcept { return engine_; }
    /// What the run did since construction, over every advance_to call (odestep::counts): the evaluations of
    /// f (the first step's estimate, the attempts, the interpolants' extra stages), the accepted and rejected
    /// steps. A caller who wants one call's counts subtracts two readings.
    odestep::counts counts() const noexcept { return detail::engine_work(engine_, start_, tally_); }

private:
    engine_type engine_;
    odestep::counts start_;             // the engine's counts when the run began (its copy's history)
    detail::evaluation_tally tally_{};  // f over every advance_to
    dense_step<Method, State> dense_{};
    T t0_;
    T t1_;
    T t_;
    T last_out_;
    State y_;
    step_count max_attempts_;
    step_count steps_ = 0;
    bool has_step_ = false;
};

}  // namespace odestep

#endif
