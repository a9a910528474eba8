// SPDX-License-Identifier: BSL-1.0
// Must NOT compile with -Werror: a status is [[nodiscard]] (a ctest checks the diagnostic).
#include <odestep/odestep.hpp>

int main() {
    using state = std::array<double, 1>;
    state y{1.0};
    odestep::euler<state>{}.step([](double, const state& s) { return s; }, y, 0.0, 0.1);
    return 0;
}
