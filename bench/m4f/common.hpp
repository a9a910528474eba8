// SPDX-License-Identifier: BSL-1.0
// What the units of the emulated Cortex-M4F table share (bench/m4f/steppers.cpp, main.cpp; the method is in
// main.cpp's header comment): the problems, the contexts a step function works on, and the registry of rows.
#ifndef ODESTEP_BENCH_M4F_COMMON_HPP
#define ODESTEP_BENCH_M4F_COMMON_HPP

#include <array>
#include <cstddef>

/// A step function of the table: not inlined into the timing loop, nothing about it assumed there.
#define M4F_STEP __attribute__((noipa))

namespace m4f {

using State = std::array<float, 4>;  ///< y = (x1, x2, v1, v2)
using vec2 = std::array<float, 2>;   ///< x or v of the Newtonian steppers
using vec3 = std::array<float, 3>;   ///< x or v of the Boris pusher

/// Two masses, three springs: x1'' = -2 x1 + x2, x2'' = x1 - 2 x2, as y' = f(t, y).
struct oscillators {
    void operator()(float, const State& y, State& d) const noexcept {
        d[0] = y[2];
        d[1] = y[3];
        d[2] = -2.0f * y[0] + y[1];
        d[3] = y[0] - 2.0f * y[1];
    }
};
/// The same springs as a force of position alone, odestep's form a(t, x).
struct springs_force {
    vec2 operator()(float, const vec2& x) const noexcept { return {-2.0f * x[0] + x[1], x[0] - 2.0f * x[1]}; }
};
/// The same, the hand loops' form f(t, x, acc).
struct hand_springs_force {
    void operator()(float t, const vec2& x, vec2& a) const noexcept { a = springs_force{}(t, x); }
};
/// A Penning trap: the quadrupole E = (x/2, y/2, -z) in a uniform B along z (Boris' fields(t, x, E, B)).
struct penning {
    void operator()(float, const vec3& x, vec3& E, vec3& B) const noexcept {
        E = {x[0] / 2.0f, x[1] / 2.0f, -x[2]};
        B[2] = 1.0f;
    }
};

constexpr oscillators rhs{};
constexpr springs_force springs{};
constexpr hand_springs_force hand_springs{};

constexpr State y0{1.0f, 0.0f, 0.0f, 0.5f};
constexpr vec2 x0{1.0f, 0.0f};
constexpr vec2 v0{0.0f, 0.5f};

/// The state the runs of a row are compared on.
using result_t = std::array<float, 6>;

// The contexts a step function gets, each with its start (the initial state, before the untimed warm-up)
// and its result.

/// A first-order state, and the error estimate of the estimating steps.
struct first_order {
    State y;
    State err;
};
inline void start(first_order& c) { c = {y0, {}}; }
inline result_t result(const first_order& c) { return {c.y[0], c.y[1], c.y[2], c.y[3]}; }

/// The Newtonian hand loops' state and what they keep (acc = a(x) on entry, Beeman's a_{n-1} and start).
struct newtonian {
    vec2 x, v, acc, acc_prev;
    bool started;
};
inline void start(newtonian& c) { c = {x0, v0, springs(0.0f, x0), {}, false}; }
inline result_t result(const newtonian& c) { return {c.x[0], c.x[1], c.v[0], c.v[1]}; }

/// A stepper object kept between steps (the stepper-kept forms keep their history in it) and x, v.
template <class Stepper>
struct kept {
    Stepper s;
    vec2 x, v;
};
template <class Stepper>
void start(kept<Stepper>& c) {
    c = {Stepper{}, x0, v0};
}
template <class Stepper>
result_t result(const kept<Stepper>& c) {
    return {c.x[0], c.x[1], c.v[0], c.v[1]};
}

/// A multistep stepper (its history) kept between steps, and y.
template <class Stepper>
struct multistep {
    Stepper s;
    State y;
};
template <class Stepper>
void start(multistep<Stepper>& c) {
    c = {Stepper{}, y0};
}
template <class Stepper>
result_t result(const multistep<Stepper>& c) {
    return {c.y[0], c.y[1], c.y[2], c.y[3]};
}

/// A charged particle.
struct particle {
    vec3 x, v;
};
inline void start(particle& c) { c = {{1.0f, 0.0f, 0.1f}, {0.0f, 0.5f, 0.0f}}; }
inline result_t result(const particle& c) { return {c.x[0], c.x[1], c.x[2], c.v[0], c.v[1], c.v[2]}; }

/// The context behind a step function's pointer.
template <class C>
C& as(void* p) {
    return *static_cast<C*>(p);
}

/// int step(context, t, dt): 0 when the step succeeded.
using step_fn = int (*)(void*, float, float);

/// One variant of a row: its step function and context (with the context's start and result).
struct variant {
    step_fn step = nullptr;
    void* context = nullptr;
    void (*start)(void*) = nullptr;
    result_t (*result)(const void*) = nullptr;
};
template <class C>
variant make(step_fn f, C& context) {
    return {f, &context, [](void* p) { start(*static_cast<C*>(p)); },
            [](const void* p) { return result(*static_cast<const C*>(p)); }};
}

/// A row of the table: odestep's step, and the hand loops where they exist.
struct row_def {
    const char* name = nullptr;
    variant odestep, hand, checked;
};
/// A unit's static `registration` puts its row in the table (main.cpp), at `index` (its M4F_UNIT).
struct registration {
    registration(int index, const char* name, const variant& odestep, const variant& hand = {},
                 const variant& checked = {});
};

/// odestep's steps on the contexts above, for the rows that need nothing more.
template <class Stepper>
M4F_STEP int step_first_order(void* p, float t, float dt) {
    return static_cast<int>(Stepper{}.step(rhs, as<first_order>(p).y, t, dt));
}
template <class Stepper>
M4F_STEP int step_newtonian(void* p, float t, float dt) {
    kept<Stepper>& c = as<kept<Stepper>>(p);
    return static_cast<int>(c.s.step(springs, c.x, c.v, t, dt));
}
template <class Stepper>
M4F_STEP int step_multistep(void* p, float t, float dt) {
    multistep<Stepper>& c = as<multistep<Stepper>>(p);
    return static_cast<int>(c.s.step(rhs, c.y, t, dt));
}

}  // namespace m4f

#endif
