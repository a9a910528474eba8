// SPDX-License-Identifier: BSL-1.0
// odestep: the cubic Hermite interpolant of a step, shared by dense output (adaptive/dense.hpp) and the event
// loop's location on the interpolant (events/location.hpp).
#ifndef ODESTEP_DETAIL_HERMITE_HPP
#define ODESTEP_DETAIL_HERMITE_HPP

#include <cstddef>

#include "../state.hpp"

namespace odestep {

/// The cubic Hermite interpolant of a step from (t0, y0) to (t0 + h, y1) with slopes f0 = f(t0, y0) and
/// f1 = f(t0 + h, y1), at t0 + theta h:
///     u(theta) = (1 - theta) y0 + theta y1
///                + theta (theta - 1) ((1 - 2 theta)(y1 - y0) + (theta - 1) h f0 + theta h f1)
/// (HNW I, Sec. II.6, eq. (6.7)). It matches y and y' at both ends; its error is O(h^4) locally (order 3),
/// whatever the stepper that made the step, so it serves any stepper of the library.
template <class State>
void hermite_cubic(const State& y0, const State& f0, const State& y1, const State& f1, value_type_t<State> h,
                   value_type_t<State> theta, State& out) noexcept {
    using T = value_type_t<State>;
    const T a = theta * (theta - T(1));
    const T p = T(1) - T(2) * theta;
    const T q = (theta - T(1)) * h;
    const T r = theta * h;
    for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
        const T d = y1[i] - y0[i];
        out[i] = y0[i] + theta * d + a * (p * d + q * f0[i] + r * f1[i]);
    }
}

}  // namespace odestep

#endif
