// SPDX-License-Identifier: BSL-1.0
// odestep: what a run did, counted: the one counts struct every result holds, and the counting the loops use to
// fill it (derived where the work is fixed by construction, counted one by one where it is not).
#ifndef ODESTEP_COUNTS_HPP
#define ODESTEP_COUNTS_HPP

#include <type_traits>
#include <utility>

#include "detail/grid_clock.hpp"
#include "state.hpp"
#include "system.hpp"

namespace odestep {

/// \brief What one call of a driving loop did (SciPy's nfev, njev, nlu; SUNDIALS' nfe, nje, nni, nsetups,
/// nge): every result holds one as `r.counts`. A member is zero for work the method does not do.
///
/// - rhs_evals: evaluations of f (Newtonian: of the acceleration a; Boris: of the fields), all of them: the
///   steps, the differences of a Jacobian, the re-steps and Hermite slopes of event location, the dense
///   output's extra stages, the first-step estimate of an adaptive run.
/// - jacobian_evals: Jacobians formed, by the system's own `jacobian` or by differences (whose N evaluations of
///   f are in rhs_evals too).
/// - event_evals: evaluations of event functions g, each g of a set counted once per call (the start's too).
/// - factorizations: LU factorizations of an iteration matrix (Radau IIA 5: a real and a complex one per
///   decomposition, two, as SciPy's nlu counts them).
/// - newton_iterations: Newton iterations: of the fixed-step implicit steppers (implicit_rk: every solve's,
///   a fully implicit table's all stages at once, a diagonally implicit one's stage by stage) and of the
///   error-controlled engines (radau5, the SDIRK pairs); zero for the methods without a Newton solve.
/// - accepted_steps: steps that stand: a fixed-grid loop's completed grid steps; an adaptive or stiff engine's
///   accepted steps (adaptive_substeps / stiff_substeps: their engine's, inside the grid steps).
/// - rejected_steps: attempts an error-controlled engine rejected (zero on a fixed grid).
/// - firings: event firings.
struct counts {
    step_count rhs_evals = 0;          ///< evaluations of f (a, fields)
    step_count jacobian_evals = 0;     ///< Jacobians formed (the system's own or by differences)
    step_count event_evals = 0;        ///< evaluations of event functions g
    step_count factorizations = 0;     ///< LU factorizations
    step_count newton_iterations = 0;  ///< Newton iterations (implicit_rk, radau5, the SDIRK pairs)
    step_count accepted_steps = 0;     ///< steps that stand
    step_count rejected_steps = 0;     ///< attempts rejected by an error-controlled engine
    step_count firings = 0;            ///< event firings
};

namespace detail {

// Evaluations counted one by one, by a counting_system around the caller's system, and the Newton iterations
// a fixed-step implicit stepper reports through it (count_newton_iteration).
struct evaluation_tally {
    step_count rhs = 0;
    step_count jacobian = 0;
    step_count newton = 0;
};

// The caller's system with every call counted: called as the system is called (either form, first order or
// Newtonian, any arguments), and with its `jacobian` member forwarded (and counted) when it has one, so that
// every compile-time detection (in place or returning, own Jacobian or not) sees what it sees on the system.
template <class F>
struct counting_system {
    F& f;
    evaluation_tally& tally;

    template <class... A>
    constexpr auto operator()(A&&... a) const -> decltype(std::declval<F&>()(std::forward<A>(a)...)) {
        ++tally.rhs;
        return f(std::forward<A>(a)...);
    }
    template <class... A, class G = F>  // (G: the member is looked up at the call, not with the class)
    constexpr auto jacobian(A&&... a) const -> decltype(std::declval<G&>().jacobian(std::forward<A>(a)...)) {
        ++tally.jacobian;
        return f.jacobian(std::forward<A>(a)...);
    }
};
template <class F>
counting_system<F> counting(F& f, evaluation_tally& tally) noexcept {
    return counting_system<F>{f, tally};
}

// One Newton iteration of a fixed-step implicit stepper (implicit_rk), counted when the loop gave it a
// counting_system; on any other system nothing (a step called directly costs no counter).
template <class F>
constexpr void count_newton_iteration(const F&) noexcept {}
template <class F>
constexpr void count_newton_iteration(const counting_system<F>& f) noexcept {
    ++f.tally.newton;
}

// A stepper whose every step call makes exactly rhs_evals_per_step evaluations (trait exact_rhs_evals): its
// loops derive the count (calls x rhs_evals_per_step) and leave f uncounted, at no cost per step.
template <class S, class = void>
struct has_exact_rhs_evals : std::false_type {};
template <class S>
struct has_exact_rhs_evals<S, std::void_t<decltype(S::exact_rhs_evals)>> : std::bool_constant<S::exact_rhs_evals> {};
template <class S>
inline constexpr bool exact_rhs_evals_v = has_exact_rhs_evals<std::remove_cv_t<std::remove_reference_t<S>>>::value;

template <class S, class = void>
struct has_implicit_work : std::false_type {};
template <class S>
struct has_implicit_work<S, std::void_t<decltype(S::jacobians_per_step), decltype(S::factorizations_per_step)>>
    : std::true_type {};

// The Jacobians and factorizations of `calls` step calls of a fixed-step stepper that publishes
// jacobians_per_step and factorizations_per_step (implicit_rk, rosenbrock): each call forms them, the system's
// own Jacobian (own_jacobian: counted by the tally) or one by differences; the Newton iterations the tally
// was told of.
template <class Stepper>
void add_implicit_work(counts& c, step_count calls, const evaluation_tally& tally, bool own_jacobian) noexcept {
    using S = std::remove_cv_t<std::remove_reference_t<Stepper>>;
    c.jacobian_evals = tally.jacobian;
    c.newton_iterations = tally.newton;
    if constexpr (has_implicit_work<S>::value) {
        if (!own_jacobian) c.jacobian_evals = calls * static_cast<step_count>(S::jacobians_per_step);
        c.factorizations = calls * static_cast<step_count>(S::factorizations_per_step);
    } else {
        (void)calls, (void)own_jacobian;
    }
}

// What an error-controlled engine (adaptive_rk, radau5, rosenbrock_adaptive) has counted since construction;
// the loops report the difference over their call.
template <class E, class = void>
struct has_jacobian_count : std::false_type {};
template <class E>
struct has_jacobian_count<E, std::void_t<decltype(std::declval<const E&>().jacobian_evaluations())>> : std::true_type {
};
template <class E, class = void>
struct has_factorization_count : std::false_type {};
template <class E>
struct has_factorization_count<E, std::void_t<decltype(std::declval<const E&>().factorizations())>> : std::true_type {};
template <class E, class = void>
struct has_newton_count : std::false_type {};
template <class E>
struct has_newton_count<E, std::void_t<decltype(std::declval<const E&>().newton_iterations())>> : std::true_type {};

template <class Engine>
counts engine_counts(const Engine& e) noexcept {
    counts c;
    c.accepted_steps = e.accepted_steps();
    c.rejected_steps = e.rejected_steps();
    if constexpr (has_jacobian_count<Engine>::value) c.jacobian_evals = e.jacobian_evaluations();
    if constexpr (has_factorization_count<Engine>::value) c.factorizations = e.factorizations();
    if constexpr (has_newton_count<Engine>::value) c.newton_iterations = e.newton_iterations();
    return c;
}

// The engine's work over one call (after - before), with f and the system's own J from the tally. An engine
// that counts its Jacobians (own or by differences) reports those; otherwise the tally's own-J calls.
template <class Engine>
counts engine_work(const Engine& e, const counts& before, const evaluation_tally& tally) noexcept {
    counts c = engine_counts(e);
    c.accepted_steps -= before.accepted_steps;
    c.rejected_steps -= before.rejected_steps;
    c.factorizations -= before.factorizations;
    c.newton_iterations -= before.newton_iterations;
    if constexpr (has_jacobian_count<Engine>::value) {
        c.jacobian_evals -= before.jacobian_evals;
    } else {
        c.jacobian_evals = tally.jacobian;
    }
    c.rhs_evals = tally.rhs;
    return c;
}

// A stepper that runs an error-controlled engine inside each grid step (adaptive_substeps, stiff_substeps)
// exposes it as engine(): its loops report the engine's work.
template <class S, class = void>
struct has_engine : std::false_type {};
template <class S>
struct has_engine<S, std::void_t<decltype(std::declval<const S&>().engine().accepted_steps())>> : std::true_type {};

}  // namespace detail

}  // namespace odestep

#endif
