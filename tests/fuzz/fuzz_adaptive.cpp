// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the adaptive and the stiff entry points. (1) The course's adaptive stepper
// (adaptive_substeps over Bogacki-Shampine 3(2), Cash-Karp 5(4) and Dormand-Prince 5(4), tolerances and the
// substep cap drawn) and the implicit and Rosenbrock steppers (backward Euler, SDIRK 3, RODAS3; the Jacobian
// by differences) under integrate and integrate_n_steps, checked as fuzz_loops checks the explicit steppers
// (fuzz_support.hpp, loop_check; the bound per step is the stepper's published rhs_evals_per_step).
// (2) The free-running loop integrate_adaptive and integrate_times with drawn tolerances, controller
// settings, span, output times and cap on attempts, checked against docs/adaptive.md's promises: one status of
// the enum; after a rejected argument nothing evaluated, observed or touched; no more evaluations than
// rhs_evals_to_start + max_attempts * rhs_evals_per_attempt; observer times finite, monotone, inside the span
// (integrate_times: exactly the times asked for, in order); an ok run ends at t1 with the last observed state;
// any other status leaves y the last observed state, bit for bit, at r.t; no ok run from an f that gave NaN.
#include <odestep/adaptive.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

template <class T>
using state = std::array<T, 2>;
using sd = state<double>;
using sf = state<float>;

template <class T>
odestep::tolerances<state<T>> draw_tolerances(reader& in) {
    if (in.flag()) return odestep::tolerances<state<T>>::uniform(in.number<T>(), in.number<T>());
    return odestep::tolerances<state<T>>::per_component(state<T>{in.number<T>(), in.number<T>()},
                                                        state<T>{in.number<T>(), in.number<T>()});
}

template <class T>
odestep::step_control<T> draw_control(reader& in) {
    odestep::step_control<T> c;
    if (in.flag()) {  // mostly the defaults, sometimes anything
        c.safety = in.number<T>();
        c.min_factor = in.number<T>();
        c.max_factor = in.number<T>();
        c.alpha = in.number<T>();
        c.beta = in.number<T>();
        c.max_step = in.number<T>();
    }
    return c;
}

// --- (1) steppers under the fixed-grid loops ----------------------------------------------------------------

template <class Stepper>
Stepper make_stepper(reader& in) {
    using T = typename Stepper::value_type;
    if constexpr (Stepper::implicit) {
        return Stepper{};
    } else {
        const auto tol = draw_tolerances<T>(in);
        const auto control = draw_control<T>(in);
        // 0 and past the bound: invalid_setting from the loop, before anything runs
        return Stepper(tol, control, in.index(Stepper::max_substeps_bound + 2));
    }
}

template <class Stepper>
void run_grid(reader& in) {
    using T = typename Stepper::value_type;
    using S = typename Stepper::state_type;
    script<T, 2> f;
    f.read(in);
    Stepper stepper = make_stepper<Stepper>(in);
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const T dt = in.number<T>();
    const bool n_steps = in.flag();
    const T t1 = n_steps ? T(0) : draw_t1(in, t0, dt);
    // (Small counts only: a step of an adaptive stepper whose t + dt rounds to t is empty and evaluates nothing,
    // so 2^64 of them would take that long, within their bound of rhs_evals_per_step each.)
    const std::uint64_t n = n_steps ? in.byte() % 64 : 0;
    const T t_end = n_steps ? t0 + static_cast<T>(n) * dt : t1;
    // A dt below the rounding of t0 makes every adaptive interval empty (t + dt == t): ok steps that evaluate
    // nothing, so f's budget cannot end a run of up to 2^62 of them (bounded, but not in a fuzzer's second).
    // integrate_n_steps draws at most 63 steps, so only integrate needs the guard.
    if constexpr (!Stepper::implicit)
        if (!n_steps && std::isfinite(t0) && t0 + dt == t0 && dt != T(0)) return;
    loop_check<T, S, 1, script<T, 2>> check{&f, Stepper::rhs_evals_per_step, t0, dt, t_end, false, {y}};
    auto rhs = [&f](T t, const S& x) { return f(t, x); };
    const auto r = n_steps ? odestep::integrate_n_steps(stepper, rhs, y, t0, dt, n, check)
                           : odestep::integrate(stepper, rhs, y, t0, t1, dt, check);
    check.finish(r, {y}, n_steps, n);
}

// --- (2) the free-running loops ------------------------------------------------------------------------------

template <class T, class S>
struct free_check {
    script<T, 2>* f;
    T t0;
    T t1;
    S initial;
    S last{};
    T last_t = T(0);
    std::uint64_t observed = 0;
    const T* times = nullptr;  // integrate_times: the times asked for
    std::size_t count = 0;

    bool along(T a, T b) const { return t1 < t0 ? a >= b : a <= b; }

    void operator()(T t, const S& y) {
        ODESTEP_FUZZ_TRACE("observe #%llu t=%.17g y0=%.17g (evaluations %u)\n",
                           static_cast<unsigned long long>(observed), static_cast<double>(t), static_cast<double>(y[0]),
                           f->since);
        ODESTEP_FUZZ_CHECK(std::isfinite(t), "an observer time that is not finite");
        if (times != nullptr) {
            ODESTEP_FUZZ_CHECK(observed < count, "more observations than output times");
            ODESTEP_FUZZ_CHECK(same_scalar(t, times[observed]), "an observation not at the next output time");
        } else if (observed == 0) {  // integrate_adaptive: (t0, y0) first, before any evaluation
            ODESTEP_FUZZ_CHECK(t == t0 && same_bits(y, initial), "the first observation is not (t0, y0)");
            ODESTEP_FUZZ_CHECK(f->evaluations == 0, "an evaluation before the first observation");
        }
        if (observed > 0) ODESTEP_FUZZ_CHECK(along(last_t, t), "observer times not monotone");
        ODESTEP_FUZZ_CHECK(along(t0, t) && along(t, t1), "an observer time outside [t0, t1]");
        // (The initial state, observed at t0, is the caller's: it may be anything.)
        ODESTEP_FUZZ_CHECK(finite(y) || (t == t0 && same_bits(y, initial)), "an observed state not finite");
        if (times == nullptr && observed > 0)
            ODESTEP_FUZZ_CHECK(!f->non_finite_since, "an accepted step whose right-hand side returned NaN or Inf");
        f->mark();
        last = y;
        last_t = t;
        ++observed;
    }
};

template <class Method, class T>
void run_free(reader& in) {
    using S = state<T>;
    using engine_t = odestep::adaptive_rk<Method, S>;
    script<T, 2> f;
    f.read(in);
    engine_t engine(draw_tolerances<T>(in), draw_control<T>(in));
    if (in.flag()) engine.set_step_size(in.number<T>());
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const bool sample = in.flag();
    std::array<T, 4> times{};
    T t1;
    if (sample) {
        T t = t0;
        for (auto& ti : times) {
            t = in.flag() ? in.number<T>() : t + in.number<T>();
            ti = t;
        }
        t1 = times[times.size() - 1];
    } else {
        t1 = in.flag() ? in.number<T>() : t0 + in.number<T>();
    }
    const odestep::step_count max_attempts = in.byte() % 200;
    const S initial = y;
    free_check<T, S> check{&f, t0, t1, y};
    if (sample) {
        check.times = times.data();
        check.count = times.size();
    }
    auto rhs = [&f](T t, const S& x) { return f(t, x); };
    const auto r = sample ? odestep::integrate_times(engine, rhs, y, t0, times, check, max_attempts)
                          : odestep::integrate_adaptive(engine, rhs, y, t0, t1, check, max_attempts);
    ODESTEP_FUZZ_TRACE(
        "result %s t=%.17g steps=%llu evaluations %u (%zu stages, fsal %d, max_attempts %llu, "
        "rejected %llu)\n",
        odestep::to_string(r.status), static_cast<double>(r.t), static_cast<unsigned long long>(r.steps), f.evaluations,
        engine_t::stages, int(engine_t::fsal), static_cast<unsigned long long>(max_attempts),
        static_cast<unsigned long long>(engine.rejected_steps()));
    ODESTEP_FUZZ_CHECK(valid(r.status), "a status outside the enum");
    // integrate_times completes the interpolant in a step with an output time inside: its evaluations too.
    const std::uint64_t per_attempt =
        engine_t::rhs_evals_per_attempt + (sample ? odestep::dense_step<Method, S>::rhs_evals_to_complete : 0);
    const std::uint64_t bound = engine_t::rhs_evals_to_start + max_attempts * per_attempt;
    ODESTEP_FUZZ_CHECK(f.evaluations <= bound, "more evaluations than the published bound");
    if (rejects_argument(r.status)) {
        ODESTEP_FUZZ_CHECK(f.evaluations == 0 && check.observed == 0 && r.steps == 0,
                           "a rejected argument, and yet something was evaluated or observed");
        ODESTEP_FUZZ_CHECK(same_bits(y, initial) && same_scalar(r.t, t0), "a rejected argument, and y or t moved");
        return;
    }
    ODESTEP_FUZZ_CHECK(std::isfinite(r.t) && (finite(y) || same_bits(y, initial)),
                       "a run that left a time or a state not finite");
    if (r.status == odestep::status::ok) {
        ODESTEP_FUZZ_CHECK(r.t == t1, "an ok run that did not end at t1");
        ODESTEP_FUZZ_CHECK(check.observed > 0 && same_bits(y, check.last), "ok, and y is not the last observed state");
        if (sample) ODESTEP_FUZZ_CHECK(check.observed == check.count, "ok, and an output time was not observed");
        return;
    }
    if (!sample) {
        ODESTEP_FUZZ_CHECK(r.t == check.last_t && same_bits(y, check.last),
                           "a failed run whose y is not the last observed state at r.t");
        ODESTEP_FUZZ_CHECK(r.steps + 1 == check.observed, "steps do not match the observations");
    }
}

template <class Method, class T>
struct free_run {};

using entries =
    list<odestep::adaptive_substeps<odestep::tables::bogacki_shampine32, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::cash_karp54, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::dormand_prince54, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::dormand_prince54, sf, 16>, odestep::backward_euler<sd>,
         odestep::sdirk3<sd>, odestep::rodas3<sd>, odestep::backward_euler<sf>,
         free_run<odestep::tables::dormand_prince54, double>, free_run<odestep::tables::cash_karp54, double>,
         free_run<odestep::tables::bogacki_shampine32, double>, free_run<odestep::tables::dop853, double>,
         free_run<odestep::tables::dormand_prince54, float>>;

template <class Method, class T>
void run_entry(reader& in, free_run<Method, T>*) {
    run_free<Method, T>(in);
}
template <class E>
void run_entry(reader& in, E*) {
    run_grid<E>(in);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    dispatch(in.index(entries::size), entries{}, [&](auto e) {
        using E = typename decltype(e)::t;
        run_entry(in, static_cast<E*>(nullptr));
    });
    return 0;
}
