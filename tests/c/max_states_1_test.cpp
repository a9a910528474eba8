// SPDX-License-Identifier: BSL-1.0
// The C API built with ODESTEP_C_MAX_STATES 1, the smallest maximum: the library's double half is compiled
// into this program with it (its own build of src/, not odestep_c's). It must compile (every stepper
// object and the binding fit the stepper's storage: Adams-Bashforth-Moulton 4's did not, at 1 and 2) and
// step: RK4 on y' = -y, whose step on a linear problem is exactly 1 - h + h^2/2 - h^3/6 + h^4/24 times y
// (the Taylor polynomial of exp(-h): Hairer, Norsett and Wanner, Solving ODE I, II.1), ABM4 (the largest
// object) against exp(-t), and n = 2 refused.
#define ODESTEP_C_MAX_STATES 1
#include <cmath>
#include <cstdio>

#include "../../src/capi.cpp"
#include "../../src/capi_double.cpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
    if (!ok) {
        std::printf("max_states_1_test: %s failed\n", what);
        ++failures;
    }
}

void decay(double, const double* y, double* dydt, void*) { dydt[0] = -y[0]; }

}  // namespace

int main() {
    check(odestep_max_states() == 1, "odestep_max_states() is 1");
    const odestep_system_d sys{decay, nullptr, 1};

    // RK4: 10 steps of h = 0.1, each y *= R(h) = 1 - h + h^2/2 - h^3/6 + h^4/24 (to round-off: the step sums
    // its stages in another order).
    odestep_stepper_d rk4;
    check(odestep_stepper_init_d(&rk4, &odestep_rk4_d) == ODESTEP_OK, "rk4 init");
    double y = 1.0;
    double expected = 1.0;
    const double h = 0.1;
    const double r = 1.0 - h + h * h / 2.0 - h * h * h / 6.0 + h * h * h * h / 24.0;
    for (int k = 0; k < 10; ++k) {
        check(odestep_step_d(&rk4, &sys, &y, h * k, h) == ODESTEP_OK, "rk4 step");
        expected *= r;
    }
    check(std::fabs(y - expected) <= 1e-15, "rk4 gives R(h)^10");

    // ABM4, the largest stepper object: 20 steps to t = 2 against exp(-2); the method's global error there is
    // of order h^4 = 1e-4 times a small constant (measured: 1.0e-6), so 1e-5 separates a working history
    // from a broken one (a garbled history is off by far more, or the step is refused).
    odestep_stepper_d abm4;
    check(odestep_stepper_init_d(&abm4, &odestep_abm4_d) == ODESTEP_OK, "abm4 init");
    double z = 1.0;
    for (int k = 0; k < 20; ++k) check(odestep_step_d(&abm4, &sys, &z, h * k, h) == ODESTEP_OK, "abm4 step");
    check(std::fabs(z - std::exp(-2.0)) <= 1e-5, "abm4 reaches exp(-2)");

    // n = 2 is above the maximum: refused, nothing touched.
    double two[2] = {1.0, 2.0};
    const odestep_system_d sys2{decay, nullptr, 2};
    check(odestep_step_d(&rk4, &sys2, two, 0.0, h) == ODESTEP_INVALID_SETTING, "n = 2 refused");
    check(two[0] == 1.0 && two[1] == 2.0, "n = 2 touches nothing");

    std::printf("c api max states 1: %d failed checks\n", failures);
    return failures == 0 ? 0 : 1;
}
