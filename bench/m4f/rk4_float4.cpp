// SPDX-License-Identifier: BSL-1.0
// Instructions per step on the emulated Cortex-M4F (scripts/bench-m4f.sh builds and runs it): QEMU mps2-an386 with
// -icount shift=0 advances the virtual clock 1 ns per instruction, and the board's CMSDK APB timer 0 counts at
// 25 MHz, so one tick is 40 instructions. Each variant runs 100000 steps between two timer reads; the empty
// step's ticks (the loop and the call) are subtracted.
// float RK4, 4 states (two coupled oscillators): odestep::rk4 against the hand loops of bench/hand.hpp
// (unrolled, right-hand side inlined), plain and checked.
#include <array>
#include <cstdint>
#include <cstdio>

#include <odestep/odestep.hpp>

#include "hand.hpp"

using State = std::array<float, 4>;
namespace {
constexpr auto rhs = [](float, const State& y, State& d) {
    d[0] = y[2];
    d[1] = y[3];
    d[2] = -2.0f * y[0] + y[1];
    d[3] = y[0] - 2.0f * y[1];
};
// The CMSDK APB timer 0 of the MPS2 boards: CTRL (bit 0 enables), VALUE (counts down), RELOAD.
volatile std::uint32_t* const timer = reinterpret_cast<volatile std::uint32_t*>(0x40000000u);
}  // namespace

extern "C" __attribute__((noipa)) int step_empty(State&, float, float) { return 0; }
extern "C" __attribute__((noipa)) int step_odestep(State& y, float t, float dt) {
    return static_cast<int>(odestep::rk4<State>{}.step(rhs, y, t, dt));
}
extern "C" __attribute__((noipa)) int step_hand(State& y, float t, float dt) {
    bench::hand::rk4(rhs, y, t, dt);
    return 0;
}
extern "C" __attribute__((noipa)) int step_hand_checked(State& y, float t, float dt) {
    return bench::hand::rk4_checked(rhs, y, t, dt);
}

using step_fn = int (*)(State&, float, float);
static std::uint32_t run(step_fn f, int n, State& y) {
    const float dt = 0.01f;
    int bad = 0;
    timer[2] = 0xFFFFFFFFu;
    timer[1] = 0xFFFFFFFFu;
    timer[0] = 1u;
    const std::uint32_t start = timer[1];
    for (int i = 0; i < n; ++i) bad |= f(y, static_cast<float>(i) * dt, dt);
    const std::uint32_t end = timer[1];
    timer[0] = 0u;
    if (bad) std::printf("a step failed\n");
    return start - end;
}

int main() {
    const int n = 100000;
    State y0{1.0f, 0.0f, 0.0f, 0.5f};
    State y = y0;
    const std::uint32_t empty = run(step_empty, n, y);
    const char* names[] = {"odestep", "hand", "hand_checked"};
    step_fn fns[] = {step_odestep, step_hand, step_hand_checked};
    State out[3];
    for (int k = 0; k < 3; ++k) {
        y = y0;
        const std::uint32_t ticks = run(fns[k], n, y);
        out[k] = y;
        const double per = (static_cast<double>(ticks) - static_cast<double>(empty)) * 40.0 / n;
        std::printf("%s\t%.1f\tinstructions/step (ticks %lu, empty loop %lu)\n", names[k], per,
                    static_cast<unsigned long>(ticks), static_cast<unsigned long>(empty));
    }
    // The variants compute the same arithmetic (the same factored RK4 sums): after 100000 steps (t = 1000,
    // amplitude about 1) they must agree to float round-off, or one of them is fast by being wrong.
    float worst = 0.0f;
    for (int k = 1; k < 3; ++k)
        for (std::size_t i = 0; i < 4; ++i) {
            const float d = out[k][i] - out[0][i];
            worst = d > worst ? d : (-d > worst ? -d : worst);
        }
    const bool agree = worst <= 1e-3f;  // 1e5 steps of a few ulps each, on values of size 1
    std::printf("CHECK\t%s\tmax |y_hand - y_odestep| = %.3g (tol 1e-3)\n", agree ? "ok" : "FAIL",
                static_cast<double>(worst));
    return agree ? 0 : 1;
}
