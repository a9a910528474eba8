// SPDX-License-Identifier: BSL-1.0
// odestep: the one explicit Runge-Kutta stepper, driven by any Butcher table.
#ifndef ODESTEP_RK_EXPLICIT_RK_HPP
#define ODESTEP_RK_EXPLICIT_RK_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "../tables/runge_kutta.hpp"

namespace odestep {

namespace detail {

/// A weight vector w written as g r: one common factor g and ratios r_j = w_j / g, and the order in which
/// the stepper sums r_j k_j. Where every non-zero w_j is a small integer multiple of the smallest one
/// (exactly, in T: RK4's b is 1/6 (1, 2, 2, 1)), g is that smallest weight; otherwise g is the weight of
/// largest magnitude, so that |r_j| <= 1. Either way g takes the sign that makes the first term summed
/// positive. Terms of equal |r_j| form a class, gathered before they are scaled; the classes with
/// |r| != 1 are summed first (integer multiples: largest first, as the textbook writes
/// 2 (k2 + k3) + k1 + k4; otherwise in stage order), then the terms with |r| = 1, one by one.
template <class T, std::size_t S>
struct factored_weights {
    T g = T(0);
    std::array<T, S> r{};               // 0 where w_j = 0
    std::size_t classes = 0;            // classes with |r| != 1
    std::array<std::size_t, S> lead{};  // the first member of each, in summing order
    std::size_t first_unit = S;         // the first term with |r| = 1
};

template <class T, std::size_t S>
constexpr factored_weights<T, S> factor_weights(const std::array<T, S>& w) noexcept {
    factored_weights<T, S> f{};
    T smallest = T(0);
    T largest = T(0);
    for (std::size_t j = 0; j < S; ++j) {
        const T a = abs_value(w[j]);
        if (w[j] == T(0)) continue;
        if (smallest == T(0) || a < smallest) smallest = a;
        if (a > largest) largest = a;
    }
    if (largest == T(0)) return f;
    bool integer = true;
    for (std::size_t j = 0; j < S && integer; ++j) {
        if (w[j] == T(0)) continue;
        const T q = abs_value(w[j]) / smallest;
        const long m = q <= T(16) ? static_cast<long>(q + T(1) / T(2)) : 0;
        integer = m >= 1 && T(m) * smallest == abs_value(w[j]);  // an exact multiple in T
    }
    const T unit = integer ? smallest : largest;
    for (std::size_t j = 0; j < S; ++j) f.r[j] = w[j] / unit;  // exact for |r| = 1, and for integer multiples
    // Summing order: the classes with |r| != 1 by first member (integer: largest |r| first), then units.
    std::array<bool, S> taken{};
    for (;;) {
        std::size_t next = S;
        for (std::size_t j = 0; j < S; ++j) {
            const T a = abs_value(f.r[j]);
            if (f.r[j] == T(0) || a == T(1) || taken[j]) continue;
            if (next == S || (integer && a > abs_value(f.r[next]))) next = j;
        }
        if (next == S) break;
        f.lead[f.classes++] = next;
        for (std::size_t j = 0; j < S; ++j) taken[j] = taken[j] || abs_value(f.r[j]) == abs_value(f.r[next]);
    }
    for (std::size_t j = 0; j < S && f.first_unit == S; ++j)
        if (abs_value(f.r[j]) == T(1)) f.first_unit = j;
    // The sign of g: the first term summed comes out positive.
    const std::size_t first = f.classes > 0 ? f.lead[0] : f.first_unit;
    const bool flip = f.r[first] < T(0);
    f.g = flip ? -unit : unit;
    if (flip)
        for (std::size_t j = 0; j < S; ++j) f.r[j] = -f.r[j];
    return f;
}

}  // namespace detail

/// An explicit Runge-Kutta step for y' = f(t, y) from the table `Method::table<T>`.
///
/// The stage loop is unrolled over the table at compile time: a zero a_ij, b_i or (b_i - bhat_i) emits no
/// instruction, and a stage that nothing reads is never evaluated (Dormand-Prince's seventh stage costs
/// nothing unless the error estimate is asked for). The stepper holds no state: the stage derivatives
/// live on the stack of one `step` call, (stages + 2) states at most.
///
/// Check (odestep::checked, the default, or odestep::unchecked): whether the step tests its results for
/// NaN and Inf (and returns `status::non_finite` with y untouched) or writes them as they come. The
/// arithmetic is the same in both.
template <class Method, class State, class Check = checked>
class explicit_rk : public stepper_defaults<State> {
public:
    using state_type = State;                ///< the state, std::array<T, N> or a user type
    using value_type = value_type_t<State>;  ///< T, the scalar type of the state and the table
    using method_type = Method;              ///< the table's type (odestep::tables)
    using check_type = Check;                ///< the check policy: odestep::checked or odestep::unchecked
    /// The same stepper under check policy C (odestep::with_check_t).
    template <class C>
    using with_check = explicit_rk<Method, State, C>;
    /// The step tests its results for NaN and Inf (trait; see odestep::stepper_defaults).
    static constexpr bool checks_finiteness = Check::checks_finiteness;

private:
    using T = value_type;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t S = table_type::stages;
    static constexpr std::size_t E = table_type::embedded;
    static_assert(is_consistent(tab), "odestep: the table's rows do not sum to c, or its weights to 1");
    static_assert(is_explicit(tab),
                  "odestep: explicit_rk needs an explicit table (a strictly lower triangular); an implicit table "
                  "is stepped by odestep::implicit_rk (odestep/rk/implicit_rk.hpp)");

    // Stage i is needed when its weight is non-zero or a needed later stage reads it. With the error
    // estimate, a non-zero embedded weight also counts (b_i - bhat_i != 0 needs k_i).
    static constexpr std::array<bool, S> needed_stages(bool with_error) noexcept {
        std::array<bool, S> needed{};
        for (std::size_t i = S; i-- > 0;) {
            bool used = tab.b[i] != T(0);
            for (std::size_t e = 0; with_error && e < E; ++e) used = used || tab.bhat[e][i] != T(0);
            for (std::size_t j = i + 1; j < S; ++j) used = used || (needed[j] && tab.a[j][i] != T(0));
            needed[i] = used;
        }
        return needed;
    }
    static constexpr std::size_t count(const std::array<bool, S>& flags) noexcept {
        std::size_t n = 0;
        for (bool f : flags) n += f ? 1U : 0U;
        return n;
    }
    static constexpr std::array<bool, S> plain_stages = needed_stages(false);
    static constexpr std::array<bool, S> error_stages = needed_stages(true);

    // The stages a step evaluates whose value reaches none of the results it tests for finiteness: a zero
    // weight b_i (the midpoint rule's b_1, Dormand-Prince's b_2), and for the estimating steps a zero
    // b_i - bhat_i in each estimate the step returns. Such a stage is read only through later stage inputs,
    // where a NaN need not survive (an f that ignores its input: a forcing f(t), a switch, a saturation), so
    // its value is added to the finiteness test itself. A stage with a non-zero weight needs nothing more:
    // w NaN and w Inf are not finite, and neither is a sum with such a term.
    static constexpr std::array<bool, S> unweighted_stages(bool with_error, std::size_t estimates) noexcept {
        const std::array<bool, S> evaluated = needed_stages(with_error);
        std::array<bool, S> unweighted{};
        for (std::size_t i = 0; i < S; ++i) {
            bool reached = tab.b[i] != T(0);
            for (std::size_t e = 0; e < estimates && e < E; ++e) reached = reached || tab.b[i] != tab.bhat[e][i];
            unweighted[i] = evaluated[i] && !reached;
        }
        return unweighted;
    }

public:
    static constexpr int order = tab.order;   ///< the method's order, from the table
    static constexpr std::size_t stages = S;  ///< the table's stages
    /// Right-hand-side evaluations of `step(f, y, t, dt)`, the most it ever makes.
    static constexpr std::size_t rhs_evals_per_step = count(plain_stages);
    /// Right-hand-side evaluations of the step that also returns the error estimate (0 without one).
    static constexpr std::size_t rhs_evals_per_error_step = E > 0 ? count(error_stages) : 0;
    static constexpr bool error_estimate = E > 0;      ///< the table has an embedded method
    static constexpr std::size_t error_estimates = E;  ///< how many embedded methods the table has
    /// The order of the (first) embedded method, 0 without one.
    static constexpr int embedded_order = E > 0 ? tab.embedded_order[0] : 0;

    /// y <- y(t + dt). Checked: on `status::non_finite` y is left as it was. Unchecked: always `ok`.
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt) const {
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        State next;
        run_stages<false>(f, y, t, dt, k, next, std::make_index_sequence<S>{});
        constexpr std::size_t estimates = 0;
        constexpr bool in_place = !checks_finiteness && !next_from_stage<false>;
        State& out = detail::result_target<in_place>(next, y);
        T total = -T(0);  // x + (-0) is x, exactly: the compiler drops that first addition
        ODESTEP_STEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (!next_from_stage<false>) out[n] = y[n] + sum<b_weights>(k, n, dt);
            if constexpr (fused_total) {
                total += next[n];
                add_stage_components<estimates>(total, k, n);
            }
        }
        if constexpr (separate_total) {
            add_all(total, next);
            add_stages<estimates>(total, k);
        }
        if (ODESTEP_UNLIKELY(!detail::finite_sum_under<Check>(total)) &&
            !(detail::each_finite(next) && stages_finite<estimates>(k)))
            return status::non_finite;
        if constexpr (!in_place) detail::assign<detail::copy_form::block_at_size>(y, next);
        return status::ok;
    }

    /// As above, and `error` = y_{n+1} - yhat_{n+1} from the first embedded weights (signed, per
    /// component; for the midpoint table this is the Euler-Richardson estimate h (k2 - k1)).
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error) const {
        static_assert(E >= 1, "odestep: this table has no embedded weights, so no error estimate");
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        State next;
        run_stages<true>(f, y, t, dt, k, next, std::make_index_sequence<S>{});
        constexpr std::size_t estimates = 1;
        constexpr bool in_place = !checks_finiteness && !next_from_stage<true>;
        State& out = detail::result_target<in_place>(next, y);
        State err;
        State& err_out = detail::result_target<!checks_finiteness>(err, error);
        T total = -T(0);
        ODESTEP_STEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (!next_from_stage<true>) out[n] = y[n] + sum<b_weights>(k, n, dt);
            err_out[n] = sum<error_weights<0>>(k, n, dt);
            if constexpr (fused_total) {
                total += next[n] + err[n];
                add_stage_components<estimates>(total, k, n);
            }
        }
        if constexpr (separate_total) {
            add_all(total, next);
            add_all(total, err);
            add_stages<estimates>(total, k);
        }
        if (ODESTEP_UNLIKELY(!detail::finite_sum_under<Check>(total)) &&
            !(detail::each_finite(next) && detail::each_finite(err) && stages_finite<estimates>(k)))
            return status::non_finite;
        if constexpr (!in_place) detail::assign<detail::copy_form::block_at_size>(y, next);
        if constexpr (checks_finiteness) detail::assign<detail::copy_form::block_at_size>(error, err);
        return status::ok;
    }

    /// As above with both estimates of a table with two embedded solutions (DOP853: 5th and 3rd order).
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error, State& error2) const {
        static_assert(E >= 2, "odestep: this table has fewer than two embedded weight vectors");
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        State next;
        run_stages<true>(f, y, t, dt, k, next, std::make_index_sequence<S>{});
        constexpr std::size_t estimates = 2;
        constexpr bool in_place = !checks_finiteness && !next_from_stage<true>;
        State& out = detail::result_target<in_place>(next, y);
        State err;
        State err2;
        State& err_out = detail::result_target<!checks_finiteness>(err, error);
        State& err2_out = detail::result_target<!checks_finiteness>(err2, error2);
        T total = -T(0);
        ODESTEP_STEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (!next_from_stage<true>) out[n] = y[n] + sum<b_weights>(k, n, dt);
            err_out[n] = sum<error_weights<0>>(k, n, dt);
            err2_out[n] = sum<error_weights<1>>(k, n, dt);
            if constexpr (fused_total) {
                total += next[n] + err[n] + err2[n];
                add_stage_components<estimates>(total, k, n);
            }
        }
        if constexpr (separate_total) {
            add_all(total, next);
            add_all(total, err);
            add_all(total, err2);
            add_stages<estimates>(total, k);
        }
        if (ODESTEP_UNLIKELY(!detail::finite_sum_under<Check>(total)) &&
            !(detail::each_finite(next) && detail::each_finite(err) && detail::each_finite(err2) &&
              stages_finite<estimates>(k)))
            return status::non_finite;
        if constexpr (!in_place) detail::assign<detail::copy_form::block_at_size>(y, next);
        if constexpr (checks_finiteness) {
            detail::assign<detail::copy_form::block_at_size>(error, err);
            detail::assign<detail::copy_form::block_at_size>(error2, err2);
        }
        return status::ok;
    }

private:
    static constexpr std::size_t N = state_traits<State>::size;

    // The finiteness test's sum (detail::finite_sum) of the new state, and of the estimates. Optimizing for
    // size, it is accumulated in the loop that computes them (one loop, not two); otherwise after that
    // loop, which leaves it free to be vectorized. Unchecked: no sum.
    static constexpr bool fused_total = checks_finiteness && detail::optimizing_for_size;
    static constexpr bool separate_total = checks_finiteness && !detail::optimizing_for_size;
    ODESTEP_INLINE static void add_all(T& total, const State& v) noexcept {
        ODESTEP_STEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) total += v[n];
    }
    // The unweighted stages' values (unweighted_stages) in the finiteness test of a step that returns
    // Estimates estimates: their components added to the sum, component n (in the fused loop) or all of
    // them, and the exact test of the slow path. Expanded at compile time: for a table whose weights are
    // all non-zero the set is empty and nothing is emitted.
    template <std::size_t Estimates>
    static constexpr std::array<bool, S> unweighted = unweighted_stages(Estimates > 0, Estimates);
    template <std::size_t Estimates>
    ODESTEP_INLINE static void add_stage_components(T& total, const std::array<State, S>& k, std::size_t n) noexcept {
        add_stage_components<Estimates>(total, k, n, std::make_index_sequence<S>{});
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static void add_stage_components(T& total, const std::array<State, S>& k, std::size_t n,
                                                    std::index_sequence<I...>) noexcept {
        ((unweighted<Estimates>[I] ? void(total += k[I][n]) : void()), ...);
    }
    template <std::size_t Estimates>
    ODESTEP_INLINE static void add_stages(T& total, const std::array<State, S>& k) noexcept {
        ODESTEP_STEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) add_stage_components<Estimates>(total, k, n);
    }
    template <std::size_t Estimates>
    ODESTEP_INLINE static bool stages_finite(const std::array<State, S>& k) noexcept {
        return stages_finite<Estimates>(k, std::make_index_sequence<S>{});
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static bool stages_finite(const std::array<State, S>& k, std::index_sequence<I...>) noexcept {
        return ((!unweighted<Estimates>[I] || detail::each_finite(k[I])) && ...);
    }

    // Weight rows as types, so that each weight is a constant expression inside `sum`.
    template <std::size_t I>
    using a_row = typename detail::table_rows<Method, T>::template a_row<I>;
    using b_weights = typename detail::table_rows<Method, T>::b_weights;
    template <std::size_t Which>
    using error_weights = typename detail::table_rows<Method, T>::template error_weights<Which>;
    template <class W>
    static constexpr std::size_t first_nonzero() noexcept {
        for (std::size_t j = 0; j < S; ++j)
            if (W::value(j) != T(0)) return j;
        return S;
    }
    // The stage whose row of a is b, if any (Dormand-Prince's seventh: FSAL). Its input is y_{n+1} itself,
    // the same sum in the same order, so a step that evaluates that stage keeps its input as the new state
    // instead of computing it twice.
    static constexpr std::size_t find_b_row() noexcept {
        for (std::size_t i = 1; i < S; ++i) {
            bool same = true;
            for (std::size_t j = 0; j < S; ++j) same = same && (j < i ? tab.a[i][j] : T(0)) == tab.b[j];
            if (same) return i;
        }
        return S;
    }
    static constexpr std::size_t b_row = find_b_row();
    template <bool WithError>
    static constexpr bool next_from_stage = b_row < S && (WithError ? error_stages[b_row] : plain_stages[b_row]);

    // sum_j (dt w_j) k_j[n] over the non-zero w_j, as (dt g) (sum_j r_j k_j[n]) with w = g r (factor_weights):
    // one product by a loop-invariant dt g, hoisted out of the loop over n, and the ratios as constants, a
    // ratio of 1 costing no product and a ratio of 2 an addition. For RK4's b that is the textbook
    // dt/6 (2 (k2 + k3) + k1 + k4). Per component this is as many operations as the form
    // sum_j (dt w_j) k_j, and per step one product instead of one per weight.
    template <class W>
    static constexpr std::array<T, S> weights_of() noexcept {
        std::array<T, S> w{};
        for (std::size_t j = 0; j < S; ++j) w[j] = W::value(j);
        return w;
    }
    template <class W>
    static constexpr detail::factored_weights<T, S> factors = detail::factor_weights(weights_of<W>());

    template <class W>
    ODESTEP_INLINE static constexpr T sum(const std::array<State, S>& k, std::size_t n, T dt) noexcept {
        static_assert(first_nonzero<W>() < S, "odestep: a weight row that is all zero has no sum");
        return (dt * factors<W>.g) * combination<W>(k, n);
    }
    // sum_j r_j k_j[n]
    template <class W>
    ODESTEP_INLINE static constexpr T combination(const std::array<State, S>& k, std::size_t n) noexcept {
        T acc{};
        add_classes<W>(acc, k, n, std::make_index_sequence<factors<W>.classes>{});
        add_unit_terms<W>(acc, k, n, std::make_index_sequence<S>{});
        return acc;
    }
    // The classes with |r| != 1, in summing order: r_L (k_L +- k_j ...) for each, the first one starting acc.
    template <class W, std::size_t... C>
    ODESTEP_INLINE static constexpr void add_classes([[maybe_unused]] T& acc,
                                                     [[maybe_unused]] const std::array<State, S>& k,
                                                     [[maybe_unused]] std::size_t n,
                                                     std::index_sequence<C...>) noexcept {
        (add_class<W, C>(acc, k, n), ...);
    }
    template <class W, std::size_t C>
    ODESTEP_INLINE static constexpr void add_class(T& acc, const std::array<State, S>& k, std::size_t n) noexcept {
        constexpr std::size_t lead = factors<W>.lead[C];
        constexpr T r = factors<W>.r[lead];
        const T g = class_sum<W, lead>(k, n, std::make_index_sequence<S>{});
        if constexpr (C == 0) {
            if constexpr (r == T(2)) {
                acc = g + g;
            } else {
                acc = r * g;
            }
        } else if constexpr (r == T(2)) {
            acc += g + g;
        } else if constexpr (r == T(-2)) {
            acc -= g + g;
        } else {
            acc += r * g;
        }
    }
    // k_L[n], plus or minus k_j[n] for every later j with r_j = r_L or r_j = -r_L.
    template <class W, std::size_t L, std::size_t... J>
    ODESTEP_INLINE static constexpr T class_sum(const std::array<State, S>& k, std::size_t n,
                                                std::index_sequence<J...>) noexcept {
        T g = k[L][n];
        auto member = [&](auto j) {
            constexpr std::size_t jj = decltype(j)::value;
            constexpr T rl = factors<W>.r[L];
            if constexpr (jj > L && factors<W>.r[jj] == rl) {
                g += k[jj][n];
            } else if constexpr (jj > L && factors<W>.r[jj] == -rl) {
                g -= k[jj][n];
            }
        };
        (member(std::integral_constant<std::size_t, J>{}), ...);
        return g;
    }
    // +-k_j[n] for r_j = +-1, in stage order; the first of them starts acc when no class did (it has r = 1).
    template <class W, std::size_t... J>
    ODESTEP_INLINE static constexpr void add_unit_terms(T& acc, const std::array<State, S>& k, std::size_t n,
                                                        std::index_sequence<J...>) noexcept {
        auto term = [&](auto j) {
            constexpr std::size_t jj = decltype(j)::value;
            constexpr T r = factors<W>.r[jj];
            if constexpr (jj == factors<W>.first_unit && factors<W>.classes == 0) {
                acc = k[jj][n];
            } else if constexpr (r == T(1)) {
                acc += k[jj][n];
            } else if constexpr (r == T(-1)) {
                acc -= k[jj][n];
            }
        };
        (term(std::integral_constant<std::size_t, J>{}), ...);
    }

    template <bool WithError, class System, std::size_t... I>
    static void run_stages(System& f, const State& y, T t, T dt, std::array<State, S>& k, State& next,
                           std::index_sequence<I...>) {
        (stage<I, WithError>(f, y, t, dt, k, next), ...);
    }

    // k_I = f(t + c_I dt, y + dt sum_{j<I} a_Ij k_j), emitted only when the step reads k_I.
    template <std::size_t I, bool WithError, class System>
    static void stage(System& f, const State& y, T t, T dt, std::array<State, S>& k, State& next) {
        constexpr bool needed = WithError ? error_stages[I] : plain_stages[I];
        if constexpr (needed) {
            if constexpr (first_nonzero<a_row<I>>() == S) {
                detail::evaluate(f, t + tab.c[I] * dt, y, k[I]);  // no a_Ij: the stage input is y itself
            } else {
                State input;
                State& in = I == b_row ? next : input;  // the b row's input is y_{n+1}: kept as the new state
                ODESTEP_STEP_UNROLL
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + sum<a_row<I>>(k, n, dt);
                detail::evaluate(f, t + tab.c[I] * dt, static_cast<const State&>(in), k[I]);
            }
        }
    }
};

// The named steppers. A pair steps as a method of its higher order; its error-estimating `step` overload
// returns the difference to the embedded solution.
template <class State>
using euler = explicit_rk<tables::euler, State>;
template <class State>
using midpoint = explicit_rk<tables::midpoint, State>;
template <class State>
using euler_richardson = explicit_rk<tables::midpoint, State>;
template <class State>
using heun = explicit_rk<tables::heun, State>;
template <class State>
using ralston2 = explicit_rk<tables::ralston2, State>;
template <class State>
using kutta3 = explicit_rk<tables::kutta3, State>;
template <class State>
using ssprk3 = explicit_rk<tables::ssprk3, State>;
template <class State>
using rk4 = explicit_rk<tables::rk4, State>;
template <class State>
using rk38 = explicit_rk<tables::rk38, State>;
template <class State>
using bogacki_shampine32 = explicit_rk<tables::bogacki_shampine32, State>;
template <class State>
using fehlberg45 = explicit_rk<tables::fehlberg45, State>;
template <class State>
using cash_karp54 = explicit_rk<tables::cash_karp54, State>;
template <class State>
using dormand_prince54 = explicit_rk<tables::dormand_prince54, State>;
template <class State>
using fehlberg78 = explicit_rk<tables::fehlberg78, State>;
template <class State>
using dop853 = explicit_rk<tables::dop853, State>;

}  // namespace odestep

#endif
