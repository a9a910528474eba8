// SPDX-License-Identifier: BSL-1.0
// odestep: Adams-Bashforth and Adams-Bashforth-Moulton (PECE) multistep methods for y' = f(t, y).
#ifndef ODESTEP_MULTISTEP_ADAMS_HPP
#define ODESTEP_MULTISTEP_ADAMS_HPP

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../detail/continuation.hpp"
#include "../detail/ops.hpp"
#include "../rk/explicit_rk.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/adams.hpp"

namespace odestep {

namespace detail {
template <class Stepper>
struct is_explicit_rk : std::false_type {};
template <class Method, class State, class Check>
struct is_explicit_rk<explicit_rk<Method, State, Check>> : std::true_type {};
}  // namespace detail

/// A fixed-step Adams method (Adams-Bashforth, or Adams-Bashforth-Moulton PECE) from `Method::table<T>`.
///
/// Each step evaluates f_n = f(t_n, y_n) at its start and combines it with the k-1 derivatives of the
/// previous steps, which the stepper keeps (with the dt they were taken with and the time of the last step,
/// which the next continues by dt) in a fixed-size array inside the object (newest first, shifted each step, for a small
/// state; a ring for a large one): no heap. An Adams-Bashforth step then
/// costs one evaluation of f, a PECE step two (the second E of PECE is the next step's f_n).
///
/// Starting: while fewer than k-1 derivatives are known, `step` takes the step with the one-step `Starter`
/// (an explicit_rk, rk4 by default) and records the derivative at the start of the step from the starter's
/// own first evaluation (the first needed stage of an explicit table has c = 0 and reads y itself, so it is
/// f(t_n, y_n); no extra evaluation). Those k-1 steps are exactly the starter's; the formula takes over at
/// step k. The starter's order p should be at least k - 1 for the method to keep its order.
///
/// History checks. A NaN or infinite t returns `status::invalid_time` and touches nothing, on any step (it is
/// on no grid, and no history can start there). The first step after construction or `reset()` accepts any
/// finite t and any dt. After that, a step
/// whose dt differs from the history's (exact comparison) or whose t is not the end of the previous step
/// returns `status::step_mismatch` and touches nothing: neither y nor the history. "The end of the previous
/// step" is t_prev + dt to within 8 eps (|t_prev + dt| + |dt| + |t_first|), t_first being the time of the
/// first step since the reset. That admits the times t0 + i dt of a step counter (as odestep::integrate
/// computes them), whose rounding is relative to t0 and i dt and not only to t (from t0 = -1000 with
/// dt = 0.1, a slack of a few ULPs of |t| + |dt| alone fails near t = -50), but not a state from another time.
/// After a mismatch the caller may `reset()` and go on with the new dt or t (the next k-1 steps are the
/// starter's again), or go on with the right ones as if the bad call had not happened.
///
/// Because of that, `odestep::integrate` over an interval that is not a whole number of steps fails at its
/// last, shortened step with `step_mismatch` (y is then the state at the returned t, the last good one).
/// Over a whole number of steps it works: integrate takes its last step as dt exactly when t1 - t_{n-1}
/// differs from dt by the rounding of the grid only (over [0, 1] with dt = 0.1, 0.09999999999999998).
///
/// A NaN or Inf from f or in the new state returns `status::non_finite`, and y and the history are left
/// exactly as they were: the call may be retried.
///
/// After changing y by hand (an event, a new initial condition), call `reset()`: the history belongs to the
/// old trajectory, and the t check cannot tell a changed y at the right time.
///
/// Check (odestep::checked, the default, or odestep::unchecked): with `unchecked` the step does not test y_{n+1}
/// (nor, starting, f_n) for NaN and Inf, and writes y in place; the history's checks (step_mismatch,
/// invalid_time) stay. The first k-1 steps are the Starter's, under the Starter's own policy (give
/// `unchecked_t<rk4<State>>` for none at all).
template <class Method, class State, class Starter = rk4<State>, class Check = checked>
class adams : public stepper_defaults<State> {
public:
    /// The state, std::array<T, N>.
    using state_type = State;
    /// The scalar type T.
    using value_type = value_type_t<State>;
    /// The method (table tag) type.
    using method_type = Method;
    using starter_type = Starter;  ///< the one-step method of the first k-1 steps
    using check_type = Check;      ///< the check policy: odestep::checked or odestep::unchecked
    /// The same stepper under check policy C (odestep::with_check_t); the starter stays as it is.
    template <class C>
    using with_check = adams<Method, State, Starter, C>;
    /// The step tests its results for NaN and Inf (trait; see odestep::stepper_defaults).
    static constexpr bool checks_finiteness = Check::checks_finiteness;

private:
    using T = value_type;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t K = table_type::steps;
    static constexpr std::size_t M = K - 1;  // derivatives kept between steps
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr bool pece = table_type::has_corrector;
    static_assert(detail::is_explicit_rk<Starter>::value, "odestep: the starter must be an odestep::explicit_rk");
    static_assert(std::is_same_v<typename Starter::state_type, State>,
                  "odestep: the starter must step the same State as the multistep method");

public:
    /// The order of the global error (trait; see odestep::stepper_defaults).
    static constexpr int order = tab.order;
    /// Stages per step (trait; see odestep::stepper_defaults).
    static constexpr std::size_t stages = 1;
    /// k: the method reads f at k successive steps, f_n (evaluated in the step) and the k-1 it keeps.
    static constexpr std::size_t steps = K;
    /// Right-hand-side evaluations of a step once the history is full: 1 (Adams-Bashforth) or 2 (PECE).
    static constexpr std::size_t rhs_evals_per_started_step = pece ? 2 : 1;
    /// The most one `step` call makes, the starter's steps included.
    static constexpr std::size_t rhs_evals_per_step = Starter::rhs_evals_per_step > rhs_evals_per_started_step
                                                          ? Starter::rhs_evals_per_step
                                                          : rhs_evals_per_started_step;
    /// Every step continues the history's grid: the same dt (see step_mismatch).
    static constexpr bool uniform_steps = true;

    /// y <- y(t + dt). See the class comment for `step_mismatch` and `non_finite`; on either, neither y nor
    /// the history changed.
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt) {
        // The common path: the history is full (grid_dt_ is NaN until then, which equals nothing), dt is the
        // history's, and t continues its grid: t - dt is the last step's t exactly (which proves t finite, as
        // last_t_ and dt are: an infinite t minus dt is infinite, a NaN one NaN), or failing that t is within
        // near_grid's allowance of t_prev + dt, both inside what the full check accepts. Everything else (the
        // k-1 starting steps, the rest of the full check's allowance, a mismatch, a non-finite t) goes out of
        // line, to off_grid.
        if (ODESTEP_UNLIKELY(!(dt == grid_dt_ && (t - dt == last_t_ || near_grid(t, dt)))))
            return off_grid(f, y, t, dt);
        return formula_step(f, y, t, dt);
    }

    /// Empties the history: the next step accepts any t and dt and the next k-1 steps are the starter's.
    void reset() noexcept {
        count_ = 0;
        slot_ = 0;
        grid_dt_ = std::numeric_limits<T>::quiet_NaN();
    }

    /// How many past derivatives are kept, 0 to k-1; at k-1 the multistep formula steps.
    std::size_t history_size() const noexcept { return count_; }

    /// What a step changes in the stepper: the derivatives kept, how many, and where the next step must start.
    /// (The history's dt and its first time change only at a step that starts a history, after which a
    /// restored count of 0 starts it again.)
    struct memory_type {
        std::array<State, M> history;  ///< the kept derivatives, as history_
        T last_t;                      ///< the time of the last step (the next continues it by dt)
        std::size_t count;             ///< derivatives kept
        std::size_t slot;              ///< the ring's next free slot (0 for a shifted history)
    };
    /// The memory a step changes, to hand back to restore_memory(): a caller that may undo a step (the event
    /// engine, when it rolls a step back to its start) keeps it from before the step.
    memory_type memory() const noexcept { return memory_type{history_, last_t_, count_, slot_}; }
    /// Puts back the memory() kept before the last step (which is then undone: the caller puts y back too).
    void restore_memory(const memory_type& m) noexcept {
        history_ = m.history;
        last_t_ = m.last_t;
        count_ = m.count;
        slot_ = m.slot;
        grid_dt_ = count_ == M ? next_.dt : std::numeric_limits<T>::quiet_NaN();
    }

private:
    // The history's layout. A small state's is newest first (history_[j] = f_{n-1-j}), shifted down as a block
    // after each step, so that every read is at a place fixed at compile time. A large state's is a ring
    // (the next f_n goes to slot_, f_{n-j} is at slot_ - j mod M), where the shift's (M - 1) N copies a step
    // would cost more than the ring's index arithmetic and selects, a few instructions per entry.
    static constexpr bool shifted = (M - 1) * N <= 32;
    std::array<State, M> history_{};
    // The grid's full check (detail::continuation: its dt, the first step's time, and the expected time, set
    // from last_t_ where it is needed), the last step's time (finite), the common path's dt (the history's
    // once it is full, NaN before) and near_grid's constant term.
    detail::continuation<State> next_{};
    T last_t_ = T(0);
    T grid_dt_ = std::numeric_limits<T>::quiet_NaN();
    T slack_ = T(0);
    std::size_t count_ = 0;
    std::size_t slot_ = 0;
    // dt times each weight, the predictor's then the corrector's, for the history's dt: set when the history
    // starts, as every later step has the same dt (the grid check; exact comparison, under which -0 equals
    // +0, so a history of steps of zero may form 0 * f_j with the other zero's sign). The product, once per
    // history instead of once per weight and step (docs/performance.md has the figures).
    std::array<T, pece ? 2 * K : K> scaled_{};

    // Weight rows as types, so each weight is a constant expression inside `combine`. Index 0 is the
    // derivative evaluated in this step (f_n for the predictor, f(t_{n+1}, p) for the corrector), index 1 the
    // next one (f_n for the corrector), and the rest come from the history: predictor index j is f_{n-j},
    // corrector index j is f_{n+1-j}.
    struct predictor {
        /// The number of coefficients of each kind.
        static constexpr std::size_t size = K;
        static constexpr std::size_t from_history = 1;  // first index read from the history
        static constexpr std::size_t offset = 0;        // its first weight in scaled_
        static constexpr T weight(std::size_t j) noexcept { return tab.beta[j]; }
    };
    struct corrector {
        /// The number of coefficients of each kind.
        static constexpr std::size_t size = pece ? K : 0;
        static constexpr std::size_t from_history = 2;
        static constexpr std::size_t offset = K;
        static constexpr T weight(std::size_t j) noexcept { return pece ? tab.gamma[j] : T(0); }
    };

    // out = y + sum_j (dt w_j) v_j with v_0 = first, v_1 = second (if W reads it there) and the history.
    // The weights and the sources are expanded at compile time at every -O, -Os included (there, as loops,
    // the arrays of weights and of pointers were built at run time), so each weight is
    // read from scaled_ and the history through K - 1 pointers chosen once per step; the loop over the
    // components is unrolled at every -O (ODESTEP_STEP_UNROLL_ALWAYS; rolled at -Os, with the right-hand side called
    // out of line: docs/performance.md).
    template <class W>
    ODESTEP_INLINE void combine(State& out, const State& y, const State& first, const State& second) const noexcept {
        combine_terms<W>(out, y, first, second, std::make_index_sequence<W::size - 1>{});
    }
    template <class W, std::size_t... J>
    ODESTEP_INLINE void combine_terms(State& out, const State& y, const State& first, const State& second,
                                      std::index_sequence<J...>) const noexcept {
        const T w0 = scaled_[W::offset];
        const std::array<T, sizeof...(J)> w{scaled_[W::offset + J + 1]...};
        const std::array<const State*, sizeof...(J)> v{&source<W>(J + 1, second)...};
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) {
            T acc = w0 * first[n];
            ((acc += w[J] * (*v[J])[n]), ...);  // j = 1, 2, ... in order
            out[n] = y[n] + acc;
        }
    }
    // Term j >= 1 of W: `second` where W reads it (the corrector's f_n), else the history.
    template <class W>
    ODESTEP_INLINE const State& source(std::size_t j, const State& second) const noexcept {
        if (W::from_history == 2 && j == 1) return second;
        return past(j + 1 - W::from_history);
    }

    // f_{n-back}, back = 1 .. M: shifted, entry back - 1; in the ring, the entry `back` slots before the next
    // free one (slot_ < M).
    ODESTEP_INLINE const State& past(std::size_t back) const noexcept {
        if constexpr (shifted) {
            return history_[back - 1];
        } else {
            return history_[slot_ >= back ? slot_ - back : slot_ + M - back];
        }
    }

    // f_n into the history: shifted, in front, the others one place down (the oldest dropped); in the ring,
    // in the oldest entry's slot.
    ODESTEP_INLINE void record(const State& fn) noexcept {
        if constexpr (shifted) {
            for (std::size_t j = M - 1; j > 0; --j) detail::assign(history_[j], history_[j - 1]);
            detail::assign(history_[0], fn);
        } else {
            detail::assign(history_[slot_], fn);
            slot_ = slot_ + 1 == M ? 0 : slot_ + 1;
        }
    }

    // The user's f, called through detail::evaluate, recording f(t, y) the first time the starter asks for it.
    template <class System>
    struct recording_system {
        System& f;
        const T t;
        const State& y;
        State& fn;
        bool recorded;
        void operator()(T time, const State& x, State& dydt) {
            detail::evaluate(f, time, x, dydt);
            if (!recorded && time == t && detail::same_values(x, y)) {
                detail::assign(fn, dydt);
                recorded = true;
            }
        }
    };

    // The rare calls of step(), out of line, whole (a tail call, so that the common path keeps no frame for
    // it): the k-1 starting steps, and the full check of the history's grid (detail::continuation: the same
    // dt, t the last step's t + dt to within the rounding of a counter's t0 + i dt), then the step. A NaN or
    // infinite t is on no grid: invalid_time, tested only where the grid check failed (it passes only finite
    // times).
    template <class System>
    ODESTEP_NOINLINE status off_grid(System& f, State& y, T t, T dt) {
        if (count_ < M) return starter_step(f, y, t, dt);
        if (!continues(t, dt, y)) return detail::is_finite(t) ? status::step_mismatch : status::invalid_time;
        return formula_step(f, y, t, dt);
    }

    // A step of the formula, once the grid is checked.
    template <class System>
    ODESTEP_INLINE status formula_step(System& f, State& y, T t, T dt) {
        State fn;
        detail::evaluate(f, t, y, fn);
        // Unchecked, y_{n+1} is computed into y itself (component n of the formula reads y[n] alone).
        State next;
        State& out = detail::result_target<!checks_finiteness>(next, y);
        if constexpr (pece) {
            State predicted;
            combine<predictor>(predicted, y, fn, fn);  // the second fn is not read: beta has no f_{n+1}
            State fp;
            detail::evaluate(f, t + dt, static_cast<const State&>(predicted), fp);
            combine<corrector>(out, y, fp, fn);
        } else {
            combine<predictor>(out, y, fn, fn);
        }
        // f_n enters y_{n+1} with a non-zero weight (as does f(t_{n+1}, p) in PECE), and x * Inf or x * NaN is
        // never finite, nor is a sum with a non-finite term: testing y_{n+1} tests the derivatives too.
        if (!detail::all_finite_under<Check>(next)) return status::non_finite;
        last_t_ = t;
        record(fn);
        if constexpr (checks_finiteness) detail::assign(y, next);
        return status::ok;
    }

    // |t - (t_prev + dt)| <= 4 eps |t_prev| + slack_, slack_ = 4 eps (|dt| + |t_first|): half the full check's
    // allowance (detail::continuation, 8 eps (|t_prev + dt| + |dt| + |t_first|)), measured from t_prev, which
    // is finite, so that the bound is finite and an infinite or NaN t fails (as does t_prev + dt overflowing,
    // Inf). A subset of what the full check accepts, inline, for the counter's times t0 + i dt, which are a
    // few ULPs off t_prev + dt at a quarter of the steps.
    ODESTEP_INLINE bool near_grid(T t, T dt) const noexcept {
        constexpr T c = T(4) * std::numeric_limits<T>::epsilon();
        return detail::abs_value(t - (last_t_ + dt)) <= c * detail::abs_value(last_t_) + slack_;
    }

    // The full grid check after a step: where the last step ended (last_t_ + dt, NaN when not finite).
    bool continues(T t, T dt, const State& y) noexcept {
        next_.expect(last_t_, next_.dt, y, true);
        return next_.on_grid(t, dt);
    }

    // Out of line (and off_grid's call): the k-1 starting steps are rare, and their frame (the starter's stages) would otherwise
    // be every step's (x86-64 -Os, Lorenz AB4: 14 instructions a step for the registers saved and restored).
    template <class System>
    ODESTEP_NOINLINE status starter_step(System& f, State& y, T t, T dt) {
        // After the first step since reset(), the grid check of step(). A non-finite t starts no grid. (It
        // would also miss the recorder, NaN == NaN being false, and cost the evaluation below on top of the
        // starter's: one more than rhs_evals_per_step.)
        if (count_ > 0 && !continues(t, dt, y))
            return detail::is_finite(t) ? status::step_mismatch : status::invalid_time;
        if (!detail::is_finite(t)) return status::invalid_time;
        State next = y;
        State fn{};  // written by the recorder; zeroed so that g++ -O1 sees it initialised
        recording_system<System> recorder{f, t, static_cast<const State&>(y), fn, false};
        const status s = Starter{}.step(recorder, next, t, dt);
        if (s != status::ok) return s;
        // Not reached with an explicit_rk starter (its first evaluation is f(t, y)); kept so that a starter
        // that never asks for f(t, y) costs an evaluation rather than a wrong history.
        if (!recorder.recorded) detail::evaluate(f, t, static_cast<const State&>(y), fn);
        // The starter checked its new state; f_n is checked here, as a starter may read it only through a
        // stage input (the midpoint rule's b_1 = 0), where a non-finite value need not reach the new state.
        if (!detail::all_finite_under<Check>(fn)) return status::non_finite;
        next_.expect(t, dt, y, count_ > 0);  // the first step since reset() starts the grid (its t_start)
        last_t_ = t;
        if (count_ == 0) {
            for (std::size_t j = 0; j < K; ++j) scaled_[j] = dt * predictor::weight(j);
            for (std::size_t j = 0; j < corrector::size; ++j) scaled_[K + j] = dt * corrector::weight(j);
        }
        record(fn);
        if (++count_ == M) {  // the fast path's, from the next step on
            grid_dt_ = next_.dt;
            constexpr T c = T(4) * std::numeric_limits<T>::epsilon();
            slack_ = c * detail::abs_value(dt) + c * detail::abs_value(next_.t_start);  // finite: see near_grid
        }
        detail::assign(y, next);
        return status::ok;
    }
};

/// The named multistep steppers. The starter, for the first k-1 steps, is rk4 unless given.
template <class State, class Starter = rk4<State>>
using adams_bashforth2 = adams<tables::bashforth2, State, Starter>;
template <class State, class Starter = rk4<State>>
using adams_bashforth3 = adams<tables::bashforth3, State, Starter>;
template <class State, class Starter = rk4<State>>
using adams_bashforth4 = adams<tables::bashforth4, State, Starter>;
template <class State, class Starter = rk4<State>>
using adams_bashforth5 = adams<tables::bashforth5, State, Starter>;
template <class State, class Starter = rk4<State>>
using adams_bashforth_moulton4 = adams<tables::bashforth_moulton4, State, Starter>;

}  // namespace odestep

#endif
