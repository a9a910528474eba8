#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs what is missing, then runs every test: the host suite under g++ and clang++, C++17 and C++20,
# and ASan+UBSan (each preset builds the tests, the examples and their checks), the suite on emulated
# Cortex-M cores, the firmware audit, and the benchmark's quick instruction-count check.
set -uo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh test || { echo "test: could not install the dependencies"; exit 1; }

passed=0 failed=0 failures=()
run() {  # run NAME COMMAND...
  local name=$1; shift
  local start=$SECONDS
  echo "===== $name"
  if "$@"; then passed=$((passed + 1)); echo "===== $name: ok ($((SECONDS - start)) s)"
  else failed=$((failed + 1)); failures+=("$name"); echo "===== $name: FAILED ($((SECONDS - start)) s)"; fi
}
host_preset() {
  cmake --preset "$1" >/dev/null && cmake --build --preset "$1" -j"$(nproc)" && ctest --preset "$1"
}

# The sources follow .clang-format; every source file carries the license's SPDX line; Doxygen documents every
# public name without a warning.
run format scripts/format.sh --check
run spdx scripts/spdx.sh --check
run docs scripts/docs.sh
# cppcheck's MISRA C:2012 addon over the C API's header, example and tests: only the documented deviations.
run misra-c scripts/misra_c.sh
for preset in host host-cxx20 host-clang host-clang-cxx20 host-sanitize; do
  run "$preset" host_preset "$preset"
done
# libFuzzer targets for the loops, the steps and the event loops, about a minute in all; any finding fails.
run fuzz scripts/fuzz.sh --quick
# The same portable tests cross-compiled and run on emulated Cortex-M3/M4F/M7/M33/M55 (M0+ built only),
# then the firmware audit: no heap, no double arithmetic in float builds, flash and stack per stepper.
run cortex-m scripts/test-targets.sh
run audit scripts/audit.sh
# Instruction counts are deterministic: RK4 on Lorenz must stay within 1.05x a hand-written loop at -O2.
run bench-quick scripts/bench.sh --quick

echo
[ $failed -eq 0 ] || echo "failed: ${failures[*]}"
echo "test: $passed passed, $failed failed"
[ $failed -eq 0 ]
