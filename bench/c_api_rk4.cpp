// SPDX-License-Identifier: BSL-1.0
// The C API's RK4 step against the C++ one, in instructions per step (issue 16: "a C RK4 step on 4 states
// costs at most 1.1x the C++ step's instructions, the function-pointer call per stage counted"). Not part of
// scripts/bench.sh (no Boost or GSL variant); built and counted by hand, the library compiled as the
// odestep_c target compiles it:
//
//   for f in capi capi_double; do
//     g++ -std=c++17 -O2 -fno-exceptions -fno-rtti -ffp-contract=off -DODESTEP_C_MAX_STATES=4 -Iinclude
//         -c src/$f.cpp -o /tmp/$f.o; done
//   g++ -std=c++17 -O2 -DODESTEP_C_MAX_STATES=4 -Iinclude bench/c_api_rk4.cpp /tmp/capi.o /tmp/capi_double.o
//       -o /tmp/c_api_rk4
//   valgrind --tool=callgrind --collect-atstart=no '--toggle-collect=bench_step_*' /tmp/c_api_rk4
//   callgrind_annotate --inclusive=yes callgrind.out.* | grep bench_step     (1000 steps of each)
//
// bench_step_cpp: odestep::rk4<std::array<double, 4>> with the right-hand side inlined; bench_step_cpp_fnptr:
// the same with the right-hand side called through a C function pointer, as the C API calls it;
// bench_step_c: odestep_step_d (n = 4). The program prints "0 1 1": no failed step, and the three runs equal.
#include <array>
#include <cstdio>
#include "odestep/explicit_rk.hpp"
#include "odestep/odestep.h"
using S = std::array<double, 4>;
// two masses, three springs (the audit's 4-state system)
static void springs(const double* y, double* d) {
    d[0] = y[2];
    d[1] = y[3];
    d[2] = -2.0 * y[0] + y[1];
    d[3] = y[0] - 2.0 * y[1];
}
extern "C" void rhs_c(double, const double* y, double* d, void*) { springs(y, d); }
extern "C" __attribute__((noipa)) int bench_step_cpp(S& y, double t, double dt) {
    return static_cast<int>(
        odestep::rk4<S>{}.step([](double, const S& a, S& d) { springs(a.data(), d.data()); }, y, t, dt));
}
extern "C" __attribute__((noipa)) int bench_step_cpp_fnptr(S& y, double t, double dt,
                                                           void (*f)(double, const double*, double*, void*)) {
    return static_cast<int>(
        odestep::rk4<S>{}.step([f](double tt, const S& a, S& d) { f(tt, a.data(), d.data(), nullptr); }, y, t, dt));
}
extern "C" __attribute__((noipa)) int bench_step_c(odestep_stepper_d* s, const odestep_system_d* sys, double* y,
                                                   double t, double dt) {
    return odestep_step_d(s, sys, y, t, dt);
}
int main() {
    S y{1, 0, 0, 0};
    double yc[4] = {1, 0, 0, 0};
    S y2{1, 0, 0, 0};
    odestep_stepper_d s;
    odestep_stepper_init_d(&s, &odestep_rk4_d);
    const odestep_system_d sys{rhs_c, nullptr, 4};
    int bad = 0;
    for (int i = 0; i < 1000; ++i) {
        bad += bench_step_cpp(y, i * 0.01, 0.01);
        bad += bench_step_cpp_fnptr(y2, i * 0.01, 0.01, rhs_c);
        bad += bench_step_c(&s, &sys, yc, i * 0.01, 0.01);
    }
    std::printf("%d %d %d\n", bad, y[0] == yc[0], y2[0] == yc[0]);
}
