// SPDX-License-Identifier: BSL-1.0
// odestep: the work bounds of the event loop: the most right-hand-side and event-function evaluations one step or
// one tick can cost, published as constexpr functions, and the check that refuses limits whose bounds do not fit.
#ifndef ODESTEP_EVENTS_BOUNDS_HPP
#define ODESTEP_EVENTS_BOUNDS_HPP

#include <cstddef>
#include <limits>
#include <type_traits>

#include "../status.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {
// The root finder's cap: the user's, or else the finder's own worst case from a bracket of dt down to the
// default tolerance (at least 4 eps dt): enough for it always to converge.
template <class T, class Finder>
constexpr std::size_t event_iterations(event_limits limits) noexcept {
    return limits.max_iterations != 0 ? limits.max_iterations
                                      : Finder::worst_case_evaluations(T(1), T(4) * std::numeric_limits<T>::epsilon());
}

// The bounds' arithmetic saturates at SIZE_MAX instead of wrapping: a bound that does not fit std::size_t is
// SIZE_MAX, and limits with such a bound are refused (status::invalid_setting).
constexpr std::size_t count_max = std::numeric_limits<std::size_t>::max();
constexpr std::size_t sat_add(std::size_t a, std::size_t b) noexcept { return a > count_max - b ? count_max : a + b; }
constexpr std::size_t sat_mul(std::size_t a, std::size_t b) noexcept {
    return b != 0 && a > count_max / b ? count_max : a * b;
}
}  // namespace detail

/// The most right-hand-side evaluations (accelerations, for Newton's equations) one step with events can
/// cost, for a stepper whose own step costs at most Stepper::rhs_evals_per_step:
///   S [ (1 + F)(1 + P) + F E C ] + F
/// with F firings per step, P probes, E events and C root-finder iterations: the step and its probes, once
/// more after each location whose action ran (the rest of the step from the event), at most C re-steps
/// for each event narrowed in each location (a step makes at most F locations, whether they fire or not),
/// and one evaluation after each location whose action ran (f at the event, for the way g heads next).
/// With no event firing and no probes it is S: the step itself, nothing more. SIZE_MAX when the bound does
/// not fit std::size_t (such limits are refused with status::invalid_setting).
///
/// Located on the interpolant (Finder = on_interpolant<...>) it is (1 + F)(S + 2) + F (S when F = P = 0):
/// at most 1 + F passes, each the step and, if it probes or locates, f at its two ends for the Hermite
/// slopes, and f at each event whose action ran; probes and the finder's iterations read the interpolant
/// and cost no evaluation. That is S [(1 + F) P + F E C] - 2 (1 + F) fewer than re-stepping (fewer whenever
/// F E C >= 4, so for every default cap: RK4, two events, the default limits: 62 against 6572).
template <class Stepper, class Finder = default_root_finder,
          class T = typename std::remove_reference_t<Stepper>::value_type>
constexpr std::size_t max_rhs_evals_per_step(std::size_t events, event_limits limits = {}) noexcept {
    using detail::sat_add;
    using detail::sat_mul;
    const std::size_t s = std::remove_reference_t<Stepper>::rhs_evals_per_step;
    const std::size_t f = limits.max_firings_per_step;
    const std::size_t p = limits.probes;
    if constexpr (detail::locates_on_interpolant_v<Finder>) {
        (void)events;
        if (f == 0 && p == 0) return s;  // no pass probes or locates: no slopes
        return sat_add(sat_mul(sat_add(1, f), sat_add(s, 2)), f);
    }
    return sat_add(sat_mul(s, sat_add(sat_mul(sat_add(1, f), sat_add(1, p)),
                                      sat_mul(sat_mul(f, events), detail::event_iterations<T, Finder>(limits)))),
                   f);
}

/// The most evaluations of event functions one step can cost (all events together):
///   E (1 + F)(1 + P) + F E (C + E + 3)
/// (the last E of each location: every g along the tangent after an action, for the way it heads next).
/// With no event firing and no probes it is E: one per event, at the step's end. SIZE_MAX when it does not
/// fit std::size_t.
template <class T, class Finder = default_root_finder>
constexpr std::size_t max_g_evals_per_step(std::size_t events, event_limits limits = {}) noexcept {
    using detail::sat_add;
    using detail::sat_mul;
    const std::size_t f = limits.max_firings_per_step;
    const std::size_t p = limits.probes;
    const std::size_t c = detail::event_iterations<T, Finder>(limits);
    return sat_add(sat_mul(events, sat_mul(sat_add(1, f), sat_add(1, p))),
                   sat_mul(sat_mul(f, events), sat_add(c, sat_add(events, 3))));
}

/// The most right-hand-side evaluations one `event_stepper::tick` can cost: two steps' worth (a tick after
/// one that ended early first completes the rest of that tick's period, then takes its own; see
/// event_stepper). SIZE_MAX when it does not fit std::size_t.
template <class Stepper, class Finder = default_root_finder,
          class T = typename std::remove_reference_t<Stepper>::value_type>
constexpr std::size_t max_rhs_evals_per_tick(std::size_t events, event_limits limits = {}) noexcept {
    return detail::sat_mul(2, max_rhs_evals_per_step<Stepper, Finder, T>(events, limits));
}

/// The most event-function evaluations one `event_stepper::tick` can cost: two steps' worth.
template <class T, class Finder = default_root_finder>
constexpr std::size_t max_g_evals_per_tick(std::size_t events, event_limits limits = {}) noexcept {
    return detail::sat_mul(2, max_g_evals_per_step<T, Finder>(events, limits));
}

namespace detail {
// Limits are valid when the per-tick bounds (twice the per-step ones) fit std::size_t: then nothing in the
// loop's counting wraps either (probes + 1, the bounds themselves).
template <class Stepper, class Finder, class T>
constexpr status limits_status(std::size_t events, event_limits limits) noexcept {
    const bool fits = max_rhs_evals_per_tick<Stepper, Finder, T>(events, limits) < count_max &&
                      max_g_evals_per_tick<T, Finder>(events, limits) < count_max;
    return fits ? status::ok : status::invalid_setting;
}
}  // namespace detail

}  // namespace odestep

#endif
