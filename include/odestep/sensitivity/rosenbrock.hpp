// SPDX-License-Identifier: BSL-1.0
// odestep: the derivative of a Rosenbrock step (RODAS3), Phi = d y_{n+1} / d y_n, its stages differentiated
// with the Jacobian's own dependence on y_n included.
#ifndef ODESTEP_SENSITIVITY_ROSENBROCK_HPP
#define ODESTEP_SENSITIVITY_ROSENBROCK_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../detail/ops.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../rk/rosenbrock.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "../tables/rosenbrock.hpp"
#include "transition.hpp"

namespace odestep {
namespace detail {

// The system rosenbrock steps when a transition is asked for: f and the Jacobian pass through unchanged (the
// step is the plain one, bit for bit), and it keeps what the plain step evaluated, in the order rosenbrock
// evaluates it with the system's own Jacobian: f(t_n, y_n), J(t_n, y_n), f(t_n + delta, y_n) for df/dt, then
// each stage whose input is new (a stage that reuses the previous input is filled in afterwards).
template <class Method, class State, class System>
struct rosenbrock_listener {
    using T = value_type_t<State>;
    static constexpr auto co = transform_rosenbrock(Method::template table<T>);
    static constexpr std::size_t S = Method::template table<T>.stages;
    // new_stage[k]: the stage of the k-th stage evaluation after f(t_n, y_n) and the df/dt one.
    static constexpr std::array<std::size_t, S> new_stages() noexcept {
        std::array<std::size_t, S> list{};
        std::size_t k = 0;
        for (std::size_t i = 1; i < S; ++i)
            if (!co.reuses_previous[i]) list[k++] = i;
        return list;
    }
    static constexpr std::array<std::size_t, S> new_stage = new_stages();

    System& f;
    std::array<State, S>& input;  // the stage inputs Y_i
    std::array<State, S>& value;  // f(t + alpha_i h, Y_i)
    State& shifted;               // f(t_n + delta, y_n)
    jacobian_t<State>& jac;       // J(t_n, y_n)
    std::size_t calls = 0;

    void operator()(T t, const State& y, State& dydt) {
        evaluate(f, t, y, dydt);
        if (calls == 0) {
            input[0] = y;
            value[0] = dydt;
        } else if (calls == 1) {
            shifted = dydt;
        } else if (calls - 2 < S - 1) {
            const std::size_t i = new_stage[calls - 2];
            input[i] = y;
            value[i] = dydt;
        }
        ++calls;
    }
    void jacobian(T t, const State& y, jacobian_t<State>& dfdy) {
        evaluate_jacobian(f, t, y, dfdy);
        jac = dfdy;
    }
};

}  // namespace detail

/// \brief A Rosenbrock step (odestep::rosenbrock<Method, State>, the library's own: RODAS3) that also returns
/// its derivative Phi = d y_{n+1} / d y_n.
///
/// The step solves, in Hairer & Wanner's transformed form (rk/rosenbrock.hpp),
///
///     (I - h gamma J) u_i = h gamma f(t + alpha_i h, Y_i) + h^2 gamma gamma_i g + sum_{j<i} gc_ij u_j,
///     Y_i = y_n + sum_{j<i} a_ij u_j,     y_{n+1} = y_n + sum_i m_i u_i,
///
/// with J = J(t_n, y_n) and g = (f(t_n + delta, y_n) - f(t_n, y_n)) / delta. Its derivative U_i = d u_i / d y_n
/// (W_i = d Y_i / d y_n = I + sum_{j<i} a_ij U_j) solves
///
///     (I - h gamma J) U_i = h gamma J_i W_i + h^2 gamma gamma_i G + sum_{j<i} gc_ij U_j + h gamma J'[u_i],
///
/// with J_i = J(t + alpha_i h, Y_i), G = (J(t_n + delta, y_n) - J(t_n, y_n)) / delta (exactly what the step's g
/// depends on) and J'[u_i] = d/ds J(t_n, y_n + s u_i), the derivative of the step's own Jacobian along u_i
/// (by the symmetry of second derivatives, d J / d y_n applied to u_i). Phi = I + sum_i m_i U_i.
///
/// A Rosenbrock step uses J inside the formula, so its exact derivative needs second derivatives of f. The
/// transition takes them as a forward difference of the Jacobian along each stage direction,
/// (J(t_n, y_n + s u_i) - J(t_n, y_n)) / s with s |u_i| = sqrt(eps) max(1, |y_n|) (max norms): a relative
/// error of about sqrt(eps) (1.5e-8 in double, 3.5e-4 in float) on a term of size h^2 |f''| |f|. On a
/// linear system that term is zero and Phi is the stability function R(hA) to round-off. Without the term
/// (J frozen) Phi would differ from the step's derivative by about h^2 (b^T Gamma 1) f''(f, .) (5/12 for
/// RODAS3), the same order as Phi = I + hJ's error.
///
/// The system must carry its Jacobian (odestep::with_jacobian, odestep::with_dual_jacobian) and f must be
/// twice differentiable. Cost beyond the plain step: one Jacobian at t_n + delta, one per new stage input
/// (RODAS3: 2), one along each stage direction (RODAS3: 4), one LU of I - h gamma J, and per stage M solves
/// and three N x N by N x M products. Stack: S stage derivatives (N x M each), S stage inputs and values, four
/// N x N matrices.
///
/// Failures leave y and Phi untouched: the plain step's (`non_finite`, `singular_matrix`), and `non_finite`
/// when Phi is not finite (a NaN or Inf in a Jacobian at a stage or along a stage direction, an overflow).
template <class Method, class State>
class rosenbrock_transition {
public:
    using state_type = State;                          ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;            ///< T
    using method_type = Method;                        ///< the table's tag
    using stepper_type = rosenbrock<Method, State>;    ///< the plain stepper whose step this is
    using matrix_type = jacobian_t<State>;             ///< Phi, N x N
    static constexpr int order = stepper_type::order;  ///< the method's order

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr std::size_t S = stepper_type::stages;
    static constexpr auto tab = Method::template table<T>;
    static constexpr auto co = detail::transform_rosenbrock(tab);
    static constexpr T gamma = tab.gamma[0][0];
    static constexpr std::size_t count_new_inputs() noexcept {
        std::size_t n = 0;
        for (std::size_t i = 1; i < S; ++i) n += co.reuses_previous[i] ? 0U : 1U;
        return n;
    }

public:
    /// Jacobians per step: the plain step's, one at t_n + delta, one per new stage input, one per stage
    /// direction.
    static constexpr std::size_t jacobian_evals_per_step = 2 + count_new_inputs() + S;

    /// y <- y_{n+1}, phi <- d y_{n+1} / d y_n. On any status but ok, y and phi are untouched.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, matrix_type& phi, T t, T dt) const {
        matrix_type seed;
        detail::set_identity(seed);
        return advance<N>(f, y, seed, phi, t, dt);
    }

    /// y <- y_{n+1}, s <- Phi s for a sensitivity s = d y_n / d p of N rows and M columns.
    template <class System, std::size_t M>
    [[nodiscard]] status propagate(System&& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        return advance<M>(f, y, s, s, t, dt);
    }

private:
    template <std::size_t M, class System>
    static status advance(System& f, State& y, const sensitivity_matrix<T, N, M>& seed,
                          sensitivity_matrix<T, N, M>& out, T t, T dt) {
        using system_type = std::remove_reference_t<System>;
        detail::require_jacobian<system_type, State>();
        using block = sensitivity_matrix<T, N, M>;
        std::array<State, S> input;
        std::array<State, S> value;
        State shifted;
        jacobian_t<State> j0;
        detail::rosenbrock_listener<Method, State, system_type> listener{f, input, value, shifted, j0};
        State next = y;
        const status ps = stepper_type{}.step(listener, next, t, dt);
        if (ps != status::ok) return ps;
        for (std::size_t i = 1; i < S; ++i)
            if (co.reuses_previous[i]) {
                input[i] = input[i - 1];
                value[i] = value[i - 1];
            }
        // g and its derivative G S, with the step's own delta.
        const T later = t + difference_increment(t);
        const T delta = later - t;
        State g;
        for (std::size_t n = 0; n < N; ++n) g[n] = (shifted[n] - value[0][n]) / delta;
        jacobian_t<State> work;  // J at t_n + delta, then each stage's J, then each direction's
        detail::evaluate_jacobian(f, later, y, work);
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) work[r][c] = (work[r][c] - j0[r][c]) / delta;
        block gs;
        detail::multiply(work, seed, gs);
        // I - h gamma J, factored.
        const T hg = dt * gamma;
        const T h2 = dt * dt;
        linalg::matrix<T, N> e;
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) e[r][c] = (r == c ? T(1) : T(0)) - hg * j0[r][c];
        linalg::pivots<N> pivot{};
        if (linalg::lu_factor(e, pivot) != status::ok) return status::singular_matrix;
        const T root_eps = std::sqrt(std::numeric_limits<T>::epsilon());
        const T scale = detail::max_value(T(1), max_norm(y));
        std::array<State, S> u;
        std::array<block, S> du;
        jacobian_t<State> ji = j0;  // J_i, kept for a stage that reuses the previous input
        for (std::size_t i = 0; i < S; ++i) {
            // u_i, as the plain step computes it (its arithmetic), for the direction of J'[u_i].
            for (std::size_t n = 0; n < N; ++n) {
                T sum = hg * value[i][n] + h2 * co.time_weight[i] * g[n];
                for (std::size_t j = 0; j < i; ++j) sum += co.gc[i][j] * u[j][n];
                u[i][n] = sum;
            }
            linalg::lu_solve(e, pivot, u[i]);
            // W_i = S + sum_{j<i} a_ij U_j, and the right-hand side h gamma J_i W_i + h^2 gamma gamma_i G S
            // + sum_{j<i} gc_ij U_j + h gamma J'[u_i] S.
            block w = seed;
            for (std::size_t j = 0; j < i; ++j)
                if (co.a[i][j] != T(0)) detail::add_scaled(w, co.a[i][j], du[j]);
            if (i > 0 && !co.reuses_previous[i])
                detail::evaluate_jacobian(f, t + co.node[i] * dt, static_cast<const State&>(input[i]), ji);
            block rhs;
            detail::multiply(ji, w, rhs);
            for (std::size_t r = 0; r < N; ++r)
                for (std::size_t c = 0; c < M; ++c) rhs[r][c] *= hg;
            detail::add_scaled(rhs, h2 * co.time_weight[i], gs);
            for (std::size_t j = 0; j < i; ++j)
                if (co.gc[i][j] != T(0)) detail::add_scaled(rhs, co.gc[i][j], du[j]);
            const T size = max_norm(u[i]);
            if (size > T(0)) {
                const T step = root_eps * scale / size;
                State moved;
                for (std::size_t n = 0; n < N; ++n) moved[n] = y[n] + step * u[i][n];
                jacobian_t<State> jd;
                detail::evaluate_jacobian(f, t, static_cast<const State&>(moved), jd);
                for (std::size_t r = 0; r < N; ++r)
                    for (std::size_t c = 0; c < N; ++c) jd[r][c] = (jd[r][c] - j0[r][c]) / step;
                block second;
                detail::multiply(jd, seed, second);
                detail::add_scaled(rhs, hg, second);
            }
            for (std::size_t c = 0; c < M; ++c) {
                State col;
                for (std::size_t r = 0; r < N; ++r) col[r] = rhs[r][c];
                linalg::lu_solve(e, pivot, col);
                for (std::size_t r = 0; r < N; ++r) du[i][r][c] = col[r];
            }
        }
        block d = seed;  // Phi S = S + sum_i m_i U_i
        for (std::size_t i = 0; i < S; ++i)
            if (co.m[i] != T(0)) detail::add_scaled(d, co.m[i], du[i]);
        if (!detail::matrix_finite(d)) return status::non_finite;
        y = next;
        out = d;
        return status::ok;
    }

    static T max_norm(const State& v) noexcept {
        T largest = T(0);
        for (std::size_t n = 0; n < N; ++n) largest = detail::max_value(largest, detail::abs_value(v[n]));
        return largest;
    }
};

/// RODAS3 with Phi.
template <class State>
using rodas3_transition = rosenbrock_transition<tables::rodas3, State>;

}  // namespace odestep

#endif
