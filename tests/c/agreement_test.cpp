// SPDX-License-Identifier: BSL-1.0
// The C API agrees with the C++ library: every status name is the C++ one (every status code has the C++
// enum's value: src/capi.cpp checks it at compile time), and C runs give the C++ results bit for bit (same method, same system, same steps; the C state is padded
// to ODESTEP_C_MAX_STATES with zeros, which changes no operation on the first n components).
#include <array>
#include <cstdio>
#include <cstring>

#include "agree.hpp"
#include "odestep/events/events.hpp"
#include "odestep/integrate.hpp"
#include "odestep/multistep/adams.hpp"
#include "odestep/newtonian/classic.hpp"
#include "odestep/newtonian/splitting.hpp"
#include "odestep/odestep.h"
#include "odestep/rk/explicit_rk.hpp"
#include "odestep/status.hpp"

namespace {

using agree::failures;

// The status values agree at compile time in the library itself (src/capi.cpp), so that no build of
// odestep_c can have them differ.

// Every status name agrees too (the C function wraps to_string).
void test_names() {
    for (int i = 0; i <= 17; ++i) {
        AGREE(std::strcmp(odestep_status_name(static_cast<odestep_status>(i)),
                          odestep::to_string(static_cast<odestep::status>(i))) == 0);
    }
}

// Lorenz, as C and as C++.
void lorenz_c(double, const double* y, double* dydt, void*) {
    dydt[0] = 10.0 * (y[1] - y[0]);
    dydt[1] = y[0] * (28.0 - y[2]) - y[1];
    dydt[2] = y[0] * y[1] - 8.0 / 3.0 * y[2];
}
using state3 = std::array<double, 3>;
void lorenz_cpp(double t, const state3& y, state3& dydt) { lorenz_c(t, y.data(), dydt.data(), nullptr); }

template <class Stepper>
void compare_first_order(const odestep_method_d* method, const char* name) {
    odestep_stepper_d s;
    AGREE(odestep_stepper_init_d(&s, method) == ODESTEP_OK);
    const odestep_system_d sys{lorenz_c, nullptr, 3};
    double yc[3] = {1.0, 1.0, 1.0};
    state3 ycpp{1.0, 1.0, 1.0};
    AGREE(odestep_integrate_d(&s, &sys, yc, 0.0, 2.0, 0.01, nullptr, nullptr, nullptr) == ODESTEP_OK);
    AGREE(odestep::integrate(Stepper{}, lorenz_cpp, ycpp, 0.0, 2.0, 0.01).status == odestep::status::ok);
    const bool same = yc[0] == ycpp[0] && yc[1] == ycpp[1] && yc[2] == ycpp[2];
    if (!same)
        std::printf("%s: C %.17g %.17g %.17g, C++ %.17g %.17g %.17g\n", name, yc[0], yc[1], yc[2], ycpp[0], ycpp[1],
                    ycpp[2]);
    AGREE(same);
}

void compare_estimates() {
    odestep_stepper_d s;
    AGREE(odestep_stepper_init_d(&s, &odestep_dop853_d) == ODESTEP_OK);
    const odestep_system_d sys{lorenz_c, nullptr, 3};
    double yc[3] = {1.0, 1.0, 1.0};
    double e1[3];
    double e2[3];
    state3 ycpp{1.0, 1.0, 1.0};
    state3 f1;
    state3 f2;
    AGREE(odestep_step_error_d(&s, &sys, yc, 0.0, 0.01, e1, e2) == ODESTEP_OK);
    AGREE(odestep::dop853<state3>{}.step(lorenz_cpp, ycpp, 0.0, 0.01, f1, f2) == odestep::status::ok);
    for (std::size_t i = 0; i < 3; ++i) AGREE(yc[i] == ycpp[i] && e1[i] == f1[i] && e2[i] == f2[i]);
}

using state2 = std::array<double, 2>;
void springs_c(double, const double* x, double* a, void*) {
    a[0] = -2.0 * x[0] + x[1];
    a[1] = x[0] - 2.0 * x[1];
}
state2 springs_cpp(double t, const state2& x) {
    state2 a;
    springs_c(t, x.data(), a.data(), nullptr);
    return a;
}

template <class Stepper>
void compare_newton(const odestep_method_d* method, const char* name) {
    odestep_stepper_d s;
    AGREE(odestep_stepper_init_d(&s, method) == ODESTEP_OK);
    const odestep_newton_d sys{springs_c, nullptr, 2};
    double xc[2] = {1.0, 0.0};
    double vc[2] = {0.0, 0.5};
    state2 x{1.0, 0.0};
    state2 v{0.0, 0.5};
    AGREE(odestep_integrate_newton_d(&s, &sys, xc, vc, 0.0, 10.0, 0.05, nullptr, nullptr, nullptr) == ODESTEP_OK);
    AGREE(odestep::integrate(Stepper{}, springs_cpp, x, v, 0.0, 10.0, 0.05).status == odestep::status::ok);
    const bool same = xc[0] == x[0] && xc[1] == x[1] && vc[0] == v[0] && vc[1] == v[1];
    if (!same) std::printf("%s: Newtonian runs differ\n", name);
    AGREE(same);
    // One step at a time through the C API (each evaluating afresh) is the C++ single step too.
    double xs[2] = {1.0, 0.0};
    double vs[2] = {0.0, 0.5};
    state2 x1{1.0, 0.0};
    state2 v1{0.0, 0.5};
    AGREE(odestep_step_newton_d(&s, &sys, xs, vs, 0.0, 0.05) == ODESTEP_OK);
    Stepper fresh{};
    AGREE(fresh.step(springs_cpp, x1, v1, 0.0, 0.05) == odestep::status::ok);
    AGREE(xs[0] == x1[0] && xs[1] == x1[1] && vs[0] == v1[0] && vs[1] == v1[1]);
}

// The event loop: a bouncing ball ticked through the C API and through odestep::event_stepper, the same
// firing times and states bit for bit (the C loop's unused event slots never fire and change nothing).
void ball_c(double, const double* y, double* dydt, void*) {
    dydt[0] = y[1];
    dydt[1] = -9.81;
}
double height_c(double, const double* y, void*) { return y[0]; }
odestep_event_result bounce_c(double, double* y, void*) {
    y[1] = -0.8 * y[1];
    return ODESTEP_PROCEED;
}
void compare_events() {
    using state = std::array<double, 2>;
    odestep_event_loop_d loop;
    const odestep_system_d sys{ball_c, nullptr, 2};
    odestep_event_d ground{};
    ground.g = height_c;
    ground.direction = ODESTEP_FALLING;
    ground.action = bounce_c;
    double yc[2] = {1.0, 0.0};
    AGREE(odestep_event_loop_start_d(&loop, &odestep_rk4_d, &ground, 1, nullptr, &sys, yc, 0.0, 0.01) == ODESTEP_OK);

    auto f = [](double t, const state& y, state& dydt) { ball_c(t, y.data(), dydt.data(), nullptr); };
    auto g = [](double, const state& y) { return y[0]; };
    auto bounce = [](double, state& y) {
        y[1] = -0.8 * y[1];
        return odestep::event_result::proceed;
    };
    auto cpp = odestep::make_event_stepper(
        odestep::rk4<state>{}, odestep::watch(odestep::make_event<state>(g, odestep::direction::falling, bounce)));
    state y{1.0, 0.0};
    AGREE(cpp.start(0.0, 0.01, y) == odestep::status::ok);
    int firings = 0;
    for (int k = 0; k < 300; ++k) {
        odestep_tick_d tick;
        const odestep_status sc = odestep_event_loop_tick_d(&loop, &sys, yc, &tick);
        const auto r = cpp.tick(f, y);
        AGREE(static_cast<int>(sc) == static_cast<int>(r.status) && tick.t == r.t && tick.fired == r.fired);
        for (std::size_t i = 0; i < tick.fired && i < r.fired; ++i) AGREE(tick.firings[i].t == r.firings[i].t);
        AGREE(yc[0] == y[0] && yc[1] == y[1]);
        firings += static_cast<int>(r.fired);
    }
    AGREE(firings >= 4);
}

// The Newtonian event loop against event_stepper with velocity Verlet on x'' = -g, bouncing.
void fall_c(double, const double*, double* a, void*) { a[0] = -9.81; }
double floor_c(double, const double* x, const double*, void*) { return x[0]; }
odestep_event_result kick_c(double, double*, double* v, void*) {
    v[0] = -0.8 * v[0];
    return ODESTEP_PROCEED;
}
void compare_newton_events() {
    using state = std::array<double, 1>;
    odestep_newton_event_loop_d loop;
    const odestep_newton_d sys{fall_c, nullptr, 1};
    odestep_newton_event_d ground{};
    ground.g = floor_c;
    ground.direction = ODESTEP_FALLING;
    ground.action = kick_c;
    double xc = 1.0;
    double vc = 0.0;
    AGREE(odestep_newton_event_loop_start_d(&loop, &odestep_velocity_verlet_d, &ground, 1, nullptr, &sys, &xc, &vc, 0.0,
                                            0.01) == ODESTEP_OK);
    auto a = [](double, const state&) { return state{-9.81}; };
    auto g = [](double, const state& x, const state&) { return x[0]; };
    auto kick = [](double, state&, state& v) {
        v[0] = -0.8 * v[0];
        return odestep::event_result::proceed;
    };
    auto cpp =
        odestep::make_event_stepper(odestep::velocity_verlet<state>{},
                                    odestep::watch(odestep::make_event<state>(g, odestep::direction::falling, kick)));
    state x{1.0};
    state v{0.0};
    AGREE(cpp.start(0.0, 0.01, x, v) == odestep::status::ok);
    int firings = 0;
    for (int k = 0; k < 300; ++k) {
        odestep_tick_d tick;
        const odestep_status sc = odestep_newton_event_loop_tick_d(&loop, &sys, &xc, &vc, &tick);
        const auto r = cpp.tick(a, x, v);
        AGREE(static_cast<int>(sc) == static_cast<int>(r.status) && tick.t == r.t && tick.fired == r.fired);
        for (std::size_t i = 0; i < tick.fired && i < r.fired; ++i) AGREE(tick.firings[i].t == r.firings[i].t);
        AGREE(xc == x[0] && vc == v[0]);
        firings += static_cast<int>(r.fired);
    }
    AGREE(firings >= 4);
}

}  // namespace

int main() {
    test_names();
    compare_first_order<odestep::euler<state3>>(&odestep_euler_d, "euler");
    compare_first_order<odestep::euler_richardson<state3>>(&odestep_euler_richardson_d, "euler_richardson");
    compare_first_order<odestep::heun<state3>>(&odestep_heun_d, "heun");
    compare_first_order<odestep::rk4<state3>>(&odestep_rk4_d, "rk4");
    compare_first_order<odestep::bogacki_shampine32<state3>>(&odestep_bs32_d, "bs32");
    compare_first_order<odestep::dormand_prince54<state3>>(&odestep_dp54_d, "dp54");
    compare_first_order<odestep::dop853<state3>>(&odestep_dop853_d, "dop853");
    compare_first_order<odestep::adams_bashforth4<state3>>(&odestep_ab4_d, "ab4");
    compare_first_order<odestep::adams_bashforth_moulton4<state3>>(&odestep_abm4_d, "abm4");
    compare_estimates();
    compare_events();
    compare_newton_events();
    compare_newton<odestep::euler_cromer<state2>>(&odestep_euler_cromer_d, "euler_cromer");
    compare_newton<odestep::velocity_verlet<state2>>(&odestep_velocity_verlet_d, "velocity_verlet");
    compare_newton<odestep::forest_ruth<state2>>(&odestep_forest_ruth_d, "forest_ruth");
    std::printf("c api agreement: %d failed checks\n", failures);
    return failures == 0 ? 0 : 1;
}
