// SPDX-License-Identifier: BSL-1.0
// An extended Kalman filter at 1 kHz: a damped pendulum observed by a noisy angle sensor. The filter predicts
// with one RK4 step and its state-transition matrix Phi = d x_{k+1} / d x_k (odestep::rk4_transition, with
// the Jacobian of the model by dual numbers: odestep::with_dual_jacobian), P <- Phi P Phi^T + Q, and updates
// with each measurement.
//
// The truth is the filter's own model, x_{k+1} = RK4(x_k) + w_k with w_k ~ N(0, Q) and z_k = theta_k + v_k,
// v_k ~ N(0, R), so a consistent filter's errors are distributed as its covariance says. Checked
// (Bar-Shalom, Li & Kirubarajan, Estimation with Applications to Tracking and Navigation, 2001, Sec. 5.4):
//   - NEES, e^T P^-1 e with e = x - x_hat (n = 2): its average over M independent runs at one time, times M,
//     is chi-square with nM degrees of freedom. At each of 20 checkpoints (every 0.25 s) the M-run average
//     must lie in the two-sided 95% region [chi2_0.025(nM), chi2_0.975(nM)] / M, at 18 of the 20 at least
//     (the expected count is 19); the average over the 20 checkpoints must lie in its 95% region with 20 nM
//     degrees of freedom. That last region treats the checkpoints as independent: the filter's bandwidth is
//     about (q / (R dt))^(1/4) = 19 rad/s (the steady-state filter of a double integrator observed in
//     position), so its errors forget in about 0.075 s, and 0.25 s apart they are nearly uncorrelated.
//   - NIS, nu^2 / S of each innovation (n_z = 1): white for a consistent filter, so the sum over all M K
//     innovations is chi-square with M K degrees of freedom; its average must lie in the 95% region.
// The quantiles are Wilson & Hilferty's (1931) approximation chi2_p(v) = v (1 - 2/(9v) + z_p sqrt(2/(9v)))^3,
// z_0.975 = 1.959964; for v = 50 it gives 32.35 and 71.42 against the tables' 32.357 and 71.420 (Abramowitz
// & Stegun, Handbook of Mathematical Functions, Table 26.8).
//   - A second filter whose Phi comes from central differences of the plain RK4 step (the approach without
//     a Jacobian) must give the same estimates: to 1e-7 of the state's scale (the differences' error).
//
// The noise is seeded and deterministic: a 64-bit linear congruential generator (Knuth's MMIX constants) and
// the Box-Muller transform, written here, so every platform draws the same numbers (no <random>
// distribution, whose algorithm the C++ standard leaves to the library). Prints its checked numbers; returns
// 1 when a check fails. The model, the noise, the filters and the runs are in ekf_pendulum.hpp, which
// tests/sensitivity/ekf_test.cpp also runs (shorter) on the host and the emulated Cortex-M cores.
#include <array>
#include <cstddef>
#include <cstdio>

#include "ekf_pendulum.hpp"

int main() {
    using namespace ekf_pendulum;
    constexpr int runs = 25;         // M
    constexpr int steps = 5000;      // K: 5 s per run
    constexpr int checkpoints = 20;  // every 0.25 s
    const monte_carlo<checkpoints> r = simulate<checkpoints>(runs, steps);
    if (!r.stepped) {
        std::printf("FAIL a prediction step failed at t = %g\n", r.failed_at);
        return 1;
    }
    bool ok = true;
    const std::array<double, 2> region = nees_region(runs);
    std::printf("runs %d steps %d dt %g\n", runs, steps, dt);
    std::printf("nees_region %.4f %.4f (chi2 95%% region, %d dof, over %d runs)\n", region[0], region[1], 2 * runs,
                runs);
    int inside = 0;
    double average = 0.0;
    for (int c = 0; c < checkpoints; ++c) {
        const double a = r.nees_sum[static_cast<std::size_t>(c)] / runs;
        const double b = r.nees_sum_differences[static_cast<std::size_t>(c)] / runs;
        const bool in = a >= region[0] && a <= region[1];
        inside += in ? 1 : 0;
        average += a / checkpoints;
        std::printf("nees t %.2f %.4f %s differences %.4f\n", (c + 1) * (steps / checkpoints) * dt, a,
                    in ? "in" : "out", b);
    }
    ok = ok && inside >= checkpoints - 2;
    const std::array<double, 2> all = nees_average_region(runs, checkpoints);
    const bool average_ok = average >= all[0] && average <= all[1];
    ok = ok && average_ok;
    std::printf("nees_inside %d of %d\n", inside, checkpoints);
    std::printf("nees_average %.4f region %.4f %.4f %s\n", average, all[0], all[1], average_ok ? "ok" : "FAIL");
    const double nis = r.nis_sum / (static_cast<double>(runs) * steps);
    const std::array<double, 2> nr = nis_region(runs, steps);
    const bool nis_ok = nis >= nr[0] && nis <= nr[1];
    ok = ok && nis_ok;
    std::printf("nis_average %.5f region %.5f %.5f %s\n", nis, nr[0], nr[1], nis_ok ? "ok" : "FAIL");
    const bool same = r.largest_difference <= 1e-7;
    ok = ok && same;
    std::printf("differences_filter_gap %.3e %s\n", r.largest_difference, same ? "ok" : "FAIL");
    std::printf("%s\n", ok ? "consistent" : "FAIL");
    return ok ? 0 : 1;
}
