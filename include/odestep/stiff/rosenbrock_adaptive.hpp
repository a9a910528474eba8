// SPDX-License-Identifier: BSL-1.0
// odestep: error-controlled stepping with a Rosenbrock pair (a rosenbrock_tableau with an embedded solution:
// Rodas4, RODAS3): the engine under odestep::rosenbrock_substeps and integrate_adaptive.
#ifndef ODESTEP_STIFF_ROSENBROCK_ADAPTIVE_HPP
#define ODESTEP_STIFF_ROSENBROCK_ADAPTIVE_HPP

#include <cstddef>
#include <limits>

#include "../adaptive/adaptive_rk.hpp"
#include "../adaptive/control.hpp"
#include "../detail/hermite.hpp"
#include "../detail/ops.hpp"
#include "../rk/rosenbrock.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"
#include "hermite_step.hpp"
#include "step_control.hpp"

namespace odestep {

/// \brief The dense output of one accepted Rosenbrock step: the cubic Hermite interpolant (odestep::hermite_cubic,
/// order 3 between the step's ends) through y and f at both ends. The step's attempt does not keep f at its
/// ends, so complete(f) evaluates them once the caller needs a value inside the step: f at the end, and f at the
/// start unless the step before was completed and ended there (then its end slope serves): at most
/// rhs_evals_to_complete evaluations per step. The engine's accept sink:
/// `engine.attempt(f, t, y, t_end, accepted, dense)`, then `dense.complete(f)` and `dense.at(t, u)`.
template <class State>
class rosenbrock_dense : public hermite_step<State> {
    using T = value_type_t<State>;

public:
    /// The most evaluations of f one complete() makes.
    static constexpr std::size_t rhs_evals_to_complete = 2;

    /// The accept sink: the step of size h from (t0, y0) to y1.
    void operator()(T t0, T h, const State& y0, const State& y1) noexcept {
        // f at this step's start is the completed previous step's end slope when the run is continuous
        f0_valid_ =
            end_valid_ && detail::same_point_time(t0, this->t0_ + this->h_) && detail::same_values(y0, this->y1_);
        if (f0_valid_) detail::assign(this->f0_, this->f1_);
        end_valid_ = false;
        this->t0_ = t0;
        this->h_ = h;
        detail::assign(this->y0_, y0);
        detail::assign(this->y1_, y1);
    }
    /// Evaluates what the interpolant needs (f at the step's ends): status::non_finite when f gives NaN or Inf.
    template <class System>
    status complete(System& f) {
        if (end_valid_) return status::ok;
        if (!f0_valid_) {
            detail::evaluate(f, this->t0_, static_cast<const State&>(this->y0_), this->f0_);
            if (!detail::all_finite(this->f0_)) return status::non_finite;
            f0_valid_ = true;
        }
        detail::evaluate(f, this->t0_ + this->h_, static_cast<const State&>(this->y1_), this->f1_);
        if (!detail::all_finite(this->f1_)) return status::non_finite;
        end_valid_ = true;
        return status::ok;
    }

private:
    bool f0_valid_ = false;
    bool end_valid_ = false;
};

/// \brief Error-controlled Rosenbrock stepping: each attempt is one step of odestep::rosenbrock<Method, State>
/// with its embedded solution (Method a table with embedded weights: tables::rodas4, tables::rodas3), the
/// estimate measured with the scaled RMS norm and the step size chosen by the PI controller of
/// adaptive/control.hpp (step_factor, with k = embedded_order + 1).
///
/// No iteration: an attempt costs exactly what a step of the fixed-step stepper costs (one Jacobian, df/dt by
/// a difference, one factorization, `stages` solves), rhs_evals_per_attempt evaluations at most. A step that
/// fails (singular I - h gamma J, NaN or Inf from f or in the result) is retried with h halved, at most
/// max_failures_in_a_row times in a row; then its status is returned. Every failure leaves y and t as they
/// were. What it carries: the step size, the controller's memory; no heap, no static state.
template <class Method, class State>
class rosenbrock_adaptive : public engine_settings<rosenbrock_adaptive<Method, State>, State> {
    using settings = engine_settings<rosenbrock_adaptive, State>;

public:
    using state_type = State;                        ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;          ///< its scalar T
    using method_type = Method;                      ///< the table's tag
    using stepper_type = rosenbrock<Method, State>;  ///< the step it attempts

private:
    using T = value_type;
    static_assert(stepper_type::error_estimate,
                  "odestep: error control needs a Rosenbrock table with an embedded solution (tables::rodas4, "
                  "tables::rodas3)");

public:
    /// The order of the solution.
    static constexpr int order = stepper_type::order;
    /// Stages of one step.
    static constexpr std::size_t stages = stepper_type::stages;
    /// k in err ~ C h^k: the embedded order plus one.
    static constexpr int estimate_order = stepper_type::embedded_order + 1;
    /// No Newton iteration.
    static constexpr std::size_t max_newton_iterations = 0;
    /// Failed steps (singular matrix, NaN or Inf) tolerated in a row, each halving h, before the status is
    /// returned.
    static constexpr std::size_t max_failures_in_a_row = 5;
    /// The most evaluations of f one attempt makes (a step with a difference Jacobian).
    static constexpr std::size_t rhs_evals_per_attempt = stepper_type::rhs_evals_per_step;
    /// The evaluations before the first attempt when no step size is carried: f(t, y) and the first-step
    /// estimate's one.
    static constexpr std::size_t rhs_evals_to_start = 2;

    /// Tolerances 1e-6 (float: 1e-4), the default controller.
    rosenbrock_adaptive() noexcept
        : rosenbrock_adaptive(
              tolerances<State>::uniform(detail::default_tolerance<T>(), detail::default_tolerance<T>())) {}
    /// The given tolerances and controller settings (checked by settings_status() before any use).
    explicit rosenbrock_adaptive(const tolerances<State>& tol, const step_control<T>& control = {}) noexcept
        : settings(tol, control) {}

    /// Forgets the step size and the controller's memory.
    void restart() noexcept { ctl_.restart(); }
    /// Jacobians formed since construction (the system's own or by differences): one per step tried.
    step_count jacobian_evaluations() const noexcept { return tried_; }
    /// LU factorizations since construction: one per step tried.
    step_count factorizations() const noexcept { return tried_; }

    /// One attempted step from (t, y) toward t_end, never past it, landing exactly on t_end when the step
    /// reaches it (or within 1% of it, if that stays within max_step). Accepted: y and t advance. Rejected:
    /// y and t unchanged, the step size shrunk. Failures leave y and t as they were. Settings are the caller's
    /// to check first. An accepted step is given to sink(t_old, h, y_old, y_new) (rosenbrock_dense).
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
        T mag = ctl_.h;
        if (!(mag > T(0))) {
            State f0;
            detail::evaluate(f, t, y, f0);
            if (!detail::all_finite(f0)) return status::non_finite;
            mag = detail::first_step_size(f, t, y, f0, estimate_order, tol_, control_, rem, dir);
            if (!(mag > T(0))) return status::non_finite;
        }
        const detail::step_plan<T> p = detail::plan_step(control_, mag, rem);
        const bool last = p.last;
        const T h = last ? span : dir * p.mag;
        if (!last && detail::unresolved_step(h, t)) return status::step_too_small;
        State y_new = y;
        State err{};
        ++tried_;
        const status s = stepper_type{}.step(f, y_new, t, h, err);
        if (s != status::ok) return ctl_.retry_smaller(h, s, max_failures_in_a_row);
        T e = scaled_error_norm(err, y, y_new, tol_);
        if (!(e <= std::numeric_limits<T>::max())) e = std::numeric_limits<T>::max();
        const T habs = detail::abs_value(h);
        if (e <= T(1)) {
            T log_e;
            T next = ctl_.next_step(control_, estimate_order, habs, e, log_e);
            // A step shortened to land on t_end says nothing against the size planned, unless it asked for less.
            if (last && !(next < habs) && p.mag > next) next = p.mag;
            ctl_.accept(next, habs, log_e);
            sink(static_cast<const T&>(t), static_cast<const T&>(h), static_cast<const State&>(y),
                 static_cast<const State&>(y_new));
            detail::assign(y, y_new);
            t = last ? t_end : t + h;
            accepted = true;
            ++ctl_.accepted;
            return status::ok;
        }
        return ctl_.reject_error(control_, estimate_order, habs, e);
    }

private:
    using settings::control_;
    using settings::ctl_;
    using settings::tol_;
    step_count tried_ = 0;
};

}  // namespace odestep

#endif
