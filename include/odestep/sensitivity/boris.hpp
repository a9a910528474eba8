// SPDX-License-Identifier: BSL-1.0
// odestep: the Boris step's derivative, Phi = d (x, v)_{n+1} / d (x, v)_n, the state-transition matrix of the
// staggered Boris pusher (newtonian/boris.hpp), from the fields' Jacobians dE/dx and dB/dx.
#ifndef ODESTEP_SENSITIVITY_BORIS_HPP
#define ODESTEP_SENSITIVITY_BORIS_HPP

#include <array>
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
    using ops = detail::boris_ops<T>;
    using vec = State;
    T qm_ = T(1);

    template <std::size_t M, bool Identity, class Fields, class FieldJacobian>
    status advance(Fields& fields, FieldJacobian& field_jacobian, State& x, State& v,
                   const sensitivity_matrix<T, 6, M>& seed, sensitivity_matrix<T, 6, M>& out, T t, T dt) const {
        static_assert(is_field_jacobian_v<std::remove_reference_t<FieldJacobian>, State>,
                      "odestep: the field Jacobian must be callable as `void jac(T t, const State& x, "
                      "odestep::jacobian_t<State>& dEdx, odestep::jacobian_t<State>& dBdx)`");
        // The plain step's own arithmetic (boris::step), its intermediates kept for the derivative.
        State E;
        State B;
        detail::boris_fields(fields, t, static_cast<const State&>(x), E, B);
        jacobian_t<State> ex{};
        jacobian_t<State> bx{};
        field_jacobian(t, static_cast<const State&>(x), ex, bx);
        const T h = qm_ * dt / T(2);
        const vec hE = ops::scaled(h, E);
        const vec tau = ops::scaled(h, B);
        const T tt = ops::dot(tau, tau);
        const vec vm = ops::plus(v, hE);
        const vec vn = ops::plus(ops::rotate(vm, tau, tt), hE);
        const vec xn = ops::plus(x, ops::scaled(dt, vn));
        if (!detail::all_finite(xn, vn, tt)) return status::non_finite;
        // What rotate computes inside, for the derivative: v' = v- + v- x tau, s = 2 tau / (1 + tt).
        const vec vprime = ops::plus(vm, ops::cross(vm, tau));
        const T inv = T(1) / (T(1) + tt);
        const vec s = ops::scaled(T(2) * inv, tau);
        sensitivity_matrix<T, 6, M> d;
        for (std::size_t j = 0; j < M; ++j) {
            vec dx;
            vec dv;
            for (std::size_t i = 0; i < 3; ++i) {
                if constexpr (Identity) {
                    dx[i] = j == i ? T(1) : T(0);
                    dv[i] = j == 3 + i ? T(1) : T(0);
                } else {
                    dx[i] = seed[i][j];
                    dv[i] = seed[3 + i][j];
                }
            }
            const vec hdE = ops::scaled(h, times(ex, dx));   // h E_x dx
            const vec dtau = ops::scaled(h, times(bx, dx));  // h B_x dx
            const T dtt = T(2) * ops::dot(tau, dtau);
            const vec dvm = ops::plus(dv, hdE);
            const vec dvprime = ops::plus(ops::plus(dvm, ops::cross(dvm, tau)), ops::cross(vm, dtau));
            const vec ds = ops::minus(ops::scaled(T(2) * inv, dtau), ops::scaled(T(2) * dtt * inv * inv, tau));
            const vec dvn = ops::plus(ops::plus(ops::plus(dvm, ops::cross(dvprime, s)), ops::cross(vprime, ds)), hdE);
            const vec dxn = ops::plus(dx, ops::scaled(dt, dvn));
            for (std::size_t i = 0; i < 3; ++i) {
                d[i][j] = dxn[i];
                d[3 + i][j] = dvn[i];
            }
        }
        if (!detail::matrix_finite(d)) return status::non_finite;
        x = xn;
        v = vn;
        out = d;
        return status::ok;
    }

    // m a, m 3 x 3.
    static constexpr vec times(const jacobian_t<State>& m, const vec& a) noexcept {
        return {ops::dot(m[0], a), ops::dot(m[1], a), ops::dot(m[2], a)};
    }
};

}  // namespace odestep

#endif
