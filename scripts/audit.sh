#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Firmware-discipline audit of odestep with arm-none-eabi-g++ (writes build/audit/, prints a markdown report):
#
#  1. examples/firmware_loop.cpp (and, 1b, examples/c_firmware.c on the C API), linked with the bare board (toolchains/board/, no C library I/O) for
#     Cortex-M0+, M3, M4F and M33 with the allocator wrapped away (-Wl,--wrap=malloc,...: an allocation
#     anywhere fails the link), holds no malloc/free/_sbrk/operator new/delete/__cxa_* symbol, and, being a
#     float program, no __aeabi_d* double-precision routine; run under QEMU where the core has a board.
#  2. Every stepper's step() in float, compiled for M0+ and M4F at -Os and -O2, calls no __aeabi_d* routine
#     (nothing in the library promotes float to double).
#  3. Flash (.text) and stack of one step() per stepper (4-state system), float and double, on M4F and M0+ at
#     -Os and -O2, with a hand-written RK4 of the same system for comparison:
#     the step's own code plus every function of the library it reaches (not the compiler's soft-float or
#     libc helpers, listed under the table), and the deepest path of -fstack-usage frames through them
#     (-fcallgraph-info=su), for a 4-state system (two masses, three springs).
# 3b. The same for the Newtonian steppers of symplectic.hpp and newtonian.hpp (x and v two states of 2, the
#     same springs, undamped, as a force of position alone) and the Boris pusher (x and v of 3), their step()
#     under the checks of 2 and 3 as well; no step unit calls the allocator or the C++ run-time.
# 3c. The same for the implicit steppers (backward Euler, trapezoid, SDIRK 3, Radau IIA 5) and RODAS3 on the
#     4-state system of 3, with their float steps checked for __aeabi_d* as in 2; and RK4 with its
#     state-transition matrix (rk4_transition, the Jacobian by hand).
#  4. Instructions per step of every stepper on the emulated Cortex-M4F, float, -O2 and -Os, against the scalar
#     hand loops (scripts/bench-m4f.sh, QEMU -icount): the table goes into the report and into build/audit/cortex-m.md
#     (between its bench-m4f markers). Fails only if the image does not build or run or a row fails its check.
#
# Usage: scripts/audit.sh            Exits non-zero if a check fails. Needs arm-none-eabi-g++ (newlib) and
# awk; qemu-system-arm to run the firmware image (skipped without it). Installs nothing. Compiles JOBS units at
# a time (default: nproc), every image and unit first, then checks them.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
root=$PWD
out=$root/build/audit
mkdir -p "$out"

for tool in arm-none-eabi-g++ arm-none-eabi-nm awk; do
  command -v "$tool" > /dev/null 2>&1 || {
    echo "audit: $tool is missing (Debian: apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi" \
         "libstdc++-arm-none-eabi-newlib)" >&2
    exit 2
  }
done
have_qemu=0
command -v qemu-system-arm > /dev/null 2>&1 && have_qemu=1

# The per-core settings, read from the toolchain files so there is one source of truth.
setting() {  # setting CORE VARIABLE
  sed -n "s/^set($2 \"\{0,1\}\([^\")]*\)\"\{0,1\}).*/\1/p" "$root/toolchains/$1.cmake"
}

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

board=$root/toolchains/board
common_flags=(-std=c++17 -ffunction-sections -fdata-sections -fno-exceptions -fno-rtti
              -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror -I"$root/include")
# shellcheck disable=SC2054  # the commas belong to the linker options
no_alloc=(-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free,--wrap=aligned_alloc,--wrap=memalign
          -Wl,--wrap=posix_memalign,--wrap=_malloc_r,--wrap=_calloc_r,--wrap=_realloc_r,--wrap=_free_r)
forbidden='^(malloc|free|calloc|realloc|_malloc_r|_free_r|_sbrk|_sbrk_r|_Znw.*|_Zna.*|_Zdl.*|_Zda.*|__cxa_.*)$'

report=$out/report.md
# check_image NAME CORE IMAGE MACHINE CPU_FLAGS: a firmware image's sizes, no allocator or C++ run-time symbol,
# no __aeabi_d* (float programs), and its run under QEMU where the core has a board; one row of the report.
check_image() {
  local name=$1 core=$2 image=$3 machine=$4 flags=$5 text data bss symbols runtime doubles run
  read -r text data bss _ < <(arm-none-eabi-size "$image" | awk 'NR == 2')
  symbols=$(arm-none-eabi-nm "$image" | awk '{print $NF}')
  runtime=$(grep -E "$forbidden" <<< "$symbols" | tr '\n' ' ')
  doubles=$(grep -E '^__aeabi_d' <<< "$symbols" | tr '\n' ' ')
  [[ -z "$runtime" ]] || fail "$core: $name contains $runtime"
  [[ -z "$doubles" ]] || fail "$core: the float $name contains $doubles"
  run=-
  if [[ -n "$machine" && $have_qemu == 1 ]]; then
    if timeout 60 qemu-system-arm -M "$machine" -nographic -monitor none \
         -semihosting-config enable=on,target=native -kernel "$image" > "$out/$name-$core.out" 2>&1; then
      run="ok ($machine)"
    else
      run="FAILED ($machine)"
      fail "$core: $name failed under QEMU: $(tail -1 "$out/$name-$core.out")"
    fi
  fi
  echo "| $core | \`$flags\` | $text | $data | $bss | ${runtime:-none} | ${doubles:-none} | $run |" >> "$report"
}
# The images of sections 1 and 1b, built `audit_jobs` at a time before they are checked (an image that does not
# build or link is absent; its log says why).
audit_jobs=${JOBS:-$(nproc 2> /dev/null || echo 2)}
pool_wait() {  # blocks until fewer than audit_jobs background jobs run
  while (($(jobs -rp | wc -l) >= audit_jobs)); do wait -n; done
}
build_firmware_loop() {  # build_firmware_loop CORE
  local cpu script image=$out/firmware_loop-$1.elf
  read -r -a cpu <<< "$(setting "$1" ODESTEP_TARGET_CPU_FLAGS)"
  script=$(setting "$1" ODESTEP_TARGET_LINKER_SCRIPT)
  rm -f "$image"
  arm-none-eabi-g++ "${cpu[@]}" "${common_flags[@]}" -Os -DODESTEP_BOARD_BARE=1 \
    "$root/examples/firmware_loop.cpp" "$board/startup.cpp" "$board/syscalls.cpp" \
    -nostartfiles -L"$board" -T"$board/$script" -Wl,--gc-sections "${no_alloc[@]}" -o "$image" \
    2> "$out/firmware_loop-$1.log" || rm -f "$image"
}
build_c_firmware() {  # build_c_firmware CORE
  local cpu script objects=$out/c_firmware-$1 image=$out/c_firmware-$1.elf ok=1 src
  read -r -a cpu <<< "$(setting "$1" ODESTEP_TARGET_CPU_FLAGS)"
  script=$(setting "$1" ODESTEP_TARGET_LINKER_SCRIPT)
  rm -rf "$image" "$objects" "$objects.log"
  mkdir -p "$objects"
  for src in capi capi_float capi_events_float; do
    arm-none-eabi-g++ "${cpu[@]}" "${common_flags[@]}" -Os -ffp-contract=off -c "$root/src/$src.cpp" \
      -o "$objects/$src.o" 2>> "$objects.log" || ok=0
  done
  arm-none-eabi-gcc "${cpu[@]}" -std=c99 -Os -ffunction-sections -fdata-sections -Wall -Wextra -Wpedantic -Wconversion \
    -Wshadow -Wdouble-promotion -Werror -I"$root/include" -c "$root/examples/c_firmware.c" -o "$objects/main.o" \
    2>> "$objects.log" || ok=0
  if ((ok == 1)); then
    arm-none-eabi-g++ "${cpu[@]}" "${common_flags[@]}" -Os -DODESTEP_BOARD_BARE=1 "$objects"/*.o "$board/startup.cpp" \
      "$board/syscalls.cpp" -nostartfiles -L"$board" -T"$board/$script" -Wl,--gc-sections "${no_alloc[@]}" -lm \
      -o "$image" 2>> "$objects.log" || rm -f "$image"
  fi
}
for core in cortex-m0plus cortex-m3 cortex-m4f cortex-m33; do
  pool_wait
  build_firmware_loop "$core" &
  pool_wait
  build_c_firmware "$core" &
done
wait

{
  echo "# odestep firmware audit"
  echo
  echo "arm-none-eabi-g++ $(arm-none-eabi-g++ -dumpversion), $(date -u +%Y-%m-%d)"
  echo
  echo "## 1. Firmware image (examples/firmware_loop.cpp, float RK4 at 1 kHz, bare board)"
  echo
  echo "| core | flags | .text | .data | .bss | allocator / C++ runtime symbols | \`__aeabi_d*\` | QEMU run |"
  echo "|---|---|---:|---:|---:|---|---|---|"
} > "$report"

# check_images NAME: each core's image $out/NAME-<core>.elf checked and its row written, or its build log shown.
check_images() {
  local name=$1 core cpu machine image
  for core in cortex-m0plus cortex-m3 cortex-m4f cortex-m33; do
    read -r -a cpu <<< "$(setting "$core" ODESTEP_TARGET_CPU_FLAGS)"
    machine=$(setting "$core" ODESTEP_TARGET_QEMU_MACHINE)
    image=$out/$name-$core.elf
    if [[ ! -f "$image" ]]; then
      cat "$out/$name-$core.log" >&2
      fail "$core: $name does not build or link without an allocator"
      echo "| $core | \`${cpu[*]}\` | - | - | - | link FAILED | - | - |" >> "$report"
      continue
    fi
    check_image "$name" "$core" "$image" "$machine" "${cpu[*]}"
  done
}
check_images firmware_loop

# --- 1b: the C firmware example (examples/c_firmware.c on the C API, odestep::odestep_c from src/) ---
{
  echo
  echo "## 1b. C firmware image (examples/c_firmware.c, C99 on the C API: float RK4 plant + event loop, bare board)"
  echo
  echo "| core | flags | .text | .data | .bss | allocator / C++ runtime symbols | \`__aeabi_d*\` | QEMU run |"
  echo "|---|---|---:|---:|---:|---|---|---|"
} >> "$report"
check_images c_firmware

# step_wrappers PARAMETERS CALL STEPPER...: per stepper, the extern "C" audit_step_<stepper>(PARAMETERS) that
# returns CALL, @ standing for the stepper's name in both (the units' symbols the sections below measure).
step_wrappers() {
  local parameters=$1 call=$2 m
  shift 2
  for m in "$@"; do
    echo "extern \"C\" __attribute__((noinline, used)) odestep::status audit_step_$m(${parameters//@/$m}) {"
    echo "  return ${call//@/$m};"
    echo "}"
  done
}
# --- 2 and 3: one translation unit per (core, type, optimisation) with a step() wrapper per stepper ---
methods=$(sed -n 's/^using [a-z0-9_]* = explicit_rk<tables::\([a-z0-9_]*\), State>;$/\1/p' \
            "$root/include/odestep/rk/explicit_rk.hpp" | awk '!seen[$0]++')
unit=$out/step_unit.cpp
{
  echo "// Generated by scripts/audit.sh: one non-inlined step() per stepper, state std::array<AUDIT_T, 4>,"
  echo "// and the same RK4 written by hand as a careful engineer would (loops, h/2 and h/6 hoisted, no check)."
  echo "#include <odestep/odestep.hpp>"
  echo "#include <array>"
  echo "using state = std::array<AUDIT_T, 4>;"
  echo "struct two_masses {  // x1'' = -2 x1 + x2 - c x1', x2'' = x1 - 2 x2 - c x2': two masses, three springs"
  echo "  void operator()(AUDIT_T, const state& y, state& d) const noexcept {"
  echo "    d[0] = y[1];"
  echo "    d[1] = AUDIT_T(-2) * y[0] + y[2] - AUDIT_T(0.1) * y[1];"
  echo "    d[2] = y[3];"
  echo "    d[3] = y[0] - AUDIT_T(2) * y[2] - AUDIT_T(0.1) * y[3];"
  echo "  }"
  echo "};"
  step_wrappers "state& y, AUDIT_T t, AUDIT_T dt" "odestep::explicit_rk<odestep::tables::@, state>{}.step(two_masses{}, y, t, dt)" $methods
  cat <<'HAND'
extern "C" __attribute__((noinline, used)) odestep::status audit_step_hand_rk4(state& y, AUDIT_T t, AUDIT_T dt) {
  two_masses f;
  const AUDIT_T h2 = dt / AUDIT_T(2), h6 = dt / AUDIT_T(6);
  state k1, k2, k3, k4, tmp;
  f(t, y, k1);
  for (unsigned i = 0; i < 4; ++i) tmp[i] = y[i] + h2 * k1[i];
  f(t + h2, tmp, k2);
  for (unsigned i = 0; i < 4; ++i) tmp[i] = y[i] + h2 * k2[i];
  f(t + h2, tmp, k3);
  for (unsigned i = 0; i < 4; ++i) tmp[i] = y[i] + dt * k3[i];
  f(t + dt, tmp, k4);
  for (unsigned i = 0; i < 4; ++i) y[i] += h6 * (k1[i] + AUDIT_T(2) * k2[i] + AUDIT_T(2) * k3[i] + k4[i]);
  return odestep::status::ok;
}
HAND
} > "$unit"
# The event loop's row is compiled on its own, so that sharing step() and the system with the rows above does
# not change how -Os inlines them there.
event_unit=$out/event_unit.cpp
{
  sed -n '1,/^};/p' "$unit"
  cat <<'EVENTS'
// One tick of the per-tick event loop: RK4 and one event (y[0] falling through 0, recorded), the loop object
// kept by the caller between ticks.
struct first_coordinate {
  AUDIT_T operator()(AUDIT_T, const state& y) const noexcept { return y[0]; }
};
using one_event_loop = odestep::event_stepper<odestep::rk4<state>,
    decltype(odestep::watch(odestep::make_event<state>(first_coordinate{}, odestep::direction::falling, odestep::record)))>;
extern "C" __attribute__((noinline, used)) odestep::status audit_step_rk4_one_event(one_event_loop& loop, state& y) {
  return loop.tick(two_masses{}, y).status;
}
EVENTS
} > "$event_unit"
# The implicit and Rosenbrock steppers on the same 4-state system, Jacobian by differences (4 evaluations of f),
# the default Newton policy (at most 10 iterations); compiled on their own, like the event loop.
stiff_steppers=(backward_euler trapezoid sdirk3 radau_iia5 rodas3)
stiff_unit=$out/stiff_unit.cpp
{
  sed -n '1,/^};/p' "$unit"
  step_wrappers "state& y, AUDIT_T t, AUDIT_T dt" "odestep::@<state>{}.step(two_masses{}, y, t, dt)" "${stiff_steppers[@]}"
  cat <<'TRANSITION'
// RK4 with its state-transition matrix Phi (sensitivity/transition.hpp), the springs' Jacobian by hand.
struct two_masses_jacobian {
  void operator()(AUDIT_T, const state&, odestep::jacobian_t<state>& J) const noexcept {
    J = {{{AUDIT_T(0), AUDIT_T(1), AUDIT_T(0), AUDIT_T(0)}, {AUDIT_T(-2), AUDIT_T(-0.1), AUDIT_T(1), AUDIT_T(0)},
          {AUDIT_T(0), AUDIT_T(0), AUDIT_T(0), AUDIT_T(1)}, {AUDIT_T(1), AUDIT_T(0), AUDIT_T(-2), AUDIT_T(-0.1)}}};
  }
};
extern "C" __attribute__((noinline, used)) odestep::status audit_step_rk4_transition(state& y, odestep::jacobian_t<state>& phi, AUDIT_T t, AUDIT_T dt) {
  return odestep::rk4_transition<state>{}.step(odestep::with_jacobian(two_masses{}, two_masses_jacobian{}), y, phi, t, dt);
}
TRANSITION
} > "$stiff_unit"
# The error-controlled stiff forms (stiff/substeps.hpp): one interval of the caller's grid per step(), on a
# stepper object kept by the caller (it carries the engine: step size, Jacobian, factorizations), the same
# system, Jacobian by differences. Compiled on their own, and for the M4F in float only (the issue's rows;
# each compile takes seconds, and the audit runs in CI).
substeps_steppers=(radau5_substeps rodas4_substeps)
substeps_unit=$out/substeps_unit.cpp
{
  sed -n '1,/^};/p' "$unit"
  step_wrappers "odestep::@<state>& s, state& y, AUDIT_T t, AUDIT_T dt" "s.step(two_masses{}, y, t, dt)" "${substeps_steppers[@]}"
} > "$substeps_unit"
# The Newtonian steppers: one step() per splitting (symplectic.hpp, aliases of one table once) and per
# stepper of newtonian.hpp, each on a stepper object kept by the caller between steps (the history-keeping
# ones keep theirs there), and the caller-kept forms of the first-same-as-last splittings and of Beeman.
# Compiled on their own, like the event loop, so that they change nothing in the rows above.
splittings=$(sed -n 's/^using \([a-z0-9_]*\) = splitting<tables::\([a-z0-9_]*\), State>;$/\1 \2/p' \
               "$root/include/odestep/newtonian/splitting.hpp" | awk '!seen[$2]++ { print $1 }')
newtonians=$(sed -n 's/^class \([a-z0-9_]*\) : public newtonian_traits<.*/\1/p' "$root/include/odestep/newtonian/classic.hpp")
caller_kept=(velocity_verlet_caller_kept blanes_moan4_caller_kept beeman_caller_kept)
# And the Adams methods (multistep.hpp), on the same springs as a first-order system of 4 states.
multisteps=$(sed -n 's/^using \(adams_[a-z0-9_]*\) = adams<.*/\1/p' "$root/include/odestep/multistep/adams.hpp")
newton_unit=$out/newton_unit.cpp
{
  echo "// Generated by scripts/audit.sh: one non-inlined step() per Newtonian stepper, x and v std::array<AUDIT_T, 2>."
  echo "#include <odestep/odestep.hpp>"
  echo "#include <array>"
  echo "using vec2 = std::array<AUDIT_T, 2>;"
  echo "using vec3 = std::array<AUDIT_T, 3>;"
  echo "struct springs {  // x1'' = -2 x1 + x2, x2'' = x1 - 2 x2: two masses, three springs, undamped"
  echo "  vec2 operator()(AUDIT_T, const vec2& x) const noexcept { return {AUDIT_T(-2) * x[0] + x[1], x[0] - AUDIT_T(2) * x[1]}; }"
  echo "};"
  step_wrappers "odestep::@<vec2>& s, vec2& x, vec2& v, AUDIT_T t, AUDIT_T dt" "s.step(springs{}, x, v, t, dt)" $splittings $newtonians
  echo "using vec4 = std::array<AUDIT_T, 4>;"
  echo "struct springs4 {  // the same, y = (x1, x2, v1, v2)"
  echo "  void operator()(AUDIT_T, const vec4& y, vec4& d) const noexcept { d = {y[2], y[3], AUDIT_T(-2) * y[0] + y[1], y[0] - AUDIT_T(2) * y[1]}; }"
  echo "};"
  step_wrappers "odestep::@<vec4>& s, vec4& y, AUDIT_T t, AUDIT_T dt" "s.step(springs4{}, y, t, dt)" $multisteps
  cat <<'KEPT'
extern "C" __attribute__((noinline, used)) odestep::status audit_step_velocity_verlet_caller_kept(vec2& x, vec2& v, vec2& acc, AUDIT_T t, AUDIT_T dt) {
  return odestep::velocity_verlet<vec2>{}.step(springs{}, x, v, acc, t, dt);
}
extern "C" __attribute__((noinline, used)) odestep::status audit_step_blanes_moan4_caller_kept(vec2& x, vec2& v, vec2& acc, AUDIT_T t, AUDIT_T dt) {
  return odestep::blanes_moan4<vec2>{}.step(springs{}, x, v, acc, t, dt);
}
extern "C" __attribute__((noinline, used)) odestep::status audit_step_beeman_caller_kept(vec2& x, vec2& v, odestep::beeman<vec2>::history& hist, AUDIT_T t, AUDIT_T dt) {
  return odestep::beeman<vec2>{}.step(springs{}, x, v, hist, t, dt);
}
// A Penning trap: uniform B along z, the quadrupole E = (x/2, y/2, -z).
struct penning {
  void operator()(AUDIT_T, const vec3& x, vec3& E, vec3& B) const noexcept {
    E = {x[0] / AUDIT_T(2), x[1] / AUDIT_T(2), -x[2]};
    B[2] = AUDIT_T(1);
  }
};
extern "C" __attribute__((noinline, used)) odestep::status audit_step_boris(odestep::boris<vec3>& s, vec3& x, vec3& v, AUDIT_T t, AUDIT_T dt) {
  return s.step(penning{}, x, v, t, dt);
}
KEPT
} > "$newton_unit"

# measure OBJECT CALLGRAPH: prints "method text stack helpers" for every audit_step_* wrapper
# (scripts/callgraph.awk).
measure() {
  awk -v sizes_cmd="arm-none-eabi-nm -S $1" -v roots='^audit_step_' -f "$root/scripts/callgraph.awk" "$2" |
    sed 's/^audit_step_//'
}

declare -A text_of stack_of
helpers_seen=""
# Every unit of every (core, type, optimisation) first, compiled `audit_jobs` at a time (they are independent); then
# the checks and measurements, tag by tag, on the objects. A unit that does not compile leaves no object.
compile_unit() {  # compile_unit TAG KIND SOURCE CPU_FLAGS OPT TYPE: $out/KIND-TAG.o and .ci, or no object
  local object=$out/$2-$1.o
  read -r -a flags <<< "$4"
  arm-none-eabi-g++ "${flags[@]}" "${common_flags[@]}" "$5" -DAUDIT_T="$6" -fstack-usage -fcallgraph-info=su \
    -c "$3" -o "$object" 2> "$out/$2-$1.log" || rm -f "$object"
}
for core in cortex-m4f cortex-m0plus; do
  cpu_flags=$(setting "$core" ODESTEP_TARGET_CPU_FLAGS)
  for type in float double; do
    for opt in -Os -O2; do
      tag=$core-$type$opt
      for kind in step newton events stiff substeps; do
        case $kind in
          step) source=$unit ;; newton) source=$newton_unit ;; events) source=$event_unit ;; stiff) source=$stiff_unit ;;
          substeps) source=$substeps_unit ;;
        esac
        rm -f "$out/$kind-$tag.o"
        [[ $kind == substeps && $core-$type != cortex-m4f-float ]] && continue
        pool_wait
        compile_unit "$tag" "$kind" "$source" "$cpu_flags" "$opt" "$type" &
      done
    done
  done
done
wait

for core in cortex-m4f cortex-m0plus; do
  for type in float double; do
    for opt in -Os -O2; do
      tag=$core-$type$opt
      object=$out/step-$tag.o
      newton_object=$out/newton-$tag.o
      events_object=$out/events-$tag.o
      stiff_object=$out/stiff-$tag.o
      substeps_object=$out/substeps-$tag.o
      if [[ ! -f "$newton_object" ]]; then
        cat "$out/newton-$tag.log" >&2
        fail "$tag: the Newtonian step unit does not compile"
      fi
      if [[ ! -f "$object" ]]; then
        cat "$out/step-$tag.log" >&2
        fail "$tag: the step unit does not compile"
        continue
      fi
      stepper_objects=("$object")
      [[ -f "$newton_object" ]] && stepper_objects+=("$newton_object")
      called=$(arm-none-eabi-nm -u "${stepper_objects[@]}" | awk 'NF > 1 {print $NF}' | sort -u)
      runtime=$(grep -E "$forbidden" <<< "$called" | tr '\n' ' ')
      [[ -z "$runtime" ]] || fail "$tag: steps call the allocator or the C++ run-time: $runtime"
      if [[ $type == float ]]; then
        doubles=$(grep -E '^__aeabi_d' <<< "$called" | tr '\n' ' ')
        [[ -z "$doubles" ]] || fail "$tag: float steps call double-precision routines: $doubles"
        echo "$tag ${doubles:-none}" >> "$out/float-doubles.txt"
      fi
      if [[ ! -f "$events_object" ]]; then
        cat "$out/events-$tag.log" >&2
        fail "$tag: the event unit does not compile"
      fi
      if [[ ! -f "$stiff_object" ]]; then
        cat "$out/stiff-$tag.log" >&2
        fail "$tag: the implicit step unit does not compile"
      elif [[ $type == float ]]; then
        stiff_doubles=$(arm-none-eabi-nm -u "$stiff_object" | awk 'NF > 1 {print $NF}' | grep -E '^__aeabi_d' | tr '\n' ' ')
        [[ -z "$stiff_doubles" ]] || fail "$tag: float implicit steps call double-precision routines: $stiff_doubles"
      fi
      if [[ $core-$type == cortex-m4f-float ]]; then
        if [[ ! -f "$substeps_object" ]]; then
          cat "$out/substeps-$tag.log" >&2
          fail "$tag: the substeps unit does not compile"
        else
          called=$(arm-none-eabi-nm -u "$substeps_object" | awk 'NF > 1 {print $NF}' | sort -u)
          runtime=$(grep -E "$forbidden" <<< "$called" | tr '\n' ' ')
          [[ -z "$runtime" ]] || fail "$tag: the substep forms call the allocator or the C++ run-time: $runtime"
          stiff_doubles=$(grep -E '^__aeabi_d' <<< "$called" | tr '\n' ' ')
          [[ -z "$stiff_doubles" ]] || fail "$tag: float substep forms call double-precision routines: $stiff_doubles"
        fi
      fi
      while read -r method text stack helpers; do
        text_of[$method,$tag]=$text
        stack_of[$method,$tag]=$stack
        [[ $helpers == - ]] || helpers_seen+=" $tag:$helpers"
      done < <(measure "$object" "${object%.o}.ci"
               [[ -f "$events_object" ]] && measure "$events_object" "${events_object%.o}.ci"
               [[ -f "$newton_object" ]] && measure "$newton_object" "${newton_object%.o}.ci"
               [[ -f "$stiff_object" ]] && measure "$stiff_object" "${stiff_object%.o}.ci"
               [[ -f "$substeps_object" ]] && measure "$substeps_object" "${substeps_object%.o}.ci")
    done
  done
done

# The columns of sections 3 and 3b.
table_head() {
  printf '| stepper |'
  for core in cortex-m4f cortex-m0plus; do for type in float double; do for opt in -Os -O2; do
    printf ' %s %s %s text / stack |' "${core#cortex-}" "$type" "$opt"
  done; done; done
  echo
  printf '|---|'
  for _ in 1 2 3 4 5 6 7 8; do printf -- '---:|'; done
  echo
}
table_row() {  # table_row METHOD LABEL
  printf '| %s |' "$2"
  for core in cortex-m4f cortex-m0plus; do for type in float double; do for opt in -Os -O2; do
    tag=$core-$type$opt
    printf ' %s / %s |' "${text_of[$1,$tag]:--}" "${stack_of[$1,$tag]:--}"
  done; done; done
  echo
}

{
  echo
  echo "## 2. No double promotion in float steps"
  echo
  echo "| build | \`__aeabi_d*\` called by float step() of every stepper |"
  echo "|---|---|"
  [[ -f "$out/float-doubles.txt" ]] && awk '{ $1 = "| " $1 " |"; print $0 " |" }' "$out/float-doubles.txt"
  rm -f "$out/float-doubles.txt"
  echo
  echo "## 3. Flash and stack of one step() (4-state system), bytes"
  echo
  echo "text = the step wrapper and every function it reaches in the unit (the library and the system itself); stack = deepest path of frames."
  echo
  table_head
  for m in $methods hand_rk4 rk4_one_event; do
    case $m in
      hand_rk4) label="rk4 by hand (no NaN check)" ;;
      rk4_one_event) label="rk4 + one event: event_stepper tick (location included)" ;;
      *) label=$m ;;
    esac
    table_row "$m" "$label"
  done
  echo
  lib=${text_of[rk4,cortex-m4f-float-Os]:-0} hand=${text_of[hand_rk4,cortex-m4f-float-Os]:-0}
  if ((hand > 0)); then
    echo "RK4, float, 4 states, M4F, -Os: odestep ${lib} bytes / ${stack_of[rk4,cortex-m4f-float-Os]} bytes of stack," \
         "by hand ${hand} / ${stack_of[hand_rk4,cortex-m4f-float-Os]}: flash ratio $(awk -v a="$lib" -v b="$hand" 'BEGIN { printf "%.2f", a / b }')" \
         "(target 1.10); stack bound (stages + 2) N sizeof(T) + 64 = 160 bytes."
  fi
  echo
  echo "## 3b. Flash and stack of one step() of the Newtonian steppers (x and v: 2 states each) and the Adams methods (4 states), bytes"
  echo
  echo "Measured as in 3, x'' = a(t, x) for the same two masses and three springs, undamped (a force of position alone)." \
       "The stepper object is the caller's, kept between steps; \"caller keeps\" is the form whose history the caller holds" \
       "(a stateless stepper). Boris: x and v of 3 (6 states), a Penning trap's fields. The Adams methods: y' = f(t, y) for" \
       "the same springs, y = (x, v), their RK4 starter included (it runs out of line, for the first k-1 steps)."
  echo
  table_head
  for m in $splittings $newtonians "${caller_kept[@]}" boris $multisteps; do
    case $m in
      velocity_verlet_caller_kept | blanes_moan4_caller_kept) label="${m%_caller_kept}, caller keeps acc: step(a, x, v, acc, t, dt)" ;;
      beeman_caller_kept) label="beeman, caller keeps hist: step(a, x, v, hist, t, dt)" ;;
      boris) label="boris (x, v: 3 states each)" ;;
      *) label=$m ;;
    esac
    table_row "$m" "$label"
  done
  echo
  echo "## 3c. Flash and stack of one step() of the implicit and Rosenbrock steppers, and of RK4 with Phi (4 states), bytes"
  echo
  echo "Measured as in 3, on the same two masses and three springs; Jacobian by forward differences, the default Newton" \
       "policy (newton<10>). The LU factorization and solve and the difference Jacobian are included. rk4_transition:" \
       "the RK4 step and its 4 x 4 state-transition matrix (sensitivity/transition.hpp), the Jacobian by hand."
  echo
  table_head
  for m in "${stiff_steppers[@]}"; do table_row "$m" "$m"; done
  for m in "${substeps_steppers[@]}"; do table_row "$m" "$m: one grid interval, stepper kept by the caller (M4F float only)"; done
  table_row rk4_transition "rk4_transition: step and Phi (4 x 4), Jacobian by hand"
  echo
  echo "The substep forms (stiff/substeps.hpp): the whole interval loop with its error-controlled engine; the" \
       "engine's Jacobian and factorizations live in the stepper object (the caller's), not on the stack."
  echo "Not counted: the compiler's run-time helpers the steps call (shared by every stepper):"
  tr ' ' '\n' <<< "$helpers_seen" | awk -F: 'NF == 2 { split($2, h, ","); for (i in h) set[$1] = set[$1] " " h[i] }
    END { for (k in set) { n = split(set[k], a, " "); s = ""; delete u
          for (i = 1; i <= n; i++) if (!(a[i] in u)) { u[a[i]] = 1; s = s " " a[i] }
          print "- " k ":" s } }' | sort
} >> "$report"

# --- 4: instructions per step on the emulated M4F (scripts/bench-m4f.sh), also into build/audit/cortex-m.md ---
{
  echo
  echo "## 4. Instructions per step on the emulated Cortex-M4F (scripts/bench-m4f.sh)"
  echo
} >> "$report"
if ((have_qemu == 1)); then
  # Fails only when an image does not build or run, or a row fails its check (odestep and the hand loops
  # ending in different states, a step that did not return ok); the ratios are reported, not asserted.
  # The table goes into a copy of docs/cortex-m.md under build/audit/ (the test command leaves the work tree as
  # it found it); the report says when the committed page is out of date (`cp` the copy over it to update it).
  cp "$root/docs/cortex-m.md" "$out/cortex-m.md"
  if "$root/scripts/bench-m4f.sh" --report "$out/m4f-icount.md" --docs "$out/cortex-m.md" > "$out/bench-m4f.log" 2>&1; then
    cat "$out/m4f-icount.md" >> "$report"
    cmp -s "$out/cortex-m.md" "$root/docs/cortex-m.md" ||
      echo "Note: docs/cortex-m.md differs from these figures: build/audit/cortex-m.md has them." >> "$report"
  else
    fail "scripts/bench-m4f.sh: $(grep -E '^bench-m4f:|FAIL' "$out/bench-m4f.log" | head -3 | tr '\n' ' ')(build/audit/bench-m4f.log)"
    [[ -f "$out/m4f-icount.md" ]] && cat "$out/m4f-icount.md" >> "$report"
    echo "FAILED: see build/audit/bench-m4f.log" >> "$report"
  fi
else
  echo "Not measured: qemu-system-arm is missing." >> "$report"
fi

cat "$report"
if ((failures > 0)); then
  echo "audit: $failures check(s) FAILED" >&2
  exit 1
fi
echo
echo "audit: all checks passed (report: build/audit/report.md)"
