// SPDX-License-Identifier: BSL-1.0
// The convergence diagram: every method of the library on one problem, error against step size and
// against the evaluations of the right-hand side it cost.
//
// The problem: the Kepler orbit of eccentricity 0.5 (GM = 1, semi-major axis 1, period 2 pi) from
// perihelion, x = (0.5, 0), v = (0, sqrt(3)), for 1.25 periods. The exact position then is Kepler's: mean
// anomaly pi/2 = E - e sin E, x = (cos E - e, sqrt(1 - e^2) sin E). (Not a whole or half period: there
// the orbit's symmetry cancels the leading error of some methods, and Euler-Cromer looks second order.)
// The error is the distance of the final position from the exact one. Each method runs with N = 16, 32,
// 64, ... steps (two per halving: 16, 23, 32, 45, ...) until its error is below 1e-11 or N = 2^20; the right-hand side counts its own calls
// (Adams' starting steps and the corrector's iterations included). The predictor-corrector's iteration
// does not converge within its cap at the coarsest steps; those runs are reported and left out.
//
// Families: every explicit Runge-Kutta table (on y = (x, v), y' = (v, a)); the Newtonian steppers (x and v
// apart, a(t, x) = -x / |x|^3); the Adams methods (on y, started with RK4).
//
// Data: convergence_rk.csv, convergence_newtonian.csv, convergence_adams.csv, one data set per method,
// each headed by the method's name: N, dt, evaluations, error.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using state = std::array<double, 4>;  // x, y, vx, vy
using vec = std::array<double, 2>;

constexpr double eccentricity = 0.5;
const double t_end = 1.25 * 2 * std::acos(-1.0);
const double v_perihelion = std::sqrt((1 + eccentricity) / (1 - eccentricity));

// The exact position at t_end: Kepler's equation E - e sin E = pi/2 by Newton's method from E = pi/2.
vec exact_position() {
    const double m = std::acos(-1.0) / 2;
    double e_anomaly = m;
    for (int i = 0; i < 50; ++i)
        e_anomaly -= (e_anomaly - eccentricity * std::sin(e_anomaly) - m) / (1 - eccentricity * std::cos(e_anomaly));
    return {std::cos(e_anomaly) - eccentricity, std::sqrt(1 - eccentricity * eccentricity) * std::sin(e_anomaly)};
}
const vec exact = exact_position();
constexpr std::size_t most_steps = std::size_t{1} << 20;

struct kepler_rhs {
    std::size_t* calls;
    state operator()(double, const state& y) const noexcept {
        ++*calls;
        const double r2 = y[0] * y[0] + y[1] * y[1];
        const double r3 = r2 * std::sqrt(r2);
        return {y[2], y[3], -y[0] / r3, -y[1] / r3};
    }
};

struct kepler_accel {
    std::size_t* calls;
    vec operator()(double, const vec& x) const noexcept {
        ++*calls;
        const double r2 = x[0] * x[0] + x[1] * x[1];
        const double r3 = r2 * std::sqrt(r2);
        return {-x[0] / r3, -x[1] / r3};
    }
};

struct outcome {
    odestep::status status;
    vec x;
};

template <class Stepper>
outcome first_order(std::size_t n, std::size_t& calls) {
    Stepper stepper;  // fresh: the Adams methods keep a history
    state y{1 - eccentricity, 0.0, 0.0, v_perihelion};
    const auto r = odestep::integrate_n_steps(stepper, kepler_rhs{&calls}, y, 0.0, t_end / static_cast<double>(n), n);
    return {r.status, {y[0], y[1]}};
}

template <class Stepper>
outcome newtonian(std::size_t n, std::size_t& calls) {
    Stepper stepper;
    vec x{1 - eccentricity, 0.0};
    vec v{0.0, v_perihelion};
    const auto r =
        odestep::integrate_n_steps(stepper, kepler_accel{&calls}, x, v, 0.0, t_end / static_cast<double>(n), n);
    return {r.status, x};
}

// Runs one method at N = 16, 32, ... and prints and writes each point.
template <class Run>
bool sweep(const char* family, const char* name, int order, Run run, example::csv_file& out) {
    out.csv.header(name, "dt", "evaluations", "error");
    for (int k = 0;; ++k) {
        // N = 16 2^(k/2), rounded: two points per halving of the step
        const std::size_t n = static_cast<std::size_t>(std::lround(16.0 * std::pow(2.0, k / 2.0)));
        if (n > most_steps) break;
        std::size_t calls = 0;
        const outcome o = run(n, calls);
        if (o.status == odestep::status::no_convergence) {  // the corrector's cap, at a coarse step: no point
            std::printf("conv_stopped %-9s %-26s %zu %s\n", family, name, n, odestep::to_string(o.status));
            continue;
        }
        if (o.status != odestep::status::ok) return false;
        const double dt = t_end / static_cast<double>(n);
        const double error = std::hypot(o.x[0] - exact[0], o.x[1] - exact[1]);
        std::printf("conv %-9s %-26s %d %8zu %.10e %9zu %.6e %.17g %.17g\n", family, name, order, n, dt, calls, error,
                    o.x[0], o.x[1]);
        out.csv.row(n, dt, calls, error);
        if (error < 1e-11) break;
    }
    out.next_block();
    return true;
}

template <template <class> class Stepper>
bool rk(const char* name, example::csv_file& out) {
    using S = Stepper<state>;
    return sweep("rk", name, S::order, first_order<S>, out);
}

template <template <class> class Stepper>
bool newton(const char* name, example::csv_file& out) {
    using S = Stepper<vec>;
    return sweep("newtonian", name, S::order, newtonian<S>, out);
}

template <template <class> class Stepper>
bool adams(const char* name, example::csv_file& out) {
    using S = Stepper<state>;
    return sweep("adams", name, S::order, first_order<S>, out);
}

// The Adams aliases take a second (defaulted) template parameter, the starter.
template <class State>
using ab2 = odestep::adams_bashforth2<State>;
template <class State>
using ab3 = odestep::adams_bashforth3<State>;
template <class State>
using ab4 = odestep::adams_bashforth4<State>;
template <class State>
using ab5 = odestep::adams_bashforth5<State>;
template <class State>
using abm4 = odestep::adams_bashforth_moulton4<State>;
}  // namespace

int main(int argc, char** argv) {
    example::csv_file rk_out(argc, argv, "convergence_rk.csv");
    example::csv_file newton_out(argc, argv, "convergence_newtonian.csv");
    example::csv_file adams_out(argc, argv, "convergence_adams.csv");
    std::printf("# Kepler e = %g, 1.25 periods from perihelion; exact x = (%.17g, %.17g); N = 16 ... 2^20 steps\n",
                eccentricity, exact[0], exact[1]);
    std::printf("conv %-9s %-26s %s %8s %16s %9s %12s %s\n", "family", "method", "p", "N", "dt", "evals", "error",
                "x y");
    bool ok = rk<odestep::euler>("euler", rk_out);
    ok = ok && rk<odestep::midpoint>("midpoint", rk_out);
    ok = ok && rk<odestep::heun>("heun", rk_out);
    ok = ok && rk<odestep::ralston2>("ralston2", rk_out);
    ok = ok && rk<odestep::kutta3>("kutta3", rk_out);
    ok = ok && rk<odestep::ssprk3>("ssprk3", rk_out);
    ok = ok && rk<odestep::bogacki_shampine32>("bogacki_shampine32", rk_out);
    ok = ok && rk<odestep::rk4>("rk4", rk_out);
    ok = ok && rk<odestep::rk38>("rk38", rk_out);
    ok = ok && rk<odestep::fehlberg45>("fehlberg45", rk_out);
    ok = ok && rk<odestep::cash_karp54>("cash_karp54", rk_out);
    ok = ok && rk<odestep::dormand_prince54>("dormand_prince54", rk_out);
    ok = ok && rk<odestep::fehlberg78>("fehlberg78", rk_out);
    ok = ok && rk<odestep::dop853>("dop853", rk_out);

    ok = ok && newton<odestep::newtonian_euler>("newtonian_euler", newton_out);
    ok = ok && newton<odestep::newtonian_midpoint>("newtonian_midpoint", newton_out);
    ok = ok && newton<odestep::euler_cromer>("euler_cromer", newton_out);
    ok = ok && newton<odestep::euler_cromer_drift_first>("euler_cromer_drift_first", newton_out);
    ok = ok && newton<odestep::half_step>("half_step", newton_out);
    ok = ok && newton<odestep::newtonian_euler_richardson>("newtonian_euler_richardson", newton_out);
    ok = ok && newton<odestep::velocity_verlet>("velocity_verlet", newton_out);
    ok = ok && newton<odestep::position_verlet>("position_verlet", newton_out);
    ok = ok && newton<odestep::leapfrog_position_form>("leapfrog_position_form", newton_out);
    ok = ok && newton<odestep::beeman>("beeman", newton_out);
    ok = ok && newton<odestep::predictor_corrector>("predictor_corrector", newton_out);
    ok = ok && newton<odestep::forest_ruth>("forest_ruth", newton_out);
    ok = ok && newton<odestep::blanes_moan4>("blanes_moan4", newton_out);
    ok = ok && newton<odestep::yoshida6>("yoshida6", newton_out);

    ok = ok && adams<ab2>("adams_bashforth2", adams_out);
    ok = ok && adams<ab3>("adams_bashforth3", adams_out);
    ok = ok && adams<ab4>("adams_bashforth4", adams_out);
    ok = ok && adams<ab5>("adams_bashforth5", adams_out);
    ok = ok && adams<abm4>("adams_bashforth_moulton4", adams_out);
    return ok && rk_out.good() && newton_out.good() && adams_out.good() ? 0 : 1;
}
