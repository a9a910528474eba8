// SPDX-License-Identifier: BSL-1.0
// odestep: Newton's equations x'' = a(t, x, v) with position and velocity as two states, and the
// textbook methods for them that are not symplectic compositions (those are in symplectic.hpp).
#ifndef ODESTEP_NEWTONIAN_CLASSIC_HPP
#define ODESTEP_NEWTONIAN_CLASSIC_HPP

#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "../detail/continuation.hpp"
#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"

namespace odestep {

/// \brief The trait set of the Newtonian steppers below: odestep::stepper_traits with system_form::newtonian
/// and the traits each names (odestep::trait), e.g. `newtonian_traits<State, trait::order<2>,
/// trait::rhs_evals_per_step<2>, trait::symplectic<true>>`. rhs_evals_per_step is the most one step can cost
/// (the first step of a history-keeping method, or the corrector's cap); velocity_forces, whether
/// a(t, x, v) is accepted.
template <class State, class... Named>
struct newtonian_traits : stepper_traits<State, trait::system<system_form::newtonian>, Named...> {
    /// The former name of rhs_evals_per_step.
    [[deprecated("odestep: use rhs_evals_per_step")]] static constexpr std::size_t accelerations_per_step =
        stepper_traits<State, trait::system<system_form::newtonian>, Named...>::rhs_evals_per_step;
};

/// Euler for Newton's equations: x_{n+1} = x_n + v_n dt, v_{n+1} = v_n + a(t_n, x_n, v_n) dt.
/// Order 1; on the oscillator its energy grows by exactly (1 + dt^2) per step.
template <class State>
class newtonian_euler : public newtonian_traits<State, trait::order<1>, trait::stages<1>, trait::rhs_evals_per_step<1>,
                                                trait::velocity_forces<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) const {
        const State acc = detail::acceleration(a, t, x, v);
        const State x1 = detail::plus_scaled(x, dt, v);    // x_{n+1} = x_n + v_n dt
        const State v1 = detail::plus_scaled(v, dt, acc);  // v_{n+1} = v_n + a_n dt
        if (!detail::all_finite(x1, v1)) return status::non_finite;
        x = x1;
        v = v1;
        return status::ok;
    }
};

/// The midpoint algorithm: v_{n+1} = v_n + a_n dt, x_{n+1} = x_n + (v_n + v_{n+1}) dt / 2
/// (so x_{n+1} = x_n + v_n dt + a_n dt^2 / 2). Globally first order, like Euler, in v.
template <class State>
class newtonian_midpoint : public newtonian_traits<State, trait::order<1>, trait::stages<1>,
                                                   trait::rhs_evals_per_step<1>, trait::velocity_forces<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) const {
        using T = value_type;
        const State acc = detail::acceleration(a, t, x, v);
        State x1;
        State v1;
        const T half = dt / T(2);
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < x1.size(); ++n) {
            v1[n] = v[n] + acc[n] * dt;
            x1[n] = x[n] + (v[n] + v1[n]) * half;
        }
        if (!detail::all_finite(x1, v1)) return status::non_finite;
        x = x1;
        v = v1;
        return status::ok;
    }
};

/// Euler-Richardson for Newton's equations (the explicit midpoint method on (x, v)):
///   a_n = a(t, x, v), v_mid = v + a_n dt/2, x_mid = x + v dt/2, a_mid = a(t + dt/2, x_mid, v_mid),
///   v_{n+1} = v + a_mid dt, x_{n+1} = x + v_mid dt.
/// Its error estimate is the difference to the Euler step of the same start: x: a_n dt^2 / 2,
/// v: (a_mid - a_n) dt.
template <class State>
class newtonian_euler_richardson : public newtonian_traits<State, trait::order<2>, trait::stages<2>,
                                                           trait::rhs_evals_per_step<2>, trait::velocity_forces<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T
    /// The order of the embedded solution (trait; see odestep::stepper_defaults).
    static constexpr int embedded_order = 1;
    /// The most evaluations of the estimating step (trait; see odestep::stepper_defaults).
    static constexpr std::size_t rhs_evals_per_error_step = 2;
    /// Whether the stepper has an error-estimating step (trait; see odestep::stepper_defaults).
    static constexpr bool error_estimate = true;

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) const {
        State ex;
        State ev;
        return advance(a, x, v, t, dt, ex, ev);
    }

    /// As above, and (error_x, error_v) = the (x, v) step minus the Euler step from the same start.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt,
                                                   State& error_x, State& error_v) const {
        return advance(a, x, v, t, dt, error_x, error_v);
    }

private:
    template <class Accel>
    static status advance(Accel& a, State& x, State& v, value_type t, value_type dt, State& error_x, State& error_v) {
        using T = value_type;
        const T half = dt / T(2);
        const State a0 = detail::acceleration(a, t, x, v);
        const State v_mid = detail::plus_scaled(v, half, a0);
        const State x_mid = detail::plus_scaled(x, half, v);
        const State a_mid = detail::acceleration(a, t + half, x_mid, v_mid);
        State x1;
        State v1;
        State ex;
        State ev;
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < x1.size(); ++n) {
            x1[n] = x[n] + v_mid[n] * dt;
            v1[n] = v[n] + a_mid[n] * dt;
            ex[n] = a0[n] * (half * dt);
            ev[n] = (a_mid[n] - a0[n]) * dt;
        }
        // Every value the step returns: ex = a0 dt^2 / 2 can overflow while x1 = x + v_mid dt stays finite
        // (v cancelling a0 dt / 2 in v_mid), so it is tested in its own right.
        if (!detail::all_finite(x1, v1, ex, ev)) return status::non_finite;
        x = x1;
        v = v1;
        error_x = ex;
        error_v = ev;
        return status::ok;
    }
};

/// The half-step (staggered leapfrog) algorithm for a force of position alone:
///   v_{n+1/2} = v_{n-1/2} + a_n dt,  x_{n+1} = x_n + v_{n+1/2} dt,  self-started with v_{1/2} = v_0 + a_0 dt/2.
/// The staggered velocity lives in the stepper; the caller's v is kept at integer times,
/// v_{n+1} = v_{n+1/2} + a_{n+1} dt/2, with a_{n+1} evaluated once and reused as the next step's a_n, so a
/// step costs one evaluation (two on the first step). A step that does not continue the last one (another
/// t, dt or position object) self-starts again; after changing x or v in place, call reset().
template <class State>
class half_step : public newtonian_traits<State, trait::order<2>, trait::stages<1>, trait::rhs_evals_per_step<2>,
                                          trait::symplectic<true>, trait::time_reversible<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T

    /// Forgets the history: the next step starts afresh (call it after changing x or v yourself).
    constexpr void reset() noexcept { next_.clear(); }
    /// What a step changes (the whole stepper: its history and where the next step must start), to hand back
    /// to restore_memory() and undo a step (the event engine does, when it rolls a step back to its start).
    constexpr half_step memory() const noexcept { return *this; }
    /// Puts back the memory() kept before the last step (the caller puts x and v back too).
    constexpr void restore_memory(const half_step& m) noexcept { *this = m; }

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) {
        using T = value_type;
        const T half = dt / T(2);
        State v_half;
        const bool continuing = next_.matches(t, dt, x);
        if (continuing) {
            v_half = detail::plus_scaled(v_half_, dt, a_next_);  // v_{n+1/2} = v_{n-1/2} + a_n dt
        } else {
            v_half = detail::plus_scaled(v, half, detail::acceleration(a, t, x));  // v_{1/2} = v_0 + a_0 dt/2
        }
        const State x1 = detail::plus_scaled(x, dt, v_half);  // x_{n+1} = x_n + v_{n+1/2} dt
        const State a1 = detail::acceleration(a, t + dt, x1);
        const State v1 = detail::plus_scaled(v_half, half, a1);  // v_{n+1} = v_{n+1/2} + a_{n+1} dt/2
        // a1 and v_half need no test of their own: v1 = v_half + a1 dt/2 and x1 = x + v_half dt are +-Inf or
        // NaN when they are (0 Inf is NaN, for dt = 0 too).
        if (!detail::all_finite(x1, v1)) return status::non_finite;
        x = x1;
        v = v1;
        v_half_ = v_half;
        a_next_ = a1;
        next_.expect(t, dt, x, continuing);
        return status::ok;
    }

private:
    State v_half_{};
    State a_next_{};
    detail::continuation<State> next_{};
};

/// The original (position) form of the leapfrog, Stormer's method, for a force of position alone:
///   x_{n+1} = 2 x_n - x_{n-1} + a_n dt^2,   v_n = (x_{n+1} - x_{n-1}) / (2 dt),
/// self-started with x_1 = x_0 + v_0 dt + a_0 dt^2 / 2. To give v at the new time, each step also forms
/// x_{n+2} from a_{n+1}, which it keeps as the next step's a_n: one evaluation per step (two on the first).
template <class State>
class leapfrog_position_form
    : public newtonian_traits<State, trait::order<2>, trait::stages<1>, trait::rhs_evals_per_step<2>,
                              trait::symplectic<true>, trait::time_reversible<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T

    /// Forgets the history: the next step starts afresh (call it after changing x or v yourself).
    constexpr void reset() noexcept { next_.clear(); }
    /// What a step changes (the whole stepper: its history and where the next step must start), to hand back
    /// to restore_memory() and undo a step (the event engine does, when it rolls a step back to its start).
    constexpr leapfrog_position_form memory() const noexcept { return *this; }
    /// Puts back the memory() kept before the last step (the caller puts x and v back too).
    constexpr void restore_memory(const leapfrog_position_form& m) noexcept { *this = m; }

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) {
        using T = value_type;
        const T dt2 = dt * dt;
        State x1;
        const bool continuing = next_.matches(t, dt, x);
        if (continuing) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < x1.size(); ++n) x1[n] = T(2) * x[n] - x_prev_[n] + a_next_[n] * dt2;
        } else {
            const State a0 = detail::acceleration(a, t, x);
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < x1.size(); ++n) x1[n] = x[n] + v[n] * dt + a0[n] * (dt2 / T(2));
        }
        const State a1 = detail::acceleration(a, t + dt, x1);
        State v1;
        const T two_dt = T(2) * dt;
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < v1.size(); ++n) {
            const T x2 = T(2) * x1[n] - x[n] + a1[n] * dt2;  // x_{n+2}
            v1[n] = (x2 - x[n]) / two_dt;                    // v_{n+1} = (x_{n+2} - x_n) / (2 dt)
        }
        if (!detail::all_finite(x1, v1)) return status::non_finite;
        x_prev_ = x;
        x = x1;
        v = v1;
        a_next_ = a1;
        next_.expect(t, dt, x, continuing);
        return status::ok;
    }

private:
    State x_prev_{};
    State a_next_{};
    detail::continuation<State> next_{};
};

/// Beeman's algorithm (Beeman 1976):
///   x_{n+1} = x_n + v_n dt + (4 a_n - a_{n-1}) dt^2 / 6,
///   v_{n+1} = v_n + (2 a_{n+1} + 5 a_n - a_{n-1}) dt / 6,
/// self-started by one velocity Verlet step (x_1 = x_0 + v_0 dt + a_0 dt^2/2, v_1 = v_0 + (a_0 + a_1) dt/2).
/// a_{n+1} is kept for the next step: one evaluation per step (two on the first). A force a(t, x, v) is
/// evaluated with the velocity at hand: a_{n+1} = a(t_{n+1}, x_{n+1}, v_n); the method is then first order.
///
/// Two forms, as velocity Verlet has (splitting.hpp):
/// - step(a, x, v, t, dt): the stepper keeps a_n and a_{n-1}, and checks that a step continues its history
///   (the same position object, dt, and time, detail::continuation); a step that does not self-starts.
/// - step(a, x, v, hist, t, dt): the caller keeps them in a `history`, as a hand-written loop keeps them
///   next to the state. Nothing is checked: the caller promises that hist belongs to x, v and this dt. A
///   `history{}` (started false) makes the next step a self-starting one; assign `history{}` again after
///   changing x or v outside the stepper, the force, or dt. This step is const: one stepper serves any
///   number of states.
template <class State>
class beeman : public newtonian_traits<State, trait::order<2>, trait::stages<1>, trait::rhs_evals_per_step<2>,
                                       trait::velocity_forces<true>> {
public:
    using value_type = value_type_t<State>;  ///< its scalar T

    /// What the caller-kept form keeps between steps. On status::ok, acc is a(t + dt, x) of the new x and
    /// acc_prev the acc it had on entry (or a(t, x) after a self-starting step), and started is true; on
    /// status::non_finite all three are left exactly as they were.
    struct history {
        State acc{};           ///< a_n = a(t_n, x_n), when started
        State acc_prev{};      ///< a_{n-1}, when started
        bool started = false;  ///< false: the next step evaluates a_n itself and is a velocity Verlet step
    };

    /// Forgets the history: the next step starts afresh (call it after changing x or v yourself).
    constexpr void reset() noexcept { next_.clear(); }
    /// What a step changes (the whole stepper: its history and where the next step must start), to hand back
    /// to restore_memory() and undo a step (the event engine does, when it rolls a step back to its start).
    constexpr beeman memory() const noexcept { return *this; }
    /// Puts back the memory() kept before the last step (the caller puts x and v back too).
    constexpr void restore_memory(const beeman& m) noexcept { *this = m; }

    /// (x, v) <- (x, v)(t + dt), the history kept and checked by the stepper. On status::non_finite x and v
    /// are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) {
        const bool continuing = next_.matches(t, dt, x);
        const status s = advance(a, x, v, t, dt, continuing, kept_.acc, kept_.acc_prev);
        if (s == status::ok) next_.expect(t, dt, x, continuing);
        return s;
    }

    /// (x, v) <- (x, v)(t + dt), the history kept by the caller in hist (see above). On status::non_finite
    /// x, v and hist are left exactly as they were. hist is an object of its own (not part of x or v).
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, history& hist, value_type t,
                                                   value_type dt) const {
        const status s = advance(a, x, v, t, dt, hist.started, hist.acc, hist.acc_prev);
        if (s == status::ok) hist.started = true;
        return s;
    }

private:
    history kept_{};  // the stepper-kept form's a_n and a_{n-1} (its started is not used: next_ decides)
    detail::continuation<State> next_{};

    // One step. continuing: a_now is a_n = a(t, x) and a_prev is a_{n-1}; otherwise a_n is evaluated here
    // and the step is velocity Verlet's. On status::ok x, v are the new state, a_prev the a_n and a_now the
    // a_{n+1} of this step; otherwise nothing is written.
    template <class Accel>
    ODESTEP_INLINE static status advance(Accel& a, State& x, State& v, value_type t, value_type dt, bool continuing,
                                         State& a_now, State& a_prev) {
        using T = value_type;
        const State a0 = continuing ? a_now : detail::acceleration(a, t, x, v);
        const T dt2_6 = dt * dt / T(6);
        const T dt_6 = dt / T(6);
        // The choice made once per step, not in every component (at -Os the loops stay loops).
        State x1;
        if (continuing) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < x1.size(); ++n) x1[n] = x[n] + v[n] * dt + (T(4) * a0[n] - a_prev[n]) * dt2_6;
        } else {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < x1.size(); ++n) x1[n] = x[n] + v[n] * dt + a0[n] * (dt * dt / T(2));
        }
        const State a1 = detail::acceleration(a, t + dt, x1, v);  // a(t, x, v): the velocity at hand, v_n
        State v1;
        if (continuing) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < v1.size(); ++n) v1[n] = v[n] + (T(2) * a1[n] + T(5) * a0[n] - a_prev[n]) * dt_6;
        } else {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < v1.size(); ++n) v1[n] = v[n] + (a0[n] + a1[n]) * (dt / T(2));
        }
        // a1 needs no test of its own: v1 is +-Inf or NaN when it is (0 Inf is NaN, for dt = 0 too).
        if (!detail::all_finite(x1, v1)) return status::non_finite;
        x = x1;
        v = v1;
        a_prev = a0;
        a_now = a1;
        return status::ok;
    }
};

/// The predictor-corrector of the course material: predict x_p = x_{n-1} + 2 v_n dt, then correct
///   v_{n+1} = v_n + (a_p + a_n) dt / 2,   x_{n+1} = x_n + (v_{n+1} + v_n) dt / 2,
/// with a_p = a(t_{n+1}, x_p, v_p), repeating the correction (x_p, v_p <- x_{n+1}, v_{n+1}) until the change
/// in every component is within `tolerance` relative to the state (default 16 ULPs), at most `max_iterations`
/// times; past the cap, status::no_convergence and the step is rolled back. Self-started with the Taylor
/// prediction x_p = x_0 + v_0 dt + a_0 dt^2 / 2. Accepts velocity-dependent forces (v_p starts as
/// v_n + a_n dt).
template <class State>
class predictor_corrector : public newtonian_traits<State, trait::order<2>, trait::stages<2>,
                                                    trait::rhs_evals_per_step<1 + 16>, trait::velocity_forces<true>> {
public:
    using value_type = value_type_t<State>;    ///< its scalar T
    static constexpr int max_iterations = 16;  ///< the corrector's cap: rhs_evals_per_step = 1 + max_iterations

    /// Relative tolerance of the corrector iteration, in units of the state's magnitude.
    value_type tolerance = value_type(16) * std::numeric_limits<value_type>::epsilon();

    /// Forgets the history: the next step starts afresh (call it after changing x or v yourself).
    constexpr void reset() noexcept { next_.clear(); }
    /// What a step changes (the whole stepper: its history and where the next step must start), to hand back
    /// to restore_memory() and undo a step (the event engine does, when it rolls a step back to its start).
    constexpr predictor_corrector memory() const noexcept { return *this; }
    /// Puts back the memory() kept before the last step (the caller puts x and v back too).
    constexpr void restore_memory(const predictor_corrector& m) noexcept { *this = m; }

    /// Corrector iterations the last successful step needed.
    constexpr int last_iterations() const noexcept { return iterations_; }

    /// status::invalid_tolerance when `tolerance` is zero, negative, NaN or infinite; else ok. `step` checks
    /// it, and the driving loops ask before the run begins (nothing observed, nothing evaluated).
    constexpr status settings_status() const noexcept {
        const value_type tol = tolerance;
        return tol > value_type(0) && detail::is_finite(tol) ? status::ok : status::invalid_tolerance;
    }

    /// (x, v) <- (x, v)(t + dt). On any status but ok, x and v are left exactly as they were.
    template <class Accel>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, value_type t, value_type dt) {
        using T = value_type;
        if (settings_status() != status::ok) return status::invalid_tolerance;
        const State a0 = detail::acceleration(a, t, x, v);
        State xp;
        const bool continuing = next_.matches(t, dt, x);
        if (continuing) {
            xp = detail::plus_scaled(x_prev_, T(2) * dt, v);  // x_p = x_{n-1} + 2 v_n dt
        } else {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < xp.size(); ++n) xp[n] = x[n] + v[n] * dt + a0[n] * (dt * dt / T(2));
        }
        State vp = detail::plus_scaled(v, dt, a0);
        const T half = dt / T(2);
        for (int k = 1; k <= max_iterations; ++k) {
            const State ap = detail::acceleration(a, t + dt, xp, vp);
            State x1;
            State v1;
            T change = T(0);
            T size = T(0);
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < x1.size(); ++n) {
                v1[n] = v[n] + (ap[n] + a0[n]) * half;
                x1[n] = x[n] + (v1[n] + v[n]) * half;
                change = detail::max_value(
                    change, detail::max_value(detail::abs_value(x1[n] - xp[n]), detail::abs_value(v1[n] - vp[n])));
                size = detail::max_value(size, detail::max_value(detail::abs_value(x1[n]), detail::abs_value(v1[n])));
            }
            if (!detail::all_finite(x1, v1)) return status::non_finite;
            xp = x1;
            vp = v1;
            if (change <= tolerance * size) {
                x_prev_ = x;
                x = x1;
                v = v1;
                iterations_ = k;
                next_.expect(t, dt, x, continuing);
                return status::ok;
            }
        }
        return status::no_convergence;
    }

private:
    State x_prev_{};
    int iterations_ = 0;
    detail::continuation<State> next_{};
};

}  // namespace odestep

#endif
