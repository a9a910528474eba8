#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Runs odestep's tests, in two tiers (docs/testing.md says what each holds and how long it takes):
#
#   scripts/test.sh --quick   the edit-test loop, a few minutes: format, SPDX, and the host preset (g++, C++17)
#                             with the unit tests, the C tests, the fuzz corpus replayed and the examples
#                             (build and test presets host-quick, in build/host/, which the full run reuses)
#   scripts/test.sh           everything, what CI runs: the above and Doxygen, MISRA C, the host preset's whole
#                             set (each header on its own, compile-fail contracts, the package consumers); the
#                             unit, C and fuzz-replay tests under g++ C++20, clang++ C++17 (-fno-exceptions
#                             -fno-rtti) and C++20, and ASan+UBSan; libFuzzer; the portable suite on emulated
#                             Cortex-M cores; the firmware audit; the benchmark's instruction-count check
#
# Installs what is missing first (scripts/install-deps.sh). Prints "===== NAME: ok (N s)" per stage and ends
# with the line "test: N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.."

tier=full
case "${1:-}" in
  --quick) tier=quick ;;
  '') ;;
  -h | --help) sed -n '3,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  *) echo "test: unknown argument '$1' (--quick, or nothing for the full run)" >&2; exit 2 ;;
esac
jobs=$(nproc 2>/dev/null || echo 2)

if [ $tier = quick ]; then
  # The quick tier needs only the host compiler, CMake and doctest.
  missing=()
  for tool in g++ cmake ctest clang-format; do command -v "$tool" > /dev/null 2>&1 || missing+=("$tool"); done
  [ -f /usr/include/doctest/doctest.h ] || missing+=(doctest)
  if [ ${#missing[@]} -gt 0 ]; then
    scripts/install-deps.sh test || { echo "test: could not install the dependencies"; exit 1; }
  fi
else
  scripts/install-deps.sh test || { echo "test: could not install the dependencies"; exit 1; }
fi

passed=0 failed=0 failures=()
total_start=$SECONDS
# The test command leaves the work tree as it found it (build/ aside): its state now, compared at the end.
mkdir -p build
scripts/check_clean_tree.sh --save build/work_tree_before.txt
cpu_now() {  # cpu=: the CPU time (user + sys) of this shell's finished children so far, whole seconds
  times > build/test_times.txt  # `times` in this shell: in a $(...) subshell it would count the subshell's
  cpu=$(awk 'NR == 2 { t = 0; for (i = 1; i <= 2; ++i) { split($i, a, /[ms]/); t += 60 * a[1] + a[2] } printf "%d", t }' \
    build/test_times.txt)
}
run() {  # run NAME COMMAND...: wall time on the ok/FAILED line, CPU time (on a shared machine, the cost) after it
  local name=$1; shift
  local start=$SECONDS cpu_start status
  cpu_now; cpu_start=$cpu
  echo "===== $name"
  if "$@"; then passed=$((passed + 1)); status=ok
  else failed=$((failed + 1)); failures+=("$name"); status=FAILED; fi
  echo "===== $name: $status ($((SECONDS - start)) s)"
  cpu_now; echo "== $name: CPU $((cpu - cpu_start)) s (user + sys)"
}
# host_preset CONFIGURE [BUILD TEST]: configure, build and test one host preset, printing each part's time.
host_preset() {
  local configure=$1 build=${2:-$1} test=${3:-$1} start=$SECONDS
  cmake --preset "$configure" > /dev/null || return 1
  echo "== $configure: configure $((SECONDS - start)) s"; start=$SECONDS
  cmake --build --preset "$build" -j"$jobs" || return 1
  echo "== $configure: build $((SECONDS - start)) s"; start=$SECONDS
  ctest --preset "$test" -j"$jobs"
  local status=$?
  echo "== $configure: ctest $((SECONDS - start)) s"
  return $status
}

# The sources follow .clang-format; every source file carries the license's SPDX line.
run format scripts/format.sh --check
run spdx scripts/spdx.sh --check
if [ $tier = quick ]; then
  # The unit tests (in parts, ctest -j), the C tests, the fuzz corpus replayed and the examples, under g++.
  run host-quick host_preset host host-quick host-quick
else
  # Doxygen documents every public name without a warning; cppcheck's MISRA C:2012 addon over the C API's
  # header, example and tests finds only the documented deviations.
  run docs scripts/docs.sh
  run misra-c scripts/misra_c.sh
  # host: everything, the checks that a second compiler or standard would only repeat included (each header
  # on its own, the compile-fail contracts under g++ and clang++, the package consumers, the examples); the
  # other presets: the unit, C and fuzz-replay tests (CMakePresets.json).
  for preset in host host-cxx20 host-clang host-clang-cxx20 host-sanitize; do
    run "$preset" host_preset "$preset"
  done
  # libFuzzer targets for the loops, the steps and the event loops, about a minute in all; any finding fails.
  run fuzz scripts/fuzz.sh --quick
  # The same portable tests cross-compiled and run on emulated Cortex-M3/M4F/M7/M33/M55,
  # then the firmware audit: no heap, no double arithmetic in float builds, flash and stack per stepper.
  run cortex-m scripts/test-targets.sh
  # A small runner on the Cortex-M0 (QEMU microbit), its float results bit for bit the host's (tests/m0/).
  run cortex-m0 scripts/test-m0.sh
  run audit scripts/audit.sh
  # Instruction counts are deterministic: RK4 on Lorenz must stay within 1.05x a hand-written loop at -O2.
  run bench-quick scripts/bench.sh --quick
fi
run perf-gate scripts/perf_gate.sh  # instruction counts (valgrind): large states and the C API against hand loops
run clean-tree scripts/check_clean_tree.sh --check build/work_tree_before.txt

echo
cpu_now; echo "test ($tier): $((SECONDS - total_start)) s, CPU $cpu s (user + sys)"
[ $failed -eq 0 ] || echo "failed: ${failures[*]}"
echo "test: $passed passed, $failed failed"
[ $failed -eq 0 ]
