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
// any other status leaves y the last observed state, bit for bit, at r.t; no ok run from an f that gave NaN;
// no call of f after it gave NaN or Inf. (3) The solution object (integrate_adaptive into a solution of 16
// steps): the solution's span ends at r.t with y there bit for bit (storage_full when it filled first), every
// query inside the span ok and finite or non_finite, outside it invalid_time with out untouched. (4)
// adaptive_sampler with drawn times one at a time: a time going back or out of [t0, t1] is refused with
// invalid_time and nothing evaluated; each call within rhs_evals_to_start + max_attempts * (attempt +
// interpolant) evaluations; ok outputs finite; a failure leaves y_out untouched.
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
    // One read per statement (a call's arguments are evaluated in an unspecified order, and g++ and clang
    // differ): the order is the one tests/fuzz/make_seeds.py writes.
    if (in.flag()) {
        const T relative = in.number<T>();
        const T absolute = in.number<T>();
        return odestep::tolerances<state<T>>::uniform(relative, absolute);
    }
    const state<T> relative{in.number<T>(), in.number<T>()};  // a braced list is read left to right
    const state<T> absolute{in.number<T>(), in.number<T>()};
    return odestep::tolerances<state<T>>::per_component(relative, absolute);
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
    const auto tol = draw_tolerances<T>(in);
    const auto control = draw_control<T>(in);
    engine_t engine(tol, control);
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
    bool gave_non_finite = false;
    unsigned after_non_finite = 0;
    auto rhs = [&](T t, const S& x) {
        if (gave_non_finite) ++after_non_finite;
        const S out = f(t, x);
        if (!finite(out)) gave_non_finite = true;
        return out;
    };
    const auto r = sample ? odestep::integrate_times(engine, rhs, y, t0, times, check, max_attempts)
                          : odestep::integrate_adaptive(engine, rhs, y, t0, t1, check, max_attempts);
    ODESTEP_FUZZ_CHECK(after_non_finite == 0, "f called again after it gave NaN or Inf");
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

// --- (3) the solution object, (4) adaptive_sampler ---------------------------------------------------------------

template <class Method, class T>
void run_solution(reader& in) {
    using S = state<T>;
    using engine_t = odestep::adaptive_rk<Method, S>;
    constexpr std::size_t capacity = 16;
    script<T, 2> f;
    f.read(in);
    const auto tol = draw_tolerances<T>(in);
    const auto control = draw_control<T>(in);
    engine_t engine(tol, control);
    if (in.flag()) engine.set_step_size(in.number<T>());
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const T t1 = in.flag() ? in.number<T>() : t0 + in.number<T>();
    const odestep::step_count max_attempts = in.byte() % 200;
    const S initial = y;
    odestep::solution<Method, S, capacity> sol;
    auto rhs = [&f](T t, const S& x) { return f(t, x); };
    const auto r = odestep::integrate_adaptive(engine, rhs, y, t0, t1, sol, max_attempts);
    ODESTEP_FUZZ_TRACE("solution: %s t=%.17g steps=%llu held %zu\n", odestep::to_string(r.status),
                       static_cast<double>(r.t), static_cast<unsigned long long>(r.steps), sol.size());
    ODESTEP_FUZZ_CHECK(valid(r.status), "a status outside the enum");
    const std::uint64_t bound =
        engine_t::rhs_evals_to_start +
        max_attempts * (engine_t::rhs_evals_per_attempt + odestep::dense_step<Method, S>::rhs_evals_to_complete);
    ODESTEP_FUZZ_CHECK(f.evaluations <= bound, "more evaluations than the published bound");
    S out{T(7), T(7)};
    if (rejects_argument(r.status)) {
        ODESTEP_FUZZ_CHECK(f.evaluations == 0 && r.steps == 0 && same_bits(y, initial), "a rejected argument ran");
        ODESTEP_FUZZ_CHECK(sol(t0, out) == odestep::status::invalid_time, "a refused run left a solution");
        return;
    }
    ODESTEP_FUZZ_CHECK(sol.size() <= capacity && sol.size() <= r.steps, "a solution holds more than its steps");
    ODESTEP_FUZZ_CHECK(sol.t_first() == t0, "a solution that does not start at t0");
    ODESTEP_FUZZ_CHECK(r.status != odestep::status::storage_full || sol.full(), "storage_full, and room left");
    ODESTEP_FUZZ_CHECK(r.status != odestep::status::ok || r.t == t1, "an ok run that did not end at t1");
    // The solution ends where y is, except after an interpolant that could not be completed (non_finite).
    if (sol.t_last() == r.t) {
        ODESTEP_FUZZ_CHECK(sol(r.t, out) == odestep::status::ok && same_bits(out, y),
                           "the solution's end is not y at r.t");
    } else {
        ODESTEP_FUZZ_CHECK(r.status == odestep::status::non_finite, "a solution that does not end at r.t");
    }
    const bool forward = !(t1 < t0);
    const T ends[2] = {sol.t_first(), sol.t_last()};
    for (int k = 0; k < 8; ++k) {
        const T t = k < 6 ? ends[0] + (ends[1] - ends[0]) * static_cast<T>(k) / T(5) : in.number<T>();
        S u{T(7), T(7)};
        const odestep::status q = sol(t, u);
        const bool inside =
            std::isfinite(t) && (forward ? (t >= ends[0] && t <= ends[1]) : (t <= ends[0] && t >= ends[1]));
        if (inside) {
            ODESTEP_FUZZ_CHECK(q == odestep::status::ok || q == odestep::status::non_finite,
                               "a query in the span refused");
        } else {
            ODESTEP_FUZZ_CHECK(q == odestep::status::invalid_time, "a query outside the span not invalid_time");
        }
        if (q == odestep::status::ok)
            ODESTEP_FUZZ_CHECK(finite(u) || (t == ends[0] && same_bits(u, initial)), "a query gave a state not finite");
        else
            ODESTEP_FUZZ_CHECK(u[0] == T(7) && u[1] == T(7), "a refused query wrote its output");
    }
}

template <class Method, class T>
void run_sampler(reader& in) {
    using S = state<T>;
    using engine_t = odestep::adaptive_rk<Method, S>;
    script<T, 2> f;
    f.read(in);
    const auto tol = draw_tolerances<T>(in);
    const auto control = draw_control<T>(in);
    engine_t engine(tol, control);
    S y{in.number<T>(), in.number<T>()};
    const T t0 = in.number<T>();
    const T t1 = in.flag() ? in.number<T>() : t0 + in.number<T>();
    const odestep::step_count max_attempts = in.byte() % 64;
    odestep::adaptive_sampler<Method, S> sampler(engine, t0, y, t1, max_attempts);
    const std::uint64_t per_call =
        engine_t::rhs_evals_to_start +
        max_attempts * (engine_t::rhs_evals_per_attempt + odestep::dense_step<Method, S>::rhs_evals_to_complete);
    const bool forward = !(t1 < t0);
    T previous = t0;
    bool failed = false;
    for (int k = 0; k < 6 && !failed; ++k) {
        const T t = in.flag() ? in.number<T>() : previous + in.number<T>();
        S u{T(7), T(7)};
        const unsigned before = f.evaluations;
        const odestep::status s = sampler.advance_to(f, t, u);
        ODESTEP_FUZZ_TRACE("advance_to %.17g: %s\n", static_cast<double>(t), odestep::to_string(s));
        ODESTEP_FUZZ_CHECK(valid(s), "a status outside the enum");
        ODESTEP_FUZZ_CHECK(f.evaluations - before <= per_call, "a call made more evaluations than its bound");
        const bool in_order = std::isfinite(t) && std::isfinite(t0) && std::isfinite(t1) &&
                              (forward ? (t >= previous && t <= t1) : (t <= previous && t >= t1));
        if (!in_order && engine.settings_status() == odestep::status::ok && max_attempts > 0)
            ODESTEP_FUZZ_CHECK(s == odestep::status::invalid_time && f.evaluations == before,
                               "a time out of order or out of the span not refused");
        if (s == odestep::status::ok) {
            ODESTEP_FUZZ_CHECK(in_order, "an ok output at a time out of order");
            ODESTEP_FUZZ_CHECK(finite(u) || (t == t0 && same_bits(u, y)), "an output state not finite");
            previous = t;
        } else {
            ODESTEP_FUZZ_CHECK(u[0] == T(7) && u[1] == T(7), "a failed call wrote its output");
            failed = s != odestep::status::invalid_time && s != odestep::status::substep_limit;
        }
    }
}

template <class Method, class T>
struct free_run {};
template <class Method, class T>
struct solution_run {};
template <class Method, class T>
struct sampler_run {};

// The selector byte is read modulo entries::size: adding an entry changes what a committed regression input
// with a selector byte >= the old size runs (regression-12's byte was moved from 90 to 88 when the solution and
// sampler entries came: 88 % 19 is its old entry, free_run<DP 5(4), float>). Check regression-* when adding.
using entries =
    list<odestep::adaptive_substeps<odestep::tables::bogacki_shampine32, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::cash_karp54, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::dormand_prince54, sd, 16>,
         odestep::adaptive_substeps<odestep::tables::dormand_prince54, sf, 16>, odestep::backward_euler<sd>,
         odestep::sdirk3<sd>, odestep::rodas3<sd>, odestep::backward_euler<sf>,
         free_run<odestep::tables::dormand_prince54, double>, free_run<odestep::tables::cash_karp54, double>,
         free_run<odestep::tables::bogacki_shampine32, double>, free_run<odestep::tables::dop853, double>,
         free_run<odestep::tables::dormand_prince54, float>, solution_run<odestep::tables::dormand_prince54, double>,
         solution_run<odestep::tables::dop853, double>, solution_run<odestep::tables::cash_karp54, double>,
         sampler_run<odestep::tables::dormand_prince54, double>, sampler_run<odestep::tables::dop853, double>,
         sampler_run<odestep::tables::bogacki_shampine32, float>>;

template <class Method, class T>
void run_entry(reader& in, free_run<Method, T>*) {
    run_free<Method, T>(in);
}
template <class Method, class T>
void run_entry(reader& in, solution_run<Method, T>*) {
    run_solution<Method, T>(in);
}
template <class Method, class T>
void run_entry(reader& in, sampler_run<Method, T>*) {
    run_sampler<Method, T>(in);
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
