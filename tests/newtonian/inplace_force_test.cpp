// SPDX-License-Identifier: BSL-1.0
// The in-place forms of Newton's equations, `void a(t, x, a_out)` and `void a(t, x, v, a_out)`: detected at
// compile time (system.hpp) and stepped bit for bit as the returning forms `State a(t, x)` and
// `State a(t, x, v)` that compute the same values (the expected results are the returning forms' runs, an
// independent path through the library: the steppers call the user's function by its form).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "support/compare.hpp"
#include "support/methods.hpp"
#include "support/type_list.hpp"

namespace {

using state = std::array<double, 2>;

// The anharmonic oscillator x'' = -x - x^3 (each component), with a time-dependent drive in the first: the
// same arithmetic in both forms.
state spring(double t, const state& x) {
    return {-x[0] - x[0] * x[0] * x[0] + 0.1 * std::sin(t), -x[1] - x[1] * x[1] * x[1]};
}
// ... and the damped form x'' = -x - x^3 - v / 2.
state damped(double t, const state& x, const state& v) {
    const state a = spring(t, x);
    return {a[0] - 0.5 * v[0], a[1] - 0.5 * v[1]};
}

struct returning_position {
    state operator()(double t, const state& x) const { return spring(t, x); }
};
struct inplace_position {
    void operator()(double t, const state& x, state& a) const { a = spring(t, x); }
};
struct returning_velocity {
    state operator()(double t, const state& x, const state& v) const { return damped(t, x, v); }
};
struct inplace_velocity {
    void operator()(double t, const state& x, const state& v, state& a) const { a = damped(t, x, v); }
};

static_assert(odestep::is_inplace_position_force_v<inplace_position, state>);
static_assert(odestep::is_position_force_v<inplace_position, state>);
static_assert(!odestep::is_velocity_force_v<inplace_position, state>);
static_assert(odestep::is_inplace_velocity_force_v<inplace_velocity, state>);
static_assert(odestep::is_velocity_force_v<inplace_velocity, state>);
static_assert(!odestep::is_position_force_v<inplace_velocity, state>);
// A returning a(t, x, v) has the in-place position form's arity, and is not taken for it.
static_assert(!odestep::is_inplace_position_force_v<returning_velocity, state>);
static_assert(odestep::is_velocity_force_v<returning_velocity, state>);
// A generic lambda with `auto& out` is the in-place position form (and never instantiated with a const out).
constexpr auto generic_inplace = [](auto t, const auto& x, auto& a) { a = spring(t, x); };
static_assert(odestep::is_position_force_v<decltype(generic_inplace), state>);
static_assert(!odestep::is_velocity_force_v<decltype(generic_inplace), state>);

// 200 steps of `Stepper` with force A, from x = (1, -0.5), v = (0, 1), dt = 0.01: the stepper's own loop.
template <class Stepper, class A>
std::array<state, 2> run(A a) {
    Stepper stepper;
    state x{1.0, -0.5};
    state v{0.0, 1.0};
    const auto r = odestep::integrate_n_steps(stepper, a, x, v, 0.0, 0.01, 200);
    REQUIRE(r.status == odestep::status::ok);
    return {x, v};
}

}  // namespace

TEST_CASE("newtonian in place: every Newtonian stepper gives the returning form's run bit for bit, a(t, x, a_out)") {
    odestep_test::for_each_type<odestep_test::newtonian_steppers<state>>([](auto stepper) {
        using stepper_t = decltype(stepper);
        const auto expected = run<stepper_t>(returning_position{});
        const auto got = run<stepper_t>(inplace_position{});
        CHECK(odestep_test::same_bits(got[0], expected[0]));
        CHECK(odestep_test::same_bits(got[1], expected[1]));
        const auto generic = run<stepper_t>(generic_inplace);
        CHECK(odestep_test::same_bits(generic[0], expected[0]));
    });
}

TEST_CASE("newtonian in place: a(t, x, v, a_out) gives the returning a(t, x, v)'s run bit for bit") {
    odestep_test::for_each_type<
        std::tuple<odestep::newtonian_euler<state>, odestep::newtonian_euler_richardson<state>, odestep::beeman<state>,
                   odestep::predictor_corrector<state>, odestep::euler_cromer<state>, odestep::velocity_verlet<state>>>(
        [](auto stepper) {
            using stepper_t = decltype(stepper);
            const auto expected = run<stepper_t>(returning_velocity{});
            const auto got = run<stepper_t>(inplace_velocity{});
            CHECK(odestep_test::same_bits(got[0], expected[0]));
            CHECK(odestep_test::same_bits(got[1], expected[1]));
        });
}

TEST_CASE("newtonian in place: velocity Verlet's caller-kept step takes a(t, x, a_out), bit for bit") {
    odestep::velocity_verlet<state> stepper;
    state x1{1.0, -0.5}, v1{0.0, 1.0}, x2 = x1, v2 = v1;
    state acc1 = spring(0.0, x1);
    state acc2 = acc1;
    for (int i = 0; i < 100; ++i) {
        const double t = 0.01 * i;
        REQUIRE(stepper.step(returning_position{}, x1, v1, acc1, t, 0.01) == odestep::status::ok);
        REQUIRE(stepper.step(inplace_position{}, x2, v2, acc2, t, 0.01) == odestep::status::ok);
    }
    CHECK(odestep_test::same_bits(x1, x2));
    CHECK(odestep_test::same_bits(v1, v2));
    CHECK(odestep_test::same_bits(acc1, acc2));
}
