// SPDX-License-Identifier: BSL-1.0
// Writing your own stepper: a class that publishes odestep's trait set (stepper_defaults gives the usual
// values) and a step(f, y, t, dt), driven by integrate and by the event loop like the library's own.
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

// Heun's method (the explicit trapezoid), written by hand.
template <class State>
struct my_heun : odestep::stepper_defaults<State> {
    using T = typename State::value_type;
    static constexpr int order = 2;
    static constexpr std::size_t stages = 2;
    static constexpr std::size_t rhs_evals_per_step = 2;

    template <class System>
    [[nodiscard]] odestep::status step(System&& f, State& y, T t, T dt) const {
        const State k1 = f(t, y);
        State predictor;
        for (std::size_t i = 0; i < y.size(); ++i) predictor[i] = y[i] + dt * k1[i];
        const State k2 = f(t + dt, predictor);
        State next;
        for (std::size_t i = 0; i < y.size(); ++i) next[i] = y[i] + dt / T(2) * (k1[i] + k2[i]);
        for (const T v : next)
            if (!(v - v == T(0))) return odestep::status::non_finite;  // NaN or Inf: y stays as it was
        y = next;
        return odestep::status::ok;
    }
};
static_assert(odestep::check_stepper<my_heun<std::array<double, 1>>>());

int main() {
    using state = std::array<double, 1>;
    auto decay = [](double, const state& y) { return state{-y[0]}; };  // y' = -y

    state y{1.0};
    const auto r = odestep::integrate(my_heun<state>{}, decay, y, 0.0, 1.0, 0.01);
    std::printf("integrate: status %s, y(1) = %.10f (exact e^-1 = %.10f)\n", odestep::to_string(r.status), y[0],
                std::exp(-1.0));

    // The event loop re-steps the user's stepper to find y = 1/2, at t = ln 2.
    state z{1.0};
    auto half =
        odestep::make_event<state>([](double, const state& s) { return s[0] - 0.5; }, odestep::direction::falling);
    const auto e = odestep::integrate(my_heun<state>{}, decay, z, 0.0, 2.0, 0.01, odestep::watch(half));
    std::printf("event: status %s at t = %.10f (exact ln 2 = %.10f)\n", odestep::to_string(e.status), e.t,
                std::log(2.0));
    return r.status == odestep::status::ok && e.status == odestep::status::stopped_by_event ? 0 : 1;
}
