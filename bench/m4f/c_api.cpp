// SPDX-License-Identifier: BSL-1.0
// The C API's RK4 step on the emulated Cortex-M4F, float, n = 4 (issue 27: "the C API within 1.1x of the C++
// step at its default maximum, on x86-64 and on the M4F"): odestep_step_f against the C++ step
// odestep::rk4<std::array<float, 4>> with f through the same C function pointer, as bench/c_api_rk4.cpp does
// on x86-64. Two masses between three unit springs, y = (x1, x2, v1, v2). The library (src/capi.cpp,
// src/capi_float.cpp) is compiled apart, as the odestep_c target does; `scripts/bench-m4f.sh --c-api` builds
// it with ODESTEP_C_EXACT_STATES 0 (the default) and 8, at -O2 and -Os.
//
// The clock is bench/m4f/main.cpp's (QEMU mps2-an386, -icount shift=0: 1 ns of virtual time per
// instruction, the CMSDK timer 0 at 25 MHz, 40 instructions a tick): 1000 steps after 4 untimed, the same
// loop around an empty step subtracted. Both variants must end within float round-off of each other.
// Output: C_API <odestep> <cpp_fnptr> <ratio> <largest relative difference> <ok | FAIL(...)>
#include <array>
#include <cstdint>
#include <cstdio>

#include "odestep/odestep.h"
#include "odestep/rk/explicit_rk.hpp"

namespace {
using State = std::array<float, 4>;
using rhs_fn = void (*)(float, const float*, float*, void*);
using step_fn = int (*)(float, float);

extern "C" void m4f_c_api_springs(float, const float* y, float* d, void*) {
    d[0] = y[2];
    d[1] = y[3];
    d[2] = -2.0f * y[0] + y[1];
    d[3] = y[0] - 2.0f * y[1];
}
}  // namespace
// Not const, with external linkage: the compiler cannot know the function it points to.
extern "C" rhs_fn m4f_c_api_rhs;
rhs_fn m4f_c_api_rhs = m4f_c_api_springs;

namespace {
constexpr float dt = 0.01f;
constexpr int warmup = 4;
constexpr int steps = 1000;
volatile std::uint32_t* const timer = reinterpret_cast<volatile std::uint32_t*>(0x40000000u);

odestep_stepper_f c_stepper;
const odestep_system_f c_system{m4f_c_api_springs, nullptr, 4};
State y_c{1.0f, 0.0f, 0.0f, 0.0f};
State y_cpp{1.0f, 0.0f, 0.0f, 0.0f};

__attribute__((noipa)) int step_empty(float, float) { return 0; }
__attribute__((noipa)) int step_odestep(float t, float h) {
    return odestep_step_f(&c_stepper, &c_system, y_c.data(), t, h);
}
__attribute__((noipa)) int step_cpp_fnptr(float t, float h) {
    const rhs_fn f = m4f_c_api_rhs;
    return static_cast<int>(odestep::rk4<State>{}.step(
        [f](float tt, const State& a, State& d) { f(tt, a.data(), d.data(), nullptr); }, y_cpp, t, h));
}

std::uint32_t run(step_fn f, int first, int n, int& status) {
    timer[2] = 0xFFFFFFFFu;
    timer[1] = 0xFFFFFFFFu;
    timer[0] = 1u;
    const std::uint32_t begin = timer[1];
    for (int i = first; i < first + n; ++i) status |= f(static_cast<float>(i) * dt, dt);
    const std::uint32_t end = timer[1];
    timer[0] = 0u;
    return begin - end;
}
float per_step(step_fn f, std::uint32_t empty, int& status) {
    run(f, 0, warmup, status);
    const std::uint32_t ticks = run(f, warmup, steps, status);
    return static_cast<float>(static_cast<std::int32_t>(ticks - empty)) * 40.0f / static_cast<float>(steps);
}
float magnitude(float x) { return x < 0.0f ? -x : x; }
}  // namespace

int main() {
    int status = 0;
    if (odestep_max_states() != ODESTEP_C_MAX_STATES || odestep_stepper_init_f(&c_stepper, &odestep_rk4_f) != 0) {
        std::printf("C_API\t-\t-\t-\t-\tFAIL(init)\n");
        return 1;
    }
    run(step_empty, 0, warmup, status);
    const std::uint32_t empty = run(step_empty, warmup, steps, status);
    const float c = per_step(step_odestep, empty, status);
    const float cpp = per_step(step_cpp_fnptr, empty, status);
    // The same arithmetic: equal to float round-off (bit for bit in practice) after 1004 steps.
    float worst = 0.0f;
    for (std::size_t i = 0; i < y_c.size(); ++i) {
        const float d = magnitude(y_c[i] - y_cpp[i]);
        if (!(d <= worst)) worst = d;
    }
    const bool ok = status == 0 && worst <= 2e-5f;
    std::printf("C_API\t%.1f\t%.1f\t%.3f\t%.2g\t%s\n", static_cast<double>(c), static_cast<double>(cpp),
                static_cast<double>(c / cpp), static_cast<double>(worst), ok ? "ok" : "FAIL");
    return ok ? 0 : 1;
}
