// SPDX-License-Identifier: BSL-1.0
// odestep: arming, the crossing test and what the loop remembers of each event between evaluation points (its last
// g, the time of its last firing and of its bracket's end, its firings, whether it is armed); the engine's
// rearm applies the band, the dead time and max_firings to it.
#ifndef ODESTEP_EVENTS_ARMING_HPP
#define ODESTEP_EVENTS_ARMING_HPP

#include <cstddef>
#include <type_traits>
#include <utility>

#include "../detail/preflight.hpp"  // has_reset, reset_if_any
#include "event.hpp"

namespace odestep {

namespace detail {

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
    // After the last firing the state went on through zero (no action, or an action after which g heads the
    // way the crossing went, as a dose on a time event): a crossing within the tolerance after `until` is
    // that firing's own. False when the action turned g back (a bounce): such a crossing is a new one.
    bool through = true;
};

}  // namespace detail

}  // namespace odestep

#endif
