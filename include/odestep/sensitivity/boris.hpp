// SPDX-License-Identifier: BSL-1.0
// odestep: the Boris step's derivative, Phi = d (x, v)_{n+1} / d (x, v)_n, the state-transition matrix of the
// staggered Boris pushers (newtonian/boris.hpp, non-relativistic and relativistic), from the fields'
// Jacobians dE/dx and dB/dx.
#ifndef ODESTEP_SENSITIVITY_BORIS_HPP
#define ODESTEP_SENSITIVITY_BORIS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "../newtonian/boris.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "transition.hpp"

namespace odestep {

/// True when `jac(t, x, dEdx, dBdx)` writes the fields' Jacobians at (t, x): dEdx[i][j] = dE_i / dx_j and
/// dBdx[i][j] = dB_i / dx_j, both odestep::jacobian_t<State> (3 x 3).
template <class FieldJacobian, class State, class T = value_type_t<State>>
inline constexpr bool is_field_jacobian_v =
    std::is_invocable_v<FieldJacobian&, T, const State&, jacobian_t<State>&, jacobian_t<State>&>;

namespace detail {

// m a, m 3 x 3.
template <class T>
constexpr std::array<T, 3> boris_times(const std::array<std::array<T, 3>, 3>& m, const std::array<T, 3>& a) noexcept {
    using ops = boris_ops<T>;
    return {ops::dot(m[0], a), ops::dot(m[1], a), ops::dot(m[2], a)};
}

// One Boris step, the plain pusher's own arithmetic (boris::step, or boris_relativistic::step when
// Relativistic), and out <- its derivative times the seed (the identity when Identity), differentiated line
// by line with the fields' Jacobians at (t, x); inv_c2 = 1 / c^2 (not read unless Relativistic). The
// non-relativistic step is the relativistic one with gamma- = gamma+ = 1. For a perturbation (dx, du):
//     dE = E_x dx,  dB = B_x dx,  d u- = du + h dE,  d gamma- = (u- . d u-) / (c^2 gamma-)
//     tau = h B / gamma-:  d tau = h dB / gamma- - tau d gamma- / gamma-,  d tt = 2 tau . d tau
//     d u' = d u- + d u- x tau + u- x d tau;  d s = 2 d tau / (1 + tt) - 2 tau d tt / (1 + tt)^2
//     d u+ = d u- + d u' x s + u' x d s;  d u_{n+1/2} = d u+ + h dE
//     d gamma+ = (u_{n+1/2} . d u_{n+1/2}) / (c^2 gamma+)
//     d x_{n+1} = dx + (dt / gamma+) d u_{n+1/2} - (dt / gamma+) (d gamma+ / gamma+) u_{n+1/2}
// On status::non_finite x, u and out are untouched.
template <std::size_t M, bool Identity, bool Relativistic, class Fields, class FieldJacobian, class State,
          class T = value_type_t<State>>
status boris_tangent_step(Fields& fields, FieldJacobian& field_jacobian, State& x, State& u,
                          const sensitivity_matrix<T, 6, M>& seed, sensitivity_matrix<T, 6, M>& out, T t, T dt, T qm,
                          T inv_c2) {
    static_assert(is_field_jacobian_v<std::remove_reference_t<FieldJacobian>, State>,
                  "odestep: the field Jacobian must be callable as `void jac(T t, const State& x, "
                  "odestep::jacobian_t<State>& dEdx, odestep::jacobian_t<State>& dBdx)`");
    using ops = boris_ops<T>;
    using vec = State;
    // The plain step's own arithmetic, its intermediates kept for the derivative.
    State E;
    State B;
    boris_fields(fields, t, static_cast<const State&>(x), E, B);
    jacobian_t<State> ex{};
    jacobian_t<State> bx{};
    field_jacobian(t, static_cast<const State&>(x), ex, bx);
    const T h = qm * dt / T(2);
    const vec hE = ops::scaled(h, E);
    const vec um = ops::plus(u, hE);
    T gm = T(1);
    T gn = T(1);
    vec tau;
    if constexpr (Relativistic) {
        gm = std::sqrt(T(1) + ops::dot(um, um) * inv_c2);
        tau = ops::scaled(h / gm, B);
    } else {
        tau = ops::scaled(h, B);
    }
    const T tt = ops::dot(tau, tau);
    const vec un = ops::plus(ops::rotate(um, tau, tt), hE);
    vec xn;
    if constexpr (Relativistic) {
        gn = std::sqrt(T(1) + ops::dot(un, un) * inv_c2);
        xn = ops::plus(x, ops::scaled(dt / gn, un));
        if (!all_finite(xn, un, T(tt + gm + gn))) return status::non_finite;
    } else {
        xn = ops::plus(x, ops::scaled(dt, un));
        if (!all_finite(xn, un, tt)) return status::non_finite;
    }
    // What rotate computes inside, for the derivative: u' = u- + u- x tau, s = 2 tau / (1 + tt).
    const vec uprime = ops::plus(um, ops::cross(um, tau));
    const T inv = T(1) / (T(1) + tt);
    const vec s = ops::scaled(T(2) * inv, tau);
    sensitivity_matrix<T, 6, M> d;
    for (std::size_t j = 0; j < M; ++j) {
        vec dx;
        vec du;
        for (std::size_t i = 0; i < 3; ++i) {
            if constexpr (Identity) {
                dx[i] = j == i ? T(1) : T(0);
                du[i] = j == 3 + i ? T(1) : T(0);
            } else {
                dx[i] = seed[i][j];
                du[i] = seed[3 + i][j];
            }
        }
        const vec hdE = ops::scaled(h, boris_times(ex, dx));  // h E_x dx
        const vec dum = ops::plus(du, hdE);
        vec dtau;
        if constexpr (Relativistic) {
            const T dgm_over_gm = ops::dot(um, dum) * inv_c2 / (gm * gm);
            dtau = ops::minus(ops::scaled(h / gm, boris_times(bx, dx)), ops::scaled(dgm_over_gm, tau));
        } else {
            dtau = ops::scaled(h, boris_times(bx, dx));  // h B_x dx
        }
        const T dtt = T(2) * ops::dot(tau, dtau);
        const vec duprime = ops::plus(ops::plus(dum, ops::cross(dum, tau)), ops::cross(um, dtau));
        const vec ds = ops::minus(ops::scaled(T(2) * inv, dtau), ops::scaled(T(2) * dtt * inv * inv, tau));
        const vec dun = ops::plus(ops::plus(ops::plus(dum, ops::cross(duprime, s)), ops::cross(uprime, ds)), hdE);
        vec dxn;
        if constexpr (Relativistic) {
            const T dgn_over_gn = ops::dot(un, dun) * inv_c2 / (gn * gn);
            dxn = ops::plus(dx, ops::scaled(dt / gn, ops::minus(dun, ops::scaled(dgn_over_gn, un))));
        } else {
            dxn = ops::plus(dx, ops::scaled(dt, dun));
        }
        for (std::size_t i = 0; i < 3; ++i) {
            d[i][j] = dxn[i];
            d[3 + i][j] = dun[i];
        }
    }
    if (!matrix_finite(d)) return status::non_finite;
    x = xn;
    u = un;
    out = d;
    return status::ok;
}

}  // namespace detail

/// \brief A step of the Boris pusher (odestep::boris: x at the step times, v half a step behind) that also
/// returns its derivative, Phi = d (x_{n+1}, v_{n+1/2}) / d (x_n, v_{n-1/2}), a 6 x 6 odestep::phase_matrix_t
/// (rows and columns x_1 .. x_3, v_1 .. v_3).
///
/// The step is odestep::boris's own (the same x and v, bit for bit). Its derivative, differentiated line by
/// line with the fields' Jacobians at (t_n, x_n), a perturbation (dx, dv) of (x_n, v_{n-1/2}) giving
///
///     dE = E_x dx,  d tau = h B_x dx,  d tt = 2 tau . d tau
///     d v- = dv + h dE;  d v' = d v- + d v- x tau + v- x d tau
///     d s = 2 d tau / (1 + tt) - 2 tau d tt / (1 + tt)^2;  d v+ = d v- + d v' x s + v' x d s
///     d v_{n+1/2} = d v+ + h dE;  d x_{n+1} = dx + dt d v_{n+1/2}
///
/// (h = (q/m) dt / 2), so Phi is the exact derivative of what the step computes, to round-off. det Phi = 1
/// for any fields: at fixed x the velocity update is a rotation (det 1) plus a shift that depends on x, and
/// the drift x += dt v is a shear; the map is volume preserving, not symplectic (Qin et al. 2013).
///
/// **What the user supplies**: the fields as for odestep::boris, `void fields(T t, const State& x, State& E,
/// State& B)`, and their Jacobians with respect to x, `void field_jacobian(T t, const State& x,
/// jacobian_t<State>& dEdx, jacobian_t<State>& dBdx)`; both Jacobians are zeroed before the call, so a
/// uniform field writes nothing. Time enters only through the fields; the step's derivative with respect to
/// t_n or q/m is not given.
///
/// Cost per step: the plain step, one evaluation of the field Jacobians, and per column of the result about
/// 60 multiply-adds (6 columns for Phi). Always checked, as odestep::boris: a non-finite x, v or Phi (a NaN
/// or Inf in a field or a Jacobian, an overflow) returns `status::non_finite` with x, v and Phi untouched.
template <class State>
class boris_transition {
public:
    using state_type = State;                                  ///< std::array<T, 3>
    using value_type = value_type_t<State>;                    ///< T
    using stepper_type = boris<State>;                         ///< the plain stepper whose step this is
    using matrix_type = phase_matrix_t<State>;                 ///< Phi, 6 x 6 on (x, v)
    static constexpr int order = 2;                            ///< the method's order
    static constexpr std::size_t rhs_evals_per_step = 1;       ///< field evaluations per step
    static constexpr std::size_t jacobian_evals_per_step = 1;  ///< field-Jacobian evaluations per step
    static_assert(detail::is_boris_state_v<State>, "odestep: the Boris pusher needs State = std::array<T, 3>");

    /// q/m = 1.
    constexpr boris_transition() noexcept = default;
    /// The particle's charge-to-mass ratio q/m.
    explicit constexpr boris_transition(value_type charge_to_mass) noexcept : qm_(charge_to_mass) {}
    /// q/m.
    constexpr value_type charge_to_mass() const noexcept { return qm_; }

    /// (x_n, v_{n-1/2}) -> (x_{n+1}, v_{n+1/2}) and phi <- their derivative. On `status::non_finite` x, v and
    /// phi are untouched.
    template <class Fields, class FieldJacobian>
    [[nodiscard]] status step(Fields&& fields, FieldJacobian&& field_jacobian, State& x, State& v, matrix_type& phi,
                              value_type t, value_type dt) const {
        return advance<6, true>(fields, field_jacobian, x, v, phi, phi, t, dt);
    }

    /// (x, v) advanced and s <- Phi s for a sensitivity s = d (x_n, v_{n-1/2}) / d p of 6 rows and M columns
    /// (s = Phi of the run so far gives Phi of the run). On `status::non_finite` x, v and s are untouched.
    template <class Fields, class FieldJacobian, std::size_t M>
    [[nodiscard]] status propagate(Fields&& fields, FieldJacobian&& field_jacobian, State& x, State& v,
                                   sensitivity_matrix<value_type, 6, M>& s, value_type t, value_type dt) const {
        return advance<M, false>(fields, field_jacobian, x, v, s, s, t, dt);
    }

private:
    using T = value_type;
    T qm_ = T(1);

    template <std::size_t M, bool Identity, class Fields, class FieldJacobian>
    status advance(Fields& fields, FieldJacobian& field_jacobian, State& x, State& v,
                   const sensitivity_matrix<T, 6, M>& seed, sensitivity_matrix<T, 6, M>& out, T t, T dt) const {
        return detail::boris_tangent_step<M, Identity, false>(fields, field_jacobian, x, v, seed, out, t, dt, qm_,
                                                              T(0));
    }
};

/// \brief A step of the relativistic Boris pusher (odestep::boris_relativistic: x at the step times, u = gamma v
/// half a step behind) that also returns its derivative, Phi = d (x_{n+1}, u_{n+1/2}) / d (x_n, u_{n-1/2}),
/// a 6 x 6 odestep::phase_matrix_t (rows and columns x_1 .. x_3, u_1 .. u_3).
///
/// The step is odestep::boris_relativistic's own (the same x and u, bit for bit). Its derivative is
/// boris_transition's with the two Lorentz factors differentiated too: gamma- = gamma(u-) scales tau = h B /
/// gamma-, so d tau = h dB / gamma- - tau d gamma- / gamma- with d gamma- = (u- . d u-) / (c^2 gamma-), and
/// the drift x_{n+1} = x_n + dt u_{n+1/2} / gamma+ gives d x_{n+1} = dx + (dt / gamma+) (d u_{n+1/2} -
/// u_{n+1/2} d gamma+ / gamma+). det Phi = 1 here too for fields of x: at fixed x the momentum update is a
/// shift, then a rotation about B whose angle depends only on |u-|, which the rotation keeps (in cylindrical
/// coordinates about B: phi += angle(rho, z), det 1), then a shift; the drift is a shear (Higuera & Cary 2017).
///
/// What the user supplies: as for boris_transition, the fields and their Jacobians with respect to x. Cost
/// per step: the plain step, one evaluation of the field Jacobians, and per column of the result about 75
/// multiply-adds. Always checked: a non-finite x, u or Phi returns `status::non_finite` with x, u and Phi
/// untouched.
template <class State>
class boris_relativistic_transition {
public:
    using state_type = State;                                  ///< std::array<T, 3>
    using value_type = value_type_t<State>;                    ///< T
    using stepper_type = boris_relativistic<State>;            ///< the plain stepper whose step this is
    using matrix_type = phase_matrix_t<State>;                 ///< Phi, 6 x 6 on (x, u)
    static constexpr int order = 2;                            ///< the method's order
    static constexpr std::size_t rhs_evals_per_step = 1;       ///< field evaluations per step
    static constexpr std::size_t jacobian_evals_per_step = 1;  ///< field-Jacobian evaluations per step
    static_assert(detail::is_boris_state_v<State>, "odestep: the Boris pusher needs State = std::array<T, 3>");

    /// q/m = 1 and c = 1.
    constexpr boris_relativistic_transition() noexcept = default;
    /// The charge-to-rest-mass ratio q/m and the speed of light c, as for odestep::boris_relativistic.
    constexpr boris_relativistic_transition(value_type charge_to_mass, value_type speed_of_light) noexcept
        : qm_(charge_to_mass), c_(speed_of_light), inv_c2_(value_type(1) / (speed_of_light * speed_of_light)) {}
    /// q/m.
    constexpr value_type charge_to_mass() const noexcept { return qm_; }
    /// c.
    constexpr value_type speed_of_light() const noexcept { return c_; }

    /// (x_n, u_{n-1/2}) -> (x_{n+1}, u_{n+1/2}) and phi <- their derivative. On `status::non_finite` x, u and
    /// phi are untouched.
    template <class Fields, class FieldJacobian>
    [[nodiscard]] status step(Fields&& fields, FieldJacobian&& field_jacobian, State& x, State& u, matrix_type& phi,
                              value_type t, value_type dt) const {
        return detail::boris_tangent_step<6, true, true>(fields, field_jacobian, x, u, phi, phi, t, dt, qm_, inv_c2_);
    }

    /// (x, u) advanced and s <- Phi s for a sensitivity s = d (x_n, u_{n-1/2}) / d p of 6 rows and M columns.
    /// On `status::non_finite` x, u and s are untouched.
    template <class Fields, class FieldJacobian, std::size_t M>
    [[nodiscard]] status propagate(Fields&& fields, FieldJacobian&& field_jacobian, State& x, State& u,
                                   sensitivity_matrix<value_type, 6, M>& s, value_type t, value_type dt) const {
        return detail::boris_tangent_step<M, false, true>(fields, field_jacobian, x, u, s, s, t, dt, qm_, inv_c2_);
    }

private:
    using T = value_type;
    T qm_ = T(1);
    T c_ = T(1);
    T inv_c2_ = T(1);
};

}  // namespace odestep

#endif
