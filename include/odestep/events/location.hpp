// SPDX-License-Identifier: BSL-1.0
// odestep: the event engine's location: the state at a point of a step (by re-stepping from the step's start,
// or on the Hermite interpolant of the step's ends), and the narrowing of a bracket to the earliest crossing
// (locate), with the set's root finder.
#ifndef ODESTEP_EVENTS_LOCATION_HPP
#define ODESTEP_EVENTS_LOCATION_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../detail/hermite.hpp"
#include "../detail/ops.hpp"
#include "../roots/bracket.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "arming.hpp"
#include "bounds.hpp"
#include "engine_base.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {

// The location of the event engine (event_engine derives from it).
template <class State, std::size_t K, class Set>
class event_location;

template <class State, std::size_t K, class Finder, class... Events>
class event_location<State, K, event_set<Finder, Events...>>
    : public event_engine_base<State, K, event_set<Finder, Events...>> {
    using base = event_engine_base<State, K, event_set<Finder, Events...>>;

public:
    using base::E;
    using typename base::pack;
    using typename base::refs;
    using typename base::set_type;
    using typename base::T;
    using typename base::values;

    // Located on the interpolant (on_interpolant): the Hermite slopes at a pass's two ends.
    static constexpr bool interpolates = locates_on_interpolant_v<Finder>;
    struct hermite_slopes {
        pack d0;             // the derivative at the pass's start (Newtonian: v and a)
        pack d1;             // and at its end
        bool ready = false;  // computed in this pass
    };
    struct no_slopes {};  // (re-stepping: nothing, and nothing on the stack)
    using slopes = std::conditional_t<interpolates, hermite_slopes, no_slopes>;

protected:
    using base::all_finite_pack;
    using base::crossed;
    using base::evaluate_all;
    using base::evaluate_one;
    using base::memory;
    using base::pointers;
    using base::visit;
    using base::work;
    using typename base::seq;

    // The time of the point s into a step from t_s (s in [0, h]): t_s + s, except that the step's end is
    // t_end itself (from the caller's counter, which t_s + h can miss by an ULP: the step's end is then read
    // at one time by the quiet test and at another by the location, and a crossing between the two is seen
    // and not found), and no time lies past t_end.
    static T time_at(T t_s, T s, T h, T t_end) noexcept {
        if (s == h) return t_end;
        const T t = t_s + s;
        return (h > T(0) ? t > t_end : t < t_end) ? t_end : t;
    }

    // The state s into the pass from (t_s, start) to (t_end, y_end), into out: by re-stepping (the stepper's
    // own state there: `trial`, a copy of the stepper, reset first, steps s from start), or on the
    // interpolant (Hermite from start, y_end and the slopes d, which the first call of a pass computes: f at
    // both ends; NaN or Inf there is non_finite, and the caller rolls back to the pass's start).
    template <class Stepper, class System>
    ODESTEP_INLINE status state_at(Stepper& trial, System& f, const pack& start, const refs& y_end, slopes& d, T t_s,
                                   T s, T h, T t_end, pack& out) {
        if constexpr (interpolates) {
            (void)trial;
            if (ODESTEP_UNLIKELY(!d.ready)) {
                const status sl = hermite_ends(f, start, y_end, t_s, t_end, d);
                if (sl != status::ok) return sl;
            }
            interpolate(start, y_end, d, s, h, out);
            // finite ends and slopes can still give an overflowing cubic (h f near the largest T)
            return all_finite_pack(out) ? status::ok : status::non_finite;
        } else {
            (void)d, (void)y_end, (void)h, (void)t_end;
            return restep(trial, f, start, t_s, s, out);
        }
    }
    // The stepper's own state s after (t_s, start): trial, a copy of the stepper, reset, steps s.
    template <class Stepper, class System>
    ODESTEP_INLINE status restep(Stepper& trial, System& f, const pack& start, T t_s, T s, pack& out) {
        out = start;
        reset_if_any(trial);
        ++work.steps;
        return call_step(trial, f, pointers(out), t_s, s, seq{});
    }
    // The Hermite interpolant at s into the pass of h (the slopes d ready).
    ODESTEP_INLINE static void interpolate(const pack& start, const refs& y_end, const slopes& d, T s, T h, pack& out) {
        if constexpr (interpolates) {
            const T theta = s / h;
            for (std::size_t k = 0; k < K; ++k) hermite_cubic(start[k], d.d0[k], *y_end[k], d.d1[k], h, theta, out[k]);
        } else {
            (void)start, (void)y_end, (void)d, (void)s, (void)h, (void)out;
        }
    }

    // The slopes at the pass's ends: f(t, y) (Newtonian: x' = v and v' = a(t, x, v)), two evaluations. Kept
    // out of line: the rare path of the rare path.
    template <class System>
    ODESTEP_EVENTS_NOINLINE status hermite_ends(System& f, const pack& start, const refs& y_end, T t_s, T t_end,
                                                slopes& d) {
        work.rhs += 2;
        if constexpr (K == 1) {
            odestep::detail::evaluate(f, t_s, start[0], d.d0[0]);
            odestep::detail::evaluate(f, t_end, static_cast<const State&>(*y_end[0]), d.d1[0]);
        } else {
            d.d0[0] = start[1];
            d.d0[1] = acceleration(f, t_s, start[0], start[1]);
            d.d1[0] = *y_end[1];
            d.d1[1] =
                acceleration(f, t_end, static_cast<const State&>(*y_end[0]), static_cast<const State&>(*y_end[1]));
        }
        if (!all_finite_pack(d.d0) || !all_finite_pack(d.d1)) return status::non_finite;
        d.ready = true;
        return status::ok;
    }

    // Narrows [a, b] (the crossings between lo = a and b) to the earliest one: every event crossed by b is
    // located on [lo, b] in turn, and b only moves earlier. Re-steps go from the step's start (on `trial`,
    // a copy of the stepper, reset before each), so the event state is the integrator's own. On return [a, b]
    // brackets the earliest crossing, a_state and b_state are the states there and g_b all g at b.
    template <class Stepper, class System>
    ODESTEP_INLINE status locate(Stepper& trial, System& f, set_type& set, const pack& start, const refs& y_end,
                                 slopes& d, T t_s, T h, T t_end, T lo, const pack& lo_state, T& a, T& b, pack& a_state,
                                 pack& b_state, values& g_b) {
        // Half the spacing of T at the step's times: a bracket that narrow, in s, has ends whose times are
        // adjacent or equal (each end rounds by at most half a spacing). (The spacing below the larger time,
        // which is the smaller one at a power of two, and never below the least subnormal.)
        const T larger = max_value(abs_value(t_s), abs_value(t_end));
        const T default_tolerance =
            max_value((larger - std::nextafter(larger, T(0))) / T(2), std::numeric_limits<T>::denorm_min());
        const std::size_t cap = event_iterations<T, Finder>(set.limits);
        // The trial states live in h-scaled units of time: s in (0, h] (or [h, 0) integrating backwards).
        // The finders want a < b, so they work on u = s / sign(h).
        const T sign_h = h < T(0) ? T(-1) : T(1);
        pack trial_state;
        status failure = status::ok;
        // a starts at lo: a_state is the state there until an event's bracket moves it (so that it holds a
        // state on every path, which arm-none-eabi-g++'s -Wmaybe-uninitialized could not see).
        a_state = lo_state;
        for (std::size_t c = 0; c < E; ++c) {
            if (!crossed(set, c, g_b[c])) continue;
            const T side = memory[c].g > T(0) ? T(-1) : T(1);  // f = side * g is negative before the crossing
            const T fb = side * g_b[c];
            if (fb == T(0)) {  // exactly zero at b: the root is b itself
                a = b;
                a_state = b_state;
                continue;
            }
            T tolerance = T(0);
            visit(set, c, [&](const auto& e) { tolerance = e.tolerance; });
            tolerance = max_value(tolerance, default_tolerance);
            // The bracket's ends move as the finder narrows it: a_state (from lo_state) and b_state follow.
            // An earlier event's a, if the new bracket still holds it, stays the bracket's start: that
            // event's crossing lies after it, and a time in both brackets is within both tolerances (an
            // event with a wide tolerance sharing the crossing would otherwise fire both at lo).
            const T a_before = a;
            const pack a_before_state = a_state;
            a_state = lo_state;
            if constexpr (interpolates) {
                if (!d.ready) {
                    const status sl = hermite_ends(f, start, y_end, t_s, t_end, d);
                    if (sl != status::ok) return sl;
                }
            }
            auto fn = [&, sign_h, side, c, t_s, h, t_end](T u) -> T {  // (the scalars by value: in registers)
                const T s_trial = sign_h * u;
                status st = status::ok;
                if constexpr (interpolates) {  // (each branch captures only what it reads)
                    interpolate(start, y_end, d, s_trial, h, trial_state);
                    if (!all_finite_pack(trial_state)) st = status::non_finite;  // (see state_at)
                } else {
                    st = restep(trial, f, start, t_s, s_trial, trial_state);
                }
                if (st != status::ok) {
                    failure = st;
                    return std::numeric_limits<T>::quiet_NaN();
                }
                const T value = side * evaluate_one(set, c, time_at(t_s, s_trial, h, t_end), pointers(trial_state));
                if (!is_finite(value)) {
                    failure = status::non_finite_event;
                } else if (value < T(0)) {
                    a_state = trial_state;
                } else {
                    b_state = trial_state;
                }
                return value;
            };
            const root_bracket<T> r =
                Finder::narrow(fn, sign_h * lo, side * memory[c].g, sign_h * b, fb, tolerance, cap);
            if (r.failed) return failure != status::ok ? failure : status::non_finite_event;
            a = sign_h * r.a;
            b = sign_h * r.b;
            if (r.fb == T(0)) {  // g exactly zero at b: the event is at that time, with the state there
                a = b;
                a_state = b_state;
            } else if (sign_h * a_before > r.a && sign_h * a_before < r.b) {
                a = a_before;
                a_state = a_before_state;
            }
            if (!evaluate_all(set, time_at(t_s, b, h, t_end), pointers(b_state), g_b)) return status::non_finite_event;
        }
        return status::ok;
    }
};

}  // namespace detail

}  // namespace odestep

#endif
