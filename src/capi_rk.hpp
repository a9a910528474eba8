// SPDX-License-Identifier: BSL-1.0
// odestep C API: the single step of the explicit Runge-Kutta methods over the caller's n, known at run time.
//
// odestep::explicit_rk runs its loops over a state size known at compile time; the C API's n is known at run
// time. Compiling the stepper for every n (ODESTEP_C_EXACT_STATES) costs a copy of the step per size, and
// the padded state computes ODESTEP_C_MAX_STATES components and copies the caller's n in and out. This body
// is explicit_rk's step written over n: the same table (Method::table<T>), the same stages evaluated
// (a stage nothing reads is skipped), the same sums (detail::factored_sum, per component, so each of the n
// components is bit for bit explicit_rk's) and the same finiteness test (one sum of the results and of the
// stages no weight reaches, the exact test only when that sum is not finite). It reads the caller's y in
// place (the first stage's input is y itself, as in explicit_rk), hands the user's f the stage arrays,
// whose components past n f never writes and nothing reads, and writes y (and the estimates) only when the
// step is good. A test compares it with explicit_rk on std::array<T, n> (tests/c/agreement_test.cpp).
#ifndef ODESTEP_SRC_CAPI_RK_HPP
#define ODESTEP_SRC_CAPI_RK_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "odestep/config.hpp"
#include "odestep/detail/ops.hpp"
#include "odestep/detail/stage_loop.hpp"
#include "odestep/rk/explicit_rk.hpp"
#include "odestep/status.hpp"
#include "odestep/tables/butcher.hpp"

// A lambda always inlined (GCC and Clang; at -Os GCC otherwise keeps a lambda called from the unrolled
// sequence out of line).
#if defined(__GNUC__)
#define ODESTEP_CAPI_INLINE_LAMBDA __attribute__((always_inline))
#else
#define ODESTEP_CAPI_INLINE_LAMBDA
#endif

namespace odestep::capi {

/// The table of an explicit_rk stepper type (void for any other stepper).
template <class S>
struct rk_table_of {
    using type = void;
};
template <class Method, class State, class Check>
struct rk_table_of<explicit_rk<Method, State, Check>> {
    using type = Method;
};

/// body(i) for i = 0 .. n-1, 1 <= n <= Max (body(I) of a compile-time I, for Max up to 16): a jump into an
/// unrolled sequence (a switch of fall-through cases, component n-1 first), one dispatch where a loop would
/// pay an increment, a compare and a branch per component; the components are independent, so their order
/// changes no result. Above 16, a loop.
template <std::size_t I, std::size_t Max, class Body>
ODESTEP_INLINE void at(Body& body) {
    if constexpr (I < Max) body(std::integral_constant<std::size_t, I>{});
}
template <std::size_t Max, bool Rolled = false, class Body>
ODESTEP_INLINE void over_first(std::size_t n, Body&& body) {
    if constexpr (Max > 16 || Rolled) {
        for (std::size_t i = 0; i < n; ++i) body(i);
    } else {
        // (n - 1) & mask is n - 1 (n - 1 < Max <= mask + 1), and every value of it has a case (those at or
        // above Max do the first Max): the jump needs no range test.
        constexpr std::size_t mask = Max <= 2 ? 1 : Max <= 4 ? 3 : Max <= 8 ? 7 : 15;
        switch ((n - 1) & mask) {
            case 15: at<15, Max>(body); [[fallthrough]];
            case 14: at<14, Max>(body); [[fallthrough]];
            case 13: at<13, Max>(body); [[fallthrough]];
            case 12: at<12, Max>(body); [[fallthrough]];
            case 11: at<11, Max>(body); [[fallthrough]];
            case 10: at<10, Max>(body); [[fallthrough]];
            case 9: at<9, Max>(body); [[fallthrough]];
            case 8: at<8, Max>(body); [[fallthrough]];
            case 7: at<7, Max>(body); [[fallthrough]];
            case 6: at<6, Max>(body); [[fallthrough]];
            case 5: at<5, Max>(body); [[fallthrough]];
            case 4: at<4, Max>(body); [[fallthrough]];
            case 3: at<3, Max>(body); [[fallthrough]];
            case 2: at<2, Max>(body); [[fallthrough]];
            case 1: at<1, Max>(body); [[fallthrough]];
            case 0: at<0, Max>(body); break;
        }
    }
}

/// One step of the explicit Runge-Kutta table Method over n components (1 <= n <= Max), see the file's comment.
/// Fn is the C right-hand side void (*)(T t, const T* y, T* dydt, void* ctx); the size n a std::size_t, or a
/// std::integral_constant for the steps compiled for one n (ODESTEP_C_EXACT_STATES), whose jumps then fold.
template <class Method, class T, std::size_t Max>
struct any_n_rk {
    using row = std::array<T, Max>;  // one stage's derivative or input; components n .. Max-1 unused
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = std::remove_const_t<decltype(tab)>::stages;
    static constexpr std::size_t E = std::remove_const_t<decltype(tab)>::embedded;
    using rows = detail::table_rows<Method, T>;
    using sum_form = detail::factored_sum<T, row, S>;
    static constexpr std::size_t b_row = detail::b_row(tab);

    using choice = detail::stage_choice<Method, T>;  // explicit_rk's choice of stages, for the same table
    static_assert(choice::count(choice::needed_stages(false)) == explicit_rk<Method, row>::rhs_evals_per_step,
                  "the C API's step evaluates the stages explicit_rk evaluates");

    template <std::size_t Estimates>
    static constexpr std::array<bool, S> evaluated = choice::needed_stages(Estimates > 0);
    template <std::size_t Estimates>
    static constexpr std::array<bool, S> unweighted = choice::unweighted_stages(Estimates > 0, Estimates);
    template <std::size_t Estimates>
    static constexpr bool next_from_stage = b_row < S&& evaluated<Estimates>[b_row];
    // Optimizing for size, the estimating steps loop over n instead of jumping into a sequence unrolled
    // over Max: the sequences of DOP853's estimating steps took 11 KB of flash more (Cortex-M4F -Os).
    template <std::size_t Estimates>
    static constexpr bool rolled = Estimates > 0 && detail::optimizing_for_size;

    /// y[0 .. n-1] <- y(t + dt), and with Estimates 1 or 2, e1 (and e2) the estimates of the first (two)
    /// embedded weights; on non_finite nothing is written.
    template <std::size_t Estimates, class Fn, class Size>
    ODESTEP_INLINE static status step(Fn fn, void* ctx, Size n, T* y, T t, T dt, [[maybe_unused]] T* e1,
                                      [[maybe_unused]] T* e2) {
        std::array<row, S> k;  // not zeroed: f writes the first n components of each stage it evaluates
        row next;
        stages<Estimates>(fn, ctx, n, y, t, dt, t + dt, k, next, std::make_index_sequence<S>{});
        // y_{n+1} is written over y at once, y_n kept in `saved` (a store, where a copy of the results into y
        // after the test would take a load and a store, and a second pass) and put back if the step fails.
        row saved;
        [[maybe_unused]] row err0;
        [[maybe_unused]] row err1;
        T total = -T(0);  // x + (-0) is x, exactly
        over_first<Max, rolled<Estimates>>(n, [&](auto i) ODESTEP_CAPI_INLINE_LAMBDA {
            const T yi = y[i];
            saved[i] = yi;
            T result;
            if constexpr (next_from_stage<Estimates>) {
                result = next[i];
            } else {
                result = yi + sum_form::template sum<b_weights>(k, i, dt);
            }
            y[i] = result;
            total += result;
            if constexpr (Estimates >= 1) {
                err0[i] = sum_form::template sum<error_weights<0>>(k, i, dt);
                total += err0[i];
            }
            if constexpr (Estimates >= 2) {
                err1[i] = sum_form::template sum<error_weights<1>>(k, i, dt);
                total += err1[i];
            }
            add_unweighted<Estimates>(total, k, i, std::make_index_sequence<S>{});
        });
        if (ODESTEP_UNLIKELY(!detail::finite_sum(total)) && !all_each_finite<Estimates>(n, y, err0, err1, k)) {
            // saved[0 .. n-1] was written by the jump of the same n above, which GCC does not see.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
            over_first<Max, rolled<Estimates>>(n, [&](auto i) ODESTEP_CAPI_INLINE_LAMBDA { y[i] = saved[i]; });
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
            return status::non_finite;
        }
        if constexpr (Estimates >= 1) {
            over_first<Max, rolled<Estimates>>(n, [&](auto i) ODESTEP_CAPI_INLINE_LAMBDA {
                e1[i] = err0[i];
                if constexpr (Estimates >= 2) e2[i] = err1[i];
            });
        }
        return status::ok;
    }

private:
    using b_weights = typename rows::b_weights;
    template <std::size_t W>
    using error_weights = typename rows::template error_weights<W>;
    template <std::size_t I>
    using a_row = typename rows::template a_row<I>;

    template <std::size_t Estimates, class Fn, class Size, std::size_t... I>
    ODESTEP_INLINE static void stages(Fn fn, void* ctx, Size n, const T* y, T t, T h, T t_end, std::array<row, S>& k,
                                      row& next, std::index_sequence<I...>) {
        (stage<I, Estimates>(fn, ctx, n, y, t, h, t_end, k, next), ...);
    }
    // k_I = f(t + c_I h, y + h sum_{j<I} a_Ij k_j) (detail::explicit_stages, over n).
    template <std::size_t I, std::size_t Estimates, class Fn, class Size>
    ODESTEP_INLINE static void stage(Fn fn, void* ctx, Size n, const T* y, [[maybe_unused]] T t, T h,
                                     [[maybe_unused]] T t_end, std::array<row, S>& k, row& next) {
        if constexpr (evaluated<Estimates>[I]) {
            T ti;
            if constexpr (tab.c[I] == T(1)) {
                ti = t_end;
            } else {
                ti = t + tab.c[I] * h;
            }
            if constexpr (detail::first_nonzero<a_row<I>, T, S>() == S) {
                fn(ti, y, k[I].data(), ctx);  // no a_Ij: the stage input is y itself
            } else {
                row input;
                row& in = I == b_row ? next : input;  // the b row's input is y_{n+1}: kept as the new state
                over_first<Max, rolled<Estimates>>(n, [&](auto i) ODESTEP_CAPI_INLINE_LAMBDA {
                    in[i] = y[i] + sum_form::template sum<a_row<I>>(k, i, h);
                });
                fn(ti, in.data(), k[I].data(), ctx);
            }
        }
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static void add_unweighted(T& total, const std::array<row, S>& k, std::size_t i,
                                              std::index_sequence<I...>) noexcept {
        ((unweighted<Estimates>[I] ? void(total += k[I][i]) : void()), ...);
    }
    // The exact test after a sum that is not finite (a component that is not, or an overflow).
    template <std::size_t Estimates, class Size>
    ODESTEP_INLINE static bool all_each_finite(Size n, const T* next, const row& err0, const row& err1,
                                               const std::array<row, S>& k) noexcept {
        for (std::size_t i = 0; i < n; ++i) {
            bool finite = detail::is_finite(next[i]);
            if constexpr (Estimates >= 1) finite = finite && detail::is_finite(err0[i]);
            if constexpr (Estimates >= 2) finite = finite && detail::is_finite(err1[i]);
            finite = finite && stages_finite<Estimates>(k, i, std::make_index_sequence<S>{});
            if (!finite) return false;
        }
        return true;
    }
    template <std::size_t Estimates, std::size_t... I>
    ODESTEP_INLINE static bool stages_finite(const std::array<row, S>& k, std::size_t i,
                                             std::index_sequence<I...>) noexcept {
        return ((!unweighted<Estimates>[I] || detail::is_finite(k[I][i])) && ...);
    }
};

}  // namespace odestep::capi

#endif
