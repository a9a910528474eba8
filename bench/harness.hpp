// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: the driver every case shares.
//
// A case is one problem integrated by up to five variants (odestep, a hand-written loop, Boost.Odeint,
// GSL odeiv2, and informational extras). Each variant is one `BENCH_STEP` function that takes exactly one
// step: `noipa`, so the compiler neither inlines it into the driver nor specializes it for the driver's
// constant arguments, and so that what is measured is one step exactly as a caller elsewhere would get it.
//
// The binary has three modes:
//   check        every variant runs the same short, non-chaotic stretch; same-method variants must agree
//                with odestep to round-off, and every variant must agree with an independent reference
//                (DOP853 in long double with a 16x smaller step) to the truncation error of its method.
//   count N      N steps of each variant, each bracketed by Callgrind client requests; run it under
//                `valgrind --tool=callgrind --collect-atstart=no --toggle-collect=bench_step_*` and every
//                dump holds the instructions executed inside one variant's step function, N steps of it.
//   time         wall time per step, the variants interleaved round by round (the order rotates each
//                round), so that drift in the machine's speed hits all of them alike; the ratios are the
//                median over rounds of the per-round ratio.
#ifndef ODESTEP_BENCH_HARNESS_HPP
#define ODESTEP_BENCH_HARNESS_HPP

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <valgrind/callgrind.h>

#include <odestep/odestep.hpp>

#define BENCH_STEP extern "C" __attribute__((noipa))

namespace bench {

template <class State>
using value_t = typename State::value_type;

/// One step of one variant: y <- y(t + dt), err <- the error estimate where the case has one.
/// Returns 0 on success (odestep's status, GSL's return code; the others cannot fail).
template <class State>
using step_fn = int (*)(State& y, State& err, value_t<State> t, value_t<State> dt);

template <class State>
struct variant {
    const char* key;          // odestep, hand, odeint, gsl, or an extra (shown but not a reference)
    const char* description;  // the method as this variant computes it
    step_fn<State> step;
    bool same_method;  // the same arithmetic as odestep, so it must agree with it to round-off
    // For a variant that keeps something between steps (velocity Verlet's last acceleration): called before
    // every run from y0 at t0 (check, count, each timed batch), as a caller starts a new run: odestep's
    // reset(), the hand loop's a(x0) before its loop, Odeint's reset(). Stateless variants leave it null.
    void (*start)(const State& y0, value_t<State> t0) = nullptr;
};

template <class State>
struct problem {
    const char* name;
    State y0;
    value_t<State> t0;
    value_t<State> dt;
    int check_steps;    // the checked stretch; also one timed batch (the state is reset after it)
    State reference;    // the exact solution at t0 + check_steps * dt, to well below tol_method
    double tol_same;    // |y - y_odestep|_inf / max(1, |y_odestep|_inf), same-method variants
    double tol_method;  // |y - reference|_inf / max(1, |reference|_inf), every variant
    bool has_error;     // the step returns an error estimate: compare it among same-method variants
};

/// y(t1) of y' = f(y) from y0 at t0 by DOP853 in long double with `steps` steps: the reference the checks
/// compare against. Its error (h^8, in 64-bit mantissas) is far below every tolerance used here.
template <std::size_t N, class F, class T>
std::array<T, N> reference_solution(F f, const std::array<T, N>& y0, long double t0, long double t1, int steps) {
    using LState = std::array<long double, N>;
    LState y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = y0[i];
    const long double h = (t1 - t0) / steps;
    odestep::dop853<LState> stepper;
    for (int i = 0; i < steps; ++i) {
        if (stepper.step(f, y, t0 + h * i, h) != odestep::status::ok) {
            std::fprintf(stderr, "bench: the reference solution failed\n");
            std::exit(2);
        }
    }
    std::array<T, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<T>(y[i]);
    return out;
}

template <class State>
double max_abs(const State& a) {
    double m = 0;
    for (auto x : a) m = std::max(m, std::fabs(static_cast<double>(x)));
    return m;
}

template <class State>
double max_diff(const State& a, const State& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        m = std::max(m, std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
    if (!(m == m)) m = INFINITY;
    return m;
}

template <class State>
void start_run(const variant<State>& v, const problem<State>& p) {
    if (v.start != nullptr) v.start(p.y0, p.t0);
}

template <class State>
int run_steps(const variant<State>& v, const problem<State>& p, State& y, State& err, int steps) {
    int bad = 0;
    for (int i = 0; i < steps; ++i) bad |= v.step(y, err, p.t0 + static_cast<value_t<State>>(i) * p.dt, p.dt);
    return bad;
}

template <class State>
int check(const problem<State>& p, const std::vector<variant<State>>& vs) {
    int failures = 0;
    State y_ref{}, err_ref{};
    for (std::size_t k = 0; k < vs.size(); ++k) {
        const auto& v = vs[k];
        State y = p.y0, err{};
        start_run(v, p);
        const int bad = run_steps(v, p, y, err, p.check_steps);
        const double scale_ref = std::max(1.0, max_abs(p.reference));
        const double d_ref = max_diff(y, p.reference) / scale_ref;
        bool ok = bad == 0 && d_ref <= p.tol_method;
        char same[160] = "";
        if (k == 0) {
            y_ref = y;
            err_ref = err;
        } else if (v.same_method) {
            const double d_same = max_diff(y, y_ref) / std::max(1.0, max_abs(y_ref));
            ok = ok && d_same <= p.tol_same;
            int n = std::snprintf(same, sizeof same, " vs_odestep=%.2e (tol %.0e)", d_same, p.tol_same);
            if (p.has_error) {
                // The estimate is a small difference of O(1) terms, so it carries their round-off: the
                // same formula agrees to about eps |terms| / |estimate|, well inside 1e-4 of itself.
                const double d_err = max_diff(err, err_ref) / max_abs(err_ref);
                ok = ok && d_err <= 1e-4;
                std::snprintf(same + n, sizeof same - static_cast<std::size_t>(n), " err_vs_odestep=%.2e (tol 1e-04)",
                              d_err);
            }
        }
        if (!ok) ++failures;
        std::printf("CHECK\t%s\t%s\t%s\tvs_reference=%.2e (tol %.0e)%s%s\n", p.name, v.key, ok ? "ok" : "FAIL", d_ref,
                    p.tol_method, same, bad ? " step reported failure" : "");
    }
    return failures;
}

template <class State>
int count(const problem<State>& p, const std::vector<variant<State>>& vs, int steps) {
    for (const auto& v : vs) {
        State y = p.y0, err{};
        start_run(v, p);
        run_steps(v, p, y, err, 4);  // first-call effects (lazy init, resizing) stay out of the count
        y = p.y0;
        start_run(v, p);
        CALLGRIND_ZERO_STATS;
        const int bad = run_steps(v, p, y, err, steps);
        char name[128];
        std::snprintf(name, sizeof name, "%s %s %d", p.name, v.key, steps);
        CALLGRIND_DUMP_STATS_AT(name);
        if (bad) {
            std::fprintf(stderr, "bench: %s %s: a step failed while counting\n", p.name, v.key);
            return 1;
        }
    }
    return 0;
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

template <class State>
int time(const problem<State>& p, const std::vector<variant<State>>& vs, int rounds, double batch_ms) {
    using clock = std::chrono::steady_clock;
    const std::size_t V = vs.size();
    volatile double sink = 0;
    auto batch = [&](const variant<State>& v, int reps) {
        const auto start = clock::now();
        int bad = 0;
        for (int r = 0; r < reps; ++r) {
            State y = p.y0, err{};
            start_run(v, p);
            bad |= run_steps(v, p, y, err, p.check_steps);
            sink = sink + static_cast<double>(y[0]);
        }
        const std::chrono::duration<double, std::nano> ns = clock::now() - start;
        if (bad) {
            std::fprintf(stderr, "bench: %s %s: a step failed while timing\n", p.name, v.key);
            std::exit(1);
        }
        return ns.count() / (static_cast<double>(reps) * p.check_steps);
    };
    // Calibrate on the slowest variant: each batch then takes about batch_ms.
    double slowest = 0;
    for (const auto& v : vs) slowest = std::max(slowest, batch(v, 4));
    const int reps = std::max(1, static_cast<int>(batch_ms * 1e6 / (slowest * p.check_steps)));
    std::vector<std::vector<double>> ns(V);
    for (int r = 0; r < rounds; ++r)
        for (std::size_t j = 0; j < V; ++j) {
            const std::size_t k = (j + static_cast<std::size_t>(r)) % V;
            ns[k].push_back(batch(vs[k], reps));
        }
    auto find = [&](const char* key) {
        for (std::size_t k = 0; k < V; ++k)
            if (std::strcmp(vs[k].key, key) == 0) return static_cast<long>(k);
        return -1L;
    };
    const long hand = find("hand"), odeint = find("odeint");
    auto ratio = [&](std::size_t k, long ref, char* out, std::size_t size) {
        if (ref < 0) {
            std::snprintf(out, size, "-");
            return;
        }
        const auto& mine = ns[k];
        const auto& theirs = ns[static_cast<std::size_t>(ref)];
        std::vector<double> q;
        for (std::size_t r = 0; r < mine.size(); ++r) q.push_back(mine[r] / theirs[r]);
        std::snprintf(out, size, "%.3f", median(q));
    };
    for (std::size_t k = 0; k < V; ++k) {
        char rh[32], ro[32];
        ratio(k, hand, rh, sizeof rh);
        ratio(k, odeint, ro, sizeof ro);
        std::printf("TIME\t%s\t%s\t%.2f\t%s\t%s\n", p.name, vs[k].key, median(ns[k]), rh, ro);
    }
    return 0;
}

template <class State>
int main(int argc, char** argv, const problem<State>& p, const std::vector<variant<State>>& vs) {
    for (const auto& v : vs)
        std::printf("VARIANT\t%s\t%s\t%s\t%s\n", p.name, v.key, v.same_method ? "same" : "other", v.description);
    const char* mode = argc > 1 ? argv[1] : "check";
    if (std::strcmp(mode, "check") == 0) return check(p, vs) == 0 ? 0 : 1;
    if (std::strcmp(mode, "count") == 0) return count(p, vs, argc > 2 ? std::atoi(argv[2]) : 1000);
    if (std::strcmp(mode, "time") == 0)
        return time(p, vs, argc > 2 ? std::atoi(argv[2]) : 21, argc > 3 ? std::atof(argv[3]) : 2.0);
    std::fprintf(stderr, "usage: %s check | count [steps] | time [rounds] [batch_ms]\n", argv[0]);
    return 2;
}

}  // namespace bench

#endif
