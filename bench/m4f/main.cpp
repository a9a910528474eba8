// SPDX-License-Identifier: BSL-1.0
// Instructions per step of odestep's steppers on the emulated Cortex-M4F, float, against the scalar hand
// loops: the runner. scripts/bench-m4f.sh builds it with every unit of bench/m4f/steppers.cpp (one row per
// unit, each its own translation unit, so that what GCC inlines in one row does not depend on the others:
// at -Os it calls a function with several callers out of line) into one image per -O and runs it.
//
// The clock: QEMU's mps2-an386 with -icount shift=0 advances the virtual clock 1 ns per executed
// instruction, and the board's CMSDK APB timer 0 counts down at 25 MHz, so one tick is 40 instructions,
// exact to one tick per interval (a 2-instruction loop of n iterations reads 2n/40 ticks, +-1, from n = 10
// to 100000). Each variant runs `warmup` untimed steps (the Adams methods' RK4 start, Beeman's Verlet start,
// the kept forms' first evaluation), then `steps` steps between two timer reads; the same loop around an
// empty step is measured and subtracted. Per step: (ticks - empty ticks) * 40 / steps, to +-0.04.
// A step is called through a pointer, int step(void* context, float t, float dt) with t = i * dt from the
// step counter: its instructions are the step's (the right-hand side inlined or called as the step
// decides), and the call, which the empty step pays too.
//
// Where a row has hand loops, odestep and both hand loops must end in the same state to within float
// round-off, or one of them is fast by being wrong; every step must return ok and the state stay finite.
// A row that fails either is marked FAIL and the image exits with 1.
//
// Output, one line per row (tab-separated; "-" where a variant does not exist):
//   ROW <stepper> <odestep> <hand> <hand_checked> <largest relative difference to odestep> <ok | FAIL(...)>
#include <cstdint>
#include <cstdio>

#include "m4f/common.hpp"

namespace {
constexpr float dt = 0.01f;
constexpr int warmup = 4;
constexpr int steps = 1000;

// The rows, by their unit's index; the units' static registrations fill it before main.
constexpr int max_rows = 64;
m4f::row_def rows[max_rows];

// The CMSDK APB timer 0 of the MPS2 boards: CTRL (bit 0 enables), VALUE (counts down), RELOAD.
volatile std::uint32_t* const timer = reinterpret_cast<volatile std::uint32_t*>(0x40000000u);

M4F_STEP int step_empty(void*, float, float) { return 0; }

// Steps first .. first + n - 1; returns the timer ticks they took, and in `bad` whether any step failed.
std::uint32_t run(m4f::step_fn f, void* context, int first, int n, bool& bad) {
    int status = 0;
    timer[2] = 0xFFFFFFFFu;
    timer[1] = 0xFFFFFFFFu;
    timer[0] = 1u;
    const std::uint32_t begin = timer[1];
    for (int i = first; i < first + n; ++i) status |= f(context, static_cast<float>(i) * dt, dt);
    const std::uint32_t end = timer[1];
    timer[0] = 0u;
    bad = bad || status != 0;
    return begin - end;
}

std::uint32_t empty_ticks = 0;

// Runs a variant: start, warm-up, the timed steps. Returns instructions per step, negative for no variant.
float measure(const m4f::variant& v, m4f::result_t& out, bool& bad) {
    if (v.step == nullptr) return -1.0f;
    v.start(v.context);
    run(v.step, v.context, 0, warmup, bad);
    const std::uint32_t ticks = run(v.step, v.context, warmup, steps, bad);
    out = v.result(v.context);
    return static_cast<float>(static_cast<std::int32_t>(ticks - empty_ticks)) * 40.0f / static_cast<float>(steps);
}

float magnitude(float x) { return x < 0.0f ? -x : x; }

// max_i |a_i - b_i| / max(1, |b_i|); NaN if any difference is NaN.
float relative_difference(const m4f::result_t& a, const m4f::result_t& b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const float scale = magnitude(b[i]) > 1.0f ? magnitude(b[i]) : 1.0f;
        const float d = magnitude(a[i] - b[i]) / scale;
        if (!(d <= worst)) worst = d;
    }
    return worst;
}
bool finite(const m4f::result_t& r) {
    for (float c : r)
        if (!(c >= -3.4e38f && c <= 3.4e38f)) return false;
    return true;
}

// The runs of a row agree to float round-off: 1000 steps of a few ulps each, on values of size 1 (largest
// measured: 8.3e-7, Beeman). A weight off by 1e-3 in the hand midpoint rule is 1.3e-4 off.
constexpr float tolerance = 2e-5f;

int failures = 0;

void report(const m4f::row_def& r) {
    bool bad = false;
    m4f::result_t r_odestep{}, r_hand{}, r_checked{};
    const float values[3] = {measure(r.odestep, r_odestep, bad), measure(r.hand, r_hand, bad),
                             measure(r.checked, r_checked, bad)};
    float diff = 0.0f;
    if (r.hand.step != nullptr) diff = relative_difference(r_hand, r_odestep);
    if (r.checked.step != nullptr) {
        const float d = relative_difference(r_checked, r_odestep);
        if (!(d <= diff)) diff = d;
    }
    const bool agree = finite(r_odestep) && diff <= tolerance;
    if (bad || !agree) ++failures;
    char cells[3][16];
    for (int k = 0; k < 3; ++k) {
        const int whole = static_cast<int>(values[k] + 0.5f);  // a whole number where %.1f would end in .0
        if (values[k] < -0.5f)
            std::snprintf(cells[k], sizeof cells[k], "-");
        else if (magnitude(values[k] - static_cast<float>(whole)) < 0.05f)
            std::snprintf(cells[k], sizeof cells[k], "%d", whole);
        else
            std::snprintf(cells[k], sizeof cells[k], "%.1f", static_cast<double>(values[k]));
    }
    std::printf("ROW\t%s\t%s\t%s\t%s\t%.2g\t%s\n", r.name, cells[0], cells[1], cells[2], static_cast<double>(diff),
                bad ? "FAIL(a step failed)" : (agree ? "ok" : "FAIL(results differ)"));
}
}  // namespace

m4f::registration::registration(int index, const char* name, const variant& odestep, const variant& hand,
                                const variant& checked) {
    if (index >= 0 && index < max_rows) rows[index] = {name, odestep, hand, checked};
}

int main() {
    {
        bool bad = false;
        m4f::first_order c;
        m4f::start(c);
        run(step_empty, &c, 0, warmup, bad);
        empty_ticks = run(step_empty, &c, warmup, steps, bad);
    }
    std::printf("EMPTY\t%lu ticks per %d steps\n", static_cast<unsigned long>(empty_ticks), steps);
    int count = 0;
    for (const m4f::row_def& r : rows)
        if (r.name != nullptr) {
            report(r);
            ++count;
        }
    std::printf("END\t%d rows\t%d failed\n", count, failures);
    return failures == 0 && count > 0 ? 0 : 1;
}
