// SPDX-License-Identifier: BSL-1.0
// odestep: the derivative of an implicit Runge-Kutta step (backward Euler, the trapezoid, implicit midpoint,
// Gauss, SDIRK, Radau IIA), Phi = d y_{n+1} / d y_n, by the implicit function theorem on the stage equations.
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
#include "../tables/butcher.hpp"
#include "../tables/implicit_rk.hpp"
#include "transition.hpp"

namespace odestep {
namespace detail {

// The system implicit_rk steps when a transition is asked for: it passes f and the Jacobian through
// unchanged (the step is the plain one, bit for bit) and keeps, for each stage, the input Y_i = y_n + Z_i of
// its last evaluation (the last Newton iterate). Which stage an evaluation belongs to follows from the
// order implicit_rk evaluates them in: a fully implicit table evaluates all S stages, in order, once per
// iteration; a diagonally implicit one solves its stages one after the other, each Newton iteration
// starting at Z_i = 0, so a stage begins with an evaluation at y_n itself (the first stage may instead be
// the explicit f(t_n, y_n)). Should a later iterate of a stage land exactly on y_n (an increment below half
// an ulp of every component), the stages that follow are taken one early; their inputs then all lie within
// a few ulps of y_n, and so does the error of their Jacobians.
template <class Method, class State, class System>
struct implicit_stage_listener {
    using T = value_type_t<State>;
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = std::remove_const_t<decltype(tab)>::stages;
    static constexpr bool diagonal = is_lower_triangular(tab);

    System& f;
    const State& start;           // y_n
    std::array<State, S>& input;  // Y_i of each stage's last evaluation
    std::size_t calls = 0;
    std::size_t stage = 0;

    void operator()(T t, const State& y, State& dydt) {
        evaluate(f, t, y, dydt);
        if constexpr (diagonal) {
            if (calls > 0 && stage + 1 < S && y == start) ++stage;
        } else {
            stage = calls % S;
        }
        input[stage] = y;
        ++calls;
    }
    void jacobian(T t, const State& y, jacobian_t<State>& dfdy) { evaluate_jacobian(f, t, y, dfdy); }
};

// A diagonally implicit table's explicit stages: only the first may be one (implicit_rk's f(t_n, y_n)), so
// that every later stage starts at y_n and the listener can tell the stages apart.
template <class T, std::size_t S, std::size_t E>
constexpr bool explicit_stages_first_only(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 1; i < S; ++i)
        if (tab.a[i][i] == T(0)) return false;
    return true;
}

}  // namespace detail

/// \brief An implicit Runge-Kutta step (odestep::implicit_rk<Method, State, Newton>, the library's own) that
/// also returns its derivative Phi = d y_{n+1} / d y_n.
///
/// The step solves the stage equations Z_i = dt sum_j a_ij f(t + c_j dt, y_n + Z_j). Differentiating them
/// (the implicit function theorem) at the stages Y_j = y_n + Z_j, with J_j = df/dy(t + c_j dt, Y_j) and
/// W_j = d Y_j / d y_n, gives the SN x SN linear system
///
///     W_i - dt sum_j a_ij J_j W_j = I        (block (i, j) of its matrix: delta_ij I - dt a_ij J_j),
///
/// which is I - dt (A (x) J) when every J_j is the same J. Then Phi = W_S for a stiffly accurate table
/// (backward Euler, the trapezoid, SDIRK 3, Radau IIA) and Phi = I + dt sum_j b_j J_j W_j otherwise (implicit
/// midpoint, Gauss). On y' = A y, Phi is the method's stability function R(dt A): (I - dt A)^-1 for backward
/// Euler, the Pade forms for Gauss and Radau IIA.
///
/// Y_j is the input of stage j's last evaluation of f in the Newton iteration, and for the last stage of a
/// stiffly accurate table the new state itself: Phi is the derivative of the exact solution of the stage
/// equations, taken at stages that meet those equations to the Newton tolerance (newton<K>; with
/// fixed_newton<K>, to wherever K iterations got). The Newton iteration's own matrix uses J(t_n, y_n), at the
/// old state, and is not reused: it would make Phi wrong by a term of order dt |J(Y_j) - J(y_n)|.
///
/// Cost beyond the plain step: S Jacobians and one LU factorization (odestep::linalg) of the SN x SN
/// matrix, (SN)^3 / 3 multiply-adds (for a diagonally implicit table too, whose matrix is block lower
/// triangular), and one solve per column of Phi. Stack: the SN x SN matrix ((SN)^2 T: Radau IIA 5 with N = 4
/// in double, 1152 bytes), S Jacobians and S stage inputs, one N x M result; the plain step's stack before it.
///
/// The system must carry its Jacobian (odestep::with_jacobian, odestep::with_dual_jacobian). Failures leave
/// y and Phi untouched: the plain step's (`non_finite`, `singular_matrix`, `no_convergence`), then
/// `singular_matrix` when the stage system's matrix is singular or has a NaN or Inf (a NaN in a J_j of an
/// implicit stage), and `non_finite` when Phi is not finite (an overflow, a NaN in the J of the trapezoid's
/// explicit first stage).
template <class Method, class State, class Newton = newton<>>
class implicit_rk_transition {
public:
    using state_type = State;                                  ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;                    ///< T
    using method_type = Method;                                ///< the table's tag
    using stepper_type = implicit_rk<Method, State, Newton>;   ///< the plain stepper whose step this is
    using matrix_type = jacobian_t<State>;                     ///< Phi, N x N
    static constexpr int order = stepper_type::order;          ///< the method's order
    static constexpr std::size_t factorizations_per_step = 2;  ///< the Newton iteration's and Phi's
    /// Size of the stage system factored for Phi: S N.
    static constexpr std::size_t stage_matrix_size = stepper_type::stages * state_traits<State>::size;
    /// Jacobians per step: the plain step's one, and one per stage for Phi.
    static constexpr std::size_t jacobian_evals_per_step = 1 + stepper_type::stages;

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr std::size_t S = stepper_type::stages;
    static constexpr std::size_t SN = stage_matrix_size;
    static constexpr auto tab = Method::template table<T>;
    static constexpr bool stiffly_accurate = is_stiffly_accurate(tab);
    static_assert(!is_lower_triangular(tab) || detail::explicit_stages_first_only(tab),
                  "odestep: the transition of a diagonally implicit table needs every stage after the first to be "
                  "implicit");

public:
    /// The Newton tolerance of the plain step (odestep::implicit_rk::set_tolerance).
    constexpr status set_tolerance(newton_tolerance<T> tolerance) noexcept { return plain_.set_tolerance(tolerance); }

    /// y <- y_{n+1}, phi <- d y_{n+1} / d y_n. On any status but ok, y and phi are untouched.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, matrix_type& phi, T t, T dt) const {
        return advance<N, true>(f, y, phi, t, dt);
    }

    /// y <- y_{n+1}, s <- Phi s for a sensitivity s = d y_n / d p of N rows and M columns.
    template <class System, std::size_t M>
    [[nodiscard]] status propagate(System&& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        return advance<M, false>(f, y, s, t, dt);
    }

private:
    stepper_type plain_{};

    template <std::size_t M, bool Identity, class System>
    status advance(System& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        using system_type = std::remove_reference_t<System>;
        detail::require_jacobian<system_type, State>();
        std::array<State, S> input;  // every stage is evaluated at least once by a step that returns ok
        detail::implicit_stage_listener<Method, State, system_type> listener{f, y, input};
        State next = y;
        const status ps = plain_.step(listener, next, t, dt);
        if (ps != status::ok) return ps;
        if constexpr (stiffly_accurate) input[S - 1] = next;
        std::array<jacobian_t<State>, S> jac;
        for (std::size_t j = 0; j < S; ++j)
            detail::evaluate_jacobian(f, t + tab.c[j] * dt, static_cast<const State&>(input[j]), jac[j]);
        // The stage system's matrix: block (i, j) = delta_ij I - dt a_ij J_j.
        linalg::matrix<T, SN> m;
        for (std::size_t i = 0; i < S; ++i)
            for (std::size_t j = 0; j < S; ++j) {
                const T ha = dt * tab.a[i][j];
                for (std::size_t r = 0; r < N; ++r)
                    for (std::size_t c = 0; c < N; ++c)
                        m[i * N + r][j * N + c] = (i == j && r == c ? T(1) : T(0)) - ha * jac[j][r][c];
            }
        linalg::pivots<SN> pivot{};
        const status fs = linalg::lu_factor(m, pivot);
        if (fs != status::ok) return fs;
        // Column by column: W (stacked W_1 .. W_S) from the right-hand side (s, ..., s) (s = I for Phi).
        sensitivity_matrix<T, N, M> d;
        for (std::size_t c = 0; c < M; ++c) {
            std::array<T, SN> w;
            for (std::size_t i = 0; i < S; ++i)
                for (std::size_t r = 0; r < N; ++r) {
                    if constexpr (Identity) {
                        w[i * N + r] = r == c ? T(1) : T(0);
                    } else {
                        w[i * N + r] = s[r][c];
                    }
                }
            linalg::lu_solve(m, pivot, w);
            for (std::size_t r = 0; r < N; ++r) {
                if constexpr (stiffly_accurate) {
                    d[r][c] = w[(S - 1) * N + r];  // Phi s = W_S
                } else {
                    T sum = T(0);  // sum_j b_j (J_j W_j)_r
                    for (std::size_t j = 0; j < S; ++j) {
                        T jw = T(0);
                        for (std::size_t q = 0; q < N; ++q) jw += jac[j][r][q] * w[j * N + q];
                        sum += tab.b[j] * jw;
                    }
                    T seed;
                    if constexpr (Identity) {
                        seed = r == c ? T(1) : T(0);
                    } else {
                        seed = s[r][c];
                    }
                    d[r][c] = seed + dt * sum;  // Phi s = s + dt sum_j b_j J_j W_j
                }
            }
        }
        if (!detail::matrix_finite(d)) return status::non_finite;
        y = next;
        s = d;
        return status::ok;
    }
};

// The named transitions, one per implicit stepper of rk/implicit_rk.hpp.
/// Backward Euler with Phi: (I - dt J(t_{n+1}, y_{n+1})) Phi = I.
template <class State, class Newton = newton<>>
using backward_euler_transition = implicit_rk_transition<tables::backward_euler, State, Newton>;
/// The implicit trapezoid (Crank-Nicolson) with Phi.
template <class State, class Newton = newton<>>
using trapezoid_transition = implicit_rk_transition<tables::trapezoid, State, Newton>;
/// The implicit midpoint rule with Phi.
template <class State, class Newton = newton<>>
using implicit_midpoint_transition = implicit_rk_transition<tables::implicit_midpoint, State, Newton>;
/// Gauss-Legendre 4 with Phi.
template <class State, class Newton = newton<>>
using gauss4_transition = implicit_rk_transition<tables::gauss4, State, Newton>;
/// Alexander's SDIRK 3 with Phi.
template <class State, class Newton = newton<>>
using sdirk3_transition = implicit_rk_transition<tables::sdirk3, State, Newton>;
/// Radau IIA 5 with Phi.
template <class State, class Newton = newton<>>
using radau_iia5_transition = implicit_rk_transition<tables::radau_iia5, State, Newton>;

}  // namespace odestep

#endif
