// SPDX-License-Identifier: BSL-1.0
// Compiled at -O2 and inspected by check_inlined.cmake: the checked and the unchecked step of the same
// table, State and right-hand side in one translation unit (an innocent program that uses both) must each
// inline the library's internals (odestep::detail): none may be left out of line. GCC at -O2
// does not inline a large function that has two callers, and the two policies share the stage loop's
// instantiation (detail::explicit_stages::run): before it was always inlined, both steps called it, Lorenz
// RK4 at 119 and 112 instructions per step against 109 and 98 for either policy alone (callgrind, g++ 12).
#include <odestep/odestep.hpp>

#include <array>

namespace {
using state3 = std::array<double, 3>;
using state3f = std::array<float, 3>;

// Lorenz (sigma = 10, rho = 28, beta = 8/3), in place.
struct lorenz {
    template <class T>
    void operator()(T, const std::array<T, 3>& y, std::array<T, 3>& d) const noexcept {
        d[0] = T(10) * (y[1] - y[0]);
        d[1] = y[0] * (T(28) - y[2]) - y[1];
        d[2] = y[0] * y[1] - T(8) / T(3) * y[2];
    }
};
}  // namespace

#ifdef ODESTEP_INLINING_CANARY
// The check's own test: a function of the library's internals kept out of line must be reported.
namespace odestep::detail::inlining_canary {
[[gnu::noinline]] int out_of_line(int s) { return s + 1; }
}  // namespace odestep::detail::inlining_canary
#define ODESTEP_CANARY(s) odestep::detail::inlining_canary::out_of_line(s)
#else
#define ODESTEP_CANARY(s) (s)
#endif

// Each step compiled as a caller elsewhere gets it: not inlined into a caller, not specialized for one.
#if defined(__clang__)
#define ODESTEP_STEP_FN extern "C" [[gnu::noinline]]
#else
#define ODESTEP_STEP_FN extern "C" [[gnu::noipa]]
#endif

ODESTEP_STEP_FN int inlining_rk4_checked(state3& y, double t, double dt) {
    return ODESTEP_CANARY(static_cast<int>(odestep::rk4<state3>{}.step(lorenz{}, y, t, dt)));
}
ODESTEP_STEP_FN int inlining_rk4_unchecked(state3& y, double t, double dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<state3>>{}.step(lorenz{}, y, t, dt));
}
ODESTEP_STEP_FN int inlining_rk4f_checked(state3f& y, float t, float dt) {
    return static_cast<int>(odestep::rk4<state3f>{}.step(lorenz{}, y, t, dt));
}
ODESTEP_STEP_FN int inlining_rk4f_unchecked(state3f& y, float t, float dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<state3f>>{}.step(lorenz{}, y, t, dt));
}
ODESTEP_STEP_FN int inlining_dp54_checked(state3& y, state3& err, double t, double dt) {
    return static_cast<int>(odestep::dormand_prince54<state3>{}.step(lorenz{}, y, t, dt, err));
}
ODESTEP_STEP_FN int inlining_dp54_unchecked(state3& y, state3& err, double t, double dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::dormand_prince54<state3>>{}.step(lorenz{}, y, t, dt, err));
}
