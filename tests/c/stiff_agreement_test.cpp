// SPDX-License-Identifier: BSL-1.0
// The C API's stiff steppers and steps with Phi agree with the C++ library on n components:
//   - the fixed-step ones (backward Euler, SDIRK 3, Radau IIA 5, RODAS3) and the transitions bit for bit: the C
//     state and Jacobian are padded to ODESTEP_C_MAX_STATES with zeros, and the padding changes no operation
//     on the first n components (the iteration matrices are block diagonal, Newton's norm is a max norm);
//   - the error-controlled Dormand-Prince and Rodas4 to round-off: their RMS error norm over the padded state
//     is made the n components' by scaling the tolerances (src/capi_stiff_impl.hpp), so that they take the
//     C++ engine's steps; without that scaling their tolerance would be sqrt(MAX / n) times looser and the
//     results would differ at the tolerance's level, not round-off's.
#include <array>
#include <cmath>
#include <cstdio>

#include "agree.hpp"
#include "odestep/adaptive/adaptive_rk.hpp"
#include "odestep/odestep.h"
#include "odestep/rk/implicit_rk.hpp"
#include "odestep/rk/rosenbrock.hpp"
#include "odestep/sensitivity/transition.hpp"
#include "odestep/stiff/substeps.hpp"
#include "odestep/system.hpp"

namespace {

using agree::failures;

// Van der Pol with mu = 10 (mildly stiff, nonlinear, a non-symmetric Jacobian), as C and as C++.
constexpr double mu = 10.0;
void vdp_c(double, const double* y, double* dydt, void*) {
    dydt[0] = y[1];
    dydt[1] = mu * (1.0 - y[0] * y[0]) * y[1] - y[0];
}
void vdp_jacobian_c(double, const double* y, double* j, void*) {
    j[0] = 0.0;
    j[1] = 1.0;
    j[2] = -2.0 * mu * y[0] * y[1] - 1.0;
    j[3] = mu * (1.0 - y[0] * y[0]);
}
using state2 = std::array<double, 2>;
void vdp_cpp(double t, const state2& y, state2& dydt) { vdp_c(t, y.data(), dydt.data(), nullptr); }
void vdp_jacobian_cpp(double t, const state2& y, odestep::jacobian_t<state2>& j) {
    double packed[4];
    vdp_jacobian_c(t, y.data(), packed, nullptr);
    j[0] = {packed[0], packed[1]};
    j[1] = {packed[2], packed[3]};
}

// 200 steps of 0.01 from (2, 0), with the Jacobian or (null) by differences; C and C++ the same bit for bit.
template <class Stepper>
void compare_fixed(const odestep_stiff_method_d* method, bool with_jacobian, const char* name) {
    odestep_stiff_stepper_d s;
    AGREE(odestep_stiff_init_d(&s, method, 2, 0.0, 0.0) == ODESTEP_OK);
    const odestep_jac_system_d sys{vdp_c, with_jacobian ? vdp_jacobian_c : nullptr, nullptr, 2};
    double yc[2] = {2.0, 0.0};
    state2 ycpp{2.0, 0.0};
    const Stepper stepper{};
    bool ok = true;
    for (int i = 0; i < 200 && ok; ++i) {
        const double t = i * 0.01;
        ok = odestep_stiff_step_d(&s, &sys, yc, t, 0.01) == ODESTEP_OK;
        const odestep::status r = with_jacobian
                                      ? stepper.step(odestep::with_jacobian(vdp_cpp, vdp_jacobian_cpp), ycpp, t, 0.01)
                                      : stepper.step(vdp_cpp, ycpp, t, 0.01);
        ok = ok && r == odestep::status::ok;
    }
    AGREE(ok);
    const bool same = yc[0] == ycpp[0] && yc[1] == ycpp[1];
    if (!same) std::printf("%s: C %.17g %.17g, C++ %.17g %.17g\n", name, yc[0], yc[1], ycpp[0], ycpp[1]);
    AGREE(same);
}

// A 0.1 grid to t = 3 at rtol 1e-6, atol 1e-8: C and C++ within 1e-12 relative (the tolerance scaling's
// round-off) where a tolerance sqrt(4) times looser would differ by about 1e-7.
template <class Stepper>
void compare_controlled(const odestep_stiff_method_d* method, const char* name) {
    odestep_stiff_stepper_d s;
    AGREE(odestep_stiff_init_d(&s, method, 2, 1e-6, 1e-8) == ODESTEP_OK);
    const odestep_jac_system_d sys{vdp_c, vdp_jacobian_c, nullptr, 2};
    double yc[2] = {2.0, 0.0};
    state2 ycpp{2.0, 0.0};
    Stepper stepper(odestep::tolerances<state2>::uniform(1e-6, 1e-8));
    bool ok = true;
    double worst = 0.0;
    for (int i = 0; i < 30 && ok; ++i) {
        const double t = i * 0.1;
        ok = odestep_stiff_step_d(&s, &sys, yc, t, 0.1) == ODESTEP_OK;
        ok = ok && stepper.step(odestep::with_jacobian(vdp_cpp, vdp_jacobian_cpp), ycpp, t, 0.1) == odestep::status::ok;
        for (std::size_t k = 0; k < 2; ++k) worst = std::fmax(worst, std::fabs(yc[k] - ycpp[k]) / std::fabs(ycpp[k]));
    }
    AGREE(ok);
    if (!(worst <= 1e-12)) std::printf("%s: C and C++ differ by %.3g relative\n", name, worst);
    AGREE(worst <= 1e-12);
}

// Steps with Phi: y and Phi bit for bit the C++ transition's on n = 2.
template <class Transition>
void compare_transition(const odestep_transition_method_d* method, const char* name) {
    const odestep_jac_system_d sys{vdp_c, vdp_jacobian_c, nullptr, 2};
    double yc[2] = {2.0, 0.0};
    double phic[4] = {0.0, 0.0, 0.0, 0.0};
    state2 ycpp{2.0, 0.0};
    odestep::jacobian_t<state2> phicpp{};
    bool same = true;
    for (int i = 0; i < 20; ++i) {
        const double t = i * 0.01;
        AGREE(odestep_step_transition_d(method, &sys, yc, phic, t, 0.01) == ODESTEP_OK);
        AGREE(Transition{}.step(odestep::with_jacobian(vdp_cpp, vdp_jacobian_cpp), ycpp, phicpp, t, 0.01) ==
              odestep::status::ok);
        same = same && yc[0] == ycpp[0] && yc[1] == ycpp[1];
        for (std::size_t r = 0; r < 2; ++r)
            for (std::size_t c = 0; c < 2; ++c) same = same && phic[2 * r + c] == phicpp[r][c];
    }
    if (!same) std::printf("%s: C and C++ differ\n", name);
    AGREE(same);
}

}  // namespace

int main() {
    compare_fixed<odestep::backward_euler<state2>>(&odestep_backward_euler_d, true, "backward_euler");
    compare_fixed<odestep::backward_euler<state2>>(&odestep_backward_euler_d, false, "backward_euler differences");
    compare_fixed<odestep::sdirk3<state2>>(&odestep_sdirk3_d, true, "sdirk3");
    compare_fixed<odestep::radau_iia5<state2>>(&odestep_radau_iia5_d, true, "radau_iia5");
    compare_fixed<odestep::rodas3<state2>>(&odestep_rodas3_d, true, "rodas3");
    compare_fixed<odestep::radau_iia5<state2>>(&odestep_radau_iia5_d, false, "radau_iia5 differences");
    compare_fixed<odestep::rodas3<state2>>(&odestep_rodas3_d, false, "rodas3 differences");
    compare_controlled<odestep::dormand_prince54_substeps<state2>>(&odestep_dp54_substeps_d, "dp54_substeps");
    compare_controlled<odestep::rodas4_substeps<state2>>(&odestep_rodas4_substeps_d, "rodas4_substeps");
    compare_transition<odestep::rk4_transition<state2>>(&odestep_rk4_transition_d, "rk4_transition");
    compare_transition<odestep::dormand_prince54_transition<state2>>(&odestep_dp54_transition_d, "dp54_transition");
    if (failures != 0) {
        std::printf("%d agreement check(s) failed\n", failures);
        return 1;
    }
    std::printf("the C stiff steppers agree with the C++ ones\n");
    return 0;
}
