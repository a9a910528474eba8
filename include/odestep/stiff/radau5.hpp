// SPDX-License-Identifier: BSL-1.0
// odestep: error-controlled Radau IIA 5 in the form of Hairer & Wanner's RADAU5 (Solving ODE II, Sec. IV.8;
// the code radau5.f): the engine (one attempted step at a time), its dense output (the collocation
// polynomial). The course's fixed-grid form over it is odestep::radau5_substeps (stiff/substeps.hpp).
#ifndef ODESTEP_STIFF_RADAU5_HPP
#define ODESTEP_STIFF_RADAU5_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../adaptive/adaptive_rk.hpp"
#include "../adaptive/control.hpp"
#include "../detail/ops.hpp"
#include "../linalg/complex_lu.hpp"
#include "../linalg/jacobian.hpp"
#include "../linalg/lu.hpp"
#include "../rk/newton.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "../tables/implicit_rk.hpp"
#include "step_control.hpp"

namespace odestep {

/// RADAU5's step-size controller settings as a step_control: safety 0.9, a step shrinks at most to 0.2 and
/// grows at most 8 times at once (radau5.f's defaults WORK(2), WORK(8), WORK(9)); alpha and beta are not
/// used (the predictive controller has its own gains), max_step 0 (no limit).
template <class T>
constexpr step_control<T> radau5_control() noexcept {
    step_control<T> c{};
    c.safety = T(9) / T(10);
    c.min_factor = T(1) / T(5);
    c.max_factor = T(8);
    return c;
}

/// \brief The collocation polynomial of one accepted Radau IIA 5 step: the engine's dense output, of order 3
/// between the step's ends (the stage order) and exact at the three nodes and both ends.
///
/// With s = (t - t_end) / h (so s = -1 at the step's start and s = c_i - 1 at stage i),
///     u(s) = y_end + s (q_1 + (s - c_2 + 1) (q_2 + (s - c_1 + 1) q_3))
/// the Newton form radau5.f's CONTR5 evaluates; q_1..q_3 are divided differences of the stage increments.
/// Used as the engine's accept sink: `engine.attempt(f, t, y, t_end, accepted, dense)`, then `dense.at(t, u)`.
template <class State>
class radau5_dense {
public:
    using state_type = State;                ///< the state
    using value_type = value_type_t<State>;  ///< its scalar T

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr auto tab = tables::radau_iia5::table<T>;

public:
    /// The accept sink: the step of size h that ended at (t_end, y_end), with its divided differences q.
    void operator()(T t_end, T h, const State& y_end, const std::array<State, 3>& q) noexcept {
        t_end_ = t_end;
        h_ = h;
        detail::assign(y_, y_end);
        q_ = q;
    }
    /// The step's end time.
    T t_end() const noexcept { return t_end_; }
    /// The step's size (signed).
    T step() const noexcept { return h_; }
    /// The polynomial at t (meant for t inside the step).
    void at(T t, State& out) const noexcept {
        const T s = (t - t_end_) / h_;
        const T a = s - tab.c[1] + T(1);
        const T b = s - tab.c[0] + T(1);
        for (std::size_t i = 0; i < N; ++i) out[i] = y_[i] + s * (q_[0][i] + a * (q_[1][i] + b * q_[2][i]));
    }

private:
    T t_end_ = T(0);
    T h_ = T(1);
    State y_{};
    std::array<State, 3> q_{};
};

/// \brief Error-controlled Radau IIA 5 (order 5, L-stable, stiffly accurate), the method and control of
/// Hairer & Wanner's RADAU5 (Solving ODE II, 2nd ed., Sec. IV.8, and radau5.f): the engine under
/// odestep::radau5_substeps, odestep::integrate_adaptive and odestep::integrate_times.
///
/// One attempt, from (t, y) with step h (tables::radau5_coefficients for the constants):
///   - The stage increments Z solve Z = h (A (x) I) F(Z). Simplified Newton on the transformed variables
///     W = (T^-1 (x) I) Z, where T^-1 A^-1 T = diag(gamma, [[alpha, -beta], [beta, alpha]]): each iteration
///     solves one real system with E1 = (gamma / h) I - J and one complex system with
///     E2 = ((alpha + i beta) / h) I - J (linalg::complex_lu_factor), instead of one 3N x 3N system.
///   - Newton starts from the previous step's collocation polynomial extrapolated to the new nodes (zero at
///     a start), stops when theta / (1 - theta) ||dW|| <= kappa, theta the observed contraction
///     (Hairer's: the ratio of successive update norms, then the geometric mean of the last two), and gives
///     up early when theta >= 0.99 (h halved) or when the rate predicts no convergence within the
///     iteration cap (h reduced by radau5.f's formula), or at the cap (h halved). Each of these is a
///     rejected attempt; y never moves.
///   - The error estimate err = (I - h gamma0 J)^-1 gamma0 (h f(t, y) + e.Z) (gamma0 = 1 / gamma), measured
///     with the scaled RMS norm (scaled_norm, control.hpp); at the first step and after a rejection, when it
///     fails, it is filtered once more through f at y + err (HW II (8.20)), which keeps stiff components
///     from rejecting good steps.
///   - The next step: h err^(-1/4) with the safety factor lowered by Newton's iteration count, combined with
///     Gustafsson's predictive controller (Gustafsson 1994, BIT 34, 173-187; radau5.f's PRED) and kept
///     within [0.2, 8] times h; at the first attempt from a point 1/10 of the rejected h.
///   - The Jacobian is kept across steps while Newton converges fast (theta <= jacobian_reuse_rate(), 0.1),
///     and re-evaluated at the current point when it does not, or when a step is rejected with an old
///     one. When the controller asks for 1 to 1.2 times the step of the current factorization and the
///     Jacobian is kept, the step keeps its size and its factorization.
///
/// Tolerances: the caller's rtol and atol, transformed as radau5.f does (rtol' = rtol^(2/3) / 10,
/// atol' = atol rtol' / rtol) because the estimate is of order 4 while the method is of order 5, so that
/// the achieved error is proportional to rtol (docs/stiff.md gives the measured ratios). A component with
/// rtol = 0 keeps its atol. Newton's tolerance is kappa = max(10 eps / rtol', min(0.03, sqrt(rtol'))).
///
/// Work per attempt is bounded: at most max_newton_iterations iterations (3 evaluations of f and two solves
/// each), one Jacobian (N evaluations of f by differences, none with the system's own), one pair of
/// factorizations, two more evaluations (the filtered estimate, f at a new point): rhs_evals_per_attempt.
/// Failures, with y and t as they were: non_finite (f at the step's start, or by differences the Jacobian,
/// gives NaN or Inf; or stage evaluations are not finite max_failures_in_a_row times in a row, h halved
/// between them), singular_matrix (the system's Jacobian has NaN or Inf; or E1 or E2 is singular
/// max_failures_in_a_row times in a row, h halved between them), step_too_small (|h| below ten ULPs of t).
///
/// Memory: J, E1 and E2 (4 N^2 values), the collocation polynomial, f at the current point, the step size
/// and the controller's memory, all carried from one attempt to the next; no heap, no static state. A call
/// from a point other than the one the engine stopped at (another y, bit for bit, or another t) starts
/// afresh there (f, Jacobian, factorization), keeping only the step size.
template <class State>
class radau5 : public newton_engine_settings<radau5<State>, State> {
    using settings = newton_engine_settings<radau5, State>;
    friend class engine_settings<radau5, State, true>;

public:
    using state_type = State;                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;  ///< its scalar T

private:
    using T = value_type;
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr auto tab = tables::radau_iia5::table<T>;
    using co = tables::radau5_coefficients<T>;

public:
    /// The order of the solution.
    static constexpr int order = 5;
    /// The order of the error estimate: err ~ C h^4.
    static constexpr int estimate_order = 4;
    /// Stages of one step.
    static constexpr std::size_t stages = 3;
    /// The cap on Newton iterations per attempt (radau5.f's NIT).
    static constexpr std::size_t max_newton_iterations = 7;
    /// Singular iteration matrices, or stages with NaN or Inf, tolerated in a row (each halves h) before the
    /// attempt fails with singular_matrix or non_finite (radau5.f's NSING limit).
    static constexpr std::size_t max_failures_in_a_row = 5;
    /// The most evaluations of f one attempt makes: the difference Jacobian (N), every Newton iteration at
    /// the cap (3 each), the filtered estimate's one, and f at the attempt's start when the point is new.
    static constexpr std::size_t rhs_evals_per_attempt = N + 3 * max_newton_iterations + 2;
    /// The evaluations before the first attempt from a new point when no step size is carried: the
    /// first-step estimate's one (odestep::initial_step).
    static constexpr std::size_t rhs_evals_to_start = 1;
    /// Pairs of factorizations (E1 real, E2 complex) per attempt, at most.
    static constexpr std::size_t decompositions_per_attempt = 1;

    /// Tolerances 1e-6 (float: 1e-4), RADAU5's controller (radau5_control).
    radau5() noexcept
        : radau5(tolerances<State>::uniform(detail::default_tolerance<T>(), detail::default_tolerance<T>())) {}
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    explicit radau5(const tolerances<State>& tol, const step_control<T>& control = radau5_control<T>()) noexcept
        : settings(tol, control) {
        tolerance_changed();
    }

    /// LU factorizations since construction: two per decomposition (odestep::counts, as SciPy's nlu).
    step_count factorizations() const noexcept { return 2 * decompositions_; }

    /// One attempted step from (t, y) toward t_end, never past it; the step lands exactly on t_end when the
    /// step size reaches it (or within 1% of it, if that stays within max_step). Accepted (`accepted` true):
    /// y and t advance (t = t_end exactly when it landed) and sink(t_new, h, y_new, q) saw the step
    /// (radau5_dense). Rejected: y and t unchanged, the step size shrunk. Failures leave y and t as they were
    /// (see the class). t_end == t is accepted at once. Settings are the caller's to check first.
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
            mag = detail::first_step_size(f, t, y, f0_, estimate_order, tol_, control_, rem, dir);
            if (!(mag > T(0))) return status::non_finite;
        }
        const detail::step_plan<T> p = detail::plan_step(control_, mag, rem);
        const bool last = p.last;
        mag = p.mag;
        const T h = ctl_.factored_step(last ? span : dir * mag, mag, rem, dir, last, lu_valid_, h_lu_);
        if (!last && detail::unresolved_step(h, t)) return status::step_too_small;

        s = this->prepare_matrices(f, t, y, f0_, h, [&](T step) { return factor(step); });
        if (s != status::ok || !lu_valid_) return s;

        // Starting values: the last step's collocation polynomial at the new nodes (radau5.f), or zero.
        std::array<State, 3> z;
        std::array<State, 3> w;
        if (polynomial_valid_) {
            const T c3q = h / h_old_;
            const T c1q = tab.c[0] * c3q;
            const T c2q = tab.c[1] * c3q;
            const T c1m1 = tab.c[0] - T(1);
            const T c2m1 = tab.c[1] - T(1);
            for (std::size_t n = 0; n < N; ++n) {
                const T ak1 = q_[0][n];
                const T ak2 = q_[1][n];
                const T ak3 = q_[2][n];
                z[0][n] = c1q * (ak1 + (c1q - c2m1) * (ak2 + (c1q - c1m1) * ak3));
                z[1][n] = c2q * (ak1 + (c2q - c2m1) * (ak2 + (c2q - c1m1) * ak3));
                z[2][n] = c3q * (ak1 + (c3q - c2m1) * (ak2 + (c3q - c1m1) * ak3));
            }
            transform(co::t_inv, z, w);
        } else {
            for (std::size_t i = 0; i < 3; ++i) {
                z[i].fill(T(0));
                w[i].fill(T(0));
            }
        }

        // The simplified Newton iteration on W.
        const T fac1 = co::gamma / h;
        const T alphn = co::alpha / h;
        const T betan = co::beta / h;
        const T stage_time[3] = {t + tab.c[0] * h, t + tab.c[1] * h, last ? t_end : t + h};
        detail::theta_monitor<T> newton(faccon_, theta_keep_, fnewt_, max_newton_iterations);
        for (;;) {
            if (newton.iterations() >= max_newton_iterations)
                return ctl_.retry_smaller(h, status::ok, max_failures_in_a_row);
            std::array<State, 3> fz;
            for (std::size_t i = 0; i < 3; ++i) {
                State in;
                for (std::size_t n = 0; n < N; ++n) in[n] = y[n] + z[i][n];
                detail::evaluate(f, stage_time[i], static_cast<const State&>(in), fz[i]);
                if (!detail::all_finite(fz[i])) return ctl_.retry_smaller(h, status::non_finite, max_failures_in_a_row);
            }
            // r = (T^-1 (x) I) F - (Lambda / h (x) I) W, then solved with E1 and E2
            std::array<State, 3> r;
            transform(co::t_inv, fz, r);
            for (std::size_t n = 0; n < N; ++n) {
                r[0][n] -= fac1 * w[0][n];
                r[1][n] -= alphn * w[1][n] - betan * w[2][n];
                r[2][n] -= betan * w[1][n] + alphn * w[2][n];
            }
            linalg::lu_solve(e1_, piv1_, r[0]);
            linalg::complex_lu_solve(e2_, piv2_, r[1], r[2]);
            ++iterations_;
            const T n1 = scaled_norm(r[0], y, newton_tol_);
            const T n2 = scaled_norm(r[1], y, newton_tol_);
            const T n3 = scaled_norm(r[2], y, newton_tol_);
            const T dyno = std::sqrt((n1 * n1 + n2 * n2 + n3 * n3) / T(3));
            if (!detail::is_finite(dyno)) return ctl_.retry_smaller(h, status::non_finite, max_failures_in_a_row);
            const auto verdict = newton.next(dyno);
            if (verdict == detail::theta_monitor<T>::verdict::diverged)
                return ctl_.retry_smaller(h, status::ok, max_failures_in_a_row);
            // Convergence within the cap is not expected: a smaller step, by radau5.f's formula.
            if (verdict == detail::theta_monitor<T>::verdict::slow) return ctl_.reject(h, newton.shrink());
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t n = 0; n < N; ++n) w[i][n] += r[i][n];
            transform(co::t, w, z);
            if (verdict == detail::theta_monitor<T>::verdict::converged) break;
        }
        faccon_ = newton.faccon();
        const T theta = newton.theta();
        const std::size_t newt = newton.iterations();

        // The error estimate, filtered through E1 = (gamma / h) I - J (HW II (8.19), (8.20)).
        State f2;
        State err;
        for (std::size_t n = 0; n < N; ++n) {
            f2[n] = (co::e[0] * z[0][n] + co::e[1] * z[1][n] + co::e[2] * z[2][n]) / h;
            err[n] = f2[n] + f0_[n];
        }
        linalg::lu_solve(e1_, piv1_, err);
        T e = scaled_norm(err, y, newton_tol_);
        if (!(e < T(1)) && (ctl_.first || ctl_.rejected_last)) {
            State probe;
            for (std::size_t n = 0; n < N; ++n) probe[n] = y[n] + err[n];
            State f1;
            detail::evaluate(f, t, static_cast<const State&>(probe), f1);
            if (detail::all_finite(f1)) {
                for (std::size_t n = 0; n < N; ++n) err[n] = f1[n] + f2[n];
                linalg::lu_solve(e1_, piv1_, err);
                e = scaled_norm(err, y, newton_tol_);
            }
        }
        e = detail::bounded_error(e);

        // The next step size (radau5.f): the safety lowered by Newton's iterations, within [0.2, 8] times h.
        const T habs = detail::abs_value(h);
        const T quot = detail::hairer_quotient(control_, e, estimate_order, newt, max_newton_iterations);
        if (!(e < T(1))) {
            ctl_.reject_error(habs, quot);
            return status::ok;
        }
        State y_new;
        for (std::size_t n = 0; n < N; ++n) y_new[n] = y[n] + z[2][n];
        if (!detail::all_finite(y_new)) return status::non_finite;
        // The collocation polynomial's divided differences (radau5.f, CONT), for dense output and the next
        // step's starting values.
        {
            const T c1 = tab.c[0];
            const T c2 = tab.c[1];
            for (std::size_t n = 0; n < N; ++n) {
                const T z1 = z[0][n];
                const T z2 = z[1][n];
                const T z3 = z[2][n];
                q_[0][n] = (z2 - z3) / (c2 - T(1));
                const T ak = (z1 - z2) / (c1 - c2);
                const T acont3 = (ak - z1 / c1) / c2;
                q_[1][n] = (ak - q_[0][n]) / (c1 - T(1));
                q_[2][n] = q_[1][n] - acont3;
            }
        }
        polynomial_valid_ = true;
        h_old_ = h;
        const T t_new = last ? t_end : t + h;
        sink(static_cast<const T&>(t_new), static_cast<const T&>(h), static_cast<const State&>(y_new),
             static_cast<const std::array<State, 3>&>(q_));
        // the next step: Gustafsson's predictive controller (radau5.f, PRED) with the quotient above
        ctl_.accept(control_, estimate_order, habs, e, quot, last, mag, theta, theta_keep_);
        t_point_ = t_new;
        detail::assign(y_point_, y_new);
        f0_valid_ = false;
        detail::assign(y, y_new);
        t = t_new;
        accepted = true;
        ++ctl_.accepted;
        return status::ok;
    }

private:
    // out_i = sum_j m_ij in_j, per component
    static void transform(const std::array<std::array<T, 3>, 3>& m, const std::array<State, 3>& in,
                          std::array<State, 3>& out) noexcept {
        for (std::size_t n = 0; n < N; ++n) {
            const T a = in[0][n];
            const T b = in[1][n];
            const T c = in[2][n];
            for (std::size_t i = 0; i < 3; ++i) out[i][n] = m[i][0] * a + m[i][1] * b + m[i][2] * c;
        }
    }

    // f at the attempt's start: kept from the accepted step that ended there (computed once), or a new start.
    template <class System>
    status prepare_point(System& f, T t, const State& y) {
        if (point_valid_ && detail::same_point_time(t, t_point_) && detail::same_values(y, y_point_)) {
            if (f0_valid_) return status::ok;
            detail::evaluate(f, t_point_, y_point_, f0_);
            if (!detail::all_finite(f0_)) return status::non_finite;
            f0_valid_ = true;
            return status::ok;
        }
        point_valid_ = false;
        detail::evaluate(f, t, y, f0_);
        if (!detail::all_finite(f0_)) return status::non_finite;
        t_point_ = t;
        detail::assign(y_point_, y);
        point_valid_ = true;
        f0_valid_ = true;
        ctl_.new_point();
        lu_valid_ = false;
        polynomial_valid_ = false;
        faccon_ = T(1);
        return status::ok;
    }

    // E1 = (gamma / h) I - J and E2 = ((alpha + i beta) / h) I - J, factored.
    bool factor(T h) noexcept {
        const T fac1 = co::gamma / h;
        const T alphn = co::alpha / h;
        const T betan = co::beta / h;
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < N; ++c) {
                e1_[r][c] = -jac_[r][c];
                e2_.re[r][c] = -jac_[r][c];
                e2_.im[r][c] = T(0);
            }
        for (std::size_t d = 0; d < N; ++d) {
            e1_[d][d] += fac1;
            e2_.re[d][d] += alphn;
            e2_.im[d][d] = betan;
        }
        if (linalg::lu_factor(e1_, piv1_) != status::ok) return false;
        if (linalg::complex_lu_factor(e2_, piv2_) != status::ok) return false;
        h_lu_ = h;
        lu_valid_ = true;
        return true;
    }

    void tolerance_changed() noexcept {
        T smallest = T(0);
        for (std::size_t i = 0; i < N; ++i) {
            const T r = tol_.rtol[i];
            if (r > T(0) && detail::is_finite(r)) {
                const T rn = std::pow(r, T(2) / T(3)) / T(10);
                newton_tol_.rtol[i] = rn;
                newton_tol_.atol[i] = tol_.atol[i] * (rn / r);
                if (smallest == T(0) || rn < smallest) smallest = rn;
            } else {
                newton_tol_.rtol[i] = T(0);
                newton_tol_.atol[i] = tol_.atol[i];
            }
        }
        fnewt_ = detail::newton_kappa(smallest);
    }

    // What newton_engine_settings keeps for every Newton-based engine.
    using settings::control_, settings::ctl_, settings::tol_, settings::theta_keep_, settings::jac_, settings::h_lu_,
        settings::lu_valid_, settings::point_valid_, settings::jacobians_, settings::decompositions_,
        settings::iterations_;
    tolerances<State> newton_tol_{};
    T fnewt_ = T(3) / T(100);

    T h_old_ = T(1);  // the signed h of the last accepted step (its polynomial)
    T faccon_ = T(1);
    T t_point_ = T(0);
    State y_point_{};
    State f0_{};
    linalg::matrix<T, N> e1_{};
    linalg::pivots<N> piv1_{};
    linalg::complex_matrix<T, N> e2_{};
    linalg::pivots<N> piv2_{};
    std::array<State, 3> q_{};
    bool f0_valid_ = false;
    bool polynomial_valid_ = false;
};

}  // namespace odestep

#endif
