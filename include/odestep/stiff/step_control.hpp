// SPDX-License-Identifier: BSL-1.0
// odestep: the step-size and Jacobian bookkeeping the Newton-based stiff engines share (odestep::radau5,
// odestep::sdirk_adaptive): what they carry from one attempt to the next, their rejections with a smaller
// step, and the choice of the next step after an accepted one, all in the form of Hairer's radau5.f.
#ifndef ODESTEP_STIFF_STEP_CONTROL_HPP
#define ODESTEP_STIFF_STEP_CONTROL_HPP

#include <cstddef>
#include <limits>

#include "../adaptive/control.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../status.hpp"

namespace odestep::detail {

/// The time a stiff engine stopped at, as a caller's grid gives it back: equal within a few rounding errors
/// (t0 + n dt against the engine's t + dt), so a call on the next interval continues with what it carries.
template <class T>
bool same_point_time(T a, T b) noexcept {
    const T d = abs_value(a - b);
    return d <= T(4) * std::numeric_limits<T>::epsilon() * (abs_value(a) + abs_value(b));
}

/// What a Newton-based stiff engine carries between attempts for its step size and its Jacobian, and the
/// three ways an attempt ends: rejected with a smaller step (Newton failed, singular matrix, NaN stages),
/// rejected by the error test, accepted (radau5.f's logic, shared by radau5 and sdirk_adaptive).
template <class T>
struct stiff_step_control {
    T h = T(0);                   ///< |h| of the next attempt; 0: estimate it
    T h_acc = T(0);               ///< Gustafsson's memory: the last accepted |h| ...
    T err_acc = T(1);             ///< ... and its error norm (at least 1e-2)
    std::size_t failures = 0;     ///< singular matrices or NaN stages in a row
    bool need_jacobian = true;    ///< evaluate J before the next attempt
    bool jacobian_fresh = false;  ///< J was evaluated at the current point
    bool keep_lu = false;         ///< Newton was fast: a step 1 to 1.2 times the factored one keeps its LU
    bool first = true;            ///< no step accepted from this point's run yet
    bool rejected_last = false;   ///< the last attempt was rejected
    bool have_accepted = false;   ///< Gustafsson's memory is set
    step_count rejected = 0;      ///< rejected attempts since construction

    /// A start from a new point: everything but the step size and the counts forgotten.
    void new_point() noexcept {
        need_jacobian = true;
        jacobian_fresh = false;
        keep_lu = false;
        first = true;
        rejected_last = false;
        have_accepted = false;
        failures = 0;
    }
    /// A rejected attempt of size h: the next one is |h| factor, with a fresh Jacobian unless this one was.
    status reject(T step, T factor) noexcept {
        ++rejected;
        rejected_last = true;
        keep_lu = false;
        need_jacobian = !jacobian_fresh;
        h = abs_value(step) * factor;
        if (!(h > T(0))) return status::step_too_small;
        return status::ok;
    }
    /// radau5.f's "unexpected step rejection": h halved. `failure` (singular_matrix, non_finite) is returned
    /// once it has happened max_failures times in a row; ok (Newton diverged or reached its cap) never ends
    /// the attempts by itself (the caller's attempt cap bounds them).
    status retry_smaller(T step, status failure, std::size_t max_failures) noexcept {
        if (failure != status::ok && ++failures >= max_failures) {
            failures = 0;
            (void)reject(step, T(1) / T(2));
            return failure;
        }
        return reject(step, T(1) / T(2));
    }
    /// Rejected by the error test: the next |h| is |h| / quot, or a tenth of |h| at a point's first step.
    void reject_error(T habs, T quot) noexcept {
        (void)reject(habs, T(1));
        h = first ? habs / T(10) : habs / quot;
    }
    /// Accepted with error norm err and quotient quot (hairer_quotient): the next |h| from the larger of quot
    /// and Gustafsson's quotient, within max_step, not above |h| after a rejection, and not below the size
    /// planned when the step was shortened to land on t_end (`last`, `planned`). The Jacobian is kept for the
    /// next step when Newton's rate theta was at most theta_keep.
    void accept(const step_control<T>& c, int k, T habs, T err, T quot, bool last, T planned, T theta,
                T theta_keep) noexcept {
        if (have_accepted) quot = max_value(quot, gustafsson_quotient(c, habs, err, h_acc, err_acc, k));
        have_accepted = true;
        h_acc = habs;
        err_acc = max_value(T(1) / T(100), err);
        T hnew = habs / quot;
        if (c.max_step > T(0) && hnew > c.max_step) hnew = c.max_step;
        if (rejected_last && hnew > habs) hnew = habs;
        // A step shortened to land on t_end says nothing against the size planned, unless it asked for less.
        if (last && !(hnew < habs) && planned > hnew) hnew = planned;
        h = hnew > T(0) ? hnew : habs;
        rejected_last = false;
        first = false;
        keep_lu = theta <= theta_keep;
        need_jacobian = theta > theta_keep;
        jacobian_fresh = false;
        failures = 0;
    }
};

}  // namespace odestep::detail

#endif
