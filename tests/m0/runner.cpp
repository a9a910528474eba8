// SPDX-License-Identifier: BSL-1.0
// The Cortex-M0 runner (issue 27 item 7): a small image for QEMU's `microbit` (nRF51, Armv6-M, no FPU,
// 256 KiB flash, 16 KiB RAM), where the doctest images (megabytes) cannot fit. scripts/test-m0.sh compiles
// this one file twice, for the microbit and for the host (g++, -ffp-contract=off), runs both and compares
// their BITS lines: the final states' float bit patterns must be identical (the M0's soft float rounds every
// operation as the host's SSE float does). The host build also checks its results against the closed forms.
//
// Cases, float, each a fixed number of steps after `warmup` untimed ones, through a step function called by
// pointer as bench/m4f/main.cpp calls its rows (the same problems: bench/m4f/common.hpp, dt = 0.01):
//   rk4             odestep::rk4, two coupled oscillators as 4 first-order states
//   rk4_hand        bench/hand.hpp's plain hand loop on the same system
//   verlet          odestep::velocity_verlet (acceleration kept by the stepper), the same springs, x and v of 2
//   verlet_caller   the same, the acceleration kept by the caller
//   verlet_hand     bench/m4f/hand_more.hpp's kick-drift-kick hand loop
//   capi_rk4        odestep_step_f (the C API, rk4, n = 4) with f a C function
//   rk4_fnptr       the C++ rk4 step with the same C function through a pointer
//   ball_tick       event_stepper: RK4 and one event (a ball bouncing on the floor, restitution 0.8), a tick
//                   per step; the count covers every tick, the firing ones included
//
// Output (one line each):
//   BITS <case> <hex of each final component> [<hex of more values>]   on both, compared
//   COUNT <case> <instructions per step>                               on the M0 only
//   END <failures>
// The clock (M0 only): with -icount shift=0 QEMU advances the virtual clock 1 ns per instruction, and the
// microbit's SysTick, on the processor clock (16 MHz), ticks every 62.5 instructions. Each case's loop is
// timed, the same loop around an empty step subtracted: (ticks - empty ticks) * 62.5 / steps, to within
// 62.5 / steps per step either way. A loop of known length checks the clock (COUNT calibration).
// The same source runs on the Cortex-M4F (QEMU mps2-an386, whose SysTick runs at 25 MHz: compiled with
// -DRUNNER_TENTHS_PER_TICK=400), for figures beside the M0's from the same harness.
#include <odestep/odestep.h>

#include <odestep/odestep.hpp>

#include <array>
#include <cstdint>
#include <cstring>

#include "hand.hpp"
#include "m4f/common.hpp"
#include "m4f/hand_more.hpp"

#if defined(__arm__)
#define M0_TARGET 1
#else
#define M0_TARGET 0
#include <cmath>
#include <cstdio>
#endif

namespace {
using namespace m4f;
namespace o = odestep;

constexpr float dt = 0.01f;
constexpr int warmup = 4;
constexpr int steps = 1000;
int failures = 0;

// ---- output: semihosting SYS_WRITE0 on the M0, stdout on the host
void put(const char* s) {
#if M0_TARGET
    register std::uint32_t r0 __asm__("r0") = 0x04u;  // SYS_WRITE0: a NUL-terminated string
    register const char* r1 __asm__("r1") = s;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
#else
    std::fputs(s, stdout);
#endif
}
void put_hex(float x) {
    std::uint32_t u;
    std::memcpy(&u, &x, sizeof u);
    char text[10];
    text[0] = ' ';
    for (int i = 0; i < 8; ++i) text[1 + i] = "0123456789abcdef"[(u >> (28 - 4 * i)) & 0xFu];
    text[9] = '\0';
    put(text);
}
void put_unsigned(std::uint32_t n) {
    char text[12];
    int i = 11;
    text[i] = '\0';
    do {
        text[--i] = static_cast<char>('0' + n % 10u);
        n /= 10u;
    } while (n != 0u);
    put(text + i);
}
// x and v of a Newtonian result (its last two components are unused).
std::array<float, 4> newtonian_state(const result_t& r) { return {r[0], r[1], r[2], r[3]}; }
template <std::size_t N>
void put_bits(const char* name, const std::array<float, N>& values) {
    put("BITS ");
    put(name);
    for (float x : values) put_hex(x);
    put("\n");
}

// ---- the clock: SysTick (SYST_CSR, SYST_RVR, SYST_CVR), 24 bits, counting down
std::uint32_t clock_now() {
#if M0_TARGET
    return *reinterpret_cast<volatile std::uint32_t*>(0xE000E018u);
#else
    return 0u;
#endif
}
void clock_start() {
#if M0_TARGET
    volatile std::uint32_t* const systick = reinterpret_cast<volatile std::uint32_t*>(0xE000E010u);
    systick[1] = 0x00FFFFFFu;  // reload
    systick[2] = 0u;           // current value cleared
    systick[0] = 5u;           // enabled, on the processor clock, no interrupt
#endif
}

// Runs steps first .. first + n - 1 of `f`; returns the SysTick ticks they took; counts failed steps.
std::uint32_t run(step_fn f, void* context, int first, int n) {
    int status = 0;
    const std::uint32_t begin = clock_now();
    for (int i = first; i < first + n; ++i) status |= f(context, static_cast<float>(i) * dt, dt);
    const std::uint32_t end = clock_now();
    if (status != 0) ++failures;
    return (begin - end) & 0x00FFFFFFu;
}
std::uint32_t empty_ticks = 0;
M4F_STEP int step_empty(void*, float, float) { return 0; }
#if M0_TARGET
// The clock's check: the empty step and a loop of 100 two-instruction iterations after one move, 201
// instructions more (scripts/test-m0.sh expects COUNT calibration 201.0, to the clock's +-0.1).
M4F_STEP int step_calibration(void*, float, float) {
    std::uint32_t n = 100u;
    __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n\tbne 1b\n\t.syntax divided" : "+l"(n) : : "cc");
    return 0;
}
#endif

// Instructions per SysTick tick, in tenths: 62.5 on the microbit (16 MHz).
#ifndef RUNNER_TENTHS_PER_TICK
#define RUNNER_TENTHS_PER_TICK 625u
#endif

// Warm-up, the timed steps, and the COUNT line (in tenths of an instruction: ticks * RUNNER_TENTHS_PER_TICK).
void measure(const char* name, step_fn f, void* context) {
    run(f, context, 0, warmup);
    const std::uint32_t ticks = run(f, context, warmup, steps);
#if M0_TARGET
    const std::uint32_t net = ticks > empty_ticks ? ticks - empty_ticks : 0u;
    const std::uint32_t tenths = (net * RUNNER_TENTHS_PER_TICK + steps / 2u) / steps;
    put("COUNT ");
    put(name);
    put(" ");
    put_unsigned(tenths / 10u);
    put(".");
    put_unsigned(tenths % 10u);
    put("\n");
#else
    static_cast<void>(name);
    static_cast<void>(ticks);
#endif
}

// ---- the cases
first_order rk4_context, rk4_hand_context, capi_context, fnptr_context;
M4F_STEP int step_rk4(void* p, float t, float h) {
    return static_cast<int>(o::rk4<State>{}.step(rhs, as<first_order>(p).y, t, h));
}
M4F_STEP int step_rk4_hand(void* p, float t, float h) {
    bench::hand::rk4(rhs, as<first_order>(p).y, t, h);
    return 0;
}

kept<o::velocity_verlet<vec2>> verlet_context;
newtonian verlet_caller_context, verlet_hand_context;
M4F_STEP int step_verlet_caller(void* p, float t, float h) {
    newtonian& c = as<newtonian>(p);
    return static_cast<int>(o::velocity_verlet<vec2>{}.step(springs, c.x, c.v, c.acc, t, h));
}
M4F_STEP int step_verlet_hand(void* p, float t, float h) {
    newtonian& c = as<newtonian>(p);
    bench::m4f_hand::velocity_verlet_kdk(hand_springs, c.x, c.v, c.acc, t, h);
    return 0;
}

// The C API's right-hand side, and the C++ step calling the same function through a pointer.
extern "C" void oscillators_c(float t, const float* y, float* dydt, void*) {
    State in{y[0], y[1], y[2], y[3]};
    State out;
    rhs(t, in, out);
    std::memcpy(dydt, out.data(), sizeof out);
}
odestep_stepper_f capi_stepper;
const odestep_system_f capi_system{oscillators_c, nullptr, 4};
M4F_STEP int step_capi(void* p, float t, float h) {
    return static_cast<int>(odestep_step_f(&capi_stepper, &capi_system, as<first_order>(p).y.data(), t, h));
}
struct through_pointer {
    odestep_rhs_f f;
    void operator()(float t, const State& y, State& dydt) const { f(t, y.data(), dydt.data(), nullptr); }
};
odestep_rhs_f volatile rhs_pointer = oscillators_c;  // volatile: the compiler cannot see which f it is
M4F_STEP int step_rk4_fnptr(void* p, float t, float h) {
    return static_cast<int>(o::rk4<State>{}.step(through_pointer{rhs_pointer}, as<first_order>(p).y, t, h));
}

// A ball dropped from 10 m onto the floor (y = 0), g = 9.81, restitution 0.8: RK4 ticks of dt with the
// floor as a falling event whose action reverses and scales the velocity. Its bounces take sqrt(2 h / g)
// (1 + 2 e / (1 - e)) = 12.9 s in all, longer than the run (10.04 s): no Zeno cascade at the end.
using ball_state = std::array<float, 2>;
struct ball_rhs {
    void operator()(float, const ball_state& y, ball_state& d) const noexcept {
        d[0] = y[1];
        d[1] = -9.81f;
    }
};
struct floor_height {
    float operator()(float, const ball_state& y) const noexcept { return y[0]; }
};
struct bounce {
    o::event_result operator()(float, ball_state& y) const noexcept {
        y[1] = -0.8f * y[1];
        return o::event_result::proceed;
    }
};
using ball_loop_t = decltype(o::make_event_stepper(
    o::rk4<ball_state>{}, o::watch(o::make_event<ball_state>(floor_height{}, o::direction::falling, bounce{}))));
struct ball_context {
    ball_loop_t loop;
    ball_state y;
    std::uint32_t fired;
    float first_t, last_t;
};
ball_context ball{o::make_event_stepper(o::rk4<ball_state>{}, o::watch(o::make_event<ball_state>(
                                                                  floor_height{}, o::direction::falling, bounce{}))),
                  {10.0f, 0.0f},
                  0u,
                  0.0f,
                  0.0f};
M4F_STEP int step_ball(void* p, float, float) {
    ball_context& c = *static_cast<ball_context*>(p);
    const auto r = c.loop.tick(ball_rhs{}, c.y);
    if (r.fired != 0u) {
        if (c.fired == 0u) c.first_t = r.firings[0].t;
        c.last_t = r.firings[r.fired - 1u].t;
        c.fired += static_cast<std::uint32_t>(r.fired);
    }
    return r.status == o::status::ok ? 0 : 1;
}

#if !M0_TARGET
// The host's independent check of the results: the oscillators' closed form (normal modes s = x1 + x2,
// frequency 1, and d = x1 - x2, frequency sqrt(3), from x = (1, 0), v = (0, 0.5)) and the ball's first
// impact at sqrt(2 h / g), h = 10 m.
void expect_near(const char* what, double got, double want, double tolerance) {
    if (!(std::fabs(got - want) <= tolerance)) {
        std::printf("FAIL %s: %.9g, expected %.9g within %.1g\n", what, got, want, tolerance);
        ++failures;
    }
}
void check_oscillators(const char* what, float x1, float x2, float v1, float v2, double tolerance) {
    const double t = static_cast<double>(warmup + steps) * 0.01;
    const double r3 = std::sqrt(3.0);
    const double s = std::cos(t) + 0.5 * std::sin(t), sv = -std::sin(t) + 0.5 * std::cos(t);
    const double d = std::cos(r3 * t) - 0.5 / r3 * std::sin(r3 * t),
                 dv = -r3 * std::sin(r3 * t) - 0.5 * std::cos(r3 * t);
    expect_near(what, static_cast<double>(x1), (s + d) / 2.0, tolerance);
    expect_near(what, static_cast<double>(x2), (s - d) / 2.0, tolerance);
    expect_near(what, static_cast<double>(v1), (sv + dv) / 2.0, tolerance);
    expect_near(what, static_cast<double>(v2), (sv - dv) / 2.0, tolerance);
}
#endif
}  // namespace

int main() {
    clock_start();
    {
        first_order c;
        start(c);
        run(step_empty, &c, 0, warmup);
        empty_ticks = run(step_empty, &c, warmup, steps);
#if M0_TARGET
        measure("calibration", step_calibration, &c);
#endif
    }
    start(rk4_context);
    measure("rk4", step_rk4, &rk4_context);
    put_bits("rk4", rk4_context.y);

    start(rk4_hand_context);
    measure("rk4_hand", step_rk4_hand, &rk4_hand_context);
    put_bits("rk4_hand", rk4_hand_context.y);

    start(verlet_context);
    measure("verlet", step_newtonian<o::velocity_verlet<vec2>>, &verlet_context);
    put_bits("verlet", newtonian_state(result(verlet_context)));

    start(verlet_caller_context);
    measure("verlet_caller", step_verlet_caller, &verlet_caller_context);
    put_bits("verlet_caller", newtonian_state(result(verlet_caller_context)));

    start(verlet_hand_context);
    measure("verlet_hand", step_verlet_hand, &verlet_hand_context);
    put_bits("verlet_hand", newtonian_state(result(verlet_hand_context)));

    if (odestep_stepper_init_f(&capi_stepper, &odestep_rk4_f) != ODESTEP_OK) ++failures;
    start(capi_context);
    measure("capi_rk4", step_capi, &capi_context);
    put_bits("capi_rk4", capi_context.y);

    start(fnptr_context);
    measure("rk4_fnptr", step_rk4_fnptr, &fnptr_context);
    put_bits("rk4_fnptr", fnptr_context.y);

    if (ball.loop.start(0.0f, dt, ball.y) != o::status::ok) ++failures;
    measure("ball_tick", step_ball, &ball);
    put_bits("ball_tick", std::array<float, 4>{ball.y[0], ball.y[1], ball.first_t, ball.last_t});
    put("BITS ball_firings ");
    put_unsigned(ball.fired);
    put("\n");

    // The C API's RK4 and the C++ step with the same f through a pointer are one method: the same state.
    if (capi_context.y != rk4_context.y || fnptr_context.y != rk4_context.y) ++failures;
#if !M0_TARGET
    // RK4's global error at dt = 0.01 is about 1e-9 here: the float round-off of 1004 steps dominates
    // (measured 1.3e-6).
    check_oscillators("rk4", rk4_context.y[0], rk4_context.y[1], rk4_context.y[2], rk4_context.y[3], 1e-5);
    check_oscillators("rk4_hand", rk4_hand_context.y[0], rk4_hand_context.y[1], rk4_hand_context.y[2],
                      rk4_hand_context.y[3], 1e-5);
    // Velocity Verlet: second order, a phase error of about (omega dt)^2 / 24 * omega t, 2e-4 at omega =
    // sqrt(3) (measured 1.3e-4).
    const result_t v = result(verlet_context);
    check_oscillators("verlet", v[0], v[1], v[2], v[3], 5e-4);
    expect_near("ball first impact", static_cast<double>(ball.first_t), std::sqrt(20.0 / 9.81), 1e-5);
#endif
    put("END ");
    put_unsigned(static_cast<std::uint32_t>(failures));
    put("\n");
    return failures == 0 ? 0 : 1;
}
