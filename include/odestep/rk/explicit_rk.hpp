// SPDX-License-Identifier: BSL-1.0
// odestep: the one explicit Runge-Kutta stepper, driven by any Butcher table.
#ifndef ODESTEP_RK_EXPLICIT_RK_HPP
#define ODESTEP_RK_EXPLICIT_RK_HPP

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../detail/stage_loop.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "../tables/runge_kutta.hpp"

namespace odestep {

namespace detail {

/// Which stages a step of Method's table in T evaluates, and which of them it must test for finiteness itself:
/// explicit_rk's choice, which the C API's step over n (src/capi_rk.hpp) makes the same way.
template <class Method, class T>
struct stage_choice {
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = std::remove_const_t<decltype(tab)>::stages;
    static constexpr std::size_t E = std::remove_const_t<decltype(tab)>::embedded;

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
    static constexpr std::size_t count(const std::array<bool, S>& flags) noexcept {
        std::size_t n = 0;
        for (bool f : flags) n += f ? 1U : 0U;
        return n;
    }
};

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

    using choice = detail::stage_choice<Method, T>;
    static constexpr std::array<bool, S> plain_stages = choice::needed_stages(false);
    static constexpr std::array<bool, S> error_stages = choice::needed_stages(true);

public:
    static constexpr int order = tab.order;   ///< the method's order, from the table
    static constexpr std::size_t stages = S;  ///< the table's stages
    /// Right-hand-side evaluations of `step(f, y, t, dt)`, the most it ever makes.
    static constexpr std::size_t rhs_evals_per_step = choice::count(plain_stages);
    /// Every step evaluates all its stages (the finiteness test comes after them): the loops count a run's
    /// evaluations as steps x rhs_evals_per_step.
    static constexpr bool exact_rhs_evals = true;
    /// Right-hand-side evaluations of the step that also returns the error estimate (0 without one).
    static constexpr std::size_t rhs_evals_per_error_step = E > 0 ? choice::count(error_stages) : 0;
    static constexpr bool error_estimate = E > 0;      ///< the table has an embedded method
    static constexpr std::size_t error_estimates = E;  ///< how many embedded methods the table has
    /// The order of the (first) embedded method, 0 without one.
    static constexpr int embedded_order = E > 0 ? tab.embedded_order[0] : 0;

    /// y <- y(t + dt). Checked: on `status::non_finite` y is left as it was. Unchecked: always `ok`.
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt) const {
        return step_estimating(f, y, t, dt, std::make_index_sequence<0>{});
    }

    /// As above, and `error` = y_{n+1} - yhat_{n+1} from the first embedded weights (signed, per
    /// component; for the midpoint table this is the Euler-Richardson estimate h (k2 - k1)).
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error) const {
        static_assert(E >= 1, "odestep: this table has no embedded weights, so no error estimate");
        return step_estimating(f, y, t, dt, std::make_index_sequence<1>{}, error);
    }

    /// As above with both estimates of a table with two embedded solutions (DOP853: 5th and 3rd order).
    template <class System>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(System&& f, State& y, T t, T dt, State& error, State& error2) const {
        static_assert(E >= 2, "odestep: this table has fewer than two embedded weight vectors");
        return step_estimating(f, y, t, dt, std::make_index_sequence<2>{}, error, error2);
    }

private:
    static constexpr std::size_t N = state_traits<State>::size;

    // The finiteness test's sum (detail::finite_sum) of the new state, and of the estimates. Optimizing for
    // size, it is accumulated in the loop that computes them (one loop, not two); otherwise after that
    // loop, which leaves it free to be vectorized. Unchecked: no sum.
    static constexpr bool fused_total = checks_finiteness && detail::optimizing_for_size;
    static constexpr bool separate_total = checks_finiteness && !detail::optimizing_for_size;
    // The sum of a whole state: in lanes where that vectorizes (detail::add_in_lanes).
    ODESTEP_INLINE static void add_all(T& total, const State& v) noexcept { detail::add_in_lanes(total, v); }
    // The unweighted stages' values (unweighted_stages) in the finiteness test of a step that returns
    // Estimates estimates: their components added to the sum, component n (in the fused loop) or all of
    // them, and the exact test of the slow path. Expanded at compile time: for a table whose weights are
    // all non-zero the set is empty and nothing is emitted.
    template <std::size_t Estimates>
    static constexpr std::array<bool, S> unweighted = choice::unweighted_stages(Estimates > 0, Estimates);
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
        add_stages<Estimates>(total, k, std::make_index_sequence<S>{});
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static void add_stages(T& total, const std::array<State, S>& k, std::index_sequence<I...>) noexcept {
        ((unweighted<Estimates>[I] ? add_all(total, k[I]) : void()), ...);
    }
    template <std::size_t Estimates>
    ODESTEP_INLINE static bool stages_finite(const std::array<State, S>& k) noexcept {
        return stages_finite<Estimates>(k, std::make_index_sequence<S>{});
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static bool stages_finite(const std::array<State, S>& k, std::index_sequence<I...>) noexcept {
        return ((!unweighted<Estimates>[I] || detail::each_finite(k[I])) && ...);
    }

    // The one step body, returning the estimates of the embedded weights Which... (none, the first, or both)
    // in `error...`. Checked, the results go to locals and are copied out only when all are finite.
    // Flattened itself, not merely always-inlined: GCC at -Os does not flatten the calls an always-inlined
    // callee brings into the flattened `step`, and f would stay out of line.
    template <class System, std::size_t... Which, class... Errors>
    ODESTEP_STEP_FLATTEN status step_estimating(System& f, State& y, T t, T dt, std::index_sequence<Which...>,
                                                Errors&... error) const {
        constexpr std::size_t estimates = sizeof...(Which);
        constexpr bool with_error = estimates > 0;
        static_assert(estimates <= 2, "odestep: explicit_rk returns at most two estimates");
        std::array<State, S> k;  // not zeroed: every stage the step reads is written first
        State next;
        stage_loop::template run<false>(f, y, t, dt, t + dt, k, next,
                                        evaluated<with_error>(std::make_index_sequence<S>{}));
        constexpr bool in_place = !checks_finiteness && !next_from_stage<with_error>;
        State& out = detail::result_target<in_place>(next, y);
        // The estimates' locals, two objects rather than an array of two: GCC's vectorizer then pairs the
        // components as it does in the hand loop (as an array, float DOP853 took 4% more instructions at -O2).
        [[maybe_unused]] State err0;
        [[maybe_unused]] State err1;
        [[maybe_unused]] const auto err_out =
            std::tie(detail::result_target<!checks_finiteness>(local_estimate<Which>(err0, err1), error)...);
        T total = -T(0);  // x + (-0) is x, exactly: the compiler drops that first addition
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (!next_from_stage<with_error>) out[n] = y[n] + sum<b_weights>(k, n, dt);
            ((std::get<Which>(err_out)[n] = sum<error_weights<Which>>(k, n, dt)), ...);
            if constexpr (fused_total) {
                total += (next[n] + ... + local_estimate<Which>(err0, err1)[n]);
                add_stage_components<estimates>(total, k, n);
            }
        }
        if constexpr (separate_total) {
            add_all(total, next);
            (add_all(total, local_estimate<Which>(err0, err1)), ...);
            add_stages<estimates>(total, k);
        }
        if (ODESTEP_UNLIKELY(!detail::finite_sum_under<Check>(total)) &&
            !(detail::each_finite(next) && (detail::each_finite(local_estimate<Which>(err0, err1)) && ...) &&
              stages_finite<estimates>(k)))
            return status::non_finite;
        if constexpr (!in_place) detail::assign<detail::copy_form::block_at_size>(y, next);
        if constexpr (checks_finiteness)
            (detail::assign<detail::copy_form::block_at_size>(error, local_estimate<Which>(err0, err1)), ...);
        return status::ok;
    }

    // The local of estimate W (step_estimating): the first or the second.
    template <std::size_t W>
    ODESTEP_INLINE static State& local_estimate(State& first, State& second) noexcept {
        if constexpr (W == 0) {
            return first;
        } else {
            return second;
        }
    }

    // Weight rows as types, so that each weight is a constant expression inside `sum`.
    using b_weights = typename detail::table_rows<Method, T>::b_weights;
    template <std::size_t Which>
    using error_weights = typename detail::table_rows<Method, T>::template error_weights<Which>;
    // h sum_j w_j k_j[n] in the factored form (detail::factored_sum).
    template <class W>
    ODESTEP_INLINE static constexpr T sum(const std::array<State, S>& k, std::size_t n, T dt) noexcept {
        return detail::factored_sum<T, State, S>::template sum<W>(k, n, dt);
    }

    // The stage loop (detail::explicit_stages), evaluating the stages the step reads.
    using stage_loop = detail::explicit_stages<Method, State, detail::factored_sum>;
    template <bool WithError, std::size_t... I>
    static constexpr auto evaluated(std::index_sequence<I...>) noexcept {
        return std::integer_sequence<bool, (WithError ? error_stages[I] : plain_stages[I])...>{};
    }
    // The stage whose input is y_{n+1} (detail::b_row: Dormand-Prince's seventh, FSAL): a step that evaluates
    // it keeps that input as the new state instead of computing it twice.
    static constexpr std::size_t b_row = stage_loop::b_row;
    template <bool WithError>
    static constexpr bool next_from_stage = b_row < S && (WithError ? error_stages[b_row] : plain_stages[b_row]);
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
