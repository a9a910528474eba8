// SPDX-License-Identifier: BSL-1.0
// Must NOT compile, and the error must name the accepted signatures (a ctest checks the message).
#include <odestep/odestep.hpp>

int main() {
    using state = std::array<double, 2>;
    auto wrong = [](const state& y) { return y; };  // no time argument
    state y{1.0, 0.0};
    return odestep::rk4<state>{}.step(wrong, y, 0.0, 0.1) == odestep::status::ok ? 0 : 1;
}
