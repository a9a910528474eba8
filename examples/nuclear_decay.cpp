// SPDX-License-Identifier: BSL-1.0
// Course material: multiple nuclear decays (problem 3.12), a chain A -> B -> C with RK4 against Bateman's
// closed form.
//
// (a) 76Kr (half-life 14.8 h) -> 76Br (16.1 h) -> 76Se (stable), 1 g of pure 76Kr, over one week. Time is
//     measured in units of the shorter half-life, 14.8 h (so lambda_Kr = ln 2), dt = 0.01 (8.9 minutes).
// (b) 28Mn (21 h) -> 28Al (2.31 min) -> 28Si, over five days, in hours. The two time scales differ 545-fold:
//     the full chain needs dt well below the 28Al lifetime (dt = 0.01 h here), while the simplifying
//     assumption that 28Al decays as soon as it is made (dSi/dt = lambda_Mn Mn) allows dt = 0.5 h. The
//     assumption errs by exactly the 28Al present, about lambda_Mn / lambda_Al of the 28Mn.
// (c) needs the decay scheme of 211Rn, a figure whose half-lives the course text does not give: not done.
//
// Data: nuclear_decay.csv (t in hours, Kr, Br, Se from RK4, then Bateman's values).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using chain = std::array<double, 3>;  // parent, daughter, stable end (grams)

struct decay_chain {
    double la, lb;  // decay constants of the parent and the daughter
    chain operator()(double, const chain& n) const noexcept { return {-la * n[0], la * n[0] - lb * n[1], lb * n[1]}; }
};

// Bateman's solution from a pure parent of mass 1: the parent exp(-la t), the daughter
// la / (lb - la) (exp(-la t) - exp(-lb t)), the end product the rest.
chain bateman(double la, double lb, double t) {
    const double a = std::exp(-la * t);
    const double b = la / (lb - la) * (std::exp(-la * t) - std::exp(-lb * t));
    return {a, b, 1.0 - a - b};
}
}  // namespace

int main(int argc, char** argv) {
    const double ln2 = std::log(2.0);
    example::csv_file data(argc, argv, "nuclear_decay.csv");
    data.csv.header("t_hours", "Kr", "Br", "Se", "Kr_bateman", "Br_bateman", "Se_bateman");

    // (a) in units of 14.8 h
    const double unit_h = 14.8;
    const decay_chain kr{ln2, ln2 * unit_h / 16.1};
    const double week = 7 * 24 / unit_h;
    const double dt = 0.01;
    chain n{1.0, 0.0, 0.0};
    double worst = 0.0;
    std::printf("# (a) 76Kr (14.8 h) -> 76Br (16.1 h) -> 76Se, 1 g, time unit 14.8 h, RK4 dt = %g, one week\n", dt);
    const auto r = odestep::integrate(odestep::rk4<chain>{}, kr, n, 0.0, week, dt, [&](double t, const chain& m) {
        const chain exact = bateman(kr.la, kr.lb, t);
        for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(m[i] - exact[i]));
        data.csv(t * unit_h, m, exact);
    });
    if (r.status != odestep::status::ok) return 1;
    std::printf("%-8s %-6s %24s %24s %24s\n", "a", "t_h", "Kr_g", "Br_g", "Se_g");
    for (double hours : {24.0, 48.0, 72.0, 168.0}) {
        chain m{1.0, 0.0, 0.0};
        if (odestep::integrate(odestep::rk4<chain>{}, kr, m, 0.0, hours / unit_h, dt).status != odestep::status::ok)
            return 1;
        std::printf("%-8s %-6g %24.17g %24.17g %24.17g\n", "a", hours, m[0], m[1], m[2]);
    }
    std::printf("a_max_error %.6e over %zu steps\n", worst, r.steps);
    // The daughter's largest amount: at t* = ln(lb / la) / (lb - la), from Bateman's derivative.
    double peak = 0.0;
    double peak_t = 0.0;
    chain m{1.0, 0.0, 0.0};
    if (odestep::integrate(odestep::rk4<chain>{}, kr, m, 0.0, week, dt, [&](double t, const chain& s) {
            if (s[1] > peak) {
                peak = s[1];
                peak_t = t;
            }
        }).status != odestep::status::ok)
        return 1;
    std::printf("a_peak_Br t_h %.6f grams %.17g (on the grid of dt)\n", peak_t * unit_h, peak);

    // (b) in hours
    const decay_chain mn{ln2 / 21.0, ln2 / (2.31 / 60.0)};
    std::printf("# (b) 28Mn (21 h) -> 28Al (2.31 min) -> 28Si, time in hours, 5 days\n");
    std::printf("%-8s %-6s %8s %24s %24s %24s\n", "b", "t_h", "dt_h", "Mn", "Al", "Si");
    for (double hours : {12.0, 48.0, 120.0}) {
        chain full{1.0, 0.0, 0.0};
        if (odestep::integrate(odestep::rk4<chain>{}, mn, full, 0.0, hours, 0.01).status != odestep::status::ok)
            return 1;
        std::printf("%-8s %-6g %8g %24.17g %24.17g %24.17g\n", "b_full", hours, 0.01, full[0], full[1], full[2]);
        // 28Al decays at once: Mn' = -lambda_Mn Mn, Si' = lambda_Mn Mn, nothing kept as 28Al.
        chain reduced{1.0, 0.0, 0.0};
        const auto instant = [&mn](double, const chain& s) { return chain{-mn.la * s[0], 0.0, mn.la * s[0]}; };
        if (odestep::integrate(odestep::rk4<chain>{}, instant, reduced, 0.0, hours, 0.5).status != odestep::status::ok)
            return 1;
        std::printf("%-8s %-6g %8g %24.17g %24.17g %24.17g\n", "b_reduced", hours, 0.5, reduced[0], reduced[1],
                    reduced[2]);
    }
    return data.good() ? 0 : 1;
}
