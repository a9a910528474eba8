// SPDX-License-Identifier: BSL-1.0
// odestep: the step's derivative, Phi = d y_{n+1} / d y_n (the state-transition matrix of the discrete step),
// by internal differentiation: the library's own step, its stages differentiated with the system's Jacobian.
#ifndef ODESTEP_SENSITIVITY_TRANSITION_HPP
#define ODESTEP_SENSITIVITY_TRANSITION_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../newtonian/splitting.hpp"
#include "../rk/explicit_rk.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "../tables/splitting.hpp"

namespace odestep {

/// A matrix of N rows and M columns, row-major (m[i][j]: row i, column j): a sensitivity S = d y / d p of
/// a state of N components with respect to M quantities. For M = N it is odestep::jacobian_t.
template <class T, std::size_t N, std::size_t M>
using sensitivity_matrix = std::array<std::array<T, M>, N>;

/// The state-transition matrix of a Newtonian step on (x, v), both std::array<T, N>: 2N x 2N, rows and
/// columns ordered x_1 .. x_N, v_1 .. v_N; phi[i][j] = d (x, v)_{n+1, i} / d (x, v)_{n, j}.
template <class State>
using phase_matrix_t =
    sensitivity_matrix<value_type_t<State>, 2 * state_traits<State>::size, 2 * state_traits<State>::size>;

namespace detail {

// True when every entry of m is finite: one plain sum (finite_sum), and the exact test only when it fails.
template <class T, std::size_t R, std::size_t C>
constexpr bool matrix_finite(const sensitivity_matrix<T, R, C>& m) noexcept {
    T sum = T(0);
    for (std::size_t i = 0; i < R; ++i) add_components(sum, m[i]);
    if (finite_sum(sum)) return true;
    for (std::size_t i = 0; i < R; ++i)
        if (!each_finite(m[i])) return false;
    return true;
}

// Whether a product skips the row of b that a zero a_il multiplies (a Jacobian's structural zeros: a
// kinematic identity block, a banded coupling), for rows of C entries of T: always on a scalar FPU, where the
// compare and branch cost less than the C multiply-adds they save; on a vector unit (SSE2, NEON) only for rows
// wider than two 16-byte vectors, since a shorter row is one or two vector multiply-adds, less than the test
// costs when J has few zeros (bench/RESULTS.md, "Steps with Phi").
#if defined(__SSE2__) || defined(__ARM_NEON)
template <class T, std::size_t C>
inline constexpr bool skip_zero_rows = C * sizeof(T) > 32;
#else
template <class T, std::size_t C>
inline constexpr bool skip_zero_rows = true;
#endif

// to = a b (a: R x L, b: L x C), zero a_il skipped where skip_zero_rows says. Both loops over l and over
// the columns are unrolled unless -Os (fully to 16: a small product is straight-line code).
template <class T, std::size_t R, std::size_t L, std::size_t C>
constexpr void multiply(const sensitivity_matrix<T, R, L>& a, const sensitivity_matrix<T, L, C>& b,
                        sensitivity_matrix<T, R, C>& to) noexcept {
    for (std::size_t i = 0; i < R; ++i) {
        std::array<T, C> row{};
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t l = 0; l < L; ++l) {
            const T ail = a[i][l];
            if (skip_zero_rows<T, C> && ail == T(0)) continue;
            ODESTEP_UNROLL_UNLESS_SIZE
            for (std::size_t j = 0; j < C; ++j) row[j] += ail * b[l][j];
        }
        to[i] = row;
    }
}

// to = a (I + c b) = a + (c a) b (a: R x R, b: R x R), for a stage whose Z = I + c K_j reads one stage: no
// Z formed, no identity added. Zero a_il skipped as in multiply.
template <class T, std::size_t R>
constexpr void multiply_identity_plus(const sensitivity_matrix<T, R, R>& a, T c, const sensitivity_matrix<T, R, R>& b,
                                      sensitivity_matrix<T, R, R>& to) noexcept {
    for (std::size_t i = 0; i < R; ++i) {
        std::array<T, R> row = a[i];
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t l = 0; l < R; ++l) {
            const T ail = a[i][l];
            if (skip_zero_rows<T, R> && ail == T(0)) continue;
            const T cl = c * ail;
            ODESTEP_UNROLL_UNLESS_SIZE
            for (std::size_t j = 0; j < R; ++j) row[j] += cl * b[l][j];
        }
        to[i] = row;
    }
}

// The transitions' one requirement on the system: its Jacobian.
template <class System, class State>
constexpr void require_jacobian() noexcept {
    static_assert(has_jacobian_v<System, State>,
                  "odestep: the step's derivative needs the system's Jacobian: odestep::with_jacobian(f, J), or "
                  "odestep::with_dual_jacobian(f) for an f written as a template");
}

// True when the system computes J z itself (odestep::system_with_dual_jacobian's jacobian_times).
template <class System, class T, std::size_t N, std::size_t M, class = void>
struct has_jacobian_times : std::false_type {};
template <class System, class T, std::size_t N, std::size_t M>
struct has_jacobian_times<
    System, T, N, M,
    std::void_t<decltype(std::declval<System&>().jacobian_times(
        std::declval<T>(), std::declval<const std::array<T, N>&>(), std::declval<const sensitivity_matrix<T, N, M>&>(),
        std::declval<sensitivity_matrix<T, N, M>&>()))>> : std::true_type {};

// to += c m.
template <class T, std::size_t R, std::size_t C>
constexpr void add_scaled(sensitivity_matrix<T, R, C>& to, T c, const sensitivity_matrix<T, R, C>& m) noexcept {
    for (std::size_t i = 0; i < R; ++i) {
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t j = 0; j < C; ++j) to[i][j] += c * m[i][j];
    }
}

// to = c m.
template <class T, std::size_t R, std::size_t C>
constexpr void scale(sensitivity_matrix<T, R, C>& to, T c, const sensitivity_matrix<T, R, C>& m) noexcept {
    for (std::size_t i = 0; i < R; ++i) {
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t j = 0; j < C; ++j) to[i][j] = c * m[i][j];
    }
}

// The identity, or the seed s: what a sensitivity starts from.
template <class T, std::size_t N>
constexpr void set_identity(sensitivity_matrix<T, N, N>& m) noexcept {
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) m[i][j] = i == j ? T(1) : T(0);
}

// The stages explicit_rk<Method, State>::step(f, y, t, dt) evaluates, in the order it evaluates them: stage i
// when its weight b_i is not zero or a needed later stage reads it (a_ji != 0). The rule explicit_rk applies
// (its plain step); explicit_rk_transition checks the count against explicit_rk's rhs_evals_per_step.
template <class Method, class T>
struct rk_stage_plan {
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = std::remove_const_t<decltype(tab)>::stages;
    static constexpr std::array<bool, S> needed_stages() noexcept {
        std::array<bool, S> flags{};
        for (std::size_t i = S; i-- > 0;) {
            bool used = tab.b[i] != T(0);
            for (std::size_t j = i + 1; j < S; ++j) used = used || (flags[j] && tab.a[j][i] != T(0));
            flags[i] = used;
        }
        return flags;
    }
    static constexpr std::array<bool, S> needed = needed_stages();
    static constexpr std::size_t count() noexcept {
        std::size_t n = 0;
        for (bool u : needed) n += u ? 1U : 0U;
        return n;
    }
    static constexpr std::size_t evaluated = count();
    // order[m]: the stage of the m-th evaluation of f.
    static constexpr std::array<std::size_t, S> evaluation_order() noexcept {
        std::array<std::size_t, S> stage_of{};
        std::size_t m = 0;
        for (std::size_t i = 0; i < S; ++i)
            if (needed[i]) stage_of[m++] = i;
        return stage_of;
    }
    static constexpr std::array<std::size_t, S> order = evaluation_order();
};

// The system explicit_rk steps when a transition is asked for: each evaluation of f at a stage input Y_i
// also evaluates the Jacobian J_i = df/dy(t_i, Y_i) there and differentiates the stage,
//     K_i = d k_i / d p = J_i Z_i,   Z_i = d Y_i / d p = S + dt sum_{j<i} a_ij K_j,
// with S = d y_n / d p the seed (the identity when Identity: then Z_i = I and K_i = J_i for a stage that
// reads no other). explicit_rk's own stage loop computes the stages; this only listens.
template <class Method, class State, std::size_t M, bool Identity, class System>
struct rk_tangent_listener {
    using T = value_type_t<State>;
    static constexpr std::size_t N = state_traits<State>::size;
    using plan = rk_stage_plan<Method, T>;
    static constexpr std::size_t S = plan::S;
    using block = sensitivity_matrix<T, N, M>;

    System& f;
    const block& seed;  // S (not read when Identity)
    T dt;
    std::array<block, S>& k;  // K_i of the evaluated stages
    std::size_t calls = 0;

    // dydt = f(t, y), and the derivative of the stage whose input y is.
    void operator()(T t, const State& y, State& dydt) {
        evaluate(f, t, y, dydt);
        if (calls < plan::evaluated) differentiate(plan::order[calls], t, y);
        ++calls;
    }

    // Whether stage i reads an earlier stage (a_ij != 0 for some j).
    static constexpr std::array<bool, S> reading_stages() noexcept {
        std::array<bool, S> flags{};
        for (std::size_t i = 0; i < S; ++i)
            for (std::size_t j = 0; j < i; ++j) flags[i] = flags[i] || plan::tab.a[i][j] != T(0);
        return flags;
    }
    static constexpr std::array<bool, S> reads = reading_stages();
    // Whether stage i reads exactly one earlier stage (then Z_i = I + dt a_ij K_j needs no Z formed).
    static constexpr std::array<bool, S> single_reads() noexcept {
        std::array<bool, S> flags{};
        for (std::size_t i = 0; i < S; ++i) {
            std::size_t n = 0;
            for (std::size_t j = 0; j < i; ++j) n += plan::tab.a[i][j] != T(0) ? 1U : 0U;
            flags[i] = n == 1;
        }
        return flags;
    }
    static constexpr std::array<bool, S> single = single_reads();
    // The first stage j < i with a_ij != 0 (0 for a stage that reads none: not used there).
    static constexpr std::array<std::size_t, S> first_reads() noexcept {
        std::array<std::size_t, S> first{};
        for (std::size_t i = 0; i < S; ++i)
            for (std::size_t j = i; j-- > 0;)
                if (plan::tab.a[i][j] != T(0)) first[i] = j;
        return first;
    }
    static constexpr std::array<std::size_t, S> first_read = first_reads();

    // K_i = J_i Z_i, Z_i = S + dt sum_{j<i} a_ij K_j, with J_i = J(t, y) at the stage's input. One loop over
    // the table's row, not one body per stage: the plain step may be flattened (ODESTEP_STEP_FLATTEN) with
    // this listener inlined at each of its S evaluations, and S bodies per evaluation would make S^2 of them.
    // A system that forms J z itself (dual numbers seeded with z) gets Z_i and no N x N J is formed.
    void differentiate(std::size_t i, T t, const State& y) {
        if constexpr (Identity) {
            static_assert(M == N, "odestep: an identity seed is square");
            if (!reads[i]) {
                evaluate_jacobian(f, t, y, k[i]);  // K_i = J_i I
                return;
            }
            if constexpr (!has_jacobian_times<System, T, N, M>::value) {
                if (single[i]) {  // K_i = J_i (I + dt a_ij K_j), j = first_read[i]
                    jacobian_t<State> jac;
                    evaluate_jacobian(f, t, y, jac);
                    const std::size_t j = first_read[i];
                    multiply_identity_plus(jac, dt * plan::tab.a[i][j], k[j], k[i]);
                    return;
                }
            }
        }
        block z;
        if constexpr (Identity) {
            // Z_i = I + dt sum_j a_ij K_j: the first term written, not added to a zeroed identity.
            const std::size_t first = first_read[i];
            scale(z, dt * plan::tab.a[i][first], k[first]);
            for (std::size_t j = first + 1; j < i; ++j) {
                const T a = plan::tab.a[i][j];
                if (a != T(0)) add_scaled(z, dt * a, k[j]);
            }
            for (std::size_t d = 0; d < N; ++d) z[d][d] += T(1);
        } else {
            z = seed;
            for (std::size_t j = 0; j < i; ++j) {
                const T a = plan::tab.a[i][j];
                if (a != T(0)) add_scaled(z, dt * a, k[j]);
            }
        }
        if constexpr (has_jacobian_times<System, T, N, M>::value) {
            f.jacobian_times(t, y, static_cast<const block&>(z), k[i]);
        } else {
            jacobian_t<State> jac;
            evaluate_jacobian(f, t, y, jac);
            multiply(jac, z, k[i]);
        }
    }
};

}  // namespace detail

/// \brief An explicit Runge-Kutta step that also returns its derivative, Phi = d y_{n+1} / d y_n, from the
/// table `Method::table<T>` (any explicit table of odestep::tables).
///
/// Internal differentiation: the step is odestep::explicit_rk<Method, State, Check>'s own (its stage loop,
/// its arithmetic: the new state is bit for bit the plain step's), and each stage is differentiated with
/// the system's Jacobian J = df/dy at that stage's input,
///
///     K_i = J(t + c_i dt, Y_i) (I + dt sum_j a_ij K_j),      Phi = I + dt sum_i b_i K_i,
///
/// so Phi is the exact derivative of what the step computes (to round-off), not an approximation of the
/// flow's derivative. On a linear system y' = A y it is the method's stability function R(dt A).
///
/// The system must carry its Jacobian: odestep::with_jacobian(f, J), or odestep::with_dual_jacobian(f)
/// for an f written as a template (forward-mode automatic differentiation, odestep::dual).
///
/// Cost per step: the plain step, one Jacobian per evaluated stage, and per stage an N x N by N x M
/// product (M = N for Phi; J's zero entries skipped). Through odestep::with_dual_jacobian each stage is
/// instead one evaluation of f in dual<T, M> seeded with the stage's Z (its jacobian_times), and Phi equals
/// the hand Jacobian's to round-off. Stack: one N x M matrix per stage, two more, and the plain step's.
///
/// Check (odestep::checked, the default): a step whose new state, or Phi (a NaN or Inf from the
/// Jacobian, or an overflow), is not finite returns `status::non_finite` with y and Phi untouched.
/// odestep::unchecked writes them as they come.
template <class Method, class State, class Check = checked>
class explicit_rk_transition {
public:
    using state_type = State;                                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;                  ///< T
    using method_type = Method;                              ///< the table tag
    using check_type = Check;                                ///< odestep::checked or odestep::unchecked
    using stepper_type = explicit_rk<Method, State, Check>;  ///< the plain stepper whose step this is
    using matrix_type = jacobian_t<State>;                   ///< Phi, N x N: phi[i][j] = d y_{n+1,i} / d y_{n,j}
    static constexpr int order = stepper_type::order;        ///< the method's order
    /// Evaluations of f per step (those of the plain step); each also evaluates the Jacobian once.
    static constexpr std::size_t rhs_evals_per_step = stepper_type::rhs_evals_per_step;
    /// Evaluations of the Jacobian per step.
    static constexpr std::size_t jacobian_evals_per_step = rhs_evals_per_step;

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    using plan = detail::rk_stage_plan<Method, T>;
    static_assert(plan::evaluated == stepper_type::rhs_evals_per_step,
                  "odestep: the transition's stage plan must be explicit_rk's");

public:
    /// y <- y_{n+1} and phi <- d y_{n+1} / d y_n. Checked: on `status::non_finite` y and phi are untouched.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, matrix_type& phi, T t, T dt) const {
        return advance<N, true>(f, y, phi, phi, t, dt);
    }

    /// y <- y_{n+1} and s <- (d y_{n+1} / d y_n) s for a sensitivity s = d y_n / d p of N rows and any M
    /// columns (s = Phi of the run so far gives Phi of the run: the variational equation of the steps).
    /// Cheaper than step() and a product when M < N. Checked: on `status::non_finite` y and s are untouched.
    template <class System, std::size_t M>
    [[nodiscard]] status propagate(System&& f, State& y, sensitivity_matrix<T, N, M>& s, T t, T dt) const {
        return advance<M, false>(f, y, s, s, t, dt);
    }

private:
    template <std::size_t M, bool Identity, class System>
    static status advance(System& f, State& y, const sensitivity_matrix<T, N, M>& seed,
                          sensitivity_matrix<T, N, M>& out, T t, T dt) {
        using system_type = std::remove_reference_t<System>;
        detail::require_jacobian<system_type, State>();
        using listener_type = detail::rk_tangent_listener<Method, State, M, Identity, system_type>;
        std::array<typename listener_type::block, plan::S> k;  // not zeroed: only evaluated stages are read
        listener_type listener{f, seed, dt, k};
        State next = y;
        const status s = stepper_type{}.step(listener, next, t, dt);
        if (s != status::ok) return s;
        // Phi S = S + dt sum_i b_i K_i, one pass over the entries.
        sensitivity_matrix<T, N, M> d;
        add_weighted<M, Identity>(d, seed, k, dt, std::make_index_sequence<plan::S>{});
        if constexpr (Check::checks_finiteness) {
            if (!detail::matrix_finite(d)) return status::non_finite;
        }
        y = next;
        out = d;
        return status::ok;
    }
    // d = S + dt sum_i b_i K_i (S = I when Identity): the stages with b_i = 0 are not read (nor evaluated),
    // S added last (the sum's order: S + (dt sum_i b_i K_i)). Unrolled (not -Os), row by row: the row kept
    // in registers while each stage adds its row, a loop over the columns that the compiler vectorizes. At
    // -Os, where nothing is unrolled, entry by entry: a rolled row would be loaded and stored once per
    // stage, where each entry's sum stays in a register.
    template <std::size_t M, bool Identity, std::size_t... I>
    static void add_weighted(sensitivity_matrix<T, N, M>& d, const sensitivity_matrix<T, N, M>& seed,
                             const std::array<sensitivity_matrix<T, N, M>, plan::S>& k, T dt,
                             std::index_sequence<I...>) {
        const std::array<T, plan::S> w{(dt * plan::tab.b[I])...};
#if defined(__OPTIMIZE_SIZE__)
        for (std::size_t r = 0; r < N; ++r) {
            for (std::size_t c = 0; c < M; ++c) {
                T sum = T(0);
                (((plan::tab.b[I] != T(0)) ? void(sum += w[I] * k[I][r][c]) : void()), ...);
                if constexpr (Identity) {
                    d[r][c] = (r == c ? T(1) : T(0)) + sum;
                } else {
                    d[r][c] = seed[r][c] + sum;
                }
            }
        }
#else
        for (std::size_t r = 0; r < N; ++r) {
            std::array<T, M> row{};
            ODESTEP_UNROLL_UNLESS_SIZE
            for (std::size_t i = 0; i < plan::S; ++i) {
                if (plan::tab.b[i] == T(0)) continue;
                ODESTEP_UNROLL_UNLESS_SIZE
                for (std::size_t c = 0; c < M; ++c) row[c] += w[i] * k[i][r][c];
            }
            if constexpr (Identity) {
                row[r] += T(1);
            } else {
                ODESTEP_UNROLL_UNLESS_SIZE
                for (std::size_t c = 0; c < M; ++c) row[c] = seed[r][c] + row[c];
            }
            d[r] = row;
        }
#endif
    }
};

// The named transitions, one per explicit table.
template <class State>
using euler_transition = explicit_rk_transition<tables::euler, State>;  ///< forward Euler with Phi
template <class State>
using heun_transition = explicit_rk_transition<tables::heun, State>;  ///< Heun with Phi
template <class State>
using rk4_transition = explicit_rk_transition<tables::rk4, State>;  ///< classic RK4 with Phi
template <class State>
using dormand_prince54_transition = explicit_rk_transition<tables::dormand_prince54, State>;  ///< DP 5(4) with Phi

namespace detail {

// The acceleration splitting steps when a transition is asked for: each evaluation a(t, X_m) (kick m of the
// step, in order) also evaluates da/dx(t, X_m) and keeps it; the step's derivative is then the product of
// the updates' derivatives (a drift: X' += h V'; a kick: V' += h A_m X'), formed by splitting_transition.
template <class State, std::size_t Kicks, class Accel>
struct kick_listener {
    using T = value_type_t<State>;
    Accel& a;
    std::array<jacobian_t<State>, Kicks>& dadx;
    std::size_t calls = 0;

    State operator()(T t, const State& x) {
        const State acc = acceleration(a, t, x);
        if (calls < Kicks) evaluate_jacobian(a, t, x, dadx[calls]);
        ++calls;
        return acc;
    }
};

// The same for a force a(t, x, v): each kick's evaluation at (X_m, V_m) also evaluates da/dx and da/dv there
// (a.jacobian(t, x, v, dadx, dadv)); the kick's derivative is then V' += h (A_m X' + B_m V').
template <class State, std::size_t Kicks, class Accel>
struct velocity_kick_listener {
    using T = value_type_t<State>;
    Accel& a;
    std::array<jacobian_t<State>, Kicks>& dadx;
    std::array<jacobian_t<State>, Kicks>& dadv;
    std::size_t calls = 0;

    State operator()(T t, const State& x, const State& v) {
        const State acc = acceleration(a, t, x, v);
        if (calls < Kicks) a.jacobian(t, x, v, dadx[calls], dadv[calls]);
        ++calls;
        return acc;
    }
};

}  // namespace detail

/// \brief A force a(t, x, v) with its two Jacobians, as one object: made by odestep::with_velocity_jacobian
/// for odestep::splitting_transition.
template <class A, class J>
struct velocity_force_with_jacobian {
    A a;    ///< the force, State a(t, x, v) or a(t, x, v, a_out)
    J jac;  ///< its Jacobians, jac(t, x, v, dadx, dadv)

    /// a(t, x, v) (when a returns the acceleration).
    template <class T, class State>
    constexpr auto operator()(T t, const State& x, const State& v) -> decltype(std::declval<A&>()(t, x, v)) {
        return a(t, x, v);
    }
    /// a(t, x, v, a_out) (when a writes it).
    template <class T, class State>
    constexpr auto operator()(T t, const State& x, const State& v, State& out)
        -> decltype(std::declval<A&>()(t, x, v, out)) {
        return a(t, x, v, out);
    }
    /// dadx = da/dx and dadv = da/dv at (t, x, v), both zeroed before jac writes them.
    template <class T, class State>
    void jacobian(T t, const State& x, const State& v, jacobian_t<State>& dadx, jacobian_t<State>& dadv) {
        dadx = {};
        dadv = {};
        jac(t, x, v, dadx, dadv);
    }
};

/// Pairs a force of position and velocity a(t, x, v) with its Jacobians, `jac(T t, const State& x, const
/// State& v, jacobian_t<State>& dadx, jacobian_t<State>& dadv)` writing dadx[i][j] = d a_i / d x_j and
/// dadv[i][j] = d a_i / d v_j (both zeroed before the call). A callable given as an lvalue is held by
/// reference, one given as an rvalue is moved in.
template <class A, class J>
constexpr velocity_force_with_jacobian<A, J> with_velocity_jacobian(A&& a, J&& jac) {
    return {std::forward<A>(a), std::forward<J>(jac)};
}

/// \brief A step of a splitting method for x'' = a(t, x) (velocity Verlet, Forest-Ruth, Yoshida, ... any
/// table of odestep::tables' splitting tables) that also returns its derivative,
/// Phi = d (x, v)_{n+1} / d (x, v)_n, a 2N x 2N odestep::phase_matrix_t.
///
/// The step is odestep::splitting<Method, State, Check>'s own (the same x and v, bit for bit, as a step of a
/// fresh splitting stepper). Each kick's acceleration Jacobian A_m = da/dx at the kick's position is
/// evaluated with it, and Phi is the product of the updates' derivatives: a drift by h is
/// [[I, h I], [0, I]], a kick by h is [[I, 0], [h A_m, I]]. Each factor is symplectic when A_m is symmetric
/// (a force with a potential), so Phi^T J Phi = J to round-off.
///
/// The acceleration must carry its Jacobian da/dx (odestep::with_jacobian(a, J), or
/// odestep::with_dual_jacobian(a)) for a force of position alone, a(t, x). A force of position and velocity,
/// a(t, x, v) (which the splitting stepper evaluates at each kick with the velocity before it), carries both
/// Jacobians, odestep::with_velocity_jacobian(a, J); a kick is then [[I, 0], [h A_m, I + h B_m]],
/// B_m = da/dv at the kick, and the step is neither symplectic nor, but for Euler-Cromer, above first
/// order (the plain stepper's traits say so). Nothing is kept between steps:
/// a first-same-as-last method (velocity Verlet) evaluates its first kick afresh, so each step costs one
/// evaluation of a and of da/dx per kick (velocity Verlet: 2 and 2).
///
/// Check (odestep::checked, the default): a non-finite x, v or Phi returns `status::non_finite` with x, v
/// and Phi untouched.
template <class Method, class State, class Check = checked>
class splitting_transition {
public:
    using state_type = State;                                   ///< the state of x and of v, std::array<T, N>
    using value_type = value_type_t<State>;                     ///< T
    using method_type = Method;                                 ///< the table tag
    using check_type = Check;                                   ///< odestep::checked or odestep::unchecked
    using stepper_type = splitting<Method, State, Check>;       ///< the plain stepper whose step this is
    using matrix_type = phase_matrix_t<State>;                  ///< Phi, 2N x 2N on (x, v)
    static constexpr int order = stepper_type::order;           ///< the method's order
    static constexpr std::size_t kicks = stepper_type::stages;  ///< kicks per step
    /// Evaluations of a per step (each kick's, none kept from the last step).
    static constexpr std::size_t rhs_evals_per_step = kicks;
    /// Evaluations of da/dx per step.
    static constexpr std::size_t jacobian_evals_per_step = kicks;

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    using plan = detail::splitting_plan<Method, T>;

public:
    /// (x, v) <- (x, v)_{n+1}, phi <- d (x, v)_{n+1} / d (x, v)_n. Checked: on `status::non_finite` x, v and
    /// phi are untouched.
    template <class Accel>
    [[nodiscard]] status step(Accel&& a, State& x, State& v, matrix_type& phi, T t, T dt) const {
        return advance<2 * N, true>(a, x, v, phi, phi, t, dt);
    }

    /// (x, v) <- (x, v)_{n+1}, s <- Phi s for a sensitivity s = d (x, v)_n / d p of 2N rows and M columns.
    template <class Accel, std::size_t M>
    [[nodiscard]] status propagate(Accel&& a, State& x, State& v, sensitivity_matrix<T, 2 * N, M>& s, T t, T dt) const {
        return advance<M, false>(a, x, v, s, s, t, dt);
    }

private:
    template <std::size_t M, bool Identity, class Accel>
    static status advance(Accel& a, State& x, State& v, const sensitivity_matrix<T, 2 * N, M>& seed,
                          sensitivity_matrix<T, 2 * N, M>& out, T t, T dt) {
        using accel_type = std::remove_reference_t<Accel>;
        constexpr bool velocity = is_velocity_force_v<accel_type, State>;
        static_assert(velocity || has_jacobian_v<accel_type, State>,
                      "odestep: the step's derivative needs the acceleration's Jacobian da/dx: "
                      "odestep::with_jacobian(a, J), or odestep::with_dual_jacobian(a) for an a written as a "
                      "template; for a force a(t, x, v), odestep::with_velocity_jacobian(a, J)");
        std::array<jacobian_t<State>, kicks> dadx;
        std::array<jacobian_t<State>, velocity ? kicks : 0> dadv;
        State nx = x;
        State nv = v;
        stepper_type stepper;  // fresh: nothing kept, every kick evaluated (and heard)
        status s;
        if constexpr (velocity) {
            detail::velocity_kick_listener<State, kicks, accel_type> listener{a, dadx, dadv};
            s = stepper.step(listener, nx, nv, t, dt);
        } else {
            detail::kick_listener<State, kicks, accel_type> listener{a, dadx};
            s = stepper.step(listener, nx, nv, t, dt);
        }
        if (s != status::ok) return s;
        // X' and V': the x rows and the v rows of Phi S.
        sensitivity_matrix<T, N, M> dx;
        sensitivity_matrix<T, N, M> dv;
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t j = 0; j < M; ++j) {
                if constexpr (Identity) {
                    dx[i][j] = j == i ? T(1) : T(0);
                    dv[i][j] = j == N + i ? T(1) : T(0);
                } else {
                    dx[i][j] = seed[i][j];
                    dv[i][j] = seed[N + i][j];
                }
            }
        std::size_t m = 0;
        for (std::size_t k = 0; k < plan::updates; ++k) {
            const T c = plan::coefficient(k);
            if (c == T(0)) continue;
            const T h = c * dt;
            if (!plan::is_kick(k)) {
                detail::add_scaled(dx, h, dv);  // drift: X' += h V'
            } else {
                sensitivity_matrix<T, N, M> ax;
                detail::multiply(dadx[m], dx, ax);
                if constexpr (velocity) {
                    sensitivity_matrix<T, N, M> bv;
                    detail::multiply(dadv[m], dv, bv);
                    detail::add_scaled(ax, T(1), bv);  // A_m X' + B_m V'
                }
                ++m;
                detail::add_scaled(dv, h, ax);  // kick: V' += h (A_m X' + B_m V')
            }
        }
        if constexpr (Check::checks_finiteness) {
            if (!detail::matrix_finite(dx) || !detail::matrix_finite(dv)) return status::non_finite;
        }
        x = nx;
        v = nv;
        for (std::size_t i = 0; i < N; ++i) {
            out[i] = dx[i];
            out[N + i] = dv[i];
        }
        return status::ok;
    }
};

// The named transitions.
template <class State>
using velocity_verlet_transition = splitting_transition<tables::velocity_verlet, State>;  ///< velocity Verlet
template <class State>
using forest_ruth_transition = splitting_transition<tables::forest_ruth, State>;  ///< Forest-Ruth with Phi
template <class State>
using yoshida6_transition = splitting_transition<tables::yoshida6, State>;  ///< Yoshida 6 with Phi

}  // namespace odestep

#endif
