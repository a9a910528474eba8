#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Builds odestep's test images for the Cortex-M cores and runs them under QEMU (semihosting):
#   Cortex-M3 (mps2-an385), M4F (mps2-an386), M7 (mps2-an500), M33 (mps2-an505), M55 (mps3-an547): build + run
#   Cortex-M0+: build and size only (QEMU has no Cortex-M0+ board), when named: not in the default set
# with the CMake presets of the same names (build/<preset>/). Exits non-zero if any core fails to configure,
# build or pass; the others still run. A core's QEMU run overlaps the next core's build. Prints the time each
# core's build and run took.
#
# Usage: scripts/test-targets.sh [preset...]      (default: the five emulated cores)
# The M0+ images are built only when named (scripts/test-targets.sh cortex-m0plus): the test command leaves them
# out, since nothing runs them and what they would show is shown elsewhere. The compiler's front end sees the
# same sources for every core (the M3 build, soft float too, compiles them all); the ARMv6-M back end is
# exercised by scripts/audit.sh (every stepper's step for the M0+ at -Os and -O2, firmware images linked and
# run) and by scripts/test-m0.sh (a runner on an emulated Cortex-M0, its results the host's bit for bit).
# Environment: JOBS (parallel build jobs, default: nproc), ODESTEP_TARGET_CONFIGURE_ARGS (extra arguments
# for every configure, e.g. "-DODESTEP_TEST_CXX_STANDARD=20").
#
# Installs nothing: needs cmake (>= 3.25), arm-none-eabi-gcc with newlib (Debian: gcc-arm-none-eabi,
# libnewlib-arm-none-eabi, libstdc++-arm-none-eabi-newlib), qemu-system-arm and doctest-dev.
set -uo pipefail

cd "$(dirname "$0")/.." || exit 2

emulated=(cortex-m3 cortex-m4f cortex-m7 cortex-m33 cortex-m55)
build_only=(cortex-m0plus)
if (($# > 0)); then
  presets=("$@")
else
  presets=("${emulated[@]}")
fi
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
read -r -a extra_configure_args <<< "${ODESTEP_TARGET_CONFIGURE_ARGS:-}"

missing=()
for tool in cmake ctest arm-none-eabi-g++ qemu-system-arm; do
  command -v "$tool" > /dev/null 2>&1 || missing+=("$tool")
done
if ((${#missing[@]} > 0)); then
  echo "test-targets: missing ${missing[*]}." >&2
  echo "  Debian: apt-get install cmake gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm doctest-dev" >&2
  exit 2
fi

is_build_only() {
  local p
  for p in "${build_only[@]}"; do [[ "$p" == "$1" ]] && return 0; done
  return 1
}

# Each core's QEMU run goes on in the background while the next core builds (the runs use one core each, the
# builds both); a core's run waits for the previous core's run, so that at most one run and one build share
# the machine. Each run's output is printed, whole, when it ends.
declare -A result_of build_of tests_of
failed=()
run_pid=""
run_preset=""
mkdir -p build
finish_run() {  # waits for the run in the background, if any, and records its result
  [[ -n "$run_pid" ]] || return 0
  if ! wait "$run_pid"; then result_of[$run_preset]="tests FAILED"; fi
  echo "=== ${run_preset}: run under QEMU ($(cat "build/${run_preset}.qemu-seconds" 2> /dev/null || echo '?') s)"
  cat "build/${run_preset}.qemu.log"
  tests_of[$run_preset]=$(cat "build/${run_preset}.qemu-seconds" 2> /dev/null || echo -)
  run_pid=""
}
total_start=$SECONDS
for preset in "${presets[@]}"; do
  echo "=== ${preset}: configure and build"
  start=$SECONDS
  result=ok
  if ! cmake --preset "$preset" "${extra_configure_args[@]}"; then
    result="configure FAILED"
  elif ! cmake --build --preset "$preset" --parallel "$jobs"; then
    result="build FAILED"
  fi
  build_of[$preset]=$((SECONDS - start))
  tests_of[$preset]=-
  result_of[$preset]=$result
  [[ "$result" == ok ]] || continue
  if is_build_only "$preset"; then
    result_of[$preset]="ok (built only)"
    if command -v arm-none-eabi-size > /dev/null 2>&1; then
      echo "=== ${preset}: size of the test images (not run: no QEMU board)"
      arm-none-eabi-size build/"$preset"/tests/odestep_target_tests_*.elf
    fi
    continue
  fi
  finish_run
  run_preset=$preset
  (
    begin=$SECONDS
    ctest --preset "$preset" --parallel "$jobs" > "build/${preset}.qemu.log" 2>&1
    status=$?
    echo $((SECONDS - begin)) > "build/${preset}.qemu-seconds"
    exit $status
  ) &
  run_pid=$!
done
finish_run

summary=()
for preset in "${presets[@]}"; do
  [[ "${result_of[$preset]}" == ok* ]] || failed+=("$preset")
  summary+=("$(printf '%-14s %-18s build %4ss  tests %4ss' "$preset" "${result_of[$preset]}" "${build_of[$preset]}" \
    "${tests_of[$preset]}")")
done

echo
echo "=== Cortex-M summary (${jobs} build jobs)"
printf '%s\n' "${summary[@]}"
echo "total: $((SECONDS - total_start))s"
if ((${#failed[@]} > 0)); then
  echo "FAILED: ${failed[*]}" >&2
  exit 1
fi
