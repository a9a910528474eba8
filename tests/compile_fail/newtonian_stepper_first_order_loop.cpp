// SPDX-License-Identifier: BSL-1.0
// Must NOT compile: a Newtonian stepper (x and v) given to the first-order loop. A ctest checks that the
// compiler says so in one error.
#include <odestep/odestep.hpp>

int main() {
    using state = std::array<double, 2>;
    auto f = [](double, const state& y) { return y; };
    state y{1.0, 0.0};
    const auto r = odestep::integrate(odestep::velocity_verlet<state>{}, f, y, 0.0, 1.0, 0.1);
    return r.status == odestep::status::ok ? 0 : 1;
}
