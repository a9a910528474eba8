// SPDX-License-Identifier: BSL-1.0
// Fuzz target: the C API (include/odestep/odestep.h, src/), double, as C firmware calls it: the single steps
// (plain, with error estimates, Newtonian, velocity Verlet's caller-kept form) in sequences of up to 6 calls on
// one stepper, and the two loops, with every method, a state size n from 0 to ODESTEP_C_MAX_STATES + 1, null
// pointers where the header allows none, a stepper used before odestep_stepper_init_d, and a right-hand side
// drawn as fuzz_support.hpp's script (padded to the library's maximum size). Checked against the header's
// promises: one status of the enum; after a rejected argument (invalid_time, invalid_step, wrong_direction,
// too_many_steps, step_mismatch, invalid_setting) nothing evaluated and y, x, v, acc and error untouched; after
// non_finite the state unchanged; no ok step from f's NaN or Inf; no step over odestep_method_info_d's
// rhs_evals_per_step; a loop's observer at t0 first, then monotone finite times, ending on t1 when ok; a failed
// loop's state the last one observed, at run.t. Built with src/*.cpp (scripts/fuzz.sh).
#include <odestep/odestep.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_support.hpp"

namespace {

using namespace odestep_fuzz;

constexpr std::size_t M = ODESTEP_C_MAX_STATES;
using buffer = std::array<double, M>;
using f_script = script<double, M>;

const odestep_method_d* const methods[] = {&odestep_euler_d,
                                           &odestep_euler_richardson_d,
                                           &odestep_heun_d,
                                           &odestep_rk4_d,
                                           &odestep_bs32_d,
                                           &odestep_dp54_d,
                                           &odestep_dop853_d,
                                           &odestep_ab4_d,
                                           &odestep_abm4_d,
                                           &odestep_euler_cromer_d,
                                           &odestep_velocity_verlet_d,
                                           &odestep_forest_ruth_d};

bool valid_c(odestep_status s) { return std::strcmp(odestep_status_name(s), "unknown") != 0; }

bool rejects(odestep_status s) {
    return s == ODESTEP_INVALID_TIME || s == ODESTEP_INVALID_STEP || s == ODESTEP_WRONG_DIRECTION ||
           s == ODESTEP_TOO_MANY_STEPS || s == ODESTEP_STEP_MISMATCH || s == ODESTEP_INVALID_SETTING ||
           s == ODESTEP_INVALID_TOLERANCE;
}

// The script's f over the first n components (the rest zero), as the C callbacks see it. The script's own
// note of values that were not finite covers all M components; the library sees only n of them, so the
// callback notes its own (into the script's counters, which the checks read).
struct context {
    f_script* f;
    std::size_t n;
};
void rhs(double t, const double* y, double* dydt, void* ctx) {
    auto* c = static_cast<context*>(ctx);
    buffer in{};
    for (std::size_t i = 0; i < c->n; ++i) in[i] = y[i];
    const bool before = c->f->non_finite_since;
    const buffer out = (*c->f)(t, in);
    c->f->non_finite_since = before;
    for (std::size_t i = 0; i < c->n; ++i) {
        dydt[i] = out[i];
        if (!std::isfinite(out[i])) c->f->non_finite_since = true;
    }
}
void accel(double t, const double* x, double* a, void* ctx) { rhs(t, x, a, ctx); }

bool same(const buffer& a, const buffer& b) { return std::memcmp(a.data(), b.data(), sizeof(a)) == 0; }
bool finite_n(const double* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(p[i])) return false;
    return true;
}
buffer draw_state(reader& in, std::size_t n) {
    buffer b{};
    for (std::size_t i = 0; i < n && i < M; ++i) b[i] = in.number<double>();
    return b;
}

// The observer of both loops: what it saw, checked as it goes.
struct watch {
    f_script* f;
    std::size_t n;
    double t0;
    double dt;
    std::size_t bound;
    std::uint64_t observed = 0;
    double last_t = 0;
    buffer last_x{};
    buffer last_v{};

    void see(double t, const double* x, const double* v) {
        ODESTEP_FUZZ_CHECK(std::isfinite(t), "an observer time that is not finite");
        if (observed == 0) {
            ODESTEP_FUZZ_CHECK(t == t0 && f->since == 0, "the first observation is not at t0 before any evaluation");
        } else {
            ODESTEP_FUZZ_CHECK(dt > 0 ? t >= last_t : t <= last_t, "observer times not monotone");
            ODESTEP_FUZZ_CHECK(f->since <= bound, "a step made more evaluations than its published bound");
            ODESTEP_FUZZ_CHECK(!f->non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
            ODESTEP_FUZZ_CHECK(finite_n(x, n) && (v == nullptr || finite_n(v, n)), "an observed state not finite");
        }
        f->mark();
        last_t = t;
        last_x = buffer{};
        last_v = buffer{};
        for (std::size_t i = 0; i < n; ++i) {
            last_x[i] = x[i];
            if (v != nullptr) last_v[i] = v[i];
        }
        ++observed;
    }
};
void observe_first(double t, const double* y, void* ctx) { static_cast<watch*>(ctx)->see(t, y, nullptr); }
void observe_newton(double t, const double* x, const double* v, void* ctx) { static_cast<watch*>(ctx)->see(t, x, v); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    reader in(data, size);
    f_script f;
    f.read(in);
    const odestep_method_d* method = methods[in.index(sizeof(methods) / sizeof(methods[0]))];
    odestep_method_info info{};
    ODESTEP_FUZZ_CHECK(odestep_method_info_d(method, &info) == ODESTEP_OK, "method_info refused a method");
    const std::size_t n = in.index(M + 2);  // 0 and M + 1 are refused
    context ctx{&f, n};
    const bool null_f = in.byte() == 255;
    odestep_system_d system{null_f ? nullptr : rhs, &ctx, n};
    odestep_newton_d newton{null_f ? nullptr : accel, &ctx, n};
    odestep_stepper_d stepper;
    std::memset(&stepper, 0, sizeof(stepper));
    if (in.byte() != 255) ODESTEP_FUZZ_CHECK(odestep_stepper_init_d(&stepper, method) == ODESTEP_OK, "init refused");
    buffer x = draw_state(in, n);
    buffer v = draw_state(in, n);
    const std::size_t evals_bound = info.rhs_evals_per_step;

    if (in.flag()) {  // a loop
        const double t0 = in.number<double>();
        const double dt = in.number<double>();
        const double t1 = in.index(2) == 0 ? in.number<double>() : t0 + double(in.byte() % 64) * dt;
        watch w{&f, n, t0, dt, evals_bound};
        odestep_run_d run{-1.0, 77, {}};
        const buffer x0 = x;
        const buffer v0 = v;
        const odestep_status s =
            info.newtonian != 0 && in.flag()
                ? odestep_integrate_newton_d(&stepper, &newton, x.data(), v.data(), t0, t1, dt, observe_newton, &w,
                                             &run)
                : odestep_integrate_d(&stepper, &system, x.data(), t0, t1, dt, observe_first, &w, &run);
        ODESTEP_FUZZ_CHECK(valid_c(s), "a status outside the enum");
        if (rejects(s) && w.observed == 0) {
            ODESTEP_FUZZ_CHECK(f.evaluations == 0 && same(x, x0) && same(v, v0),
                               "a rejected argument touched something");
            return 0;
        }
        ODESTEP_FUZZ_CHECK(!rejects(s), "an argument rejected after the loop had begun");
        ODESTEP_FUZZ_CHECK(w.observed > 0 && run.steps + 1 == w.observed, "run.steps does not match the observations");
        ODESTEP_FUZZ_CHECK(run.t == w.last_t, "run.t is not the time of the last observation");
        ODESTEP_FUZZ_CHECK(run.counts.rhs_evals == static_cast<std::uint64_t>(f.evaluations),
                           "run.counts.rhs_evals differs from the evaluations f counted");
        ODESTEP_FUZZ_CHECK(run.counts.accepted_steps == run.steps, "run.counts.accepted_steps is not run.steps");
        buffer xn{};
        for (std::size_t i = 0; i < n; ++i) xn[i] = x[i];
        ODESTEP_FUZZ_CHECK(same(xn, w.last_x), "the loop's state is not the last one observed");
        if (s == ODESTEP_OK) ODESTEP_FUZZ_CHECK(run.t == t1, "an ok loop that did not end on t1");
        return 0;
    }

    // A sequence of single steps on one stepper.
    buffer acc{};
    bool acc_ready = false;
    double t = in.number<double>();
    const unsigned calls = 1 + in.byte() % 6;
    for (unsigned k = 0; k < calls; ++k) {
        const double dt = in.number<double>();
        const unsigned form = in.byte() % 4;
        if (in.flag()) t = in.number<double>();  // or continue from the last step's end
        buffer err{};
        buffer err2{};
        if (form == 3 && info.newtonian != 0 && !acc_ready && n >= 1 && n <= M) {  // the caller's first a(t, x)
            accel(t, x.data(), acc.data(), &ctx);
            acc_ready = true;
        }
        const buffer x0 = x;
        const buffer v0 = v;
        const buffer acc0 = acc;
        f.mark();
        odestep_status s;
        switch (form) {
            case 0: s = odestep_step_d(&stepper, &system, x.data(), t, dt); break;
            case 1: {
                double* const e1 = in.flag() ? err.data() : nullptr;  // one read per statement (fuzz_support.hpp)
                double* const e2 = in.flag() ? err2.data() : nullptr;
                s = odestep_step_error_d(&stepper, &system, x.data(), t, dt, e1, e2);
                break;
            }
            case 2: s = odestep_step_newton_d(&stepper, &newton, x.data(), v.data(), t, dt); break;
            default:
                s = odestep_step_newton_kept_d(&stepper, &newton, x.data(), v.data(), in.flag() ? acc.data() : nullptr,
                                               t, dt);
                break;
        }
        ODESTEP_FUZZ_TRACE("call %u form %u t=%.17g dt=%.17g: %s (%u evaluations)\n", k, form, t, dt,
                           odestep_status_name(s), f.since);
        ODESTEP_FUZZ_CHECK(valid_c(s), "a status outside the enum");
        ODESTEP_FUZZ_CHECK(f.since <= evals_bound, "a step made more evaluations than its published bound");
        if (s == ODESTEP_OK) {
            ODESTEP_FUZZ_CHECK(!f.non_finite_since, "a step whose right-hand side returned NaN or Inf was ok");
            t = t + dt;
            continue;
        }
        if (rejects(s)) ODESTEP_FUZZ_CHECK(f.since == 0, "a rejected argument, and yet f was evaluated");
        ODESTEP_FUZZ_CHECK(same(x, x0) && same(v, v0) && same(acc, acc0) && same(err, buffer{}) && same(err2, buffer{}),
                           "a failed step touched the state, the acceleration or the error");
    }
    return 0;
}
