// SPDX-License-Identifier: BSL-1.0
// Harmonic oscillator x'' = -x (2 states, float), classic RK4, fixed step. GSL is double only: no GSL
// variant. The rhs is trivial, so this case measures the integrators' own overhead.
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include "hand.hpp"
#include "harness.hpp"
#include "problems.hpp"

namespace {
using State = std::array<float, 2>;
constexpr auto rhs = [](float, const State& y, State& d) { bench::oscillator<float>(y, d); };
constexpr auto odeint_rhs = [](const State& y, State& d, float) { bench::oscillator<float>(y, d); };
boost::numeric::odeint::runge_kutta4<State, float, State, float> odeint_rk4;
}  // namespace

BENCH_STEP int bench_step_sho_float_rk4_odestep(State& y, State&, float t, float dt) {
    return static_cast<int>(odestep::rk4<State>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_sho_float_rk4_odestep_unchecked(State& y, State&, float t, float dt) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<State>>{}.step(rhs, y, t, dt));
}
BENCH_STEP int bench_step_sho_float_rk4_hand(State& y, State&, float t, float dt) {
    bench::hand::rk4(rhs, y, t, dt);
    return 0;
}
BENCH_STEP int bench_step_sho_float_rk4_hand_checked(State& y, State&, float t, float dt) {
    return bench::hand::rk4_checked(rhs, y, t, dt);
}
BENCH_STEP int bench_step_sho_float_rk4_odeint(State& y, State&, float t, float dt) {
    odeint_rk4.do_step(odeint_rhs, y, t, dt);
    return 0;
}

int main(int argc, char** argv) {
    const State y0{1.0f, 0.0f};
    const int steps = 100;
    const State exact{static_cast<float>(std::cos(1.0)), static_cast<float>(-std::sin(1.0))};  // t = 100 * 0.01
    bench::problem<State> p{"sho_float_rk4", y0, 0.0f, 0.01f, steps, exact,
                            // Round-off in float: 100 steps, a few ulps (6e-8) each.
                            1e-5,
                            // RK4's own error with h = 0.01 (~1e-10) is far below float round-off, so
                            // this is the round-off bound again, against the exact cos t, -sin t.
                            1e-5, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep::rk4<std::array<float, 2>>", bench_step_sho_float_rk4_odestep, true},
         {"odestep_unchecked", "odestep::unchecked_t<odestep::rk4<State>>: no NaN/Inf test (the same arithmetic)",
          bench_step_sho_float_rk4_odestep_unchecked, true},
         {"hand", "hand-written RK4 loop, float", bench_step_sho_float_rk4_hand, true},
         {"hand_checked",
          "the hand loop, checked: NaN/Inf in the new y fails the step, which is rolled back "
          "(hand.hpp rk4_checked)",
          bench_step_sho_float_rk4_hand_checked, true},
         {"odeint", "Odeint runge_kutta4<std::array<float, 2>, float> do_step", bench_step_sho_float_rk4_odeint,
          true}});
}
