// SPDX-License-Identifier: BSL-1.0
// odestep: the implicit Runge-Kutta stepper, driven by any implicit Butcher table, with a simplified Newton
// iteration whose work per step is bounded and published.
#ifndef ODESTEP_RK_IMPLICIT_RK_HPP
#define ODESTEP_RK_IMPLICIT_RK_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../counts.hpp"
#include "../detail/ops.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "../tables/implicit_rk.hpp"
#include "newton.hpp"

namespace odestep {

/// \brief An implicit Runge-Kutta step for y' = f(t, y) from the table `Method::table<T>`, its stage
/// equations solved by simplified Newton.
///
/// With Z_i = Y_i - y_n the stage increments, the step solves Z_i = h sum_j a_ij f(t + c_i h, y_n + Z_j).
/// Simplified Newton (Hairer & Wanner, Solving ODE II, Sec. IV.8): one Jacobian J = df/dy(t_n, y_n) and one
/// LU factorization per step, reused by every iteration and every stage. The start is Z = 0.
///   - A diagonally implicit table (a lower triangular: backward Euler, the trapezoid, implicit midpoint,
///     SDIRK) solves its stages one after the other, each with the N x N matrix I - h gamma J, gamma the
///     diagonal entry every implicit stage shares (a stage with a_ii = 0 is explicit and costs one
///     evaluation; the trapezoid's first stage is f(t_n, y_n)). Stage i's derivative is recovered from its
///     solution, h k_i = (Z_i - sum_{j<i} a_ij h k_j) / gamma, without evaluating f again.
///   - A fully implicit table (Gauss, Radau IIA) solves all S stages at once with the SN x SN matrix
///     I - h (A (x) J), one factorization of (SN)^3 / 3 multiply-adds.
///   - y_{n+1} = y_n + Z_S for a stiffly accurate table, y_n + sum_j d_j Z_j with d = b^T A^-1 (computed at
///     compile time) for another fully implicit one, y_n + sum_j b_j h k_j for a diagonally implicit one.
///
/// The Jacobian is the system's own when it carries one (odestep::with_jacobian, or a member `jacobian`),
/// otherwise forward differences of f (finite_difference_jacobian: N evaluations, plus f(t_n, y_n) unless
/// the table's first stage is that evaluation).
///
/// `Newton` is odestep::newton<K> (iterate until converged, at most K times per solve, the default K = 10)
/// or odestep::fixed_newton<K> (exactly K iterations, constant cost). The convergence test and its
/// tolerance are newton_tolerance's; set_tolerance changes them.
///
/// Every failure leaves y as it was: `non_finite` (f returned NaN or Inf, or the iterates overflowed),
/// `singular_matrix` (the iteration matrix is singular, or the system's Jacobian has NaN or Inf),
/// `no_convergence` (newton<K>: not converged within K iterations, or diverging). The stepper keeps only its
/// tolerance; the step is const, one stepper serves any number of states.
template <class Method, class State, class Newton = newton<>>
class implicit_rk : public stepper_defaults<State> {
public:
    using state_type = State;                ///< std::array<T, N>
    using value_type = value_type_t<State>;  ///< T
    using method_type = Method;              ///< the table's tag
    using newton_type = Newton;              ///< newton<K> or fixed_newton<K>

private:
    using T = value_type;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t S = table_type::stages;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr std::size_t K = Newton::iterations;
    static_assert(is_consistent(tab), "odestep: the table's rows do not sum to c, or its weights to 1");
    static_assert(!is_explicit(tab),
                  "odestep: implicit_rk needs an implicit table; an explicit one is stepped by odestep::explicit_rk");

    static constexpr bool diagonal = is_lower_triangular(tab);
    static constexpr bool stiffly_accurate = is_stiffly_accurate(tab);
    // The diagonal entry of the implicit stages of a diagonally implicit table (0 if there is none).
    static constexpr T shared_diagonal() noexcept {
        for (std::size_t i = 0; i < S; ++i)
            if (tab.a[i][i] != T(0)) return tab.a[i][i];
        return T(0);
    }
    static constexpr T gamma = shared_diagonal();
    static constexpr bool singly_diagonal() noexcept {
        for (std::size_t i = 0; i < S; ++i)
            if (tab.a[i][i] != T(0) && tab.a[i][i] != gamma) return false;
        return true;
    }
    static_assert(!diagonal || singly_diagonal(),
                  "odestep: a diagonally implicit table must have one diagonal entry for all its implicit stages "
                  "(SDIRK), so that one factorization serves every stage");
    static constexpr std::size_t count_explicit_stages() noexcept {
        std::size_t n = 0;
        for (std::size_t i = 0; i < S; ++i) n += (diagonal && tab.a[i][i] == T(0)) ? 1U : 0U;
        return n;
    }
    // The first stage is k_1 = f(t_n, y_n) itself (an explicit first stage): the difference Jacobian
    // shares that evaluation.
    static constexpr bool first_stage_is_f0 = diagonal && tab.a[0][0] == T(0);

    // d = b^T A^-1 (A^T d = b), for a fully implicit table that is not stiffly accurate (Gauss).
    static constexpr std::array<T, S> final_weights() noexcept {
        linalg::matrix<T, S> at{};
        for (std::size_t i = 0; i < S; ++i)
            for (std::size_t j = 0; j < S; ++j) at[i][j] = tab.a[j][i];
        linalg::pivots<S> p{};
        std::array<T, S> d = tab.b;
        if (linalg::lu_factor(at, p) == status::ok) linalg::lu_solve(at, p, d);
        return d;
    }
    static constexpr std::array<T, S> d_weights = final_weights();

public:
    static constexpr int order = tab.order;                     ///< the table's order
    static constexpr std::size_t stages = S;                    ///< the table's stages
    static constexpr bool implicit = true;                      ///< solves an equation every step
    static constexpr bool symplectic = is_symplectic(tab);      ///< computed from the table (Gauss, midpoint)
    static constexpr bool time_reversible = is_symmetric(tab);  ///< computed from the table
    /// Explicit stages of a diagonally implicit table (one evaluation each, no solve).
    static constexpr std::size_t explicit_stages = count_explicit_stages();
    /// Stages solved by Newton (all of them for a fully implicit table, solved together).
    static constexpr std::size_t implicit_stages = S - explicit_stages;
    /// Newton iterations per solve: the cap (newton<K>) or the exact count (fixed_newton<K>).
    static constexpr std::size_t newton_iterations = K;
    /// True with fixed_newton: every step makes exactly rhs_evals_per_step evaluations.
    static constexpr bool fixed_iterations = Newton::fixed;
    /// LU factorizations per step: one (N x N for a diagonally implicit table, SN x SN otherwise).
    static constexpr std::size_t factorizations_per_step = 1;
    /// Size of the factorized matrix.
    static constexpr std::size_t iteration_matrix_size = diagonal ? N : S * N;
    /// Jacobians per step: one, the system's own or by differences.
    static constexpr std::size_t jacobians_per_step = 1;
    /// Evaluations of f per step when the system carries its Jacobian: the explicit stages, and one
    /// evaluation per implicit stage per iteration (S per iteration for a fully implicit table), at the cap.
    static constexpr std::size_t rhs_evals_with_jacobian = explicit_stages + K * implicit_stages;
    /// Evaluations of f of the difference Jacobian: N, and f(t_n, y_n) unless the first stage is it.
    static constexpr std::size_t jacobian_rhs_evals = N + (first_stage_is_f0 ? 0 : 1);
    /// The most evaluations of f one step makes, whatever it is given: the difference Jacobian and every
    /// Newton iteration at the cap. fixed_newton: every step makes exactly this many (with a difference
    /// Jacobian) or rhs_evals_with_jacobian (with the system's).
    static constexpr std::size_t rhs_evals_per_step = rhs_evals_with_jacobian + jacobian_rhs_evals;
    /// Radau IIA 5 has an estimating step: step(f, y, t, dt, err) also returns RADAU5's local error estimate.
    static constexpr bool error_estimate = std::is_same_v<Method, tables::radau_iia5>;
    /// The order of the embedded solution the estimate compares with (its error behaves as h^4).
    static constexpr int embedded_order = error_estimate ? 3 : 0;
    /// The most evaluations of the estimating step: those of the plain step (f(t_n, y_n), which the estimate
    /// needs, is already counted there for the difference Jacobian).
    static constexpr std::size_t rhs_evals_per_error_step = error_estimate ? rhs_evals_per_step : 0;
    /// Evaluations of f one step with System costs at most.
    template <class System>
    static constexpr std::size_t rhs_evals_for =
        rhs_evals_with_jacobian +
        (has_jacobian_v<std::remove_cv_t<std::remove_reference_t<System>>, State> ? 0 : jacobian_rhs_evals);

    /// A stepper with the default tolerance (newton_tolerance<T>{}).
    constexpr implicit_rk() noexcept = default;

    /// The Newton tolerance. Refused with `status::invalid_tolerance` (nothing changed) unless both values
    /// are finite, relative >= 0 and absolute > 0. Without effect in fixed_newton mode.
    constexpr status set_tolerance(newton_tolerance<T> tolerance) noexcept {
        if (!tolerance.valid()) return status::invalid_tolerance;
        tolerance_ = tolerance;
        return status::ok;
    }
    /// The Newton tolerance in use.
    constexpr newton_tolerance<T> tolerance() const noexcept { return tolerance_; }

    /// y <- y(t + dt). On any status but ok, y is left as it was.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt) const {
        using Sys = std::remove_reference_t<System>;
        constexpr bool own_jacobian = has_jacobian_v<std::remove_cv_t<Sys>, State>;
        constexpr bool need_f0 = first_stage_is_f0 || !own_jacobian;
        State f0;
        if constexpr (need_f0) {
            detail::evaluate(f, t, y, f0);
            if (!detail::all_finite(f0)) return status::non_finite;
        }
        jacobian_t<State> jac;
        // With the system's own Jacobian and no explicit first stage, f0 is never computed and neither
        // jacobian_of nor solve_diagonal reads fy: y stands in, so that no uninitialized array is passed on
        // (g++ -O1 flagged f0 passed to solve_diagonal as maybe uninitialized).
        const State& fy = need_f0 ? f0 : y;
        const status js = detail::jacobian_of(f, t, y, fy, jac);
        if (js != status::ok) return js;
        State next;
        status s;
        if constexpr (diagonal) {
            s = solve_diagonal(f, y, t, dt, fy, jac, next);
        } else {
            s = solve_coupled(f, y, t, dt, jac, next);
        }
        if (s != status::ok) return s;
        if (!detail::all_finite(next)) return status::non_finite;
        detail::assign(y, next);
        return status::ok;
    }

    /// Radau IIA 5 only: y <- y(t + dt) as step(f, y, t, dt) computes it, and err = the local error estimate of
    /// Hairer & Wanner's RADAU5 (Solving ODE II, Sec. IV.8, (8.19)):
    ///     err = (I - h gamma0 J)^-1 gamma0 (h f(t_n, y_n) + e_1 Z_1 + e_2 Z_2 + e_3 Z_3)
    /// (tables::radau5_coefficients: gamma0 = 1 / gamma, e), with J the step's Jacobian: one more N x N
    /// factorization and solve, and f(t_n, y_n) when the system carries its Jacobian. The estimate behaves as
    /// h^4 where the solution is smooth and stays bounded on stiff components. It does not choose dt: a
    /// fixed-step caller compares err with its tolerance (odestep::scaled_error_norm) and acts;
    /// odestep::radau5_substeps does this itself. On any status but ok y and err are left as they were.
    template <class System, bool E = error_estimate, std::enable_if_t<E, int> = 0>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& err) const {
        State f0;
        detail::evaluate(f, t, y, f0);
        if (!detail::all_finite(f0)) return status::non_finite;
        jacobian_t<State> jac;
        const status js = detail::jacobian_of(f, t, y, f0, jac);
        if (js != status::ok) return js;
        State next;
        std::array<T, S * N> z;
        const status s = solve_coupled(f, y, t, dt, jac, next, &z);
        if (s != status::ok) return s;
        if (!detail::all_finite(next)) return status::non_finite;
        using co = tables::radau5_coefficients<T>;
        const T g0 = T(1) / co::gamma;
        linalg::matrix<T, N> m;
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) m[r][c] = (r == c ? T(1) : T(0)) - dt * g0 * jac[r][c];
        linalg::pivots<N> piv;
        if (linalg::lu_factor(m, piv) != status::ok) return status::singular_matrix;
        State e;
        for (std::size_t n = 0; n < N; ++n)
            e[n] = g0 * (dt * f0[n] + co::e[0] * z[n] + co::e[1] * z[N + n] + co::e[2] * z[2 * N + n]);
        linalg::lu_solve(m, piv, e);
        if (!detail::all_finite(e)) return status::non_finite;
        detail::assign(err, e);
        detail::assign(y, next);
        return status::ok;
    }

private:
    newton_tolerance<T> tolerance_{};

    // One Newton solve's bookkeeping: returns ok to go on, or the failure; sets done when converged.
    template <std::size_t M>
    static status judge(detail::newton_monitor<T>& monitor, const std::array<T, M>& dz, const std::array<T, N>& weights,
                        bool& done) noexcept {
        if constexpr (Newton::fixed) {
            (void)monitor;
            (void)dz;
            (void)weights;
            done = false;
            return status::ok;
        } else {
            if (!detail::all_finite(dz)) return status::non_finite;
            T norm = T(0);
            for (std::size_t i = 0; i < M; ++i)
                norm = detail::max_value(norm, detail::abs_value(dz[i]) * weights[i % N]);
            const auto verdict = monitor.next(norm);
            done = verdict == detail::newton_monitor<T>::verdict::converged;
            return verdict == detail::newton_monitor<T>::verdict::diverged ? status::no_convergence : status::ok;
        }
    }

    // Diagonally implicit: the stages in order, each an N-dimensional Newton solve with I - h gamma J.
    template <class System>
    status solve_diagonal(System& f, const State& y, T t, T dt, const State& f0, jacobian_t<State>& m,
                          State& next) const {
        // m <- I - h gamma J, in place of J
        const T hg = dt * gamma;
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) m[r][c] = (r == c ? T(1) : T(0)) - hg * m[r][c];
        linalg::pivots<N> piv;
        if (linalg::lu_factor(m, piv) != status::ok) return status::singular_matrix;
        const std::array<T, N> weights = detail::newton_weights(tolerance_, y);
        std::array<State, S> hk;  // h k_i, every stage's scaled derivative
        State z;
        for (std::size_t i = 0; i < S; ++i) {
            // v = sum_{j<i} a_ij h k_j, the known part of Z_i
            State v;
            for (std::size_t n = 0; n < N; ++n) {
                T sum = T(0);
                for (std::size_t j = 0; j < i; ++j) sum += tab.a[i][j] * hk[j][n];
                v[n] = sum;
            }
            const T ti = t + tab.c[i] * dt;
            if (tab.a[i][i] == T(0)) {  // an explicit stage
                State k;
                if (i == 0 && first_stage_is_f0) {
                    k = f0;
                } else {
                    State in;
                    for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + v[n];
                    detail::evaluate(f, ti, static_cast<const State&>(in), k);
                    if (!detail::all_finite(k)) return status::non_finite;
                }
                for (std::size_t n = 0; n < N; ++n) {
                    hk[i][n] = dt * k[n];
                    z[n] = v[n];
                }
                continue;
            }
            z.fill(T(0));
            detail::newton_monitor<T> monitor;
            bool done = false;
            for (std::size_t it = 0; it < K && !done; ++it) {
                State in;
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + z[n];
                State fz;
                detail::evaluate(f, ti, static_cast<const State&>(in), fz);
                State dz;  // the residual v + h gamma f(Y) - Z, then the update
                for (std::size_t n = 0; n < N; ++n) dz[n] = v[n] + hg * fz[n] - z[n];
                linalg::lu_solve(m, piv, dz);
                for (std::size_t n = 0; n < N; ++n) z[n] += dz[n];
                detail::count_newton_iteration(f);
                const status s = judge(monitor, dz, weights, done);
                if (s != status::ok) return s;
            }
            if (!Newton::fixed && !done) return status::no_convergence;
            constexpr T inverse_gamma = T(1) / gamma;
            for (std::size_t n = 0; n < N; ++n) hk[i][n] = (z[n] - v[n]) * inverse_gamma;
        }
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (stiffly_accurate) {
                next[n] = y[n] + z[n];
            } else {
                T sum = T(0);
                for (std::size_t j = 0; j < S; ++j) sum += tab.b[j] * hk[j][n];
                next[n] = y[n] + sum;
            }
        }
        return status::ok;
    }

    // Fully implicit: all stages at once, Z in R^{SN}, with I - h (A (x) J).
    template <class System>
    status solve_coupled(System& f, const State& y, T t, T dt, const jacobian_t<State>& jac, State& next,
                         std::array<T, S * N>* keep = nullptr) const {
        constexpr std::size_t M = S * N;
        linalg::matrix<T, M> m;
        for (std::size_t i = 0; i < S; ++i)
            for (std::size_t j = 0; j < S; ++j) {
                const T ha = dt * tab.a[i][j];
                for (std::size_t r = 0; r < N; ++r)
                    for (std::size_t c = 0; c < N; ++c)
                        m[i * N + r][j * N + c] = (i == j && r == c ? T(1) : T(0)) - ha * jac[r][c];
            }
        linalg::pivots<M> piv;
        if (linalg::lu_factor(m, piv) != status::ok) return status::singular_matrix;
        const std::array<T, N> weights = detail::newton_weights(tolerance_, y);
        std::array<T, M> z{};
        detail::newton_monitor<T> monitor;
        bool done = false;
        for (std::size_t it = 0; it < K && !done; ++it) {
            std::array<State, S> fz;
            for (std::size_t i = 0; i < S; ++i) {
                State in;
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + z[i * N + n];
                detail::evaluate(f, t + tab.c[i] * dt, static_cast<const State&>(in), fz[i]);
            }
            std::array<T, M> dz;  // the residual h (A (x) I) F(Z) - Z, then the update
            for (std::size_t i = 0; i < S; ++i)
                for (std::size_t n = 0; n < N; ++n) {
                    T sum = T(0);
                    for (std::size_t j = 0; j < S; ++j) sum += tab.a[i][j] * fz[j][n];
                    dz[i * N + n] = dt * sum - z[i * N + n];
                }
            linalg::lu_solve(m, piv, dz);
            for (std::size_t q = 0; q < M; ++q) z[q] += dz[q];
            detail::count_newton_iteration(f);
            const status s = judge(monitor, dz, weights, done);
            if (s != status::ok) return s;
        }
        if (!Newton::fixed && !done) return status::no_convergence;
        if (keep != nullptr) *keep = z;
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (stiffly_accurate) {
                next[n] = y[n] + z[(S - 1) * N + n];
            } else {
                T sum = T(0);
                for (std::size_t j = 0; j < S; ++j) sum += d_weights[j] * z[j * N + n];
                next[n] = y[n] + sum;
            }
        }
        return status::ok;
    }
};

// The named steppers. The second argument picks the Newton policy: newton<K> (the default, K = 10) or
// fixed_newton<K>, e.g. odestep::backward_euler<state, odestep::fixed_newton<2>>.
/// Backward Euler: order 1, L-stable.
template <class State, class Newton = newton<>>
using backward_euler = implicit_rk<tables::backward_euler, State, Newton>;
/// The implicit trapezoid (Crank-Nicolson): order 2, A-stable, symmetric.
template <class State, class Newton = newton<>>
using trapezoid = implicit_rk<tables::trapezoid, State, Newton>;
/// The implicit trapezoid under its PDE name.
template <class State, class Newton = newton<>>
using crank_nicolson = implicit_rk<tables::trapezoid, State, Newton>;
/// The implicit midpoint rule: order 2, A-stable, symplectic.
template <class State, class Newton = newton<>>
using implicit_midpoint = implicit_rk<tables::implicit_midpoint, State, Newton>;
/// Gauss-Legendre with two stages: order 4, A-stable, symplectic.
template <class State, class Newton = newton<>>
using gauss4 = implicit_rk<tables::gauss4, State, Newton>;
/// Alexander's SDIRK: order 3, L-stable, three stages sharing one factorization.
template <class State, class Newton = newton<>>
using sdirk3 = implicit_rk<tables::sdirk3, State, Newton>;
/// Radau IIA with three stages: order 5, L-stable.
template <class State, class Newton = newton<>>
using radau_iia5 = implicit_rk<tables::radau_iia5, State, Newton>;

}  // namespace odestep

#endif
