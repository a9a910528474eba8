// SPDX-License-Identifier: BSL-1.0
// odestep: where a history-keeping stepper expects its next step.
#ifndef ODESTEP_DETAIL_CONTINUATION_HPP
#define ODESTEP_DETAIL_CONTINUATION_HPP

#include <limits>

#include "../state.hpp"
#include "ops.hpp"

namespace odestep::detail {

// Where a history-keeping stepper expects its next step: the time (within a few ULPs of the run's times:
// integrate computes t0 + i dt from its counter, the stepper t + dt, and far from zero the two differ by
// more than an ULP of dt), the same dt, and the same position object. Anything else, a non-finite t
// included, means someone else's state or a new grid, and the stepper starts afresh.
//
// "Within a few ULPs" is |t_now - t| <= 8 eps (|t| + |dt| + |t_start|). The common case, a caller whose
// time is exactly the t + dt the stepper computed (t += dt, or the counter's time when it rounds the same
// way), is one comparison: expect() stores t only when it is finite (NaN otherwise, which equals nothing),
// so t_now == t proves t_now finite, and |t_now - t| = 0 is within any allowance. Only the other times
// compute the allowance, as 8 eps |t| + 8 eps |dt| + 8 eps |t_start|: each term is at most 8 eps times the
// largest finite value, so the sum is finite whenever t is (written as one product of the sum, it overflowed
// near the top of the range, on a finite grid, and accepted nothing). A NaN t makes it NaN, which accepts
// nothing, and with a finite allowance and a finite t a non-finite t_now fails the comparison by itself.
template <class State, class T = value_type_t<State>>
struct continuation {
    T t = T(0);  // the time the next step is expected at; NaN when that was not finite
    T dt = T(0);
    T t_start = T(0);  // where this history began: the counter's times are t_start + i dt
    const State* x = nullptr;

    /// The same position object at the expected time, whatever the dt (what a kept acceleration a(t, x)
    /// needs: it does not depend on the next step's size).
    constexpr bool at(T t_now, const State& x_now) const noexcept { return x == &x_now && (t_now == t || near(t_now)); }
    /// ... and the same dt (what a history on a grid needs).
    constexpr bool matches(T t_now, T dt_now, const State& x_now) const noexcept {
        return dt == dt_now && at(t_now, x_now);
    }
    /// The same dt at the expected time, whatever the state object (a history the caller vouches for: the
    /// Adams methods, which say step_mismatch rather than restart). After expect() only.
    constexpr bool on_grid(T t_now, T dt_now) const noexcept { return dt == dt_now && (t_now == t || near(t_now)); }
    /// After a step from t_now by dt_now on x_now: the next is expected at t_now + dt_now. `continued` is
    /// the caller's answer before the step (matches() for a history on a grid, at() for a value of x alone,
    /// a(t, x), which does not depend on dt), which nothing has changed since. A step that did not continue
    /// starts a fresh history here; one that did keeps its t_start, the time the allowance is measured from
    /// (for an at() caller whatever the dt: a new dt can only make the allowance smaller than the rounding
    /// of a counter restarted at the change, and a miss costs an evaluation, never a wrong value).
    constexpr void expect(T t_now, T dt_now, const State& x_now, bool continued) noexcept {
        if (!continued) {
            t_start = t_now;
            x = &x_now;
        }
        const T next = t_now + dt_now;
        t = next - next + next;  // next when finite (a zero's sign aside); Inf - Inf is NaN
        dt = dt_now;
    }
    constexpr void clear() noexcept { x = nullptr; }

private:
    // t_now within the allowance of t (which is finite or NaN; dt and t_start are finite).
    constexpr bool near(T t_now) const noexcept {
        constexpr T c = T(8) * std::numeric_limits<T>::epsilon();
        const T s = c * abs_value(t) + c * abs_value(dt) + c * abs_value(t_start);  // no overflow: see above
        return abs_value(t_now - t) <= s;
    }
};

}  // namespace odestep::detail

#endif
