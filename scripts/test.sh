#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Runs odestep's tests, in two tiers (docs/testing.md says what each holds and how long it takes):
#
#   scripts/test.sh --quick   the edit-test loop, a few minutes: format, SPDX, and the host preset (g++, C++17)
#                             with the unit tests, the C tests, the fuzz corpus replayed and the examples
#                             (build and test presets host-quick, in build/host/, which the full run reuses)
#   scripts/test.sh           everything, what CI runs: the above and Doxygen, MISRA C, the host preset's whole
#                             set (each header on its own, compile-fail contracts, the package consumers); the
#                             unit and C tests under g++ C++20, clang++ C++20 (with the fuzz replays), and
#                             clang++ C++17 (-fno-exceptions -fno-rtti) with ASan+UBSan; libFuzzer (ASan+UBSan,
#                             over the same corpus first); the portable suite on
#                             emulated Cortex-M cores; the firmware audit; the instruction-count checks. After
#                             format and SPDX, its stages run in two lanes side by side, each stage's output
#                             printed whole when it ends.
#   scripts/test.sh --stage NAME...   the named stages only, one after the other (to time or repeat one):
#                             format spdx host-quick docs misra-c host host-cxx20 host-clang host-clang-cxx20
#                             host-sanitize fuzz cortex-m cortex-m0 audit bench-quick perf-gate
#
# Installs what is missing first (scripts/install-deps.sh). Prints "===== NAME: ok (N s)" and the stage's CPU
# time (user + sys) per stage, a table of them at the end (build/test-logs/results.txt; the full run keeps
# each stage's output there too, NAME.log), and ends with the line "test: N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2

tier=full
stages=()
case "${1:-}" in
  --quick) tier=quick ;;
  --stage)
    tier=stage
    shift
    stages=("$@")
    [ ${#stages[@]} -gt 0 ] || { echo "test: --stage needs at least one stage name" >&2; exit 2; }
    ;;
  '') ;;
  -h | --help) sed -n '3,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
  *) echo "test: unknown argument '$1' (--quick, --stage NAME..., or nothing for the full run)" >&2; exit 2 ;;
esac
jobs=$(nproc 2>/dev/null || echo 2)

if [ $tier = full ]; then
  scripts/install-deps.sh test || { echo "test: could not install the dependencies"; exit 1; }
else
  # The quick tier needs only the host compiler, CMake and doctest (a named stage: what it calls).
  missing=()
  for tool in g++ cmake ctest clang-format; do command -v "$tool" > /dev/null 2>&1 || missing+=("$tool"); done
  [ -f /usr/include/doctest/doctest.h ] || missing+=(doctest)
  if [ ${#missing[@]} -gt 0 ]; then
    scripts/install-deps.sh test || { echo "test: could not install the dependencies"; exit 1; }
  fi
fi

total_start=$SECONDS
mkdir -p build/test-logs
results=build/test-logs/results.txt  # one line per finished stage: NAME STATUS WALL CPU
: > "$results"
cpu_now() {  # cpu=: the CPU time (user + sys) of this shell's finished children so far, whole seconds
  # `times` in this shell (in a $(...) subshell it would count the subshell's); one file per shell, since
  # the lanes of the full run are shells of their own.
  local file=build/test-logs/times.$BASHPID
  times > "$file"
  cpu=$(awk 'NR == 2 { t = 0; for (i = 1; i <= 2; ++i) { split($i, a, /[ms]/); t += 60 * a[1] + a[2] } printf "%d", t }' \
    "$file")
  rm -f "$file"
}
buffered=0  # 1 in the lanes of the full run: a stage's output is printed, whole, when it ends
run() {  # run NAME COMMAND...: wall time on the ok/FAILED line, CPU time (on a shared machine, the cost) after it
  local name=$1; shift
  local start=$SECONDS cpu_start status log=build/test-logs/$name.log
  cpu_now; cpu_start=$cpu
  if [ $buffered = 1 ]; then
    echo "===== $name: started"
    if "$@" > "$log" 2>&1; then status=ok; else status=FAILED; fi
  else
    echo "===== $name"
    if "$@"; then status=ok; else status=FAILED; fi
  fi
  cpu_now
  echo "$name $status $((SECONDS - start)) $((cpu - cpu_start))" >> "$results"
  {
    if [ $buffered = 1 ]; then echo "===== $name"; cat "$log"; fi
    echo "===== $name: $status ($((SECONDS - start)) s)"
    echo "== $name: CPU $((cpu - cpu_start)) s (user + sys)"
  } | if [ $buffered = 1 ]; then flock build/test-logs/print.lock cat; else cat; fi
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
stage() {  # stage NAME: one stage of the test command, by name
  case "$1" in
    # The sources follow .clang-format; every source file carries the license's SPDX line.
    format) run format scripts/format.sh --check ;;
    spdx) run spdx scripts/spdx.sh --check ;;
    # The unit tests (in parts, ctest -j), the C tests, the fuzz corpus replayed and the examples, under g++.
    host-quick) run host-quick host_preset host host-quick host-quick ;;
    # Doxygen documents every public name without a warning; cppcheck's MISRA C:2012 addon over the C API's
    # header, example and tests finds only the documented deviations.
    docs) run docs scripts/docs.sh ;;
    misra-c) run misra-c scripts/misra_c.sh ;;
    # host: everything, the checks that a second compiler or standard would only repeat included (each header
    # on its own, the compile-fail contracts under g++ and clang++, the package consumers, the examples); the
    # other presets: the unit and C tests, and under clang++ C++20 the fuzz replays and the allocation counting
    # (CMakePresets.json: the fuzz stage replays the corpus under ASan+UBSan; no header branches on the
    # standard). host-sanitize is also the clang++ C++17 -fno-exceptions -fno-rtti build (the preset
    # host-clang, which it makes redundant).
    host | host-cxx20 | host-clang | host-clang-cxx20 | host-sanitize) run "$1" host_preset "$1" ;;
    # libFuzzer targets for the loops, the steps and the event loops; any finding fails.
    fuzz) run fuzz scripts/fuzz.sh --quick ;;
    # The same portable tests cross-compiled and run on emulated Cortex-M3/M4F/M7/M33/M55,
    # then the firmware audit: no heap, no double arithmetic in float builds, flash and stack per stepper.
    cortex-m) run cortex-m scripts/test-targets.sh ;;
    # A small runner on the Cortex-M0 (QEMU microbit), its float results bit for bit the host's (tests/m0/).
    cortex-m0) run cortex-m0 scripts/test-m0.sh ;;
    audit) run audit scripts/audit.sh ;;
    # Instruction counts are deterministic: RK4 on Lorenz must stay within 1.05x a hand-written loop at -O2.
    bench-quick) run bench-quick scripts/bench.sh --quick ;;
    # Instruction counts (valgrind): large states and the C API against hand loops.
    perf-gate) run perf-gate scripts/perf_gate.sh ;;
    *) echo "test: unknown stage '$1'" >&2; echo "$1 FAILED 0 0" >> "$results" ;;
  esac
}
lane() {  # lane STAGE...: the stages one after the other, each stage's output printed whole when it ends
  buffered=1
  local name
  for name in "$@"; do stage "$name"; done
}

# The test command leaves the work tree as it found it (build/ aside): its state now, compared at the end.
[ $tier = stage ] || scripts/check_clean_tree.sh --save build/work_tree_before.txt
case $tier in
  stage)
    for name in "${stages[@]}"; do stage "$name"; done
    ;;
  quick)
    for name in format spdx host-quick perf-gate; do stage "$name"; done
    ;;
  full)
    stage format
    stage spdx
    # The rest in two lanes side by side, each building with all the cores: a lane's serial parts (CMake's
    # configure, the tail of a build or a ctest run, the QEMU runs, the fuzzers' longest unit, valgrind) leave
    # a core to the other lane. The g++ and sanitizer presets in one lane; the fuzz targets, the Cortex-M
    # builds and runs, the audit and clang++ C++20 in the other; about the same CPU time in each
    # (docs/testing.md).
    host_lane=(docs misra-c host host-cxx20 host-sanitize bench-quick perf-gate)
    target_lane=(fuzz cortex-m cortex-m0 audit host-clang-cxx20)
    lane "${host_lane[@]}" &
    lane_host=$!
    lane "${target_lane[@]}" &
    lane_target=$!
    wait $lane_host
    wait $lane_target
    # A stage whose lane ended before it reported (the lane's shell killed) fails the run.
    for name in "${host_lane[@]}" "${target_lane[@]}"; do
      grep -q "^$name " "$results" || echo "$name FAILED 0 0" >> "$results"
    done
    ;;
esac
[ $tier = stage ] || run clean-tree scripts/check_clean_tree.sh --check build/work_tree_before.txt

echo
echo "stage              status   wall s   CPU s"
awk '{ printf "%-18s %-8s %6d %7d\n", $1, $2, $3, $4 }' "$results"
cpu_now; echo "test ($tier): $((SECONDS - total_start)) s, CPU $cpu s (user + sys)"
passed=$(awk '$2 == "ok"' "$results" | wc -l)
failed=$(awk '$2 != "ok"' "$results" | wc -l)
[ "$failed" -eq 0 ] || echo "failed: $(awk '$2 != "ok" { printf "%s ", $1 }' "$results")"
echo "test: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
