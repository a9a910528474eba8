// SPDX-License-Identifier: BSL-1.0
// The core of the EKF example (examples/ekf_pendulum.cpp): the damped pendulum, the seeded noise, the filter
// that predicts with odestep::rk4_transition (the Jacobian by dual numbers) and the one whose Phi comes from
// central differences, and the Monte Carlo runs with their consistency figures. The example runs it at full
// size and prints; tests/sensitivity/ekf_test.cpp runs a short version on the host and the emulated cores.
#ifndef ODESTEP_EXAMPLES_EKF_PENDULUM_HPP
#define ODESTEP_EXAMPLES_EKF_PENDULUM_HPP

#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace ekf_pendulum {

using state = std::array<double, 2>;  // theta (rad), omega (rad/s)
using matrix = odestep::jacobian_t<state>;

constexpr double omega0_squared = 9.81;  // g / L with L = 1 m
constexpr double damping = 0.2;          // 1/s
constexpr double dt = 1e-3;              // 1 kHz
constexpr double q = 0.05;               // process noise: white angular acceleration, (rad/s^2)^2 / Hz
constexpr double sigma_z = 0.02;         // the angle sensor's noise, rad

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

inline matrix multiply(const matrix& a, const matrix& b) {
    matrix c{};
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
    return c;
}
inline matrix transpose(const matrix& a) { return {{{a[0][0], a[1][0]}, {a[0][1], a[1][1]}}}; }

// Phi by central differences of the plain RK4 step, column j: (step(x + h e_j) - step(x - h e_j)) / (2h).
inline bool phi_by_differences(const state& x, double t, matrix& phi) {
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
inline double chi2_quantile(double v, double z) {
    const double c = 2.0 / (9.0 * v);
    const double b = 1.0 - c + z * std::sqrt(c);
    return v * b * b * b;
}

// What M runs of K steps give: the sums of the NEES at each checkpoint (the exact-Phi filter and the
// differences one), the sum of the NIS, the largest gap between the two filters' estimates.
template <int Checkpoints>
struct monte_carlo {
    std::array<double, Checkpoints> nees_sum{};
    std::array<double, Checkpoints> nees_sum_differences{};
    double nis_sum = 0.0;
    double largest_difference = 0.0;
    bool stepped = true;  ///< false if a step failed (then failed_at is its time)
    double failed_at = 0.0;
};

// M runs of K steps each, checkpoints every K / Checkpoints steps.
template <int Checkpoints>
monte_carlo<Checkpoints> simulate(int runs, int steps) {
    monte_carlo<Checkpoints> r;
    const int checkpoint_every = steps / Checkpoints;
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
            const double n1 = rng.normal();
            const double n2 = rng.normal();
            const double nz = rng.normal();
            if (rk4.step(pendulum{}, truth, t, dt) != odestep::status::ok || !f.predict<false>(t) ||
                !g.predict<true>(t)) {
                r.stepped = false;
                r.failed_at = t;
                return r;
            }
            truth[0] += l00 * n1;
            truth[1] += l10 * n1 + l11 * n2;
            const double z = truth[0] + sigma_z * nz;
            r.nis_sum += f.update(z);
            (void)g.update(z);
            for (std::size_t i = 0; i < 2; ++i) {
                const double d = std::fabs(f.x[i] - g.x[i]);
                r.largest_difference = d > r.largest_difference ? d : r.largest_difference;
            }
            if ((k + 1) % checkpoint_every == 0) {
                const auto c = static_cast<std::size_t>((k + 1) / checkpoint_every - 1);
                r.nees_sum[c] += f.nees(truth);
                r.nees_sum_differences[c] += g.nees(truth);
            }
        }
    }
    return r;
}

// The 95% regions of the averages (Bar-Shalom et al. Sec. 5.4), by Wilson & Hilferty's quantiles.
constexpr double z975 = 1.959964;
// The region of the M-run average NEES at one checkpoint (n M degrees of freedom, n = 2).
inline std::array<double, 2> nees_region(int runs) {
    return {chi2_quantile(2.0 * runs, -z975) / runs, chi2_quantile(2.0 * runs, z975) / runs};
}
// The region of the average over C checkpoints (n M C degrees of freedom).
inline std::array<double, 2> nees_average_region(int runs, int checkpoints) {
    const double dof = 2.0 * runs * checkpoints;
    const double m = static_cast<double>(runs) * checkpoints;
    return {chi2_quantile(dof, -z975) / m, chi2_quantile(dof, z975) / m};
}
// The region of the average NIS over M K innovations (M K degrees of freedom).
inline std::array<double, 2> nis_region(int runs, int steps) {
    const double innovations = static_cast<double>(runs) * steps;
    return {chi2_quantile(innovations, -z975) / innovations, chi2_quantile(innovations, z975) / innovations};
}

}  // namespace ekf_pendulum

#endif
