// SPDX-License-Identifier: BSL-1.0
// Must NOT compile: a state is a std::array<T, N>, never a std::vector (no step may allocate). A ctest checks
// that the compiler says so in one error.
#include <odestep/odestep.hpp>

#include <vector>

int main() {
    using state = std::vector<double>;
    auto f = [](double, const state& y) { return y; };
    state y{1.0, 0.0};
    odestep::rk4<state> stepper;
    const auto r = odestep::integrate(stepper, f, y, 0.0, 1.0, 0.1);
    return r.status == odestep::status::ok ? 0 : 1;
}
