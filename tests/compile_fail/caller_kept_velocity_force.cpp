// SPDX-License-Identifier: BSL-1.0
// Must NOT compile: the caller-kept acceleration of velocity Verlet needs a force of position alone (with
// a(t, x, v) the last kick's acceleration is not the next step's first). A ctest checks the one message.
#include <odestep/odestep.hpp>

int main() {
    using S = std::array<double, 2>;
    auto drag = [](double, const S& x, const S& v) { return S{-x[0] - v[0], -x[1] - v[1]}; };
    S x{1.0, 0.0};
    S v{0.0, 1.0};
    S acc{-1.0, 0.0};
    return odestep::velocity_verlet<S>{}.step(drag, x, v, acc, 0.0, 0.1) == odestep::status::ok ? 0 : 1;
}
