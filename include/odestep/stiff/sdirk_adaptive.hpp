// SPDX-License-Identifier: BSL-1.0
// odestep: error-controlled stepping with an embedded SDIRK pair (tables::sdirk4): the engine (one attempted
// step at a time) and its dense output (cubic Hermite). The course's fixed-grid form over it is
// odestep::sdirk4_substeps (stiff/substeps.hpp).
#ifndef ODESTEP_STIFF_SDIRK_ADAPTIVE_HPP
#define ODESTEP_STIFF_SDIRK_ADAPTIVE_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "../adaptive/adaptive_rk.hpp"
#include "../adaptive/control.hpp"
#include "../detail/hermite.hpp"
#include "../detail/ops.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../rk/newton.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "../tables/implicit_rk.hpp"
#include "hermite_step.hpp"
#include "radau5.hpp"
#include "step_control.hpp"

namespace odestep {

/// \brief The dense output of one accepted SDIRK step: the cubic Hermite interpolant (odestep::hermite_cubic,
/// order 3 between the step's ends) through y and the slopes at both ends. The slopes are the step's own: the
/// last stage's derivative at its end (the stiffly accurate pair's y_{n+1} is that stage), the previous
/// step's at its start, so no evaluation of f is added. The engine's accept sink:
/// `engine.attempt(f, t, y, t_end, accepted, dense)`, then `dense.at(t, u)`.
template <class State>
class sdirk_dense : public hermite_step<State> {
    using T = value_type_t<State>;

public:
    /// The accept sink: the step of size h from (t0, y0) with slope f0 to y1 with slope f1.
    void operator()(T t0, T h, const State& y0, const State& f0, const State& y1, const State& f1) noexcept {
        this->t0_ = t0;
        this->h_ = h;
        detail::assign(this->y0_, y0);
        detail::assign(this->f0_, f0);
        detail::assign(this->y1_, y1);
        detail::assign(this->f1_, f1);
    }
};

/// \brief Error-controlled stepping with an embedded SDIRK pair (`Method` a table tag whose table is lower
/// triangular with one diagonal entry gamma, stiffly accurate, with one embedded weight vector:
/// tables::sdirk4), with the Newton iteration and the step-size control of odestep::radau5.
///
/// One attempt, from (t, y) with step h:
///   - The stages one after the other: stage i's increment z_i solves z_i = known_i + h gamma f(t + c_i h,
///     y + z_i), known_i = h sum_{j<i} a_ij k_j, by simplified Newton with the one matrix
///     E = (1 / (h gamma)) I - J for every stage (one LU per step, reused by all stages and kept across steps
///     while Newton converges fast). A stage starts from its predecessor's slope (zero for the first), and its
///     iteration is monitored as radau5's (detail::theta_monitor: Hairer's theta, stop at theta / (1 - theta)
///     ||dz|| <= kappa, kappa = max(10 eps / rtol, min(0.03, sqrt(rtol)))); divergence, a predicted failure
///     or the cap reject the attempt with a smaller h, y unchanged.
///   - The estimate: the embedded difference y_{n+1} - yhat_{n+1} = h sum (b_i - bhat_i) k_i, filtered through
///     the step's (I - h gamma J)^-1 (the filtering of Hairer & Wanner's RADAU5 estimate, HW II Sec. IV.8,
///     (8.19); one more solve): it keeps the estimate's order for smooth components and damps the stiff ones,
///     which otherwise reject good steps. Measured with the scaled RMS norm (scaled_error_norm).
///   - The next step: radau5's (detail::hairer_quotient with k = embedded order + 1, Gustafsson's predictive
///     controller, [0.2, 8] times h with radau5_control), the first attempt from a point 1/10 of a rejected h.
///   - The Jacobian: kept while the slowest stage's theta <= jacobian_reuse_rate(), re-evaluated at the
///     current point otherwise or when a step is rejected with an old one; a step 1 to 1.2 times the
///     factored one keeps its size and its factorization.
///
/// Work per attempt is bounded: at most max_newton_iterations iterations per stage (one evaluation of f and
/// one solve each), one Jacobian (N evaluations by differences, none with the system's own), one
/// factorization, one evaluation of f at a new point: rhs_evals_per_attempt. Failures, with y and t as they
/// were: non_finite (f at a new point, or the Jacobian by differences, NaN or Inf; or stage evaluations not
/// finite max_failures_in_a_row times in a row, h halved between them), singular_matrix (the system's
/// Jacobian not finite; or E singular max_failures_in_a_row times in a row), step_too_small.
///
/// Memory: J and E (2 N^2 values), the slope at the current point, the step size and the controller's
/// memory; no heap, no static state. A call from another point than the one it stopped at starts afresh.
template <class Method, class State>
class sdirk_adaptive : public newton_engine_settings<sdirk_adaptive<Method, State>, State> {
    using settings = newton_engine_settings<sdirk_adaptive, State>;
    friend class engine_settings<sdirk_adaptive, State, true>;

public:
    using state_type = State;                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;  ///< its scalar T
    using method_type = Method;              ///< the table's tag

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr auto tab = Method::template table<T>;
    static constexpr std::size_t S = decltype(tab)::stages;
    static constexpr bool constant_diagonal() noexcept {
        for (std::size_t i = 0; i < S; ++i)
            if (tab.a[i][i] != tab.a[0][0]) return false;
        return tab.a[0][0] > T(0);
    }
    static_assert(is_lower_triangular(tab) && constant_diagonal() && is_stiffly_accurate(tab) &&
                      decltype(tab)::embedded == 1,
                  "odestep: sdirk_adaptive needs a stiffly accurate SDIRK table with one embedded weight vector "
                  "(tables::sdirk4)");
    static constexpr T gamma = tab.a[0][0];

public:
    /// The order of the solution.
    static constexpr int order = tab.order;
    /// The order of the error estimate: err ~ C h^(embedded order + 1).
    static constexpr int estimate_order = tab.embedded_order[0] + 1;
    /// Stages of one step.
    static constexpr std::size_t stages = S;
    /// The cap on Newton iterations per stage (radau5's).
    static constexpr std::size_t max_newton_iterations = radau5<State>::max_newton_iterations;
    /// Singular matrices, or stages with NaN or Inf, tolerated in a row (each halves h) before the attempt
    /// fails with singular_matrix or non_finite.
    static constexpr std::size_t max_failures_in_a_row = radau5<State>::max_failures_in_a_row;
    /// The most evaluations of f one attempt makes: f at a new point (or at the current one before a
    /// Jacobian by differences), the difference Jacobian (N), every stage's iterations at the cap.
    static constexpr std::size_t rhs_evals_per_attempt = 1 + N + S * max_newton_iterations;
    /// The evaluations before the first attempt when no step size is carried: the first-step estimate's one.
    static constexpr std::size_t rhs_evals_to_start = 1;
    /// Factorizations per attempt, at most.
    static constexpr std::size_t decompositions_per_attempt = 1;

    /// Tolerances 1e-6 (float: 1e-4), RADAU5's controller (radau5_control).
    sdirk_adaptive() noexcept
        : sdirk_adaptive(tolerances<State>::uniform(detail::default_tolerance<T>(), detail::default_tolerance<T>())) {}
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    explicit sdirk_adaptive(const tolerances<State>& tol, const step_control<T>& control = radau5_control<T>()) noexcept
        : settings(tol, control) {
        tolerance_changed();
    }

    /// LU factorizations since construction, as odestep::counts reports them (one per decomposition of E).
    step_count factorizations() const noexcept { return decompositions_; }

    /// One attempted step from (t, y) toward t_end, never past it, landing exactly on t_end when the step
    /// size reaches it (or within 1% of it, if that stays within max_step). Accepted: y and t advance and
    /// sink(t_old, h, y_old, slope_old, y_new, slope_new) saw the step (sdirk_dense). Rejected: y and t
    /// unchanged, the step size shrunk. Failures leave y and t as they were. t_end == t is accepted at once.
    /// Settings are the caller's to check first.
    template <class System, class Sink = detail::no_step_sink>
    status attempt(System& f, T& t, State& y, T t_end, bool& accepted, Sink&& sink = Sink{}) {
        accepted = false;
        const T span = t_end - t;
        if (span == T(0)) {
            accepted = true;
            return status::ok;
        }
        const T dir = span > T(0) ? T(1) : T(-1);
        const T rem = detail::abs_value(span);
        status s = prepare_point(f, t, y);
        if (s != status::ok) return s;
        T mag = ctl_.h;
        if (!(mag > T(0))) {
            mag = detail::first_step_size(f, t, y, slope_, estimate_order, tol_, control_, rem, dir);
            if (!(mag > T(0))) return status::non_finite;
        }
        const detail::step_plan<T> p = detail::plan_step(control_, mag, rem);
        const bool last = p.last;
        mag = p.mag;
        const T h = ctl_.factored_step(last ? span : dir * mag, mag, rem, dir, last, lu_valid_, h_lu_);
        if (!last && detail::unresolved_step(h, t)) return status::step_too_small;

        if constexpr (jacobian_rhs_evals_v<System, State> != 0) {
            // differences need f(t, y) itself, not the previous step's stage slope
            if (ctl_.need_jacobian && !slope_exact_) {
                detail::evaluate(f, t, y, slope_);
                if (!detail::all_finite(slope_)) return status::non_finite;
                slope_exact_ = true;
            }
        }
        s = this->prepare_matrices(f, t, y, slope_, h, [&](T step) { return factor(step); });
        if (s != status::ok || !lu_valid_) return s;

        // The stages, one simplified Newton solve each with E = (1 / (h gamma)) I - J.
        const T hg = h * gamma;
        std::array<State, S> kh;  // h k_i = (z_i - known_i) / gamma
        State z;
        State known;
        T theta = theta_keep_;
        std::size_t most = 0;
        for (std::size_t i = 0; i < S; ++i) {
            for (std::size_t n = 0; n < N; ++n) {
                T sum = T(0);
                for (std::size_t j = 0; j < i; ++j) sum += tab.a[i][j] * kh[j][n];
                known[n] = sum;
                z[n] = i == 0 ? T(0) : sum + gamma * kh[i - 1][n];  // k_i ~ k_{i-1}
            }
            if (previous_valid_) {
                // the last step's Hermite interpolant extrapolated to the stage's time, as radau5 extrapolates
                // its collocation polynomial
                State u;
                hermite_cubic(y_prev_, slope_prev_, y, slope_, h_prev_, T(1) + tab.c[i] * h / h_prev_, u);
                for (std::size_t n = 0; n < N; ++n) z[n] = u[n] - y[n];
            }
            const T ti = (last && i + 1 == S) ? t_end : t + tab.c[i] * h;
            detail::theta_monitor<T> newton(faccon_, theta_keep_, fnewt_, max_newton_iterations);
            for (;;) {
                if (newton.iterations() >= max_newton_iterations)
                    return ctl_.retry_smaller(h, status::ok, max_failures_in_a_row);
                State in;
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + z[n];
                State r;
                detail::evaluate(f, ti, static_cast<const State&>(in), r);
                if (!detail::all_finite(r)) return ctl_.retry_smaller(h, status::non_finite, max_failures_in_a_row);
                // E dz = f(y + z) - (z - known) / (h gamma)
                for (std::size_t n = 0; n < N; ++n) r[n] -= (z[n] - known[n]) / hg;
                linalg::lu_solve(e_, piv_, r);
                ++iterations_;
                const T dyno = scaled_norm(r, y, tol_);
                if (!detail::is_finite(dyno)) return ctl_.retry_smaller(h, status::non_finite, max_failures_in_a_row);
                const auto verdict = newton.next(dyno);
                if (verdict == detail::theta_monitor<T>::verdict::diverged)
                    return ctl_.retry_smaller(h, status::ok, max_failures_in_a_row);
                if (verdict == detail::theta_monitor<T>::verdict::slow) return ctl_.reject(h, newton.shrink());
                for (std::size_t n = 0; n < N; ++n) z[n] += r[n];
                if (verdict == detail::theta_monitor<T>::verdict::converged) break;
            }
            faccon_ = newton.faccon();
            if (newton.theta() > theta || i == 0) theta = newton.theta();
            if (newton.iterations() > most) most = newton.iterations();
            for (std::size_t n = 0; n < N; ++n) kh[i][n] = (z[n] - known[n]) / gamma;
        }

        // y_{n+1} = y + z_s (stiffly accurate); the embedded difference, filtered through (I - h gamma J)^-1.
        State y_new;
        State err;
        for (std::size_t n = 0; n < N; ++n) {
            y_new[n] = y[n] + z[n];
            T d = T(0);
            for (std::size_t j = 0; j < S; ++j) d += (tab.b[j] - tab.bhat[0][j]) * kh[j][n];
            err[n] = d / hg;  // E x = d / (h gamma) gives x = (I - h gamma J)^-1 d
        }
        linalg::lu_solve(e_, piv_, err);
        const T e = detail::bounded_error(scaled_error_norm(err, y, y_new, tol_));

        const T habs = detail::abs_value(h);
        const T quot = detail::hairer_quotient(control_, e, estimate_order, most, max_newton_iterations);
        if (!(e < T(1))) {
            ctl_.reject_error(habs, quot);
            return status::ok;
        }
        if (!detail::all_finite(y_new)) return status::non_finite;
        // The last stage's slope is the new point's: k_s = (z_s - known_s) / (h gamma).
        State slope_new;
        for (std::size_t n = 0; n < N; ++n) slope_new[n] = kh[S - 1][n] / h;
        const T t_new = last ? t_end : t + h;
        sink(static_cast<const T&>(t), static_cast<const T&>(h), static_cast<const State&>(y),
             static_cast<const State&>(slope_), static_cast<const State&>(y_new), static_cast<const State&>(slope_new));
        ctl_.accept(control_, estimate_order, habs, e, quot, last, mag, theta, theta_keep_);
        t_point_ = t_new;
        detail::assign(y_point_, y_new);
        detail::assign(y_prev_, y);
        detail::assign(slope_prev_, slope_);
        h_prev_ = h;
        previous_valid_ = true;
        detail::assign(slope_, slope_new);
        slope_exact_ = false;
        detail::assign(y, y_new);
        t = t_new;
        accepted = true;
        ++ctl_.accepted;
        return status::ok;
    }

private:
    // The slope at the attempt's start: carried from the accepted step that ended there, or f at a new point.
    template <class System>
    status prepare_point(System& f, T t, const State& y) {
        if (point_valid_ && detail::same_point_time(t, t_point_) && detail::same_values(y, y_point_)) return status::ok;
        point_valid_ = false;
        detail::evaluate(f, t, y, slope_);
        if (!detail::all_finite(slope_)) return status::non_finite;
        slope_exact_ = true;
        previous_valid_ = false;
        t_point_ = t;
        detail::assign(y_point_, y);
        point_valid_ = true;
        ctl_.new_point();
        lu_valid_ = false;
        faccon_ = T(1);
        return status::ok;
    }

    // E = (1 / (h gamma)) I - J, factored.
    bool factor(T h) noexcept {
        const T d = T(1) / (h * gamma);
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) e_[r][c] = -jac_[r][c];
        for (std::size_t k = 0; k < N; ++k) e_[k][k] += d;
        if (linalg::lu_factor(e_, piv_) != status::ok) return false;
        h_lu_ = h;
        lu_valid_ = true;
        return true;
    }

    // Newton's tolerance kappa from the smallest positive rtol, as radau5's.
    void tolerance_changed() noexcept {
        T smallest = T(0);
        for (std::size_t i = 0; i < N; ++i) {
            const T r = tol_.rtol[i];
            if (r > T(0) && detail::is_finite(r) && (smallest == T(0) || r < smallest)) smallest = r;
        }
        fnewt_ = detail::newton_kappa(smallest);
    }

    // What newton_engine_settings keeps for every Newton-based engine.
    using settings::control_, settings::ctl_, settings::tol_, settings::theta_keep_, settings::jac_, settings::h_lu_,
        settings::lu_valid_, settings::point_valid_, settings::jacobians_, settings::decompositions_,
        settings::iterations_;
    T fnewt_ = T(3) / T(100);

    T faccon_ = T(1);
    T t_point_ = T(0);
    State y_point_{};
    State slope_{};
    State y_prev_{};
    State slope_prev_{};
    T h_prev_ = T(1);
    bool previous_valid_ = false;
    linalg::matrix<T, N> e_{};
    linalg::pivots<N> piv_{};
    bool slope_exact_ = false;
};

}  // namespace odestep

#endif
