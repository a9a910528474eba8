#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Flash of the C API (odestep::odestep_c) per use, on Cortex-M4F (and M0+), at -Os and -O2: a bare image
# (toolchains/board/, allocator wrapped away) whose main calls one part of the API, minus the same image
# whose main calls nothing of it. Also checks that the float images hold no __aeabi_d* routine.
# Usage: scripts/c_api_size.sh            (writes build/c_api_size/, prints a markdown table)
#        CORES=cortex-m4f scripts/c_api_size.sh   (one core only)
#        EXACT_STATES=8 scripts/c_api_size.sh     (the library built with ODESTEP_C_EXACT_STATES 8; default 0)
# Needs arm-none-eabi-gcc/g++ with newlib. Installs nothing.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
root=$PWD
out=$root/build/c_api_size${EXACT_STATES:+-exact$EXACT_STATES}
mkdir -p "$out"
board=$root/toolchains/board
setting() { sed -n "s/^set($2 \"\{0,1\}\([^\")]*\)\"\{0,1\}).*/\1/p" "$root/toolchains/$1.cmake"; }
# shellcheck disable=SC2054
no_alloc=(-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free,--wrap=_malloc_r,--wrap=_free_r)

# One C main per case; CASE selects what it calls.
cat > "$out/main.c" <<'C'
#include "odestep/odestep.h"
static void f(float t, const float* y, float* dydt, void* ctx) { (void)t; (void)ctx; dydt[0] = y[1]; dydt[1] = -y[0]; dydt[2] = -y[2]; dydt[3] = y[2] - y[3]; }
static void a(float t, const float* x, float* acc, void* ctx) { (void)t; (void)ctx; acc[0] = -x[0]; acc[1] = -x[1]; }
static float g(float t, const float* y, void* ctx) { (void)t; (void)ctx; return y[0]; }
static odestep_event_result bounce(float t, float* y, void* ctx) { (void)t; (void)ctx; y[1] = -0.8f * y[1]; return ODESTEP_PROCEED; }
static void jac(float t, const float* y, float* j, void* ctx) { int i; (void)t; (void)y; (void)ctx; for (i = 0; i < 16; ++i) j[i] = 0.0f; j[1] = 1.0f; j[4] = -1.0f; j[10] = -1.0f; j[14] = 1.0f; j[15] = -1.0f; }
volatile float sink;
int main(void) {
    float y[4] = {1.0f, 0.0f, 1.0f, 0.0f};
    const odestep_system_f sys = {f, 0, 4};
    const odestep_newton_f nsys = {a, 0, 2};
    odestep_stepper_f s;
    const odestep_jac_system_f jsys = {f, jac, 0, 4};
    (void)sys; (void)nsys; (void)s; (void)g; (void)a; (void)f; (void)bounce; (void)jsys; (void)jac;
#if CASE == 1
    odestep_stepper_init_f(&s, &METHOD);
    odestep_step_f(&s, &sys, y, 0.0f, 0.01f);
#elif CASE == 2
    odestep_stepper_init_f(&s, &METHOD);
    odestep_step_newton_f(&s, &nsys, y, y + 2, 0.0f, 0.01f);
#elif CASE == 3
    odestep_stepper_init_f(&s, &METHOD);
    odestep_integrate_f(&s, &sys, y, 0.0f, 1.0f, 0.01f, 0, 0, 0);
#elif CASE == 4
    {
        odestep_event_loop_f loop;
        odestep_event_f e = {g, ODESTEP_FALLING, 0, 0, 0.0f, 0.0f, 0.0f, 0};
        odestep_event_loop_start_f(&loop, &METHOD, &e, 1, 0, &sys, y, 0.0f, 0.01f);
        odestep_event_loop_tick_f(&loop, &sys, y, 0);
    }
#elif CASE == 5
    {
        odestep_event_loop_f loop;
        odestep_event_f e = {g, ODESTEP_FALLING, bounce, 0, 0.0f, 0.0f, 0.0f, 0};
        odestep_event_loop_start_f(&loop, &METHOD, &e, 1, 0, &sys, y, 0.0f, 0.01f);
        odestep_event_loop_tick_f(&loop, &sys, y, 0);
    }
#elif CASE == 6
    {
        odestep_stiff_stepper_f stiff;
        odestep_stiff_init_f(&stiff, &METHOD, 4, 0.0f, 0.0f);
        odestep_stiff_step_f(&stiff, &jsys, y, 0.0f, 0.01f);
    }
#elif CASE == 7
    {
        float phi[16];
        odestep_step_transition_f(&METHOD, &jsys, y, phi, 0.0f, 0.01f);
        sink = phi[5];
    }
#endif
    sink = y[0];
    return 0;
}
C

cases=("baseline|0|odestep_rk4_f"
       "euler step|1|odestep_euler_f" "heun step|1|odestep_heun_f" "rk4 step|1|odestep_rk4_f"
       "dp54 step|1|odestep_dp54_f" "dop853 step|1|odestep_dop853_f" "abm4 step|1|odestep_abm4_f"
       "velocity_verlet step|2|odestep_velocity_verlet_f" "forest_ruth step|2|odestep_forest_ruth_f"
       "rk4 integrate|3|odestep_rk4_f" "rk4 event loop (start + tick), terminal event|4|odestep_rk4_f"
       "rk4 event loop (start + tick), event with an action|5|odestep_rk4_f"
       "backward_euler stiff step|6|odestep_backward_euler_f" "sdirk3 stiff step|6|odestep_sdirk3_f"
       "radau_iia5 stiff step|6|odestep_radau_iia5_f" "rodas3 stiff step|6|odestep_rodas3_f"
       "radau5_substeps stiff step|6|odestep_radau5_substeps_f" "rodas4_substeps stiff step|6|odestep_rodas4_substeps_f"
       "dp54_substeps stiff step|6|odestep_dp54_substeps_f"
       "rk4 step with Phi|7|odestep_rk4_transition_f" "dp54 step with Phi|7|odestep_dp54_transition_f")
failures=0
echo "| core | flags | use (float, n = 4, MAX_STATES ${MAX_STATES:-8}, EXACT_STATES ${EXACT_STATES:-0}) | flash of the C API (.text + .rodata, bytes) | __aeabi_d* |"
echo "|---|---|---|---:|---|"
for core in ${CORES:-cortex-m4f cortex-m0plus}; do
  read -r -a cpu <<< "$(setting "$core" ODESTEP_TARGET_CPU_FLAGS)"
  script=$(setting "$core" ODESTEP_TARGET_LINKER_SCRIPT)
  for opt in -Os -O2; do
    lib=$out/$core$opt
    mkdir -p "$lib"
    for src in capi capi_float capi_events_float capi_stiff_float; do
      arm-none-eabi-g++ "${cpu[@]}" $opt -std=c++17 -fno-exceptions -fno-rtti -ffp-contract=off -ffunction-sections -fdata-sections \
        -DODESTEP_C_MAX_STATES="${MAX_STATES:-8}" -DODESTEP_C_EXACT_STATES="${EXACT_STATES:-0}" -I"$root/include" \
        -c "$root/src/$src.cpp" -o "$lib/$src.o" || exit 1
    done
    arm-none-eabi-g++ "${cpu[@]}" -Os -std=c++17 -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections \
      -DODESTEP_BOARD_BARE=1 -c "$board/startup.cpp" -o "$lib/startup.o" &&
    arm-none-eabi-g++ "${cpu[@]}" -Os -std=c++17 -fno-exceptions -fno-rtti -ffunction-sections -fdata-sections \
      -DODESTEP_BOARD_BARE=1 -c "$board/syscalls.cpp" -o "$lib/syscalls.o" || exit 1
    base=0
    for entry in "${cases[@]}"; do
      IFS='|' read -r name case method <<< "$entry"
      image=$lib/case-${name// /_}.elf
      arm-none-eabi-gcc "${cpu[@]}" $opt -std=c99 -Wall -Wextra -Wpedantic -Werror -ffunction-sections -fdata-sections \
        -DODESTEP_C_MAX_STATES="${MAX_STATES:-8}" -DCASE="$case" -DMETHOD="$method" -I"$root/include" \
        -c "$out/main.c" -o "$lib/main-$case-$method.o" || exit 1
      arm-none-eabi-g++ "${cpu[@]}" "$lib/main-$case-$method.o" "$lib"/capi*.o "$lib/startup.o" "$lib/syscalls.o" \
        -nostartfiles -L"$board" -T"$board/$script" -Wl,--gc-sections "${no_alloc[@]}" -o "$image" || exit 1
      text=$(arm-none-eabi-size -A "$image" | awk '$1 == ".text" || $1 == ".rodata" { s += $2 } END { print s }')
      if [ "$case" = 0 ]; then base=$text; continue; fi
      d=no
      if arm-none-eabi-nm "$image" | grep -q ' __aeabi_d'; then
        # The fixed-step loop's plan (detail::plan_run) converts float to the 64-bit step counter: libgcc's
        # __aeabi_f2ulz, which is written with double arithmetic. Known, outside the C API (the C++
        # integrate in float links the same); any other double routine is a failure.
        if [ "$case" = 3 ] && arm-none-eabi-nm "$image" | grep -q ' __aeabi_f2ulz'; then
          d="yes: libgcc __aeabi_f2ulz (plan_run's float to uint64)"
        else
          d=YES
          failures=$((failures + 1))
        fi
      fi
      echo "| $core | $opt | $name | $((text - base)) | $d |"
    done
  done
done
exit $((failures > 0))
