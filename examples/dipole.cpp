// SPDX-License-Identifier: BSL-1.0
// Course material: motion in a magnetic dipole field (problem 3.15), an electron in the Earth's Van Allen
// belt, B = B0 (re/r)^3 [3 (p.r) r - p] with B0 = 3.5e-5 T at the equator, p = -z (the field points north
// at the equator), relativistic mass (gamma) included.
//
// Units: lengths in Earth radii re = 6.37e6 m, speeds in c, time in re/c = 21.25 ms, B in B0. The electron's
// q/m is then -Omega0 = -(e/m_e) B0 re / c = -1.308e5, and its gyration frequency Omega0 |B| / gamma.
// The electron starts on the equator at 2 re, with a pitch angle of 30 degrees.
//
// Two energies. 10 MeV (ten times the course's 1 MeV): the gyroradius is 0.0013 re, and guiding-centre
// theory holds to a fraction of a percent: the electron gyrates, bounces between mirror points where
// B = B_eq / sin^2(alpha_eq), and drifts eastwards round the Earth, and its magnetic moment
// mu = u_perp^2 / |B| (relativistic: p_perp^2 / (2 m B)) is an adiabatic invariant. 1 GeV (the course's
// "about 1000 times" for a picture): the gyroradius is 0.12 re, the gyration visible in the orbit.
//
// Each energy runs with the relativistic Boris pusher (odestep::boris_relativistic) and with RK4 on
// (x, u), u = gamma v, at the same step, 1/40 of the shortest gyration period (at the mirror point).
// Printed per run: |u| at the end over |u| at the start (Boris keeps its half-step |u| exactly in a pure
// magnetic field; RK4 loses energy), the largest change of mu and its change between the first and the
// last northward equator crossing (the secular part), and, from the guiding centre
// X = x + (u x B) / ((q/m) B^2):
// the mirror latitude, the bounce period (between northward equator crossings) and the drift in longitude
// per bounce. The checker computes the last three from guiding-centre theory.
//
// Data: dipole_orbit.csv (the 1 GeV Boris orbit: t, x, y, z, u), dipole_invariants.csv (t, mu/mu0 and
// |u|/|u0| for Boris and for RK4, 10 MeV).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using vec = std::array<double, 3>;
using state = std::array<double, 6>;  // x, u for RK4

const double pi = std::acos(-1.0);
constexpr double electron_mass_mev = 0.51099895;
constexpr double e_over_m = 1.75882001076e11;  // C/kg
constexpr double b0 = 3.5e-5;                  // T
constexpr double earth_radius = 6.37e6;        // m
constexpr double light = 2.99792458e8;         // m/s
const double omega0 = e_over_m * b0 * earth_radius / light;
const double qm = -omega0;  // the electron's q/m in these units
constexpr double shell = 2.0;
const double pitch = pi / 6;

// B = [3 (p.r^) r^ - p] / r^3 with p = -z: (-3 x z, -3 y z, r^2 - 3 z^2) / r^5.
vec dipole(const vec& x) {
    const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    const double r5 = r2 * r2 * std::sqrt(r2);
    return {-3 * x[0] * x[2] / r5, -3 * x[1] * x[2] / r5, (r2 - 3 * x[2] * x[2]) / r5};
}

struct fields {
    void operator()(double, const vec& x, vec&, vec& b) const noexcept { b = dipole(x); }
};

struct lorentz {  // x' = u / gamma, u' = (q/m) (u / gamma) x B, c = 1
    state operator()(double, const state& y) const noexcept {
        const vec b = dipole({y[0], y[1], y[2]});
        const double gamma = std::sqrt(1 + y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
        const double k = qm / gamma;
        return {y[3] / gamma,
                y[4] / gamma,
                y[5] / gamma,
                k * (y[4] * b[2] - y[5] * b[1]),
                k * (y[5] * b[0] - y[3] * b[2]),
                k * (y[3] * b[1] - y[4] * b[0])};
    }
};

double dot(const vec& a, const vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
vec cross(const vec& a, const vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double magnetic_moment(const vec& x, const vec& u) {
    const vec b = dipole(x);
    const double bb = dot(b, b);
    const double upar = dot(u, b);
    return (dot(u, u) - upar * upar / bb) / std::sqrt(bb);
}

// What one run measured, from the guiding centre at every step.
struct measures {
    double u0 = 0.0, mu0 = 0.0;
    double mu_worst = 0.0;
    double u_ratio = 0.0;
    // equator crossings of the guiding centre going north: times and longitudes
    std::size_t crossings = 0;
    double first_t = 0.0, last_t = 0.0, first_phi = 0.0, last_phi = 0.0, first_mu = 0.0, last_mu = 0.0;
    double phi_unwrapped = 0.0, prev_phi = 0.0, prev_z = 0.0;
    bool started = false;
    double lat_max = 0.0;  // largest |latitude| of the guiding centre
    double last_seen_t = -1e9;
    void see(double t, const vec& x, const vec& u) {
        const vec b = dipole(x);
        const vec gc = [&] {
            const vec s = cross(u, b);
            const double k = 1 / (qm * dot(b, b));
            return vec{x[0] + k * s[0], x[1] + k * s[1], x[2] + k * s[2]};
        }();
        const double mu = magnetic_moment(x, u);
        double phi = std::atan2(gc[1], gc[0]);
        if (!started) {
            u0 = std::sqrt(dot(u, u));
            mu0 = mu;
            started = true;
            prev_phi = phi;
            phi_unwrapped = phi;
            prev_z = gc[2];
        }
        double dphi = phi - prev_phi;
        if (dphi > pi) dphi -= 2 * pi;
        if (dphi < -pi) dphi += 2 * pi;
        phi_unwrapped += dphi;
        prev_phi = phi;
        mu_worst = std::fmax(mu_worst, std::fabs(mu / mu0 - 1));
        u_ratio = std::sqrt(dot(u, u)) / u0;
        const double lat = std::asin(gc[2] / std::sqrt(dot(gc, gc)));
        lat_max = std::fmax(lat_max, std::fabs(lat));
        // northward crossing of the equator (z from <= 0 to > 0), ignoring gyration-scale re-crossings
        if (prev_z <= 0 && gc[2] > 0 && t - last_seen_t > 1.0) {
            const double frac = -prev_z / (gc[2] - prev_z);  // linear in the step (the crossing is fast)
            const double tc = t - (1 - frac) * step;
            const double pc = phi_unwrapped - (1 - frac) * dphi;
            if (crossings == 0) {
                first_t = tc;
                first_phi = pc;
                first_mu = mu;
            }
            last_t = tc;
            last_phi = pc;
            last_mu = mu;
            ++crossings;
            last_seen_t = t;
        }
        prev_z = gc[2];
    }
    double step = 0.0;
};

struct setup {
    double kinetic_mev;
    double gamma, u;
    double dt;
};

setup make_setup(double kinetic_mev) {
    setup s{};
    s.kinetic_mev = kinetic_mev;
    s.gamma = 1 + kinetic_mev / electron_mass_mev;
    s.u = std::sqrt(s.gamma * s.gamma - 1);
    // The shortest gyration period, at the mirror point: B_m = B_eq / sin^2(pitch), B_eq = 1 / shell^3.
    const double b_mirror = 1 / (shell * shell * shell) / (std::sin(pitch) * std::sin(pitch));
    s.dt = 2 * pi * s.gamma / (omega0 * b_mirror) / 40;
    return s;
}

vec start_u(const setup& s) { return {0.0, -s.u * std::sin(pitch), s.u * std::cos(pitch)}; }

template <class Observer>
bool run_boris(const setup& s, std::size_t steps, measures& m, Observer&& extra) {
    const odestep::boris_relativistic<vec> pusher(qm, 1.0);
    vec x{shell, 0.0, 0.0};
    vec u = start_u(s);
    m.step = s.dt;
    m.see(0.0, x, u);
    extra(0.0, x, u);
    if (pusher.stagger(fields{}, x, u, 0.0, s.dt) != odestep::status::ok) return false;  // u(0) -> u(-dt/2)
    const double half0 = std::sqrt(dot(u, u));
    for (std::size_t n = 0; n < steps; ++n) {
        const double t = static_cast<double>(n) * s.dt;
        if (pusher.step(fields{}, x, u, t, s.dt) != odestep::status::ok) return false;
        vec synced = u;  // u at the step's time, for the measures (the run goes on with the staggered u)
        const double t1 = static_cast<double>(n + 1) * s.dt;
        if (pusher.synchronize(fields{}, x, synced, t1, s.dt) != odestep::status::ok) return false;
        m.see(t1, x, synced);
        extra(t1, x, synced);
    }
    m.u_ratio = std::sqrt(dot(u, u)) / half0;  // the staggered |u|, which the rotation keeps exactly
    return true;
}

template <class Observer>
bool run_rk4(const setup& s, std::size_t steps, measures& m, Observer&& extra) {
    const vec u0 = start_u(s);
    state y{shell, 0.0, 0.0, u0[0], u0[1], u0[2]};
    m.step = s.dt;
    const auto r = odestep::integrate_n_steps(odestep::rk4<state>{}, lorentz{}, y, 0.0, s.dt, steps,
                                              [&](double t, const state& z) {
                                                  const vec x{z[0], z[1], z[2]};
                                                  const vec u{z[3], z[4], z[5]};
                                                  m.see(t, x, u);
                                                  extra(t, x, u);
                                              });
    return r.status == odestep::status::ok;
}

void print(const char* method, const setup& s, std::size_t steps, const measures& m) {
    const double bounces = static_cast<double>(m.crossings - 1);
    std::printf("dipole %-6s %6g %10.6f %12.6e %8zu %22.15e %12.4e %12.4e %12.6f %3zu %14.9f %14.9e\n", method,
                s.kinetic_mev, s.gamma, s.dt, steps, m.u_ratio - 1, m.mu_worst, m.last_mu / m.first_mu - 1,
                m.lat_max * 180 / pi, m.crossings, (m.last_t - m.first_t) / bounces,
                (m.last_phi - m.first_phi) / bounces);
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file orbit(argc, argv, "dipole_orbit.csv");
    example::csv_file invariants(argc, argv, "dipole_invariants.csv");
    std::printf("# electron in the dipole field, B0 = %g T, re = %g m; units re, c, re/c; Omega0 = %.9e\n", b0,
                earth_radius, omega0);
    const setup slow = make_setup(10.0);
    const vec x0{shell, 0.0, 0.0};
    // The guiding centre at the start, for the checker's theory: X = x + (u x B) / ((q/m) B^2).
    const vec b_start = dipole(x0);
    std::printf("# start: x = (%g, 0, 0), pitch angle %.9f rad, v along -y and +z\n", shell, pitch);
    std::printf("%-6s %-6s %6s %10s %12s %8s %22s %12s %12s %12s %3s %14s %14s\n", "dipole", "method", "MeV", "gamma",
                "dt", "steps", "|u|/|u0|-1", "max|dmu/mu|", "mu_drift", "mirror_deg", "n", "bounce_T", "dphi/bounce");
    for (const setup& s : {slow, make_setup(1000.0)}) {
        const vec su = start_u(s);
        const vec sc = cross(su, b_start);
        const double k = 1 / (qm * dot(b_start, b_start));
        std::printf("start %g MeV guiding_centre_L %.15g u %.15g gamma %.15g\n", s.kinetic_mev, x0[0] + k * sc[0], s.u,
                    s.gamma);
    }

    // 10 MeV: three bounces and a bit, Boris and RK4; mu and |u| written every 100 steps
    const std::size_t slow_steps = static_cast<std::size_t>(3.2 * 8.3 / slow.dt);
    measures boris_slow;
    measures rk4_slow;
    std::size_t count = 0;
    invariants.csv.header("t", "mu_over_mu0", "u_over_u0");
    if (!run_boris(slow, slow_steps, boris_slow, [&](double t, const vec& x, const vec& u) {
            if (count++ % 100 == 0)
                invariants.csv.row(t, magnetic_moment(x, u) / boris_slow.mu0, std::sqrt(dot(u, u)) / boris_slow.u0);
        }))
        return 1;
    invariants.next_block();
    count = 0;
    if (!run_rk4(slow, slow_steps, rk4_slow, [&](double t, const vec& x, const vec& u) {
            if (count++ % 100 == 0)
                invariants.csv.row(t, magnetic_moment(x, u) / rk4_slow.mu0, std::sqrt(dot(u, u)) / rk4_slow.u0);
        }))
        return 1;
    print("boris", slow, slow_steps, boris_slow);
    print("rk4", slow, slow_steps, rk4_slow);

    // 1 GeV: a whole drift round the Earth for the picture
    const setup fast = make_setup(1000.0);
    const std::size_t fast_steps = static_cast<std::size_t>(150.0 / fast.dt);
    measures boris_fast;
    measures rk4_fast;
    orbit.csv.header("t", "x", "y", "z", "ux", "uy", "uz");
    count = 0;
    if (!run_boris(fast, fast_steps, boris_fast, [&](double t, const vec& x, const vec& u) {
            if (count++ % 4 == 0) orbit.csv.row(t, x, u);
        }))
        return 1;
    if (!run_rk4(fast, fast_steps, rk4_fast, [](double, const vec&, const vec&) {})) return 1;
    print("boris", fast, fast_steps, boris_fast);
    print("rk4", fast, fast_steps, rk4_fast);
    return orbit.good() && invariants.good() ? 0 : 1;
}
