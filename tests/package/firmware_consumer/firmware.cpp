// SPDX-License-Identifier: BSL-1.0
// One control tick of a float mass-spring-damper, as firmware would call it from its timer interrupt.
#include <odestep/odestep.hpp>

#include <array>

namespace {
using state = std::array<float, 2>;
struct plant {
    float u = 0.0f;
    state operator()(float, const state& y) const { return state{y[1], u - 4.0f * y[0] - 0.4f * y[1]}; }
};
}  // namespace

extern "C" int firmware_tick(float* position, float* velocity, float input, unsigned long tick) {
    state y{*position, *velocity};
    const float dt = 1e-3f;
    const odestep::status s = odestep::rk4<state>{}.step(plant{input}, y, static_cast<float>(tick) * dt, dt);
    if (s != odestep::status::ok) return static_cast<int>(s);
    *position = y[0];
    *velocity = y[1];
    return 0;
}
