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
// 1 when a check fails.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <type_traits>

namespace {

using state = std::array<double, 2>;  // theta (rad), omega (rad/s)
using matrix = odestep::jacobian_t<state>;

constexpr double omega0_squared = 9.81;  // g / L with L = 1 m
constexpr double damping = 0.2;          // 1/s
constexpr double dt = 1e-3;              // 1 kHz
constexpr double q = 0.05;               // process noise: white angular acceleration, (rad/s^2)^2 / Hz
constexpr double sigma_z = 0.02;         // the angle sensor's noise, rad
constexpr int runs = 25;                 // M
constexpr int steps = 5000;              // K: 5 s per run
constexpr int checkpoint_every = 250;    // 0.25 s

// The model, written once as a template on its scalar: the filter differentiates it with dual numbers.
struct pendulum {
    template <class S>
    std::array<S, 2> operator()(double, const std::array<S, 2>& x) const {
        using std::sin;
        return {x[1], -omega0_squared * sin(x[0]) - damping * x[1]};
    }
};

// Seeded noise: the MMIX LCG (Knuth, TAOCP vol. 2, 3.3.4), its top 53 bits as a uniform number in (0, 1),
// and the Box-Muller transform for standard normal pairs.
struct noise {
    std::uint64_t s;
    double uniform() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return (static_cast<double>(s >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // 2^-53
    }
    bool has_spare = false;
    double spare = 0.0;
    double normal() {
        if (has_spare) {
            has_spare = false;
            return spare;
        }
        const double r = std::sqrt(-2.0 * std::log(uniform()));
        const double a = 6.283185307179586 * uniform();
        spare = r * std::sin(a);
        has_spare = true;
        return r * std::cos(a);
    }
};

// The discrete process noise of a white acceleration of density q over dt (Bar-Shalom et al., Sec. 6.2.2):
// Q = q [[dt^3/3, dt^2/2], [dt^2/2, dt]], and its Cholesky factor for drawing w = L (n1, n2).
constexpr matrix process_noise() { return {{{q * dt * dt * dt / 3, q * dt * dt / 2}, {q * dt * dt / 2, q * dt}}}; }

matrix multiply(const matrix& a, const matrix& b) {
    matrix c{};
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
    return c;
}
matrix transpose(const matrix& a) { return {{{a[0][0], a[1][0]}, {a[0][1], a[1][1]}}}; }

// Phi by central differences of the plain RK4 step, column j: (step(x + h e_j) - step(x - h e_j)) / (2h).
bool phi_by_differences(const state& x, double t, matrix& phi) {
    const odestep::rk4<state> rk4;
    for (std::size_t j = 0; j < 2; ++j) {
        const double h = 1e-5 * (std::fabs(x[j]) + 1.0);
        state plus = x;
        state minus = x;
        plus[j] += h;
        minus[j] -= h;
        if (rk4.step(pendulum{}, plus, t, dt) != odestep::status::ok) return false;
        if (rk4.step(pendulum{}, minus, t, dt) != odestep::status::ok) return false;
        for (std::size_t i = 0; i < 2; ++i) phi[i][j] = (plus[i] - minus[i]) / (2 * h);
    }
    return true;
}

struct filter {
    state x;
    matrix p;
    // Predict: x <- RK4(x), P <- Phi P Phi^T + Q, with Phi exact (Differences: from central differences).
    template <bool Differences>
    bool predict(double t) {
        matrix phi{};
        if constexpr (Differences) {
            if (!phi_by_differences(x, t, phi)) return false;
            if (odestep::rk4<state>{}.step(pendulum{}, x, t, dt) != odestep::status::ok) return false;
        } else {
            if (odestep::rk4_transition<state>{}.step(odestep::with_dual_jacobian(pendulum{}), x, phi, t, dt) !=
                odestep::status::ok)
                return false;
        }
        const matrix qd = process_noise();
        p = multiply(multiply(phi, p), transpose(phi));
        for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t j = 0; j < 2; ++j) p[i][j] += qd[i][j];
        return true;
    }
    // Update with z = theta + v (H = [1 0]), Joseph form; returns the NIS nu^2 / S.
    double update(double z) {
        const double s = p[0][0] + sigma_z * sigma_z;
        const double nu = z - x[0];
        const std::array<double, 2> k{p[0][0] / s, p[1][0] / s};
        x[0] += k[0] * nu;
        x[1] += k[1] * nu;
        const matrix a{{{1 - k[0], 0.0}, {-k[1], 1.0}}};  // I - K H
        matrix np = multiply(multiply(a, p), transpose(a));
        for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t j = 0; j < 2; ++j) np[i][j] += k[i] * k[j] * sigma_z * sigma_z;
        p = np;
        return nu * nu / s;
    }
    double nees(const state& truth) const {
        const double e0 = truth[0] - x[0];
        const double e1 = truth[1] - x[1];
        const double det = p[0][0] * p[1][1] - p[0][1] * p[1][0];
        return (p[1][1] * e0 * e0 - 2 * p[0][1] * e0 * e1 + p[0][0] * e1 * e1) / det;
    }
};

// Wilson & Hilferty's chi-square quantile for v degrees of freedom at the normal quantile z.
double chi2_quantile(double v, double z) {
    const double c = 2.0 / (9.0 * v);
    const double b = 1.0 - c + z * std::sqrt(c);
    return v * b * b * b;
}

}  // namespace

int main() {
    constexpr int checkpoints = steps / checkpoint_every;
    std::array<double, checkpoints> nees_sum{};
    std::array<double, checkpoints> nees_sum_diff{};
    double nis_sum = 0.0;
    double largest_difference = 0.0;
    const matrix qd = process_noise();
    const double l00 = std::sqrt(qd[0][0]);  // Cholesky factor of Q
    const double l10 = qd[1][0] / l00;
    const double l11 = std::sqrt(qd[1][1] - l10 * l10);
    const matrix p0{{{0.05 * 0.05, 0.0}, {0.0, 0.2 * 0.2}}};
    for (int run = 0; run < runs; ++run) {
        noise rng{0x2545F4914F6CDD1DULL + static_cast<std::uint64_t>(run) * 0x9E3779B97F4A7C15ULL};
        state truth{0.6, 0.0};
        // The initial estimate: the truth plus an error drawn from P0, so the filter starts consistent.
        filter f{{truth[0] + 0.05 * rng.normal(), truth[1] + 0.2 * rng.normal()}, p0};
        filter g = f;  // the filter with Phi by differences
        const odestep::rk4<state> rk4;
        for (int k = 0; k < steps; ++k) {
            const double t = k * dt;  // from the counter, not a running sum
            if (rk4.step(pendulum{}, truth, t, dt) != odestep::status::ok) return 1;
            const double n1 = rng.normal();
            const double n2 = rng.normal();
            truth[0] += l00 * n1;
            truth[1] += l10 * n1 + l11 * n2;
            const double z = truth[0] + sigma_z * rng.normal();
            if (!f.predict<false>(t) || !g.predict<true>(t)) {
                std::printf("FAIL a prediction step failed at t = %g\n", t);
                return 1;
            }
            nis_sum += f.update(z);
            (void)g.update(z);
            for (std::size_t i = 0; i < 2; ++i) {
                const double d = std::fabs(f.x[i] - g.x[i]);
                largest_difference = d > largest_difference ? d : largest_difference;
            }
            if ((k + 1) % checkpoint_every == 0) {
                nees_sum[static_cast<std::size_t>((k + 1) / checkpoint_every - 1)] += f.nees(truth);
                nees_sum_diff[static_cast<std::size_t>((k + 1) / checkpoint_every - 1)] += g.nees(truth);
            }
        }
    }
    bool ok = true;
    const double z975 = 1.959964;
    const double n = 2.0;
    const double lo = chi2_quantile(n * runs, -z975) / runs;
    const double hi = chi2_quantile(n * runs, z975) / runs;
    std::printf("runs %d steps %d dt %g\n", runs, steps, dt);
    std::printf("nees_region %.4f %.4f (chi2 95%% region, %d dof, over %d runs)\n", lo, hi, 2 * runs, runs);
    int inside = 0;
    double average = 0.0;
    for (int c = 0; c < checkpoints; ++c) {
        const double a = nees_sum[static_cast<std::size_t>(c)] / runs;
        const double b = nees_sum_diff[static_cast<std::size_t>(c)] / runs;
        const bool in = a >= lo && a <= hi;
        inside += in ? 1 : 0;
        average += a / checkpoints;
        std::printf("nees t %.2f %.4f %s differences %.4f\n", (c + 1) * checkpoint_every * dt, a, in ? "in" : "out", b);
    }
    ok = ok && inside >= checkpoints - 2;
    const double dof_all = n * runs * checkpoints;
    const double alo = chi2_quantile(dof_all, -z975) / (runs * checkpoints);
    const double ahi = chi2_quantile(dof_all, z975) / (runs * checkpoints);
    const bool average_ok = average >= alo && average <= ahi;
    ok = ok && average_ok;
    std::printf("nees_inside %d of %d\n", inside, checkpoints);
    std::printf("nees_average %.4f region %.4f %.4f %s\n", average, alo, ahi, average_ok ? "ok" : "FAIL");
    const double innovations = static_cast<double>(runs) * steps;
    const double nis = nis_sum / innovations;
    const double nlo = chi2_quantile(innovations, -z975) / innovations;
    const double nhi = chi2_quantile(innovations, z975) / innovations;
    const bool nis_ok = nis >= nlo && nis <= nhi;
    ok = ok && nis_ok;
    std::printf("nis_average %.5f region %.5f %.5f %s\n", nis, nlo, nhi, nis_ok ? "ok" : "FAIL");
    const bool same = largest_difference <= 1e-7;
    ok = ok && same;
    std::printf("differences_filter_gap %.3e %s\n", largest_difference, same ? "ok" : "FAIL");
    std::printf("%s\n", ok ? "consistent" : "FAIL");
    return ok ? 0 : 1;
}
