// SPDX-License-Identifier: BSL-1.0
// odestep: the course's form for stiff problems: an error-controlled engine (Radau 5(4), a Rosenbrock or SDIRK pair)
// behind the fixed-step stepper interface, one grid interval per call.
#ifndef ODESTEP_STIFF_SUBSTEPS_HPP
#define ODESTEP_STIFF_SUBSTEPS_HPP

#include <cstddef>

#include "../adaptive/adaptive_rk.hpp"
#include "../adaptive/control.hpp"
#include "../detail/ops.hpp"
#include "../detail/preflight.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../tables/implicit_rk.hpp"
#include "../tables/rosenbrock.hpp"
#include "radau5.hpp"
#include "rosenbrock_adaptive.hpp"
#include "sdirk_adaptive.hpp"

namespace odestep {

/// \brief The course's form for stiff problems: an error-controlled stiff engine as a stepper that looks like a
/// fixed-step one. `odestep::radau5_substeps<State>` (Radau 5(4), the first choice) and
/// `odestep::rodas4_substeps<State>` (a Rosenbrock pair) are its named forms.
///
/// `step(f, y, t, dt)` covers one interval of the caller's grid, [t, t + dt], with as many error-controlled
/// steps of `Engine` (odestep::radau5, odestep::rosenbrock_adaptive, odestep::sdirk_adaptive) as the tolerances ask for, the last
/// landing exactly on t + dt. What the engine carries (the step size; for Radau also the Jacobian, its
/// factorizations and the collocation polynomial) goes from one interval to the next (a step shortened to
/// land on the grid does not shrink the step size). It publishes the stepper trait set, so integrate,
/// integrate_n_steps and the event loops drive it as any stepper.
///
/// At most `max_attempts()` attempts (accepted or rejected) per interval, settable up to the compile-time
/// MaxAttempts; past it `status::substep_limit` with y back at the interval's start. Every other failure
/// (see the engine) also leaves y as it was given. ok means every internal step passed the error test.
/// `rhs_evals_per_step` is the worst case of one interval (MaxAttempts attempts): a constant bound, not the
/// typical cost.
///
///     odestep::radau5_substeps<state> s(odestep::tolerances<state>::uniform(1e-6, 1e-10));
///     auto r = odestep::integrate(s, odestep::with_jacobian(f, J), y, 0.0, 40.0, 0.1);
template <class Engine, std::size_t MaxAttempts = 1000>
class stiff_substeps : public detail::interval_cover<Engine, MaxAttempts> {
    using base = detail::interval_cover<Engine, MaxAttempts>;
    using State = typename Engine::state_type;

public:
    using state_type = State;                ///< the state, std::array<T, N>
    using value_type = value_type_t<State>;  ///< its scalar T
    using engine_type = Engine;              ///< the error-controlled engine inside

private:
    using T = value_type;

public:
    /// The order of the internal steps (over an interval the error is the tolerance's, not dt^order).
    static constexpr int order = engine_type::order;
    /// Stages of one internal step.
    static constexpr std::size_t stages = engine_type::stages;
    /// Solves equations in every step.
    static constexpr bool implicit = true;
    /// The most evaluations of f one interval can cost: f at its start and the first-step estimate, and
    /// MaxAttempts attempts at their worst.
    static constexpr std::size_t rhs_evals_per_step =
        1 + engine_type::rhs_evals_to_start + MaxAttempts * engine_type::rhs_evals_per_attempt;
    /// The compile-time cap on attempts per interval (the bound of rhs_evals_per_step).
    static constexpr std::size_t max_attempts_bound = MaxAttempts;
    /// The most Newton iterations one interval can make (0 for a Rosenbrock engine).
    static constexpr std::size_t newton_iterations_per_step = MaxAttempts * engine_type::max_newton_iterations;

    /// Tolerances 1e-6 (float: 1e-4), the engine's default controller, MaxAttempts attempts per interval.
    stiff_substeps() noexcept = default;
    /// The given tolerances and cap, the engine's default controller (all checked before any use).
    explicit stiff_substeps(const tolerances<State>& tol, std::size_t max_attempts = MaxAttempts) noexcept
        : base(max_attempts, tol) {}
    /// The given tolerances, controller settings and cap (all checked before any use).
    stiff_substeps(const tolerances<State>& tol, const step_control<T>& control,
                   std::size_t max_attempts = MaxAttempts) noexcept
        : base(max_attempts, tol, control) {}

    /// The cap on attempts per interval.
    std::size_t max_attempts() const noexcept { return this->cap_; }
    /// Sets the cap on attempts per interval: status::invalid_setting (nothing changed) outside
    /// [1, MaxAttempts].
    status set_max_attempts(std::size_t n) noexcept { return this->set_cap(n); }
};

/// Radau 5(4) (odestep::radau5) one grid interval per step: the first choice for stiff problems.
template <class State, std::size_t MaxAttempts = 1000>
using radau5_substeps = stiff_substeps<radau5<State>, MaxAttempts>;
/// Rodas4 with its embedded order 3 solution (odestep::rosenbrock_adaptive) one grid interval per step.
template <class State, std::size_t MaxAttempts = 1000>
using rodas4_substeps = stiff_substeps<rosenbrock_adaptive<tables::rodas4, State>, MaxAttempts>;
/// RODAS3 with its embedded order 2 solution, one grid interval per step.
template <class State, std::size_t MaxAttempts = 1000>
using rodas3_substeps = stiff_substeps<rosenbrock_adaptive<tables::rodas3, State>, MaxAttempts>;
/// Hairer & Wanner's SDIRK4 with its embedded order 3 solution (odestep::sdirk_adaptive), one grid interval per
/// step: one N x N factorization per step (Radau's are one real and one complex), five Newton solves.
template <class State, std::size_t MaxAttempts = 1000>
using sdirk4_substeps = stiff_substeps<sdirk_adaptive<tables::sdirk4, State>, MaxAttempts>;

}  // namespace odestep

#endif
