// SPDX-License-Identifier: BSL-1.0
// Instructions per step of the steps with Phi (sensitivity/) on the emulated Cortex-M4F, float, N = 4: the
// plain step, the step with Phi (the Jacobian by hand and by dual numbers) and Phi by forward differences
// (N + 1 = 5 plain steps), for RK4, DP 5(4), velocity Verlet (x and v of 2, a fresh stepper per step as the
// transition takes it) and backward Euler (the hand Jacobian). The problem is bench/m4f/common.hpp's two
// coupled oscillators (constant J). Rows for bench/m4f/main.cpp's runner, one translation unit per row
// (-DM4F_UNIT=k, k = 50 .. 62, after steppers.cpp's); not part of scripts/bench-m4f.sh's table: the commands
// are in docs/sensitivity.md. Each row's "odestep" figure is the variant named; no hand loop is compared.
#include "m4f/units.hpp"

#ifndef M4F_UNIT
#error "compile with -DM4F_UNIT=k (50 .. 62)"
#endif

namespace {
using namespace m4f;
namespace o = odestep;
using Jac = o::jacobian_t<State>;
using Phase = o::phase_matrix_t<vec2>;

// The oscillators written as a template on the scalar (for dual numbers), and their Jacobian.
struct oscillators_t {
    template <class S>
    std::array<S, 4> operator()(float, const std::array<S, 4>& y) const {
        return {y[2], y[3], -2.0f * y[0] + y[1], y[0] - 2.0f * y[1]};
    }
};
struct oscillators_jacobian {
    void operator()(float, const State&, Jac& j) const {
        j = {
            {{0.0f, 0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f, 1.0f}, {-2.0f, 1.0f, 0.0f, 0.0f}, {1.0f, -2.0f, 0.0f, 0.0f}}};
    }
};
struct springs_jacobian {
    void operator()(float, const vec2&, o::jacobian_t<vec2>& j) const { j = {{{-2.0f, 1.0f}, {1.0f, -2.0f}}}; }
};

struct with_phi {
    State y;
    Jac phi;
};
[[maybe_unused]] void start(with_phi& c) { c = {y0, {}}; }
[[maybe_unused]] result_t result(const with_phi& c) {
    return {c.y[0], c.y[1], c.y[2], c.y[3], c.phi[0][0], c.phi[2][1]};
}
struct newtonian_phi {
    vec2 x, v;
    Phase phi;
};
[[maybe_unused]] void start(newtonian_phi& c) { c = {x0, v0, {}}; }
[[maybe_unused]] result_t result(const newtonian_phi& c) {
    return {c.x[0], c.x[1], c.v[0], c.v[1], c.phi[0][0], c.phi[2][1]};
}

// Phi by forward differences of N + 1 plain steps: (step(y + h e_j) - step(y)) / h.
template <class Stepper, class F>
int differences(const F& f, with_phi& c, float t, float dt) {
    const Stepper s{};
    State base = c.y;
    if (s.step(f, base, t, dt) != o::status::ok) return 1;
    for (std::size_t j = 0; j < 4; ++j) {
        State moved = c.y;
        const float h = 3.5e-4f * ((moved[j] < 0.0f ? -moved[j] : moved[j]) + 1.0f);  // sqrt(eps) (|y_j| + 1)
        moved[j] += h;
        if (s.step(f, moved, t, dt) != o::status::ok) return 1;
        for (std::size_t i = 0; i < 4; ++i) c.phi[i][j] = (moved[i] - base[i]) / h;
    }
    c.y = base;
    return 0;
}

#if M4F_UNIT >= 50 && M4F_UNIT <= 53
using Plain = o::rk4<State>;
using Transition = o::rk4_transition<State>;
constexpr int first = 50;
const char* const names[4] = {"rk4 (N = 4)", "rk4_transition, hand J", "rk4_transition, dual J", "rk4, Phi by 5 steps"};
#elif M4F_UNIT >= 54 && M4F_UNIT <= 57
using Plain = o::explicit_rk<o::tables::dormand_prince54, State>;
using Transition = o::dormand_prince54_transition<State>;
constexpr int first = 54;
const char* const names[4] = {"dp54 (N = 4)", "dormand_prince54_transition, hand J",
                              "dormand_prince54_transition, dual J", "dp54, Phi by 5 steps"};
#elif M4F_UNIT >= 60 && M4F_UNIT <= 62
using Plain = o::backward_euler<State>;
using Transition = o::backward_euler_transition<State>;
constexpr int first = 60;
const char* const names[3] = {"backward_euler (N = 4, hand J)", "backward_euler_transition, hand J",
                              "backward_euler, Phi by 5 steps"};
#endif

#if M4F_UNIT >= 50 && M4F_UNIT <= 57
with_phi context;
M4F_STEP int step_plain(void* p, float t, float dt) {
    return static_cast<int>(Plain{}.step(oscillators_t{}, as<with_phi>(p).y, t, dt));
}
M4F_STEP int step_hand(void* p, float t, float dt) {
    with_phi& c = as<with_phi>(p);
    return static_cast<int>(
        Transition{}.step(o::with_jacobian(oscillators_t{}, oscillators_jacobian{}), c.y, c.phi, t, dt));
}
M4F_STEP int step_dual(void* p, float t, float dt) {
    with_phi& c = as<with_phi>(p);
    return static_cast<int>(Transition{}.step(o::with_dual_jacobian(oscillators_t{}), c.y, c.phi, t, dt));
}
M4F_STEP int step_differences(void* p, float t, float dt) {
    return differences<Plain>(oscillators_t{}, as<with_phi>(p), t, dt);
}
constexpr step_fn fns[4] = {step_plain, step_hand, step_dual, step_differences};
const registration row(M4F_UNIT, names[M4F_UNIT - first], make(fns[M4F_UNIT - first], context));
#endif

#if M4F_UNIT >= 60 && M4F_UNIT <= 62
with_phi context;
M4F_STEP int step_plain(void* p, float t, float dt) {
    return static_cast<int>(
        Plain{}.step(o::with_jacobian(oscillators_t{}, oscillators_jacobian{}), as<with_phi>(p).y, t, dt));
}
M4F_STEP int step_hand(void* p, float t, float dt) {
    with_phi& c = as<with_phi>(p);
    return static_cast<int>(
        Transition{}.step(o::with_jacobian(oscillators_t{}, oscillators_jacobian{}), c.y, c.phi, t, dt));
}
M4F_STEP int step_differences(void* p, float t, float dt) {
    return differences<Plain>(o::with_jacobian(oscillators_t{}, oscillators_jacobian{}), as<with_phi>(p), t, dt);
}
constexpr step_fn fns[3] = {step_plain, step_hand, step_differences};
const registration row(M4F_UNIT, names[M4F_UNIT - first], make(fns[M4F_UNIT - first], context));
#endif

#if M4F_UNIT == 58  // velocity Verlet: plain (fresh), with Phi, Phi by 5 steps
newtonian_phi context;
M4F_STEP int step_vv_plain(void* p, float t, float dt) {
    newtonian_phi& c = as<newtonian_phi>(p);
    o::velocity_verlet<vec2> s;  // fresh: both kicks evaluated, as the transition does
    return static_cast<int>(s.step(springs, c.x, c.v, t, dt));
}
const registration row(M4F_UNIT, "velocity_verlet (N = 2 + 2, fresh)", make(step_vv_plain, context));
#endif
#if M4F_UNIT == 59
newtonian_phi context;
M4F_STEP int step_vv_hand(void* p, float t, float dt) {
    newtonian_phi& c = as<newtonian_phi>(p);
    return static_cast<int>(o::velocity_verlet_transition<vec2>{}.step(o::with_jacobian(springs, springs_jacobian{}),
                                                                       c.x, c.v, c.phi, t, dt));
}
const registration row(M4F_UNIT, "velocity_verlet_transition, hand da/dx", make(step_vv_hand, context));
#endif
#if M4F_UNIT == 63
newtonian_phi context;
M4F_STEP int step_vv_differences(void* p, float t, float dt) {
    newtonian_phi& c = as<newtonian_phi>(p);
    vec2 bx = c.x, bv = c.v;
    if (o::velocity_verlet<vec2>{}.step(springs, bx, bv, t, dt) != o::status::ok) return 1;
    for (std::size_t j = 0; j < 4; ++j) {
        vec2 mx = c.x, mv = c.v;
        float& e = j < 2 ? mx[j] : mv[j - 2];
        const float h = 3.5e-4f * ((e < 0.0f ? -e : e) + 1.0f);
        e += h;
        if (o::velocity_verlet<vec2>{}.step(springs, mx, mv, t, dt) != o::status::ok) return 1;
        for (std::size_t i = 0; i < 2; ++i) {
            c.phi[i][j] = (mx[i] - bx[i]) / h;
            c.phi[2 + i][j] = (mv[i] - bv[i]) / h;
        }
    }
    c.x = bx;
    c.v = bv;
    return 0;
}
const registration row(M4F_UNIT, "velocity_verlet, Phi by 5 steps", make(step_vv_differences, context));
#endif

}  // namespace
