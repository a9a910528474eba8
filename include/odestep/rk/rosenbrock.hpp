// SPDX-License-Identifier: BSL-1.0
// odestep: the Rosenbrock (linearly implicit) stepper: one Jacobian, one factorization and S linear solves per
// step, no iteration, so every step costs the same.
#ifndef ODESTEP_RK_ROSENBROCK_HPP
#define ODESTEP_RK_ROSENBROCK_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../detail/ops.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/rosenbrock.hpp"

namespace odestep {

namespace detail {

/// The coefficients of a Rosenbrock table in Hairer & Wanner's transformed form (Solving ODE II, Sec. IV.7,
/// (7.7)-(7.8)), as the stepper uses them.
template <class T, std::size_t S>
struct rosenbrock_coefficients {
    std::array<std::array<T, S>, S> a{};    ///< alpha Gamma^-1, strictly lower triangular
    std::array<std::array<T, S>, S> gc{};   ///< gamma C, C = I / gamma - Gamma^-1 (strictly lower triangular)
    std::array<T, S> m{};                   ///< b^T Gamma^-1
    std::array<T, S> e{};                   ///< (b - bhat)^T Gamma^-1: the error estimate's weights
    std::array<T, S> node{};                ///< alpha_i = sum_j alpha_ij
    std::array<T, S> time_weight{};         ///< gamma gamma_i, gamma_i = sum_{j<=i} gamma_ij
    std::array<bool, S> reuses_previous{};  ///< stage i's input (time and state) is stage i-1's
};

/// Computes the transformed coefficients at compile time (Gamma^-1 by forward substitution).
template <class T, std::size_t S>
constexpr rosenbrock_coefficients<T, S> transform_rosenbrock(const rosenbrock_tableau<T, S>& tab) noexcept {
    rosenbrock_coefficients<T, S> x{};
    const T gamma = tab.gamma[0][0];
    std::array<std::array<T, S>, S> inv{};
    for (std::size_t col = 0; col < S; ++col)
        for (std::size_t i = col; i < S; ++i) {
            T sum = i == col ? T(1) : T(0);
            for (std::size_t j = col; j < i; ++j) sum -= tab.gamma[i][j] * inv[j][col];
            inv[i][col] = sum / tab.gamma[i][i];
        }
    for (std::size_t i = 0; i < S; ++i) {
        T node = T(0);
        T gi = T(0);
        for (std::size_t j = 0; j < S; ++j) {
            node += tab.alpha[i][j];
            gi += tab.gamma[i][j];
            T a = T(0);
            for (std::size_t k = 0; k < S; ++k) a += tab.alpha[i][k] * inv[k][j];
            x.a[i][j] = j < i ? a : T(0);
            x.gc[i][j] = j < i ? -gamma * inv[i][j] : T(0);
            x.m[i] += tab.b[j] * inv[j][i];
            x.e[i] += (tab.b[j] - tab.b_embedded[j]) * inv[j][i];
        }
        x.node[i] = node;
        x.time_weight[i] = gamma * gi;
    }
    for (std::size_t i = 1; i < S; ++i) {
        bool same = x.node[i] == x.node[i - 1] && x.a[i][i - 1] == T(0);
        for (std::size_t j = 0; j + 1 < i; ++j) same = same && x.a[i][j] == x.a[i - 1][j];
        x.reuses_previous[i] = same;
    }
    return x;
}

}  // namespace detail

/// \brief A Rosenbrock step for y' = f(t, y) from the table `Method::table<T>` (a rosenbrock_tableau).
///
/// Implemented in Hairer & Wanner's transformed variables (Solving ODE II, Sec. IV.7, (7.7)-(7.8)):
/// u_i = sum_{j<=i} gamma_ij k_j, so that no product with J is needed:
///
///     (I - h gamma J) u_i = h gamma f(t + alpha_i h, y_n + sum_{j<i} a_ij u_j) + gamma sum_{j<i} c_ij u_j
///                           + h^2 gamma gamma_i df/dt
///     y_{n+1} = y_n + sum_i m_i u_i
///
/// with a = alpha Gamma^-1, C = I / gamma - Gamma^-1 and m = b^T Gamma^-1, computed from the published
/// table at compile time. (Hairer and Wanner divide by h gamma instead; multiplying through keeps the
/// matrix I - h gamma J of the implicit steppers and no 1/h.) A stage whose input equals the previous
/// stage's (RODAS3's second) reuses its evaluation.
///
/// J is the system's own Jacobian when it carries one (odestep::with_jacobian), otherwise forward
/// differences (N evaluations of f); df/dt is always a forward difference in t (one evaluation). Every step
/// makes exactly rhs_evals_for<System> evaluations, one factorization and `stages` solves.
///
/// Failures leave y as it was: `non_finite` (f returned NaN or Inf, or the result overflowed),
/// `singular_matrix` (I - h gamma J is singular, or the system's Jacobian has NaN or Inf). The stepper
/// holds nothing: the step is const.
template <class Method, class State>
class rosenbrock : public stepper_defaults<State> {
public:
    using state_type = State;                ///< std::array<T, N>
    using value_type = value_type_t<State>;  ///< T
    using method_type = Method;              ///< the table's tag

private:
    using T = value_type;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t S = table_type::stages;
    static constexpr std::size_t N = state_traits<State>::size;
    static_assert(is_consistent(tab),
                  "odestep: a Rosenbrock table needs alpha strictly lower triangular, gamma lower triangular with "
                  "one diagonal entry, and weights summing to 1");
    static constexpr T gamma = tab.gamma[0][0];

    static constexpr detail::rosenbrock_coefficients<T, S> co = detail::transform_rosenbrock(tab);
    static constexpr std::size_t count_new_evaluations() noexcept {
        std::size_t n = 0;
        for (std::size_t i = 1; i < S; ++i) n += co.reuses_previous[i] ? 0U : 1U;
        return n;
    }

public:
    static constexpr int order = tab.order;   ///< the table's order
    static constexpr std::size_t stages = S;  ///< linear solves per step
    static constexpr bool implicit = true;    ///< linearly implicit: a factorization and solves every step
    /// LU factorizations per step (of the N x N matrix I - h gamma J).
    static constexpr std::size_t factorizations_per_step = 1;
    /// Size of the factorized matrix.
    static constexpr std::size_t iteration_matrix_size = N;
    /// Jacobians per step.
    static constexpr std::size_t jacobians_per_step = 1;
    /// No Newton iteration: the work of every step is fixed.
    static constexpr std::size_t newton_iterations = 0;
    /// Evaluations of f per step with the system's own Jacobian: f(t_n, y_n), df/dt by a difference, and
    /// each stage whose input is new.
    static constexpr std::size_t rhs_evals_with_jacobian = 2 + count_new_evaluations();
    /// Evaluations of f of the difference Jacobian (f(t_n, y_n) is the first stage's).
    static constexpr std::size_t jacobian_rhs_evals = N;
    /// Evaluations of f of every step with a difference Jacobian (the most, whatever the system).
    static constexpr std::size_t rhs_evals_per_step = rhs_evals_with_jacobian + jacobian_rhs_evals;
    /// The table has an embedded solution: step(f, y, t, dt, err) also returns y_{n+1} - yhat_{n+1}.
    static constexpr bool error_estimate = tab.embedded_order > 0;
    /// The order of the embedded solution (0: none).
    static constexpr int embedded_order = tab.embedded_order;
    /// The estimating step costs what the plain step costs (the estimate reuses the stages).
    static constexpr std::size_t rhs_evals_per_error_step = error_estimate ? rhs_evals_with_jacobian + N : 0;
    /// Evaluations of f of every step with System.
    template <class System>
    static constexpr std::size_t rhs_evals_for =
        rhs_evals_with_jacobian +
        (has_jacobian_v<std::remove_cv_t<std::remove_reference_t<System>>, State> ? 0 : jacobian_rhs_evals);

    /// y <- y(t + dt). On any status but ok, y is left as it was.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt) const {
        State unused;
        return advance<false>(f, y, t, dt, unused);
    }

    /// y <- y(t + dt) and err = y_{n+1} - yhat_{n+1}, the difference from the embedded solution (a local error
    /// estimate of order embedded_order + 1), from the same stages. Tables with an embedded solution only.
    /// What it does not do: choose dt. A fixed-step caller who wants "ok" to mean "accurate" compares err with
    /// its tolerance (odestep::scaled_error_norm) and acts; the error-controlled form does this itself.
    template <class System, bool E = error_estimate, std::enable_if_t<E, int> = 0>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& err) const {
        return advance<true>(f, y, t, dt, err);
    }

private:
    template <bool Estimate, class System>
    status advance(System& f, State& y, T t, T dt, State& err) const {
        State f0;
        detail::evaluate(f, t, y, f0);
        if (!detail::all_finite(f0)) return status::non_finite;
        jacobian_t<State> m;
        const status js = detail::jacobian_of(f, t, y, f0, m);
        if (js != status::ok) return js;
        State dfdt;
        const status ts = finite_difference_time_derivative(f, t, y, f0, dfdt);
        if (ts != status::ok) return ts;
        const T hg = dt * gamma;
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) m[r][c] = (r == c ? T(1) : T(0)) - hg * m[r][c];
        linalg::pivots<N> piv;
        if (linalg::lu_factor(m, piv) != status::ok) return status::singular_matrix;
        const T h2 = dt * dt;
        std::array<State, S> u;
        State fi = f0;
        for (std::size_t i = 0; i < S; ++i) {
            if (i > 0 && !co.reuses_previous[i]) {
                State in;
                for (std::size_t n = 0; n < N; ++n) {
                    T sum = T(0);
                    for (std::size_t j = 0; j < i; ++j) sum += co.a[i][j] * u[j][n];
                    in[n] = y[n] + sum;
                }
                detail::evaluate(f, t + co.node[i] * dt, static_cast<const State&>(in), fi);
                if (!detail::all_finite(fi)) return status::non_finite;
            }
            for (std::size_t n = 0; n < N; ++n) {
                T sum = hg * fi[n] + h2 * co.time_weight[i] * dfdt[n];
                for (std::size_t j = 0; j < i; ++j) sum += co.gc[i][j] * u[j][n];
                u[i][n] = sum;
            }
            linalg::lu_solve(m, piv, u[i]);
        }
        State next;
        for (std::size_t n = 0; n < N; ++n) {
            T sum = T(0);
            for (std::size_t j = 0; j < S; ++j) sum += co.m[j] * u[j][n];
            next[n] = y[n] + sum;
        }
        if (!detail::all_finite(next)) return status::non_finite;
        if constexpr (Estimate) {
            State e;
            for (std::size_t n = 0; n < N; ++n) {
                T sum = T(0);
                for (std::size_t j = 0; j < S; ++j) sum += co.e[j] * u[j][n];
                e[n] = sum;
            }
            if (!detail::all_finite(e)) return status::non_finite;
            detail::assign(err, e);
        } else {
            (void)err;
        }
        detail::assign(y, next);
        return status::ok;
    }
};

/// RODAS3 (Sandu et al. 1997): order 3, L-stable, stiffly accurate; three evaluations of f per step (plus
/// df/dt and the Jacobian).
template <class State>
using rodas3 = rosenbrock<tables::rodas3, State>;

}  // namespace odestep

#endif
