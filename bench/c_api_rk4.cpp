// SPDX-License-Identifier: BSL-1.0
// The C API's RK4 step (odestep_step_d, n = 4) against the C++ step with the same C function pointer (issue
// 27: "the C API within 1.1x of the C++ step at its default maximum"). Two masses between three unit
// springs, y = (x1, x2, v1, v2): x1'' = -2 x1 + x2, x2'' = x1 - 2 x2. The library is linked as the target
// odestep::odestep_c builds it (src/capi.cpp and src/capi_double.cpp compiled on their own with
// -fno-exceptions -fno-rtti -ffp-contract=off; scripts/bench.sh --c-api and --quick do this), so that its
// step is a call into another translation unit, as a C program gets it. ODESTEP_C_MAX_STATES is the
// library's default, 8, unless the build defines it.
//
// Variants: odestep (odestep_step_d, n = 4), cpp_fnptr (the reference: odestep::rk4<std::array<double, 4>>
// with f through a C function pointer read from a global, as the C API reads it from the system),
// cpp (the same C++ step with f inlined; shown, not a reference).
#include "harness.hpp"

#include "odestep/odestep.h"

#define BENCH_STR2(x) #x
#define BENCH_STR(x) BENCH_STR2(x)

namespace {
using State = std::array<double, 4>;
using rhs_fn = void (*)(double, const double*, double*, void*);

void springs(const double* y, double* d) {
    d[0] = y[2];
    d[1] = y[3];
    d[2] = -2.0 * y[0] + y[1];
    d[3] = y[0] - 2.0 * y[1];
}
extern "C" void bench_c_api_springs(double, const double* y, double* d, void*) { springs(y, d); }

odestep_stepper_d c_stepper;
const odestep_system_d c_system{bench_c_api_springs, nullptr, 4};
}  // namespace

// Not const, with external linkage: the compiler cannot know the function it points to.
extern "C" rhs_fn bench_c_api_rhs;
rhs_fn bench_c_api_rhs = bench_c_api_springs;

BENCH_STEP int bench_step_c_api_rk4_odestep(State& y, State&, double t, double dt) {
    return odestep_step_d(&c_stepper, &c_system, y.data(), t, dt);
}
BENCH_STEP int bench_step_c_api_rk4_cpp_fnptr(State& y, State&, double t, double dt) {
    const rhs_fn f = bench_c_api_rhs;
    return static_cast<int>(odestep::rk4<State>{}.step(
        [f](double tt, const State& a, State& d) { f(tt, a.data(), d.data(), nullptr); }, y, t, dt));
}
BENCH_STEP int bench_step_c_api_rk4_cpp(State& y, State&, double t, double dt) {
    return static_cast<int>(
        odestep::rk4<State>{}.step([](double, const State& a, State& d) { springs(a.data(), d.data()); }, y, t, dt));
}

int main(int argc, char** argv) {
    if (odestep_max_states() != ODESTEP_C_MAX_STATES ||
        odestep_stepper_init_d(&c_stepper, &odestep_rk4_d) != ODESTEP_OK) {
        std::fprintf(stderr, "c_api_rk4: the library's ODESTEP_C_MAX_STATES differs, or init failed\n");
        return 2;
    }
    const State y0{1.0, 0.0, 0.0, 0.0};
    const int steps = 100;
    // The closed form: the normal modes x1 = x2 (omega 1) and x1 = -x2 (omega sqrt 3), from x = (1, 0), v = 0:
    // x1,2 = (cos t +- cos(sqrt(3) t)) / 2, v1,2 = (-sin t -+ sqrt(3) sin(sqrt(3) t)) / 2, at t = 100 * 0.01.
    const double w = std::sqrt(3.0);
    const State exact{(std::cos(1.0) + std::cos(w)) / 2, (std::cos(1.0) - std::cos(w)) / 2,
                      (-std::sin(1.0) - w * std::sin(w)) / 2, (-std::sin(1.0) + w * std::sin(w)) / 2};
    bench::problem<State> p{"c_api_rk4", y0, 0.0, 0.01, steps, exact,
                            // The same arithmetic: equal to round-off (bit for bit in practice).
                            1e-14,
                            // RK4's global error at h = 0.01 over t = 1: C h^4 with C of order omega^5 ~ 16.
                            1e-8, false};
    return bench::main<State>(
        argc, argv, p,
        {{"odestep", "odestep_step_d (C API, n = 4, ODESTEP_C_MAX_STATES " BENCH_STR(ODESTEP_C_MAX_STATES) ")",
          bench_step_c_api_rk4_odestep, true},
         {"cpp_fnptr", "odestep::rk4<std::array<double, 4>>, f through a C function pointer (the reference)",
          bench_step_c_api_rk4_cpp_fnptr, true},
         {"cpp", "odestep::rk4<std::array<double, 4>>, f inlined", bench_step_c_api_rk4_cpp, true}});
}
