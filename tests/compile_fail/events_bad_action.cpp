// SPDX-License-Identifier: BSL-1.0
// Must not compile: an event action that returns something other than nothing or odestep::event_result
// (a bool would be ambiguous: does true mean "stop" or "go on"?).
#include <odestep/odestep.hpp>

#include <array>

int main() {
    using state = std::array<double, 1>;
    auto f = [](double, const state&) { return state{1.0}; };
    auto g = [](double, const state& y) { return y[0] - 0.5; };
    auto action = [](double, state&) { return true; };
    state y{0.0};
    const auto r =
        odestep::integrate(odestep::rk4<state>{}, f, y, 0.0, 1.0, 0.1,
                           odestep::watch(odestep::make_event<state>(g, odestep::direction::rising, action)));
    return r.status == odestep::status::ok ? 0 : 1;
}
