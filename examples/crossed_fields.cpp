// SPDX-License-Identifier: BSL-1.0
// Course material: a charged particle in crossed E and B fields (m = q = 1): Boris against RK4, checking
// the E x B / B^2 drift velocity and the gyroradius.
//
// E = 0.5 y-hat, B = 1 z-hat; the particle starts at the origin at rest across the fields, moving at 0.2
// along B. The exact motion is a cycloid drifting along x at E/B = 0.5 (the E x B / B^2 drift) with
// gyroradius |v_perp - v_E| / omega_c = 0.5 (omega_c = qB/m = 1), and uniform motion along z. Each method
// runs to t = 1000 (about 159 gyro-periods) at dt = 0.1 and 0.5, and the program prints what it measured:
//   drift    the guiding centre's velocity along x, (X(t) - X(0)) / t, with X = x + (v x B) / (omega_c B)
//   r_L      the Larmor radius |v_perp - v_E| / omega_c from the final velocity
//   orbit_r  half the peak-to-peak excursion of y (across the drift) over the last tenth of the run
// next to the exact E/B and v_perp / omega_c. The Boris pusher keeps x at the step times and v half a step
// behind: `stagger` moves the initial v back by dt/2 and `synchronize` brings the final v to t.
#include <odestep/newtonian/boris.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace {

using vec3 = std::array<double, 3>;
using state6 = std::array<double, 6>;  // x, y, z, v_x, v_y, v_z for RK4

constexpr double e_field = 0.5;      // E = e_field y-hat
constexpr double b_field = 1.0;      // B = b_field z-hat
constexpr double omega_c = b_field;  // q B / m with q = m = 1
constexpr double t_end = 1000.0;
constexpr vec3 x_start{0.0, 0.0, 0.0};
constexpr vec3 v_start{0.0, 0.0, 0.2};

struct crossed_fields {
    void operator()(double, const vec3&, vec3& E, vec3& B) const noexcept {
        E = {0.0, e_field, 0.0};
        B = {0.0, 0.0, b_field};
    }
};

// The same motion as a first-order system for RK4: x' = v, v' = (q/m) (E + v x B).
struct lorentz {
    void operator()(double, const state6& y, state6& dydt) const noexcept {
        dydt = {y[3], y[4], y[5], y[4] * b_field, e_field - y[3] * b_field, 0.0};
    }
};

// x component of the guiding centre x + (v x B) / (omega_c B); (v x B)_x = v_y B for B along z.
double guiding_centre_x(const vec3& x, const vec3& v) { return x[0] + v[1] * b_field / (omega_c * b_field); }

// |v_perp - v_E| / omega_c, v_E = (E/B) x-hat.
double larmor_radius(const vec3& v) { return std::hypot(v[0] - e_field / b_field, v[1]) / omega_c; }

// Tracks y over the last tenth of the steps.
struct excursion {
    std::size_t from_step;
    std::size_t seen = 0;
    double y_min = 0.0, y_max = 0.0;
    void see(double y) {
        if (seen++ < from_step) return;
        if (seen == from_step + 1 || y < y_min) y_min = y;
        if (seen == from_step + 1 || y > y_max) y_max = y;
    }
    double half_range() const { return (y_max - y_min) / 2; }
};

void print(const char* method, double dt, std::size_t steps, double drift, double r_l, double orbit_r) {
    std::printf("%-6s %-4g %6zu %22.15e %5g %22.15e %22.15e %5g\n", method, dt, steps, drift, e_field / b_field, r_l,
                orbit_r, larmor_radius(v_start));
}

int run_boris(double dt) {
    const std::size_t steps = static_cast<std::size_t>(t_end / dt + 0.5);
    const odestep::boris<vec3> pusher;  // q/m = 1
    const crossed_fields fields;
    vec3 x = x_start, v = v_start;
    excursion y_range{steps - steps / 10};
    if (pusher.stagger(fields, x, v, 0.0, dt) != odestep::status::ok) return 1;  // v(0) -> v(-dt/2)
    const auto r = odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, steps,
                                              [&](double, const vec3& xn, const vec3&) { y_range.see(xn[1]); });
    if (r.status != odestep::status::ok) return 1;
    if (pusher.synchronize(fields, x, v, r.t, dt) != odestep::status::ok) return 1;  // v(t - dt/2) -> v(t)
    const double drift = (guiding_centre_x(x, v) - guiding_centre_x(x_start, v_start)) / r.t;
    print("boris", dt, r.steps, drift, larmor_radius(v), y_range.half_range());
    return 0;
}

int run_rk4(double dt) {
    const std::size_t steps = static_cast<std::size_t>(t_end / dt + 0.5);
    state6 y{x_start[0], x_start[1], x_start[2], v_start[0], v_start[1], v_start[2]};
    excursion y_range{steps - steps / 10};
    const auto r = odestep::integrate_n_steps(odestep::rk4<state6>{}, lorentz{}, y, 0.0, dt, steps,
                                              [&](double, const state6& yn) { y_range.see(yn[1]); });
    if (r.status != odestep::status::ok) return 1;
    const vec3 x{y[0], y[1], y[2]}, v{y[3], y[4], y[5]};
    const double drift = (guiding_centre_x(x, v) - guiding_centre_x(x_start, v_start)) / r.t;
    print("rk4", dt, r.steps, drift, larmor_radius(v), y_range.half_range());
    return 0;
}

}  // namespace

int main() {
    std::printf("# m = q = 1, E = %g y-hat, B = %g z-hat, x(0) = 0, v(0) = (%g, %g, %g), to t = %g\n", e_field, b_field,
                v_start[0], v_start[1], v_start[2], t_end);
    std::printf("# exact: drift E x B / B^2 = (E/B) x-hat, gyroradius v_perp / omega_c = |v_perp - v_E| / omega_c\n");
    std::printf("%-6s %-4s %6s %22s %5s %22s %22s %5s\n", "method", "dt", "steps", "drift", "E/B", "r_L", "orbit_r",
                "v_perp/omega_c");
    int failed = 0;
    for (double dt : {0.1, 0.5}) {
        failed += run_boris(dt);
        failed += run_rk4(dt);
    }
    return failed;
}
