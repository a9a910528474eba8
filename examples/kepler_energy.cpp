// SPDX-License-Identifier: BSL-1.0
// Energy over 10^6 steps: the Kepler orbit of eccentricity 0.5 (GM = 1, semi-major axis 1, period 2 pi)
// from perihelion, 200 steps per period for 5000 periods, with RK4 (not symplectic: its energy error
// grows in proportion to time) and three symplectic methods, velocity Verlet, position Verlet and
// Forest-Ruth (their energy error stays within a band for the whole run).
//
// Printed for each method: the largest relative energy error over the first and over the last 10 % of the
// run, the final one, and the final relative change of the angular momentum; for RK4 also the energy error
// at each quarter of the run. The same orbit with 400 steps per period (for 2500 periods, the same time
// span as the first half) shows how each error scales with dt.
//
// Data: kepler_energy.csv, one data set per method (RK4, velocity Verlet, position Verlet, Forest-Ruth),
// each row the time in periods and the largest |dE/E0| over the last 1000 steps.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using vec = std::array<double, 2>;
using state = std::array<double, 4>;
constexpr double eccentricity = 0.5;
const double period = 2 * std::acos(-1.0);
const double v_perihelion = std::sqrt((1 + eccentricity) / (1 - eccentricity));
constexpr double e0 = -0.5;  // -GM / (2a)

struct gravity {
    vec operator()(double, const vec& x) const noexcept {
        const double r2 = x[0] * x[0] + x[1] * x[1];
        const double r3 = r2 * std::sqrt(r2);
        return {-x[0] / r3, -x[1] / r3};
    }
};
struct kepler_rhs {
    state operator()(double, const state& y) const noexcept {
        const double r2 = y[0] * y[0] + y[1] * y[1];
        const double r3 = r2 * std::sqrt(r2);
        return {y[2], y[3], -y[0] / r3, -y[1] / r3};
    }
};

double energy(double x, double y, double vx, double vy) { return 0.5 * (vx * vx + vy * vy) - 1 / std::hypot(x, y); }
const double l0 = (1 - eccentricity) * v_perihelion;

// Watches one run: the largest |dE/E0| in the first and the last tenth, at each quarter, and per window
// of 1000 steps (written to the CSV when `out` is given).
struct watcher {
    std::size_t steps;
    example::csv_file* out;
    std::size_t seen = 0;
    double first = 0.0, last = 0.0, window = 0.0;
    std::array<double, 4> quarters{};
    void see(double t, double x, double y, double vx, double vy) {
        const double de = (energy(x, y, vx, vy) - e0) / std::fabs(e0);
        const double size = std::fabs(de);
        const std::size_t n = seen++;
        if (n <= steps / 10) first = std::fmax(first, size);
        if (n >= steps - steps / 10) last = std::fmax(last, size);
        for (std::size_t q = 1; q <= 4; ++q)
            if (n == q * steps / 4) quarters[q - 1] = de;
        window = std::fmax(window, size);
        if (n > 0 && n % 1000 == 0) {
            if (out != nullptr) out->csv.row(t / period, window);
            window = 0.0;
        }
    }
};

struct result {
    bool ok;
    watcher w;
    double de, dl;
};

template <class Stepper>
result newtonian(std::size_t per_period, std::size_t periods, example::csv_file* out) {
    const std::size_t steps = per_period * periods;
    vec x{1 - eccentricity, 0.0};
    vec v{0.0, v_perihelion};
    watcher w{steps, out};
    const auto r =
        odestep::integrate_n_steps(Stepper{}, gravity{}, x, v, 0.0, period / static_cast<double>(per_period), steps,
                                   [&w](double t, const vec& q, const vec& p) { w.see(t, q[0], q[1], p[0], p[1]); });
    return {r.status == odestep::status::ok, w, (energy(x[0], x[1], v[0], v[1]) - e0) / std::fabs(e0),
            (x[0] * v[1] - x[1] * v[0]) / l0 - 1};
}

result runge_kutta(std::size_t per_period, std::size_t periods, example::csv_file* out) {
    const std::size_t steps = per_period * periods;
    state y{1 - eccentricity, 0.0, 0.0, v_perihelion};
    watcher w{steps, out};
    const auto r = odestep::integrate_n_steps(odestep::rk4<state>{}, kepler_rhs{}, y, 0.0,
                                              period / static_cast<double>(per_period), steps,
                                              [&w](double t, const state& s) { w.see(t, s[0], s[1], s[2], s[3]); });
    return {r.status == odestep::status::ok, w, (energy(y[0], y[1], y[2], y[3]) - e0) / std::fabs(e0),
            (y[0] * y[3] - y[1] * y[2]) / l0 - 1};
}

bool print(const char* name, std::size_t per_period, const result& r) {
    if (!r.ok) return false;
    std::printf("%-16s %4zu %8zu %12.4e %12.4e %12.4e %12.4e\n", name, per_period, r.w.steps, r.w.first, r.w.last, r.de,
                r.dl);
    return true;
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "kepler_energy.csv");
    std::printf("# Kepler e = %g from perihelion, E0 = %g; 200 steps per period for 5000 periods (10^6 steps), and\n",
                eccentricity, e0);
    std::printf("# 400 per period for 2500 periods\n");
    std::printf("%-16s %4s %8s %12s %12s %12s %12s\n", "method", "N/T", "steps", "first10%", "last10%", "dE/E0",
                "dL/L0");
    bool ok = true;
    const char* names[] = {"rk4", "velocity_verlet", "position_verlet", "forest_ruth"};
    for (int k = 0; k < 4 && ok; ++k) {
        data.csv.header(names[k], "max_abs_dE_over_E0");
        for (std::size_t per_period : {std::size_t{200}, std::size_t{400}}) {
            const std::size_t periods = per_period == 200 ? 5000 : 2500;
            example::csv_file* out = per_period == 200 ? &data : nullptr;
            result r{};
            if (k == 0) r = runge_kutta(per_period, periods, out);
            if (k == 1) r = newtonian<odestep::velocity_verlet<vec>>(per_period, periods, out);
            if (k == 2) r = newtonian<odestep::position_verlet<vec>>(per_period, periods, out);
            if (k == 3) r = newtonian<odestep::forest_ruth<vec>>(per_period, periods, out);
            ok = print(names[k], per_period, r);
            if (k == 0 && per_period == 200)
                std::printf("rk4_quarters %.6e %.6e %.6e %.6e\n", r.w.quarters[0], r.w.quarters[1], r.w.quarters[2],
                            r.w.quarters[3]);
        }
        data.next_block();
    }
    return ok && data.good() ? 0 : 1;
}
