// SPDX-License-Identifier: BSL-1.0
// odestep: error-controlled explicit Runge-Kutta stepping over the embedded pairs of the table library,
// and the course's form of it: a stepper that looks like a fixed-step one (one grid interval per call) and
// inside takes as many error-controlled steps as the tolerance asks for.
#ifndef ODESTEP_ADAPTIVE_ADAPTIVE_RK_HPP
#define ODESTEP_ADAPTIVE_ADAPTIVE_RK_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../detail/stage_loop.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/butcher.hpp"
#include "../tables/runge_kutta.hpp"
#include "control.hpp"

namespace odestep {

namespace detail {

/// One step of an embedded explicit pair with its stages kept: the error-controlled steppers need k_1 from
/// outside (the last stage of the step before, for a FSAL table) and give all stages out (dense output),
/// which explicit_rk's `step` does not. The sums are expanded at compile time over the constexpr table;
/// a zero coefficient emits nothing.
template <class Method, class State>
struct embedded_pair {
    using T = value_type_t<State>;
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t S = table_type::stages;
    static constexpr std::size_t E = table_type::embedded;
    static constexpr std::size_t N = state_traits<State>::size;
    static_assert(E >= 1,
                  "odestep: error control needs a table with an embedded solution (a pair: BS 3(2), RKF "
                  "4(5), Cash-Karp 5(4), DP 5(4), RKF 7(8), DOP853)");
    static_assert(is_explicit(tab), "odestep: error-controlled stepping here takes an explicit table");

    /// First same as last (detail::first_same_as_last): the last stage is the next step's first.
    static constexpr bool fsal = first_same_as_last(tab);

    /// The order of the error estimate, k in err ~ C h^k: the lower order of the pair plus one; for a
    /// table with two estimates (DOP853) Hairer's combined norm, which behaves as h^8 (HNW I, Sec. II.10).
    static constexpr int estimate_order =
        E >= 2 ? tab.order : (tab.order < tab.embedded_order[0] ? tab.order : tab.embedded_order[0]) + 1;

    /// k[0] = f(t, y) is given (finite). Fills k[1 .. S-1], y_new = y + h sum b_i k_i and
    /// err = h sum (b_i - bhat_i) k_i (err2 from the second estimate; untouched with one), and returns true; returns false
    /// at the first stage where f gave NaN or Inf, with no further call of f (a user's f may trap on NaN or
    /// index a table by y), leaving the outputs unspecified. t_end is t + h as the caller has it (the
    /// interval's end, exactly): the stage with c = 1 is evaluated there. Every sum is expanded at compile
    /// time over the table's non-zero coefficients; the terms are added in stage order from 0, as the plain
    /// loops would.
    template <class System>
    [[nodiscard]] static bool step(System& f, const State& y, T t, T h, T t_end, std::array<State, S>& k, State& y_new,
                                   State& err, State& err2) {
        if (!stage_loop::template run<true>(f, y, t, h, t_end, k, y_new, evaluated(std::make_index_sequence<S>{})))
            return false;
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) {
            if constexpr (!next_from_stage) y_new[n] = y[n] + sum_form::template sum<b_weights>(k, n, h);
            err[n] = sum_form::template sum<error_weights<0>>(k, n, h);
            if constexpr (E >= 2) err2[n] = sum_form::template sum<error_weights<1>>(k, n, h);
        }
        return true;
    }

    // The stage loop (detail::explicit_stages) over the stages after the first (given), every sum in stage
    // order from 0 (detail::ordered_sum).
    using stage_loop = detail::explicit_stages<Method, State, detail::ordered_sum>;
    using sum_form = detail::ordered_sum<T, State, S>;
    template <std::size_t... I>
    static constexpr auto evaluated(std::index_sequence<I...>) noexcept {
        return std::integer_sequence<bool, (I != 0)...>{};
    }
    // The b row's input is y_{n+1} (for a FSAL table the last stage's), kept there by the stage loop.
    static constexpr bool next_from_stage = stage_loop::b_row < S;
    using b_weights = typename detail::table_rows<Method, T>::b_weights;
    template <std::size_t Which>
    using error_weights = typename detail::table_rows<Method, T>::template error_weights<Which>;

    /// The step's results are finite: y_new and the estimates (the second only where the table has one).
    ODESTEP_INLINE static bool finite(const State& y_new, const State& err, const State& err2) noexcept {
        if constexpr (E >= 2) {
            return all_finite(y_new, err, err2);
        } else {
            (void)err2;
            return all_finite(y_new, err);
        }
    }

    /// The norm the controller sees: the scaled RMS norm of err; with two estimates (DOP853) Hairer's
    /// combination e5^2 / sqrt(e5^2 + 0.01 e3^2) of the two norms (DOP853's ERR/DENO, HNW I, Sec. II.10).
    ODESTEP_INLINE static T norm(const State& err, const State& err2, const State& y, const State& y_new,
                                 const tolerances<State>& tol) noexcept {
        const T e = scaled_error_norm(err, y, y_new, tol);
        if constexpr (E >= 2) {
            const T e3 = scaled_error_norm(err2, y, y_new, tol);
            const T deno = e * e + e3 * e3 / T(100);
            return deno > T(0) ? e * e / std::sqrt(deno) : T(0);
        } else {
            (void)err2;
            return e;
        }
    }
};

/// An accepted step's data, as a dense-output sink receives it (no sink: nothing).
struct no_step_sink {
    template <class... A>
    constexpr void operator()(const A&...) const noexcept {}
};

/// The default tolerances: 1e-6 (relative and absolute) in double and wider, 1e-4 in float.
template <class T>
constexpr T default_tolerance() noexcept {
    return std::numeric_limits<T>::digits > 24 ? T(1) / T(1000000) : T(1) / T(10000);
}

}  // namespace detail

/// \brief Error-controlled stepping with an embedded explicit Runge-Kutta pair (`Method` a table tag of
/// tables/runge_kutta.hpp with embedded weights): the engine under odestep::adaptive_substeps,
/// odestep::integrate_adaptive and odestep::integrate_times.
///
/// Its memory is the step size to try next (carried from call to call), the previous accepted error norm
/// (the PI controller's), whether the last attempt was rejected, and the first stage f(t, y) of the point it
/// stopped at (FSAL tables: the last stage of the step that ended there), reused when the next call starts
/// from that same y (compared bit for bit, so a caller that changed y between calls is never given a stale
/// derivative) at that time (to four ULPs: the grid's t0 + (i + 1) dt and the interval's t + dt). No heap, no static state; a copy is an independent engine.
template <class Method, class State>
class adaptive_rk : public engine_settings<adaptive_rk<Method, State>, State> {
    using settings = engine_settings<adaptive_rk, State>;

public:
    using state_type = State;                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;  ///< its scalar T
    using method_type = Method;              ///< the table tag

private:
    using T = value_type;
    using pair = detail::embedded_pair<Method, State>;

public:
    /// The order of the solution (the pair's higher order, which is propagated).
    static constexpr int order = pair::tab.order;
    /// Stages of one attempted step.
    static constexpr std::size_t stages = pair::S;
    /// The table is first-same-as-last: an accepted step costs stages - 1 evaluations.
    static constexpr bool fsal = pair::fsal;
    /// k in err ~ C h^k, the exponent the controller works with.
    static constexpr int estimate_order = pair::estimate_order;
    /// The most evaluations of f one attempt can make: its new stages, and f at its start when that point
    /// has none kept (every attempt of a non-FSAL table after an accepted step).
    static constexpr std::size_t rhs_evals_per_attempt = fsal ? stages - 1 : stages;
    /// The evaluations before the first attempt from a new point, at most: f(t, y) and the first-step
    /// estimate's one evaluation (when no step size is carried).
    static constexpr std::size_t rhs_evals_to_start = 2;

    /// Tolerances 1e-6 (float: 1e-4), default controller.
    adaptive_rk() noexcept
        : adaptive_rk(tolerances<State>::uniform(detail::default_tolerance<T>(), detail::default_tolerance<T>())) {}
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    explicit adaptive_rk(const tolerances<State>& tol, const step_control<T>& control = {}) noexcept
        : settings(tol, control) {}

    /// Forgets the step size, the controller's memory and the kept stage: the next call starts afresh.
    void restart() noexcept {
        ctl_.restart();
        k0_valid_ = false;
    }

    /// One attempted step from (t, y) toward t_end, never past it and never longer than
    /// step_control::max_step; the step lands exactly on t_end when the step size would reach within 1% of
    /// it (no sliver is left), or, where that step would be longer than max_step, covers half of the rest
    /// (the next one lands). Accepted (`accepted` true): y and t
    /// advance (t = t_end exactly when it landed), and sink(t, y, h, k, y_new) saw the step first (its start,
    /// size, stages and end). Rejected: y and t unchanged, the step size shrunk. Failures leave y and t as
    /// they were: non_finite (f gave NaN or Inf, or the step overflowed), step_too_small (|h| fell to ten
    /// ULPs of t). t_end == t is accepted at once. Settings are the caller's to check first.
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
        status s = first_stage(f, t, y);
        if (s != status::ok) return s;
        T mag = ctl_.h;
        if (!(mag > T(0))) {
            mag = detail::first_step_size(f, t, y, k0_, estimate_order, tol_, control_, rem, dir);
            if (!(mag > T(0))) return status::non_finite;  // f at the estimate's probe was not finite
        }
        const detail::step_plan<T> p = detail::plan_step(control_, mag, rem);
        // A rest too long to land on in one step is split into two equal steps.
        const bool last = p.last;
        const T h = last ? span : p.split ? dir * (rem / T(2)) : dir * p.mag;
        if (!last && detail::unresolved_step(h, t)) return status::step_too_small;
        std::array<State, pair::S> k;
        k[0] = k0_;
        State y_new{};  // written by pair::step (for FSAL in its stage loop, which GCC cannot always see)
        State err;
        State err2;
        // Every stage was checked as it came (k[0], kept, was checked when it was computed).
        if (!pair::step(f, y, t, h, last ? t_end : t + h, k, y_new, err, err2) || !pair::finite(y_new, err, err2))
            return status::non_finite;
        const T e = pair::norm(err, err2, y, y_new, tol_);
        const T habs = detail::abs_value(h);
        if (e <= T(1)) {
            T log_e;
            T next = ctl_.next_step(control_, estimate_order, habs, e, log_e);
            // A step shortened to land on t_end (or to split the rest) says nothing against the size planned:
            // keep the larger.
            if ((last || p.split) && p.mag > next) next = p.mag;
            ctl_.accept(next, habs, log_e);
            sink(static_cast<const T&>(t), static_cast<const State&>(y), static_cast<const T&>(h),
                 static_cast<const std::array<State, pair::S>&>(k), static_cast<const State&>(y_new));
            const T t_new = last ? t_end : t + h;
            if constexpr (pair::fsal) {
                keep_first_stage(t_new, y_new, k[pair::S - 1]);
            } else {
                k0_valid_ = false;
            }
            detail::assign(y, y_new);
            t = t_new;
            accepted = true;
            ++ctl_.accepted;
        } else {
            // Shrunk to zero (an underflow, possible only near t = 0): never back to the first-step estimate.
            return ctl_.reject_error(control_, estimate_order, habs, e);
        }
        return status::ok;
    }

    /// f(t, y) into dydt: the kept first stage when (t, y) is the point it belongs to, otherwise one
    /// evaluation, then kept for the next attempt from there. non_finite (and nothing kept) when f gives
    /// NaN or Inf.
    template <class System>
    status derivative(System& f, T t, const State& y, State& dydt) {
        const status s = first_stage(f, t, y);
        if (s == status::ok) detail::assign(dydt, k0_);
        return s;
    }

private:
    template <class System>
    status first_stage(System& f, T t, const State& y) {
        if (k0_valid_ && detail::same_point_time(t, t0_) && detail::same_values(y, y0_)) return status::ok;
        State k;
        detail::evaluate(f, t, y, k);
        if (!detail::all_finite(k)) {
            k0_valid_ = false;
            return status::non_finite;
        }
        keep_first_stage(t, y, k);
        return status::ok;
    }
    void keep_first_stage(T t, const State& y, const State& k) noexcept {
        t0_ = t;
        detail::assign(y0_, y);
        detail::assign(k0_, k);
        k0_valid_ = true;
    }

    using settings::control_;
    using settings::ctl_;
    using settings::tol_;
    bool k0_valid_ = false;
    T t0_ = T(0);
    State y0_{};
    State k0_{};
};

namespace detail {
// THE interval covered by error-controlled substeps, for adaptive_substeps and the stiff engines' substep form
// (stiff/substeps.hpp): y <- y(t + dt) in at most max_attempts attempts of `engine`, the last landing exactly on
// t + dt; on any status but ok y is the state it was given. The caller's preflight checked the settings, t and dt.
template <class Engine, class System, class State, class T>
status cover_interval(Engine& engine, System& f, State& y, T t, T dt, std::size_t max_attempts) {
    const T t_end = t + dt;
    if (!is_finite(t_end)) return status::invalid_time;
    // dt below the rounding of t: the interval is empty and y(t + dt) is y, evaluated nowhere; ok only for
    // a finite y, as a step that evaluates f at y would find.
    if (t_end == t) return all_finite(y) ? status::ok : status::non_finite;
    const State start = y;
    T tc = t;
    status s = status::ok;
    for (std::size_t n = 0; n < max_attempts; ++n) {
        bool accepted = false;
        s = engine.attempt(f, tc, y, t_end, accepted);
        if (s != status::ok) break;
        if (accepted && tc == t_end) return status::ok;
    }
    if (s == status::ok) s = status::substep_limit;
    assign(y, start);
    return s;
}
}  // namespace detail

namespace detail {
/// The substep forms' one body (odestep::adaptive_substeps, odestep::stiff_substeps): an error-controlled
/// `Engine` behind the fixed-step stepper interface, each step covering one grid interval with at most a
/// run-time cap (1 .. Max) of attempts (cover_interval). The forms add their traits and name the cap.
template <class Engine, std::size_t Max>
class interval_cover : public stepper_defaults<typename Engine::state_type> {
    static_assert(Max >= 1, "odestep: a substep form needs room for at least one attempt per interval");
    using State = typename Engine::state_type;
    using T = value_type_t<State>;

public:
    /// invalid_tolerance, invalid_setting (a controller setting, or a cap outside [1, Max]), or ok.
    /// The driving loops ask it before anything is observed or evaluated.
    status settings_status() const noexcept {
        const status s = engine_.settings_status();
        if (s != status::ok) return s;
        return cap_ >= 1 && cap_ <= Max ? status::ok : status::invalid_setting;
    }
    /// The engine: its tolerances, controller, step size and counts.
    Engine& engine() noexcept { return engine_; }
    /// The engine, read only.
    const Engine& engine() const noexcept { return engine_; }

    /// y <- y(t + dt) to the tolerances, in as many internal steps as needed. On any status but ok y is
    /// the state it was given: invalid_tolerance / invalid_setting (bad settings), invalid_time (t or
    /// t + dt not finite), invalid_step (dt zero or not finite), non_finite, singular_matrix (a stiff
    /// engine's), step_too_small, substep_limit (the cap).
    template <class System>
    [[nodiscard]] status step(System&& f, State& y, T t, T dt) {
        const status s = preflight(*this, t, dt);
        if (s != status::ok) return s;
        return cover_interval(engine_, f, y, t, dt, cap_);
    }

protected:
    /// The engine's defaults and the cap Max.
    interval_cover() noexcept = default;
    /// The engine made from `engine_args`, and the cap (both checked before any use).
    template <class... EngineArgs>
    explicit interval_cover(std::size_t cap, const EngineArgs&... engine_args) noexcept
        : engine_(engine_args...), cap_(cap) {}
    /// Sets the cap: status::invalid_setting (nothing changed) outside [1, Max].
    status set_cap(std::size_t n) noexcept {
        if (n < 1 || n > Max) return status::invalid_setting;
        cap_ = n;
        return status::ok;
    }

    Engine engine_{};        ///< the error-controlled engine
    std::size_t cap_ = Max;  ///< attempts per interval, at most
};
}  // namespace detail

/// \brief The course's adaptive solver: a stepper that looks like a fixed-step one.
///
/// `step(f, y, t, dt)` covers one interval of the caller's grid, [t, t + dt], with as many error-controlled
/// internal steps of the pair `Method` as the tolerances ask for (odestep::adaptive_rk), the last landing
/// exactly on t + dt; the internal step size is carried from one interval to the next (a step shortened to
/// land on the grid does not shrink it). It publishes the stepper trait set, so it goes wherever a
/// fixed-step stepper goes: integrate, integrate_n_steps, the event loops (an event is located by re-stepping
/// the interval, which this stepper covers adaptively again), event_stepper.
///
/// At most `max_substeps()` attempts (accepted or rejected) per interval, settable up to the compile-time
/// MaxSubsteps; past it `status::substep_limit` with y back at the interval's start (the shrunk step size
/// is kept). NaN or Inf from f: status::non_finite, y back at the interval's start. `rhs_evals_per_step`
/// is the worst case of one interval, MaxSubsteps attempts: a constant bound, not the typical cost.
///
///     odestep::adaptive_substeps<odestep::tables::cash_karp54, state> s(
///         odestep::tolerances<state>::uniform(1e-8, 1e-8));
///     auto r = odestep::integrate(s, f, y, 0.0, 10.0, 0.1, observer);  // observer sees t = 0, 0.1, ...
template <class Method, class State, std::size_t MaxSubsteps = 256>
class adaptive_substeps : public detail::interval_cover<adaptive_rk<Method, State>, MaxSubsteps> {
    using base = detail::interval_cover<adaptive_rk<Method, State>, MaxSubsteps>;

public:
    using state_type = State;                        ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;          ///< its scalar T
    using method_type = Method;                      ///< the table tag
    using engine_type = adaptive_rk<Method, State>;  ///< the error-controlled engine inside

private:
    using T = value_type;

public:
    /// The order of the pair's propagated solution (what the internal steps achieve locally; over an
    /// interval the error is the tolerance's, not dt^order).
    static constexpr int order = engine_type::order;
    /// Stages of one internal step.
    static constexpr std::size_t stages = engine_type::stages;
    /// The most evaluations one interval can cost: the start's two and MaxSubsteps attempts.
    static constexpr std::size_t rhs_evals_per_step =
        engine_type::rhs_evals_to_start + MaxSubsteps * engine_type::rhs_evals_per_attempt;
    /// The compile-time cap on attempts per interval (the bound of rhs_evals_per_step).
    static constexpr std::size_t max_substeps_bound = MaxSubsteps;

    /// Tolerances 1e-6 (float: 1e-4), default controller, MaxSubsteps attempts per interval.
    adaptive_substeps() noexcept = default;
    /// The given tolerances, controller settings and cap (all checked before any use).
    explicit adaptive_substeps(const tolerances<State>& tol, const step_control<T>& control = {},
                               std::size_t max_substeps = MaxSubsteps) noexcept
        : base(max_substeps, tol, control) {}

    /// The cap on attempts per interval.
    std::size_t max_substeps() const noexcept { return this->cap_; }
    /// Sets the cap on attempts per interval: status::invalid_setting (nothing changed) outside
    /// [1, MaxSubsteps].
    status set_max_substeps(std::size_t n) noexcept { return this->set_cap(n); }
};

/// The course's Cash-Karp 5(4) adaptive solver (its default) on State.
template <class State>
using cash_karp54_substeps = adaptive_substeps<tables::cash_karp54, State>;
/// Dormand-Prince 5(4) adaptive solver on State.
template <class State>
using dormand_prince54_substeps = adaptive_substeps<tables::dormand_prince54, State>;
/// DOP853 adaptive solver on State.
template <class State>
using dop853_substeps = adaptive_substeps<tables::dop853, State>;

}  // namespace odestep

#endif
