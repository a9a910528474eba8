// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: per-step time by the thread's CPU clock, for the stiff cases (mode `cpu`).
//
// The harness's `time` measures wall time (steady_clock) over batches of whole runs. On a loaded machine a
// batch that lasts milliseconds (one run of SUNDIALS ARKODE's variants: 400 to 800 steps of 2 to 6 us) is
// preempted by other processes, and its wall median comes out up to 3 times its CPU time, while the
// sub-millisecond batches of odestep and Odeint mostly are not. This mode times the same runs (from y0 with the
// variant's start hook, interleaved round by round, the order rotated) with CLOCK_THREAD_CPUTIME_ID, which
// does not advance while the thread waits, and prints both clocks' medians and minima: on an idle machine
// the two agree.
#ifndef ODESTEP_BENCH_CPU_TIME_HPP
#define ODESTEP_BENCH_CPU_TIME_HPP

#include <time.h>

#include <cstdio>
#include <vector>

#include "harness.hpp"

namespace bench {

inline double clock_ns(clockid_t which) {
    timespec ts{};
    clock_gettime(which, &ts);
    return static_cast<double>(ts.tv_sec) * 1e9 + static_cast<double>(ts.tv_nsec);
}

/// `rounds` rounds; in each, one run of p.check_steps steps of every variant. Prints per variant
/// "CPU <case> <variant> <cpu median> <cpu min> <wall median> <wall min>", in ns per step.
template <class State>
int cpu_time(const problem<State>& p, const std::vector<variant<State>>& vs, int rounds) {
    const std::size_t V = vs.size();
    std::vector<std::vector<double>> cpu(V), wall(V);
    for (int r = 0; r < rounds; ++r)
        for (std::size_t j = 0; j < V; ++j) {
            const std::size_t k = (j + static_cast<std::size_t>(r)) % V;
            State y = p.y0, err{};
            start_run(vs[k], p);
            const double c0 = clock_ns(CLOCK_THREAD_CPUTIME_ID), w0 = clock_ns(CLOCK_MONOTONIC);
            const int bad = run_steps(vs[k], p, y, err, p.check_steps);
            const double c1 = clock_ns(CLOCK_THREAD_CPUTIME_ID), w1 = clock_ns(CLOCK_MONOTONIC);
            if (bad) {
                std::fprintf(stderr, "bench: %s %s: a step failed while timing\n", p.name, vs[k].key);
                return 1;
            }
            cpu[k].push_back((c1 - c0) / p.check_steps);
            wall[k].push_back((w1 - w0) / p.check_steps);
        }
    for (std::size_t k = 0; k < V; ++k)
        std::printf("CPU\t%s\t%s\t%.1f\t%.1f\t%.1f\t%.1f\n", p.name, vs[k].key, median(cpu[k]),
                    *std::min_element(cpu[k].begin(), cpu[k].end()), median(wall[k]),
                    *std::min_element(wall[k].begin(), wall[k].end()));
    return 0;
}

}  // namespace bench

#endif
