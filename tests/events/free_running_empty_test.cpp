// SPDX-License-Identifier: BSL-1.0
// fuzz_free_events' finding (issue 24 item 3): integrate_adaptive and integrate_times with events from t0 = -0.0
// to t1 = +0.0 returned ok with r.t = -0.0, where an ok run ends on t1 bit for bit (docs/reference.md, the
// empty-run rule; issue 24's A on the grid loop). The expected r.t is the t1 the run was given, +0.0, and the
// state is the one it was given (no step is taken).
#include <doctest/doctest.h>
#include <odestep/adaptive.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cstring>

namespace {

using state = std::array<double, 2>;
using statef = std::array<float, 2>;

template <class T>
bool same_bits(T a, T b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

template <class T>
struct decay {  // y' = -y
    std::array<T, 2> operator()(T, const std::array<T, 2>& y) const { return {-y[0], -y[1]}; }
};

// g = y0 - 1/2 falling, with a bounce: never reached in an empty run.
template <class S>
auto half_event() {
    using T = typename S::value_type;
    return odestep::make_event<S>([](T, const S& y) { return y[0] - T(0.5); }, odestep::direction::falling,
                                  [](T, S& y) { y[1] = -y[1]; });
}

}  // namespace

TEST_CASE("free-running loops with events: an empty run from -0.0 to +0.0 ends on +0.0 bit for bit") {
    const auto events = odestep::watch(half_event<state>());
    {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state> dp5;
        state y{1.0, 2.0};
        const auto r = odestep::integrate_adaptive(dp5, decay<double>{}, y, -0.0, 0.0, events);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
        CHECK(r.steps == 0);
        CHECK((y == state{1.0, 2.0}));
    }
    {
        odestep::radau5<state> radau;
        state y{1.0, 2.0};
        const auto r = odestep::integrate_adaptive(radau, decay<double>{}, y, -0.0, 0.0, events);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
    }
    {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state> dp5;
        state y{1.0, 2.0};
        const std::array<double, 1> times{0.0};
        const auto r =
            odestep::integrate_times(dp5, decay<double>{}, y, -0.0, times, events, [](double, const state&) {});
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
    }
    {  // float, as the fuzzer found it (Dormand-Prince 5(4))
        odestep::adaptive_rk<odestep::tables::dormand_prince54, statef> dp5;
        statef y{1.0f, 2.0f};
        const auto r =
            odestep::integrate_adaptive(dp5, decay<float>{}, y, -0.0f, 0.0f, odestep::watch(half_event<statef>()));
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0f));
    }
}

// The same rule without events (the plain free-running loop and integrate_times, adaptive/integrate_adaptive.hpp):
// they too ended ok on -0.0 (fuzz_free_events' report; the same one-line fix).
TEST_CASE("free-running loops without events: an empty run from -0.0 to +0.0 ends on +0.0 bit for bit") {
    {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state> dp5;
        state y{1.0, 2.0};
        const auto r = odestep::integrate_adaptive(dp5, decay<double>{}, y, -0.0, 0.0);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
        CHECK(r.steps == 0);
        CHECK((y == state{1.0, 2.0}));
    }
    {
        odestep::radau5<state> radau;
        state y{1.0, 2.0};
        const auto r = odestep::integrate_adaptive(radau, decay<double>{}, y, -0.0, 0.0);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
    }
    {
        odestep::adaptive_rk<odestep::tables::dormand_prince54, state> dp5;
        state y{1.0, 2.0};
        const std::array<double, 1> times{0.0};
        const auto r = odestep::integrate_times(dp5, decay<double>{}, y, -0.0, times, [](double, const state&) {});
        REQUIRE(r.status == odestep::status::ok);
        CHECK(same_bits(r.t, 0.0));
    }
}
