// SPDX-License-Identifier: BSL-1.0
// odestep: the derivative of the backward Euler step, Phi = (I - dt J(t_{n+1}, y_{n+1}))^-1.
#ifndef ODESTEP_SENSITIVITY_IMPLICIT_HPP
#define ODESTEP_SENSITIVITY_IMPLICIT_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../linalg/lu.hpp"
#include "../rk/implicit_rk.hpp"
#include "../rk/newton.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "transition.hpp"

namespace odestep {

/// \brief A backward Euler step (odestep::backward_euler<State, Newton>, the library's own) that also returns
/// its derivative Phi = d y_{n+1} / d y_n.
///
/// The step solves y_{n+1} = y_n + dt f(t_{n+1}, y_{n+1}); differentiating that equation (the implicit
/// function theorem) gives (I - dt J) Phi = I with J = df/dy(t_{n+1}, y_{n+1}), so Phi = (I - dt J)^-1,
/// the Pade (0, 1) form R(z) = 1 / (1 - z) on y' = A y. Phi is formed with one more Jacobian, at the new
/// state, and one N x N LU factorization (odestep::linalg): the Newton iteration's own matrix is
/// I - dt J(t_n, y_n), at the old state, and would give Phi with an error of order dt |J(y_{n+1}) - J(y_n)|.
/// Phi is the derivative of the exact solution of the step's equation at the computed y_{n+1}; the computed
/// y_{n+1} itself meets that equation to the Newton tolerance (set_tolerance), and so does Phi.
///
/// The system must carry its Jacobian (odestep::with_jacobian, odestep::with_dual_jacobian). Failures leave
/// y and Phi untouched: the plain step's (`non_finite`, `singular_matrix`, `no_convergence`), then
/// `singular_matrix` when I - dt J at the new state is singular or has a NaN or Inf (a NaN in J), and
/// `non_finite` when Phi overflows.
template <class State, class Newton = newton<>>
class backward_euler_transition {
public:
    using state_type = State;                                  ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;                    ///< T
    using stepper_type = backward_euler<State, Newton>;        ///< the plain stepper whose step this is
    using matrix_type = jacobian_t<State>;                     ///< Phi, N x N
    static constexpr int order = stepper_type::order;          ///< 1
    static constexpr std::size_t factorizations_per_step = 2;  ///< the Newton iteration's and Phi's

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;

public:
    /// The Newton tolerance of the plain step (odestep::implicit_rk::set_tolerance).
    constexpr status set_tolerance(newton_tolerance<T> tolerance) noexcept { return plain_.set_tolerance(tolerance); }

    /// y <- y_{n+1}, phi <- d y_{n+1} / d y_n. On any status but ok, y and phi are untouched.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, matrix_type& phi, T t, T dt) const {
        return advance<N, true>(f, y, phi, t, dt);
    }

    /// y <- y_{n+1}, s <- Phi s for a sensitivity of N rows and M columns.
    template <class System, std::size_t M>
    [[nodiscard]] status propagate(System&& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        return advance<M, false>(f, y, s, t, dt);
    }

private:
    stepper_type plain_{};

    template <std::size_t M, bool Identity, class System>
    status advance(System& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        static_assert(has_jacobian_v<std::remove_reference_t<System>, State>,
                      "odestep: the step's derivative needs the system's Jacobian: odestep::with_jacobian(f, J), or "
                      "odestep::with_dual_jacobian(f) for an f written as a template");
        State next = y;
        const status ps = plain_.step(f, next, t, dt);
        if (ps != status::ok) return ps;
        jacobian_t<State> m;  // I - dt J(t + dt, y_{n+1})
        detail::evaluate_jacobian(f, t + dt, static_cast<const State&>(next), m);
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t j = 0; j < N; ++j) m[i][j] = (i == j ? T(1) : T(0)) - dt * m[i][j];
        linalg::pivots<N> pivot{};
        const status fs = linalg::lu_factor(m, pivot);
        if (fs != status::ok) return fs;
        // Column by column: (I - dt J) d_c = s_c (s = I for Phi).
        sensitivity_matrix<T, N, M> d;
        for (std::size_t c = 0; c < M; ++c) {
            State col;
            for (std::size_t i = 0; i < N; ++i) {
                if constexpr (Identity) {
                    col[i] = i == c ? T(1) : T(0);
                } else {
                    col[i] = s[i][c];
                }
            }
            linalg::lu_solve(m, pivot, col);
            for (std::size_t i = 0; i < N; ++i) d[i][c] = col[i];
        }
        if (!detail::matrix_finite(d)) return status::non_finite;
        y = next;
        s = d;
        return status::ok;
    }
};

}  // namespace odestep

#endif
