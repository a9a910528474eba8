// SPDX-License-Identifier: BSL-1.0
// odestep: the Boris pusher for a charged particle in electric and magnetic fields, non-relativistic and
// relativistic.
//
// Sources: J. P. Boris, "Relativistic plasma simulation: optimization of a hybrid code", Proc. 4th Conf.
// Numerical Simulation of Plasmas, NRL (1970) 3-67; C. K. Birdsall & A. B. Langdon, Plasma Physics via
// Computer Simulation (1985 / IOP 1991), section 4-3 (the rotation, and v at integer times as the average
// of the two half-step velocities); H. Qin et al., "Why is Boris algorithm so good?", Phys.
// Plasmas 20, 084503 (2013) (volume preserving, not symplectic); A. V. Higuera & J. R. Cary, Phys.
// Plasmas 24, 052104 (2017) (the relativistic Boris push is volume preserving too).
#ifndef ODESTEP_NEWTONIAN_BORIS_HPP
#define ODESTEP_NEWTONIAN_BORIS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"

namespace odestep {

namespace detail {

template <class State>
inline constexpr bool is_boris_state_v = state_traits<State>::size == 3;

// E and B at (t, x). Both start at zero, so a callable that writes only B (or only some components) gets
// zero for the rest, never an uninitialised value.
template <class Fields, class State, class T>
void boris_fields(Fields& fields, T t, const State& x, State& E, State& B) {
    static_assert(is_em_fields_v<Fields, State, T>,
                  "odestep: the fields must be callable as `void fields(T t, const State& x, State& E, State& B)`, "
                  "with State = std::array<T, 3>");
    E = State{};
    B = State{};
    fields(t, x, E, B);
}

// The pushers' vector operations, as static members so that each pusher names them `ops::` and they cannot
// collide with other headers' helpers.
template <class T>
struct boris_ops {
    using vec = std::array<T, 3>;

    static constexpr T dot(const vec& a, const vec& b) noexcept { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    static constexpr vec cross(const vec& a, const vec& b) noexcept {
        return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    static constexpr vec plus(const vec& a, const vec& b) noexcept { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
    static constexpr vec minus(const vec& a, const vec& b) noexcept { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    static constexpr vec scaled(T c, const vec& a) noexcept { return {c * a[0], c * a[1], c * a[2]}; }

    // The Boris rotation v- -> v+ about tau (tt = |tau|^2): v' = v- + v- x tau, s = 2 tau / (1 + tt),
    // v+ = v- + v' x s. It solves v+ - v- = (v+ + v-) x tau exactly (the implicit midpoint rule for
    // v' = v x B over one step), and is the rotation by the angle 2 atan|tau| about -tau, so |v+| = |v-|.
    static constexpr vec rotate(const vec& vm, const vec& tau, T tt) noexcept {
        const vec vprime = plus(vm, cross(vm, tau));
        return plus(vm, cross(vprime, scaled(T(2) / (T(1) + tt), tau)));
    }

    // The v with v = a + v x tau: (a + a x tau + (a . tau) tau) / (1 + tt), half a rotation, implicitly.
    static constexpr vec solve_half_rotation(const vec& a, const vec& tau, T tt) noexcept {
        return scaled(T(1) / (T(1) + tt), plus(plus(a, cross(a, tau)), scaled(dot(a, tau), tau)));
    }
};

}  // namespace detail

/// \brief The traits of both Boris pushers (boris, boris_relativistic): second order, one field evaluation
/// per step, time reversible and volume preserving but not symplectic (Qin et al. 2013; Higuera & Cary 2017
/// for the relativistic map), not self starting (v, or u, must be staggered first), on the charged particle's
/// form of system.
template <class State>
struct boris_traits : stepper_traits<State, trait::order<2>, trait::rhs_evals_per_step<1>, trait::time_reversible<true>,
                                     trait::self_starting<false>, trait::system<system_form::charged_particle>> {
    /// The map preserves phase-space volume.
    static constexpr bool volume_preserving = true;
    /// The former name of rhs_evals_per_step.
    [[deprecated("odestep: use rhs_evals_per_step")]] static constexpr std::size_t field_evals_per_step = 1;
};

/// The Boris pusher for dx/dt = v, dv/dt = (q/m) (E(t, x) + v x B(t, x)), x and v as std::array<T, 3>.
///
/// **Which time v belongs to.** This is the staggered leapfrog of plasma codes: x at the step times, v half
/// a step behind. A step takes (x_n, v_{n-1/2}) at t = t_n and leaves (x_{n+1}, v_{n+1/2}):
///
///     E, B = fields(t_n, x_n);  h = (q/m) dt / 2
///     v- = v_{n-1/2} + h E;  tau = h B;  s = 2 tau / (1 + |tau|^2)
///     v' = v- + v- x tau;  v+ = v- + v' x s
///     v_{n+1/2} = v+ + h E;  x_{n+1} = x_n + v_{n+1/2} dt
///
/// so v always lags x by dt/2: one field evaluation per step, no state in the stepper. The two conversions
/// to and from the step times, each one field evaluation at (t, x):
///   - `stagger(fields, x, v, t0, dt)`: v(t0) -> v(t0 - dt/2), before the first step. Without it a step
///     reads v(t0) as v(t0 - dt/2): an O(dt) error that makes the whole run first order.
///   - `synchronize(fields, x, v, t, dt)`: v(t - dt/2) -> v(t), for output (energy, guiding centre).
/// Integer-time v is the average of the two half-step velocities around it (Birdsall & Langdon 4-3),
/// v_n = (v_{n-1/2} + v_{n+1/2}) / 2; both conversions are exact (closed-form) and each other's inverse.
/// In a pure magnetic field |v_n| = |v_0| exactly, while |v_{n+1/2}|^2 = |v_0|^2 + |v_perp|^2 |tau|^2.
///
/// With odestep::integrate the observer sees (t_n, x_n, v_{n-1/2}). A last step shortened to h < dt (t1 - t0
/// not a multiple of dt) leaves v still dt/2 behind, so call synchronize with the regular dt; that one step
/// costs x an error of O(dt^2) (exactly -a h (dt - h) / 2 for a constant acceleration a, at most
/// |a| dt^2 / 8), which keeps the run second order. Use integrate_n_steps, or a dt that divides t1 - t0, to
/// avoid it. Integrating backwards (dt < 0) v leads x by |dt|/2: stagger with the negative dt.
///
/// Traits: second order; one field evaluation per step; volume preserving in (x, v) and time reversible,
/// but not symplectic (Qin et al. 2013). The map from synchronized (x_n, v_n) to (x_{n+1}, v_{n+1}) is
/// symmetric too, and preserves the volume weighted by 1 + |tau(x)|^2 (constant in a uniform B). Not self
/// starting: v needs `stagger` first.
///
/// Fields: `void fields(T t, const State& x, State& E, State& B)`, called in place, never copied; E and B
/// are zeroed before the call. On `status::non_finite` (a NaN or Inf field, or a result that overflowed)
/// x and v are left exactly as they were.
template <class State>
class boris : public boris_traits<State> {
public:
    /// The state, std::array<T, N>.
    using state_type = State;
    /// The scalar type T.
    using value_type = value_type_t<State>;
    static_assert(detail::is_boris_state_v<State>, "odestep: the Boris pusher needs State = std::array<T, 3>");

    /// q/m = 1.
    constexpr boris() noexcept = default;
    /// The particle's charge-to-mass ratio q/m (negative for an electron).
    explicit constexpr boris(value_type charge_to_mass) noexcept : qm_(charge_to_mass) {}
    /// q/m.
    constexpr value_type charge_to_mass() const noexcept { return qm_; }

    /// (x_n, v_{n-1/2}) at t = t_n -> (x_{n+1}, v_{n+1/2}). On `status::non_finite` x and v are unchanged.
    template <class Fields>
    [[nodiscard]] status step(Fields&& fields, State& x, State& v, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, static_cast<const State&>(x), E, B);
        const T h = qm_ * dt / T(2);
        const State hE = ops::scaled(h, E);
        const State tau = ops::scaled(h, B);
        const T tt = ops::dot(tau, tau);
        const State vn = ops::plus(ops::rotate(ops::plus(v, hE), tau, tt), hE);
        const State xn = ops::plus(x, ops::scaled(dt, vn));
        // tt takes part: a B so large that |tau|^2 overflows would otherwise give s = 0, no rotation at all.
        if (!detail::all_finite(xn, vn, tt)) return status::non_finite;
        x = xn;
        v = vn;
        return status::ok;
    }

    /// v(t) -> v(t - dt/2) at x(t): v - (q/m) (E + v x B) dt/2, the inverse of `synchronize`.
    template <class Fields>
    [[nodiscard]] status stagger(Fields&& fields, const State& x, State& v, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, x, E, B);
        const T h = qm_ * dt / T(2);
        const State tau = ops::scaled(h, B);
        const State w = ops::minus(ops::minus(v, ops::cross(v, tau)), ops::scaled(h, E));
        return commit(v, w, ops::dot(tau, tau));
    }

    /// v(t - dt/2) -> v(t) at x(t): the v with v = v(t - dt/2) + (q/m) (E + v x B) dt/2, the average of the
    /// half-step velocities around t.
    template <class Fields>
    [[nodiscard]] status synchronize(Fields&& fields, const State& x, State& v, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, x, E, B);
        const T h = qm_ * dt / T(2);
        const State tau = ops::scaled(h, B);
        const T tt = ops::dot(tau, tau);
        return commit(v, ops::solve_half_rotation(ops::plus(v, ops::scaled(h, E)), tau, tt), tt);
    }

private:
    using T = value_type;
    using ops = detail::boris_ops<T>;
    T qm_ = T(1);

    static status commit(State& v, const State& w, T extra) noexcept {
        if (!detail::all_finite(w, extra)) return status::non_finite;
        v = w;
        return status::ok;
    }
};

/// The relativistic Boris pusher for dx/dt = u / gamma, du/dt = (q/m) (E + (u / gamma) x B), with
/// u = gamma v the momentum per unit rest mass and gamma = sqrt(1 + |u|^2 / c^2). **Its "v" is u**: pass u
/// and read u back (v = u / gamma). Staggered like `boris`, u half a step behind x:
///
///     E, B = fields(t_n, x_n);  h = (q/m) dt / 2
///     u- = u_{n-1/2} + h E;  gamma- = sqrt(1 + |u-|^2 / c^2);  tau = h B / gamma-
///     u+ = the Boris rotation of u- about tau (|u+| = |u-|)
///     u_{n+1/2} = u+ + h E;  x_{n+1} = x_n + u_{n+1/2} dt / gamma_{n+1/2}
///
/// In a pure magnetic field |u|, so gamma, is conserved and the gyration frequency is omega_c / gamma
/// (omega_c = |q/m| |B|), exactly 2 atan(omega_c dt / (2 gamma)) per step. `stagger` and `synchronize`
/// convert u as for `boris`, integer-time u being the average of the half-step values around it (both in
/// closed form, each other's inverse). The traits are `boris`'s: volume preserving in (x, u) (Higuera &
/// Cary 2017), time reversible, not symplectic. Known limitation of the method (ibid.): when E + v x B = 0
/// at relativistic drift speeds it does not keep the exact E x B velocity.
template <class State>
class boris_relativistic : public boris_traits<State> {
public:
    /// The state, std::array<T, N>.
    using state_type = State;
    /// The scalar type T.
    using value_type = value_type_t<State>;
    static_assert(detail::is_boris_state_v<State>, "odestep: the Boris pusher needs State = std::array<T, 3>");

    /// q/m = 1 and c = 1.
    constexpr boris_relativistic() noexcept = default;
    /// The charge-to-rest-mass ratio q/m and the speed of light c, in the units of the fields and x.
    constexpr boris_relativistic(value_type charge_to_mass, value_type speed_of_light) noexcept
        : qm_(charge_to_mass), c_(speed_of_light), inv_c2_(value_type(1) / (speed_of_light * speed_of_light)) {}
    /// q/m.
    constexpr value_type charge_to_mass() const noexcept { return qm_; }
    /// c.
    constexpr value_type speed_of_light() const noexcept { return c_; }

    /// gamma = sqrt(1 + |u|^2 / c^2).
    value_type gamma(const State& u) const noexcept { return std::sqrt(T(1) + ops::dot(u, u) * inv_c2_); }

    /// (x_n, u_{n-1/2}) at t = t_n -> (x_{n+1}, u_{n+1/2}). On `status::non_finite` x and u are unchanged.
    template <class Fields>
    [[nodiscard]] status step(Fields&& fields, State& x, State& u, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, static_cast<const State&>(x), E, B);
        const T h = qm_ * dt / T(2);
        const State hE = ops::scaled(h, E);
        const State um = ops::plus(u, hE);
        const T gm = gamma(um);
        const State tau = ops::scaled(h / gm, B);
        const T tt = ops::dot(tau, tau);
        const State un = ops::plus(ops::rotate(um, tau, tt), hE);
        const T gn = gamma(un);
        const State xn = ops::plus(x, ops::scaled(dt / gn, un));
        // gamma- and gamma+ take part: |u|^2 overflowing to Inf would otherwise stop x silently.
        if (!detail::all_finite(xn, un, T(tt + gm + gn))) return status::non_finite;
        x = xn;
        u = un;
        return status::ok;
    }

    /// u(t) -> u(t - dt/2) at x(t): u - (q/m) (E + u x B / gamma-) dt/2 with gamma- the step's
    /// gamma(u(t - dt/2) + (q/m) E dt/2) = gamma(u - u x tau), which is in closed form: G = gamma-^2 solves
    /// G^2 - (1 + |u|^2/c^2) G - (q/m dt/2)^2 |u x B|^2 / c^2 = 0. The inverse of `synchronize`.
    template <class Fields>
    [[nodiscard]] status stagger(Fields&& fields, const State& x, State& u, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, x, E, B);
        const T h = qm_ * dt / T(2);
        const State uxb = ops::cross(u, ops::scaled(h, B));  // u x tau gamma-
        const T a = T(1) + ops::dot(u, u) * inv_c2_;
        const T b = ops::dot(uxb, uxb) * inv_c2_;
        const T gm = std::sqrt((a + std::sqrt(a * a + T(4) * b)) / T(2));
        const State w = ops::minus(ops::minus(u, ops::scaled(T(1) / gm, uxb)), ops::scaled(h, E));
        return commit(u, w, gm);
    }

    /// u(t - dt/2) -> u(t) at x(t): the u with u = u- + u x tau (u- and tau those of a step from t), the
    /// average of the half-step values around t.
    template <class Fields>
    [[nodiscard]] status synchronize(Fields&& fields, const State& x, State& u, value_type t, value_type dt) const {
        State E;
        State B;
        detail::boris_fields(fields, t, x, E, B);
        const T h = qm_ * dt / T(2);
        const State um = ops::plus(u, ops::scaled(h, E));
        const T gm = gamma(um);
        const State tau = ops::scaled(h / gm, B);
        const T tt = ops::dot(tau, tau);
        return commit(u, ops::solve_half_rotation(um, tau, tt), tt + gm);
    }

private:
    using T = value_type;
    using ops = detail::boris_ops<T>;
    T qm_ = T(1);
    T c_ = T(1);
    T inv_c2_ = T(1);

    static status commit(State& u, const State& w, T extra) noexcept {
        if (!detail::all_finite(w, extra)) return status::non_finite;
        u = w;
        return status::ok;
    }
};

}  // namespace odestep

#endif
