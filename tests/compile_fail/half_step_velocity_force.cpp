// SPDX-License-Identifier: BSL-1.0
// Must NOT compile: the half-step (staggered leapfrog) algorithm has no velocity at hand for a(t, x, v).
// A ctest checks the one message.
#include <odestep/odestep.hpp>

int main() {
    using S = std::array<double, 2>;
    auto drag = [](double, const S& x, const S& v) { return S{-x[0] - v[0], -x[1] - v[1]}; };
    S x{1.0, 0.0};
    S v{0.0, 1.0};
    return odestep::half_step<S>{}.step(drag, x, v, 0.0, 0.1) == odestep::status::ok ? 0 : 1;
}
