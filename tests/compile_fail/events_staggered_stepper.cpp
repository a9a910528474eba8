// SPDX-License-Identifier: BSL-1.0
// Must not compile: the Boris pusher keeps v half a step behind x, so a re-step to an event's time would
// mix two times; the event loop refuses it with a readable message.
#include <odestep/odestep.hpp>

#include <array>

int main() {
    using vec = std::array<double, 3>;
    auto fields = [](double, const vec&, vec& E, vec& B) {
        E = {0.0, 0.0, 0.0};
        B = {0.0, 0.0, 1.0};
    };
    auto g = [](double, const vec& x, const vec&) { return x[0]; };
    vec x{1.0, 0.0, 0.0};
    vec v{0.0, 1.0, 0.0};
    const auto r = odestep::integrate(odestep::boris<vec>{}, fields, x, v, 0.0, 1.0, 0.01,
                                      odestep::watch(odestep::make_event<vec>(g, odestep::direction::falling)));
    return r.status == odestep::status::ok ? 0 : 1;
}
