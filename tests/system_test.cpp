// SPDX-License-Identifier: BSL-1.0
// How a right-hand side is called: both signatures, any callable, detected at compile time.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>

#include "support/compare.hpp"

namespace {

using state2 = std::array<double, 2>;

state2 sho_returning(double, const state2& y) { return {y[1], -y[0]}; }
void sho_inplace(double, const state2& y, state2& dydt) {
    dydt[0] = y[1];
    dydt[1] = -y[0];
}

struct bad_arity {
    state2 operator()(const state2& y) const { return y; }
};
struct bad_return {
    int operator()(double, const state2&) const { return 0; }
};

static_assert(odestep::is_system_v<decltype(&sho_returning), state2>);
static_assert(odestep::is_system_v<decltype(&sho_inplace), state2>);
static_assert(odestep::is_returning_system_v<decltype(&sho_returning), state2>);
static_assert(odestep::is_inplace_system_v<decltype(&sho_inplace), state2>);
static_assert(!odestep::is_system_v<bad_arity, state2>);
static_assert(!odestep::is_system_v<bad_return, state2>);

template <class System>
state2 run(System&& f) {
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate(odestep::dormand_prince54<state2>{}, f, y, 0.0, 3.0, 0.1);
    REQUIRE(r.status == odestep::status::ok);
    return y;
}

}  // namespace

TEST_CASE("system: the returning and the in-place signature give bit-identical results") {
    const state2 a = run(&sho_returning);
    const state2 b = run(&sho_inplace);
    const state2 c = run([](double t, const state2& y) { return sho_returning(t, y); });
    const state2 d = run([](double t, const state2& y, state2& dydt) { sho_inplace(t, y, dydt); });
    CHECK(odestep_test::same_bits(a, b));
    CHECK(odestep_test::same_bits(a, c));
    CHECK(odestep_test::same_bits(a, d));
}

TEST_CASE("system: a stateful functor is called in place, not copied per stage") {
    struct counter {
        int calls = 0;
        void operator()(double, const state2& y, state2& dydt) {
            ++calls;
            dydt = {y[1], -y[0]};
        }
    } f;
    state2 y{1.0, 0.0};
    const auto r = odestep::integrate_n_steps(odestep::rk4<state2>{}, f, y, 0.0, 0.1, 10);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(f.calls == 40);
}
