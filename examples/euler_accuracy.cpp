// SPDX-License-Identifier: BSL-1.0
// Course material: the accuracy and the stability of Euler's method (problems 3.16 and 3.17).
//
// Accuracy: dy/dx = 2x, y(0) = 0 (exact y = x^2), Euler with dx = 0.1, 0.05, 0.025, 0.01 and 0.005; the
// difference from x^2 at x = 1 halves with dx (order one). Then the largest dx = x / n that is within
// 0.1 % of x^2 at x = 2 and at x = 4.
//
// Stability: the capacitor discharge R dQ/dt = -Q/C, R = 2000 ohm, C = 1e-6 F (RC = 2 ms), Q(0) = 10.
// The largest dt = 0.005 s / n that gives Q(0.005 s) to three decimals (within 5e-4 of 10 exp(-2.5)),
// then Q(0.05 s) with dt = 0.005, 0.0025 and 0.001 s: at dt = 0.005 s = 2.5 RC each step multiplies Q by
// 1 - dt/RC = -1.5 and the numbers grow without bound, while the exact charge has all but vanished.
//
// Data: euler_accuracy.csv (dx, the error at x = 1), euler_stability.csv (t, Q for each dt, exact).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using state = std::array<double, 1>;
constexpr double rc = 2000.0 * 1e-6;
constexpr double q0 = 10.0;

// Euler's y(x_end) for y' = 2x from y(0) = 0; NaN if the run fails.
double slope_run(double x_end, double dx) {
    state y{0.0};
    const auto r = odestep::integrate(
        odestep::euler<state>{}, [](double x, const state&) { return state{2.0 * x}; }, y, 0.0, x_end, dx);
    return r.status == odestep::status::ok ? y[0] : std::nan("");
}

struct discharge {
    state operator()(double, const state& q) const noexcept { return {-q[0] / rc}; }
};

// Euler's Q(t_end) with n steps; NaN if the run fails.
double charge_run(double t_end, std::size_t n) {
    state q{q0};
    const auto r =
        odestep::integrate_n_steps(odestep::euler<state>{}, discharge{}, q, 0.0, t_end / static_cast<double>(n), n);
    return r.status == odestep::status::ok ? q[0] : std::nan("");
}

// The fewest steps n (so the largest dt = span / n) for which good(n) holds, when good is false below
// some n and true from there on: doubling, then bisection.
template <class Good>
std::size_t fewest_steps(Good good) {
    std::size_t hi = 1;
    while (!good(hi)) hi *= 2;
    std::size_t lo = hi / 2;  // good(lo) is false (or lo = 0)
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (good(mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return hi;
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file accuracy(argc, argv, "euler_accuracy.csv");
    example::csv_file stability(argc, argv, "euler_stability.csv");
    accuracy.csv.header("dx", "y", "exact", "error");

    std::printf("# dy/dx = 2x, y(0) = 0, Euler; exact y = x^2\n");
    std::printf("%-8s %-6s %22s %22s %12s\n", "accuracy", "dx", "y(1)", "x^2 - y", "error/dx");
    for (double dx : {0.1, 0.05, 0.025, 0.01, 0.005}) {
        const double y = slope_run(1.0, dx);
        if (std::isnan(y)) return 1;
        std::printf("%-8s %-6g %22.17g %22.17g %12.9f\n", "accuracy", dx, y, 1.0 - y, (1.0 - y) / dx);
        accuracy.csv.row(dx, y, 1.0, 1.0 - y);
    }
    for (double x_end : {2.0, 4.0}) {
        const double exact = x_end * x_end;
        const std::size_t n = fewest_steps([&](std::size_t k) {
            const double y = slope_run(x_end, x_end / static_cast<double>(k));
            return std::fabs(exact - y) <= 1e-3 * exact;
        });
        const double dx = x_end / static_cast<double>(n);
        const double y = slope_run(x_end, dx);
        std::printf("within_0.1%% x %g steps %zu dx %.17g relative_error %.17g\n", x_end, n, dx, (exact - y) / exact);
    }

    std::printf("# R dQ/dt = -Q/C, RC = %g s, Q(0) = %g, Euler\n", rc, q0);
    const double t_a = 0.005;
    const double q_a = q0 * std::exp(-t_a / rc);
    const std::size_t n_a = fewest_steps([&](std::size_t k) { return std::fabs(charge_run(t_a, k) - q_a) <= 5e-4; });
    std::printf("three_decimals t %g steps %zu dt %.17g Q %.17g exact %.17g\n", t_a, n_a,
                t_a / static_cast<double>(n_a), charge_run(t_a, n_a), q_a);
    const double t_b = 0.05;
    std::printf("%-9s %-7s %6s %22s %22s\n", "stability", "dt", "steps", "Q(0.05)", "exact");
    std::array<double, 3> dts{0.005, 0.0025, 0.001};
    for (double dt : dts) {
        const std::size_t n = static_cast<std::size_t>(t_b / dt + 0.5);
        const double q = charge_run(t_b, n);
        if (std::isnan(q)) return 1;
        std::printf("%-9s %-7g %6zu %22.17g %22.17g\n", "stability", dt, n, q, q0 * std::exp(-t_b / rc));
    }
    // The curves for the picture: each dt's Euler charge at its own steps, one data set per dt, then the
    // exact charge.
    stability.csv.header("t", "Q");
    for (double dt : dts) {
        state q{q0};
        const std::size_t n = static_cast<std::size_t>(t_b / dt + 0.5);
        if (odestep::integrate_n_steps(odestep::euler<state>{}, discharge{}, q, 0.0, dt, n, stability.csv).status !=
            odestep::status::ok)
            return 1;
        stability.next_block();
    }
    for (int i = 0; i <= 500; ++i) {
        const double t = t_b * i / 500;
        stability.csv.row(t, q0 * std::exp(-t / rc));
    }
    return accuracy.good() && stability.good() ? 0 : 1;
}
