// SPDX-License-Identifier: BSL-1.0
// odestep: the one stage loop of the explicit Runge-Kutta methods (explicit_rk's step and the adaptive
// engine's embedded pair), and the two forms in which they sum a weight row against the stages.
#ifndef ODESTEP_DETAIL_STAGE_LOOP_HPP
#define ODESTEP_DETAIL_STAGE_LOOP_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../state.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "ops.hpp"

namespace odestep::detail {

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

/// The index of the first non-zero weight of the row W (table_rows), S if there is none.
template <class W, class T, std::size_t S>
constexpr std::size_t first_nonzero() noexcept {
    for (std::size_t j = 0; j < S; ++j)
        if (W::value(j) != T(0)) return j;
    return S;
}

/// h sum_j w_j k_j[n] as explicit_rk writes it: (h g) (sum_j r_j k_j[n]) with w = g r (factor_weights), one
/// product by a loop-invariant h g, hoisted out of the loop over n, and the ratios as constants, a ratio of
/// 1 costing no product and a ratio of 2 an addition. For RK4's b that is the textbook
/// dt/6 (2 (k2 + k3) + k1 + k4). Per component this is as many operations as sum_j (h w_j) k_j, and per step
/// one product instead of one per weight. W is a weight row of table_rows.
template <class T, class State, std::size_t S>
struct factored_sum {
    template <class W>
    ODESTEP_INLINE static constexpr T sum(const std::array<State, S>& k, std::size_t n, T h) noexcept {
        static_assert(first_nonzero<W, T, S>() < S, "odestep: a weight row that is all zero has no sum");
        return (h * factors<W>.g) * combination<W>(k, n);
    }

private:
    template <class W>
    static constexpr std::array<T, S> weights_of() noexcept {
        std::array<T, S> w{};
        for (std::size_t j = 0; j < S; ++j) w[j] = W::value(j);
        return w;
    }
    template <class W>
    static constexpr factored_weights<T, S> factors = factor_weights(weights_of<W>());

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
};

/// h sum_j w_j k_j[n] as the adaptive engine writes it: the terms w_j k_j[n] over the non-zero w_j added from
/// 0 in stage order, as the plain loops of the published codes do (its step counts are compared with them),
/// then one product by h. W is a weight row of table_rows.
template <class T, class State, std::size_t S>
struct ordered_sum {
    template <class W>
    ODESTEP_INLINE static constexpr T sum(const std::array<State, S>& k, std::size_t n, T h) noexcept {
        return h * weighted<W>(k, n, std::make_index_sequence<S>{});
    }

private:
    template <class W, std::size_t... J>
    ODESTEP_INLINE static constexpr T weighted(const std::array<State, S>& k, std::size_t n,
                                               std::index_sequence<J...>) noexcept {
        T acc = T(0);
        (add_term<W, J>(acc, k, n), ...);
        return acc;
    }
    template <class W, std::size_t J>
    ODESTEP_INLINE static constexpr void add_term(T& acc, const std::array<State, S>& k, std::size_t n) noexcept {
        if constexpr (W::value(J) != T(0)) acc += W::value(J) * k[J][n];
    }
};

/// The stages of one explicit Runge-Kutta step of the table `Method::table<T>`,
/// k_i = f(t + c_i h, y + h sum_{j<i} a_ij k_j), unrolled over the table at compile time, each input sum in
/// the form `Sum` (factored_sum or ordered_sum). Used by explicit_rk and by the adaptive engine's
/// embedded_pair, which differ only in which stages they evaluate, the sum form and whether they stop at a
/// stage that is not finite.
template <class Method, class State, template <class, class, std::size_t> class Sum>
struct explicit_stages {
    using T = value_type_t<State>;
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = std::remove_const_t<decltype(tab)>::stages;
    static constexpr std::size_t N = state_traits<State>::size;
    using sum_form = Sum<T, State, S>;
    static_assert(is_explicit(tab), "odestep: the stage loop takes an explicit table");

    /// The stage whose input is y_{n+1} (b_row), S if none: its input is kept in `next`.
    static constexpr std::size_t b_row = detail::b_row(tab);

    /// Evaluates the stages i with Evaluate_i true, in order (the others are given or not needed). With
    /// StopAtNonFinite, returns false at the first evaluated stage that is not finite and calls f no more (a
    /// user's f may trap on NaN or index a table by y); otherwise returns true. The stage with c = 1 is
    /// evaluated at t_end (t + h as the caller has it), the others at t + c_i h. If the b row is evaluated,
    /// `next` is y_{n+1}.
    /// Always inlined: the checked and the unchecked step of one table, State and f share this one
    /// instantiation, and GCC at -O2 does not inline a function this large that has two callers, so a
    /// program using both policies would otherwise pay a call and the stages' spills in each step.
    template <bool StopAtNonFinite, class System, bool... Evaluate>
    ODESTEP_INLINE static bool run(System& f, const State& y, T t, T h, T t_end, std::array<State, S>& k, State& next,
                                   std::integer_sequence<bool, Evaluate...> evaluate) {
        return run<StopAtNonFinite>(f, y, t, h, t_end, k, next, evaluate, std::make_index_sequence<S>{});
    }

private:
    template <std::size_t I>
    using a_row = typename table_rows<Method, T>::template a_row<I>;

    template <bool StopAtNonFinite, class System, bool... Evaluate, std::size_t... I>
    ODESTEP_INLINE static bool run(System& f, const State& y, T t, T h, T t_end, std::array<State, S>& k, State& next,
                                   std::integer_sequence<bool, Evaluate...>, std::index_sequence<I...>) {
        return (stage<I, Evaluate, StopAtNonFinite>(f, y, t, h, t_end, k, next) && ...);
    }

    // k_I = f(t + c_I h, y + h sum_{j<I} a_Ij k_j), emitted only when Evaluate.
    template <std::size_t I, bool Evaluate, bool StopAtNonFinite, class System>
    ODESTEP_INLINE static bool stage(System& f, const State& y, T t, T h, T t_end, std::array<State, S>& k,
                                     State& next) {
        if constexpr (!Evaluate) {
            return true;
        } else {
            const T ti = time<I>(t, h, t_end);
            if constexpr (first_nonzero<a_row<I>, T, S>() == S) {
                evaluate(f, ti, y, k[I]);  // no a_Ij: the stage input is y itself
            } else {
                State input;
                State& in = I == b_row ? next : input;  // the b row's input is y_{n+1}: kept as the new state
                ODESTEP_STEP_UNROLL_ALWAYS
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + sum_form::template sum<a_row<I>>(k, n, h);
                evaluate(f, ti, static_cast<const State&>(in), k[I]);
            }
            if constexpr (StopAtNonFinite) {
                return all_finite(k[I]);
            } else {
                return true;
            }
        }
    }
    template <std::size_t I>
    ODESTEP_INLINE static T time([[maybe_unused]] T t, [[maybe_unused]] T h, [[maybe_unused]] T t_end) noexcept {
        if constexpr (tab.c[I] == T(1)) {
            return t_end;
        } else {
            return t + tab.c[I] * h;
        }
    }
};

}  // namespace odestep::detail

#endif
