// odestep: the one explicit Runge-Kutta stepper, driven by any Butcher table.
#ifndef ODESTEP_EXPLICIT_RK_HPP
#define ODESTEP_EXPLICIT_RK_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "state.hpp"
#include "status.hpp"
#include "system.hpp"
#include "tableau.hpp"
#include "tableaux.hpp"

namespace odestep {

/// An explicit Runge-Kutta step for y' = f(t, y) from the table `Method::table<T>`.
///
/// The stage loop is unrolled over the table at compile time: a zero a_ij, b_i or (b_i - bhat_i) emits no
/// instruction, and a stage that nothing reads is never evaluated (Dormand-Prince's seventh stage costs
/// nothing unless the error estimate is asked for). The stepper holds no state: the stage derivatives
/// live on the stack of one `step` call, (stages + 2) states at most.
template <class Method, class State>
class explicit_rk {
public:
    using state_type = State;
    using value_type = value_type_t<State>;
    using method_type = Method;

private:
    using T = value_type;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t S = table_type::stages;
    static constexpr std::size_t E = table_type::embedded;
    static_assert(is_consistent(tab), "odestep: the table's rows do not sum to c, or its weights to 1");

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

public:
    static constexpr int order = tab.order;
    static constexpr std::size_t stages = S;
    /// Right-hand-side evaluations of `step(f, y, t, dt)`, the most it ever makes.
    static constexpr std::size_t rhs_evals_per_step = count(plain_stages);
    /// Right-hand-side evaluations of the step that also returns the error estimate.
    static constexpr std::size_t rhs_evals_per_error_step = count(error_stages);
    static constexpr bool error_estimate = E > 0;
    static constexpr std::size_t error_estimates = E;
    static constexpr int embedded_order = E > 0 ? tab.embedded_order[0] : 0;
    static constexpr bool symplectic = false;
    static constexpr bool self_starting = true;

    /// y <- y(t + dt). On `status::non_finite` y is left as it was.
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt) const {
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        run_stages<false>(f, y, t, dt, k, std::make_index_sequence<S>{});
        State next;
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) next[n] = y[n] + sum<b_weights>(k, n, dt);
        if (!detail::all_finite(next)) return status::non_finite;
        y = next;
        return status::ok;
    }

    /// As above, and `error` = y_{n+1} - yhat_{n+1} from the first embedded weights (signed, per
    /// component; for the midpoint table this is the Euler-Richardson estimate h (k2 - k1)).
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error) const {
        static_assert(E >= 1, "odestep: this table has no embedded weights, so no error estimate");
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        run_stages<true>(f, y, t, dt, k, std::make_index_sequence<S>{});
        State next;
        State err;
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) {
            next[n] = y[n] + sum<b_weights>(k, n, dt);
            err[n] = sum<error_weights<0>>(k, n, dt);
        }
        if (!detail::all_finite(next) || !detail::all_finite(err)) return status::non_finite;
        y = next;
        error = err;
        return status::ok;
    }

    /// As above with both estimates of a table with two embedded solutions (DOP853: 5th and 3rd order).
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error, State& error2) const {
        static_assert(E >= 2, "odestep: this table has fewer than two embedded weight vectors");
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        run_stages<true>(f, y, t, dt, k, std::make_index_sequence<S>{});
        State next;
        State err;
        State err2;
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) {
            next[n] = y[n] + sum<b_weights>(k, n, dt);
            err[n] = sum<error_weights<0>>(k, n, dt);
            err2[n] = sum<error_weights<1>>(k, n, dt);
        }
        if (!detail::all_finite(next) || !detail::all_finite(err) || !detail::all_finite(err2))
            return status::non_finite;
        y = next;
        error = err;
        error2 = err2;
        return status::ok;
    }

private:
    static constexpr std::size_t N = state_traits<State>::size;

    // Weight rows as types, so that each weight is a constant expression inside `sum`.
    template <std::size_t I>
    struct a_row {
        static constexpr T value(std::size_t j) noexcept { return j < I ? tab.a[I][j] : T(0); }
    };
    struct b_weights {
        static constexpr T value(std::size_t j) noexcept { return tab.b[j]; }
    };
    template <std::size_t Which>
    struct error_weights {
        static constexpr T value(std::size_t j) noexcept { return tab.b[j] - tab.bhat[Which][j]; }
    };
    template <class W>
    static constexpr std::size_t first_nonzero() noexcept {
        for (std::size_t j = 0; j < S; ++j)
            if (W::value(j) != T(0)) return j;
        return S;
    }

    // sum_j (dt w_j) k_j[n] over the non-zero w_j only, in stage order: the sum a careful hand-written
    // loop computes, with dt w_j a loop-invariant product the compiler hoists out of the loop over n.
    template <class W>
    static constexpr T sum(const std::array<State, S>& k, std::size_t n, T dt) noexcept {
        constexpr std::size_t first = first_nonzero<W>();
        static_assert(first < S, "odestep: a weight row that is all zero has no sum");
        T acc = (dt * W::value(first)) * k[first][n];
        add_terms<W, first>(acc, k, n, dt, std::make_index_sequence<S>{});
        return acc;
    }
    template <class W, std::size_t First, std::size_t... J>
    static constexpr void add_terms(T& acc, const std::array<State, S>& k, std::size_t n, T dt,
                                    std::index_sequence<J...>) noexcept {
        auto term = [&](auto j) {
            constexpr std::size_t jj = decltype(j)::value;
            if constexpr (jj > First && W::value(jj) != T(0)) acc += (dt * W::value(jj)) * k[jj][n];
        };
        (term(std::integral_constant<std::size_t, J>{}), ...);
    }

    template <bool WithError, class System, std::size_t... I>
    static void run_stages(System& f, const State& y, T t, T dt, std::array<State, S>& k,
                                     std::index_sequence<I...>) {
        (stage<I, WithError>(f, y, t, dt, k), ...);
    }

    // k_I = f(t + c_I dt, y + dt sum_{j<I} a_Ij k_j), emitted only when the step reads k_I.
    template <std::size_t I, bool WithError, class System>
    static void stage(System& f, const State& y, T t, T dt, std::array<State, S>& k) {
        constexpr bool needed = WithError ? error_stages[I] : plain_stages[I];
        if constexpr (needed) {
            if constexpr (first_nonzero<a_row<I>>() == S) {
                detail::evaluate(f, t + tab.c[I] * dt, y, k[I]);  // no a_Ij: the stage input is y itself
            } else {
                State input;
                ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) input[n] = y[n] + sum<a_row<I>>(k, n, dt);
                detail::evaluate(f, t + tab.c[I] * dt, input, k[I]);
            }
        }
    }
};

// The named steppers. A pair steps as a method of its higher order; its error-estimating `step` overload
// returns the difference to the embedded solution.
template <class State> using euler = explicit_rk<tableaux::euler, State>;
template <class State> using midpoint = explicit_rk<tableaux::midpoint, State>;
template <class State> using euler_richardson = explicit_rk<tableaux::midpoint, State>;
template <class State> using heun = explicit_rk<tableaux::heun, State>;
template <class State> using ralston2 = explicit_rk<tableaux::ralston2, State>;
template <class State> using kutta3 = explicit_rk<tableaux::kutta3, State>;
template <class State> using ssprk3 = explicit_rk<tableaux::ssprk3, State>;
template <class State> using rk4 = explicit_rk<tableaux::rk4, State>;
template <class State> using rk38 = explicit_rk<tableaux::rk38, State>;
template <class State> using bogacki_shampine32 = explicit_rk<tableaux::bogacki_shampine32, State>;
template <class State> using fehlberg45 = explicit_rk<tableaux::fehlberg45, State>;
template <class State> using cash_karp54 = explicit_rk<tableaux::cash_karp54, State>;
template <class State> using dormand_prince54 = explicit_rk<tableaux::dormand_prince54, State>;
template <class State> using fehlberg78 = explicit_rk<tableaux::fehlberg78, State>;
template <class State> using dop853 = explicit_rk<tableaux::dop853, State>;

}  // namespace odestep

#endif
