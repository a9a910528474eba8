// SPDX-License-Identifier: BSL-1.0
// Must NOT compile: a user's stepper that does not publish rhs_evals_per_step. A ctest checks that the
// compiler names the missing trait in one error.
#include <odestep/odestep.hpp>

template <class State>
struct my_euler {
    using state_type = State;
    using value_type = typename State::value_type;
    static constexpr int order = 1;
    static constexpr std::size_t stages = 1;
    template <class F>
    odestep::status step(F& f, State& y, value_type t, value_type dt) const {
        const State d = f(t, y);
        for (std::size_t i = 0; i < y.size(); ++i) y[i] += dt * d[i];
        return odestep::status::ok;
    }
};

int main() {
    using state = std::array<double, 1>;
    auto f = [](double, const state& y) { return state{-y[0]}; };
    state y{1.0};
    const auto r = odestep::integrate(my_euler<state>{}, f, y, 0.0, 1.0, 0.1);
    return r.status == odestep::status::ok ? 0 : 1;
}
