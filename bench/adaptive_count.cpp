// SPDX-License-Identifier: BSL-1.0
// The adaptive loop's instructions (issue 27 item 5): a free-running Dormand-Prince 5(4) run on Lorenz
// (sigma 10, rho 28, beta 8/3; y0 = (-8, 8, 27), t = 0 .. 10, bench/work_precision.cpp's case), odestep's
// adaptive_rk + integrate_adaptive against Boost.Odeint's make_controlled(tol, tol, runge_kutta_dopri5) +
// integrate_adaptive, at rtol = atol = 1e-4, 1e-6, 1e-7, 1e-8; both start from the first step odestep's estimate
// chooses (computed outside the count). Run by `scripts/bench.sh --adaptive`:
//   count   each run bracketed by Callgrind client requests (valgrind --tool=callgrind --collect-atstart=no
//           '--toggle-collect=adaptive_run_*'), one dump per solver and tolerance; prints per run the
//           evaluations of f and the error at t = 10 against a long double reference (odestep's DOP853 at
//           1e-18), so that instructions can be read at equal tolerance and at equal achieved error.
//   gains   the controller's question (issue 27 item 5, not changed): the same runs at rtol = atol = 1e-4 ..
//           1e-10 with odestep's default gains (0.7 / k, 0.4 / k), with Hairer's dopri5.f defaults
//           (step_control alpha 0.17, beta 0.04) and Odeint; prints evaluations and errors at t = 10, and
//           brackets each run as `count` does (adaptive_run_*: instructions under callgrind). Compiled only
//           with -DBENCH_ADAPTIVE_GAINS: a second caller of the engine changes what GCC inlines into the
//           first (odestep's count goes from about 133 to 144 instructions an evaluation), so that build's
//           counts compare the two gain sets with each other and with Odeint, not with `count`'s.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <valgrind/callgrind.h>

#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <odestep/odestep.hpp>

#include "problems.hpp"

namespace {
using S = std::array<double, 3>;
using L = std::array<long double, 3>;
constexpr double t1 = 10.0;
const S y_start{-8.0, 8.0, 27.0};
long evals = 0;

void rhs(double, const S& y, S& d) {
    ++evals;
    bench::lorenz<double>(y, d);
}
void odeint_rhs(const S& y, S& d, double) {
    ++evals;
    bench::lorenz<double>(y, d);
}

__attribute__((noipa)) int adaptive_run_odestep(S& y, double tol) {
    odestep::adaptive_rk<odestep::tables::dormand_prince54, S> engine(odestep::tolerances<S>::uniform(tol, tol));
    const auto r = odestep::integrate_adaptive(engine, rhs, y, 0.0, t1, 10000000);
    return r.status == odestep::status::ok ? 0 : 1;
}
#ifdef BENCH_ADAPTIVE_GAINS
__attribute__((noipa)) int adaptive_run_odestep_dopri5_gains(S& y, double tol) {
    odestep::step_control<double> c;
    c.alpha = 0.17;  // dopri5.f: EXPO1 = 0.2 - 0.75 BETA
    c.beta = 0.04;   // dopri5.f: BETA, its default
    odestep::adaptive_rk<odestep::tables::dormand_prince54, S> engine(odestep::tolerances<S>::uniform(tol, tol), c);
    const auto r = odestep::integrate_adaptive(engine, rhs, y, 0.0, t1, 10000000);
    return r.status == odestep::status::ok ? 0 : 1;
}
#endif
__attribute__((noipa)) int adaptive_run_odeint(S& y, double tol, double h0) {
    namespace oi = boost::numeric::odeint;
    auto st = oi::make_controlled(tol, tol, oi::runge_kutta_dopri5<S>());
    oi::integrate_adaptive(st, odeint_rhs, y, 0.0, t1, h0);
    return 0;
}

double first_step(double tol) {
    const auto f = [](double, const S& y, S& d) { bench::lorenz<double>(y, d); };
    S f0;
    f(0.0, y_start, f0);
    return odestep::initial_step(f, 0.0, y_start, f0, 4, odestep::tolerances<S>::uniform(tol, tol), t1, 1.0);
}

L reference() {
    L y{y_start[0], y_start[1], y_start[2]};
    odestep::adaptive_rk<odestep::tables::dop853, L> engine(odestep::tolerances<L>::uniform(1e-18L, 1e-18L));
    const auto r = odestep::integrate_adaptive(
        engine, [](long double, const L& x, L& d) { bench::lorenz<long double>(x, d); }, y, 0.0L, 10.0L, 10000000);
    if (r.status != odestep::status::ok) std::exit(2);
    return y;
}
double error(const S& y, const L& ref) {
    long double m = 0;
    for (std::size_t i = 0; i < 3; ++i) m = std::max(m, std::fabs(static_cast<long double>(y[i]) - ref[i]));
    return static_cast<double>(m);
}
}  // namespace

int main(int argc, char** argv) {
#ifdef BENCH_ADAPTIVE_GAINS
    const bool gains = argc == 2 && std::strcmp(argv[1], "gains") == 0;
#else
    const bool gains = false;
#endif
    if (argc != 2 || (!gains && std::strcmp(argv[1], "count") != 0)) {
        std::fprintf(stderr, "usage: %s count | gains\n", argv[0]);
        return 2;
    }
    const L ref = reference();
    int failures = 0;
    const auto count_tols = {1e-4, 1e-6, 1e-7, 1e-8};
    const auto gains_tols = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
    const char* const count_solvers[] = {"odestep", "odeint"};
    const char* const gains_solvers[] = {"odestep", "odestep_dopri5_gains", "odeint"};
    for (const double tol : gains ? gains_tols : count_tols) {
        const double h0 = first_step(tol);
        for (std::size_t k = 0; k < (gains ? 3U : 2U); ++k) {
            const char* solver = gains ? gains_solvers[k] : count_solvers[k];
            S y = y_start;
            evals = 0;
            CALLGRIND_ZERO_STATS;
            if (std::strcmp(solver, "odestep") == 0)
                failures += adaptive_run_odestep(y, tol);
            else if (std::strcmp(solver, "odeint") == 0)
                failures += adaptive_run_odeint(y, tol, h0);
#ifdef BENCH_ADAPTIVE_GAINS
            else
                failures += adaptive_run_odestep_dopri5_gains(y, tol);
#endif
            char name[64];
            std::snprintf(name, sizeof name, "adaptive %s %.0e", solver, tol);
            CALLGRIND_DUMP_STATS_AT(name);
            std::printf("RUN\t%s\t%.0e\t%ld\t%.3e\n", solver, tol, evals, error(y, ref));
        }
    }
    return failures == 0 ? 0 : 1;
}
