// Compiled with -fno-exceptions -fno-rtti and inspected for mutable static storage (.data/.bss) by
// check_static_state.cmake: every stepper instantiated in float, double and long double.
#include <odestep/odestep.hpp>

#include <array>

#include "methods.hpp"

namespace {
template <class T>
using state4 = std::array<T, 4>;

struct oscillators {
    template <class T>
    state4<T> operator()(T, const state4<T>& y) const noexcept {
        return {y[1], -y[0], y[3], T(-4) * y[2]};
    }
};

template <class T>
T run_everything() {
    T sum = T(0);
    odestep_test::for_each_method([&](auto method) {
        using stepper_t = odestep::explicit_rk<decltype(method), state4<T>>;
        state4<T> y{T(1), T(0), T(1), T(0)};
        if (odestep::integrate(stepper_t{}, oscillators{}, y, T(0), T(1), T(0.125)).status == odestep::status::ok)
            sum += y[0];
        if constexpr (stepper_t::error_estimate) {
            state4<T> err{};
            if (stepper_t{}.step(oscillators{}, y, T(0), T(0.125), err) == odestep::status::ok) sum += err[0];
        }
    });
    return sum;
}
}  // namespace

// External linkage so nothing is optimised away.
float discipline_float() { return run_everything<float>(); }
double discipline_double() { return run_everything<double>(); }
long double discipline_long_double() { return run_everything<long double>(); }
