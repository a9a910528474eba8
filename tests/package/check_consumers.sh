#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Builds and runs tests/package/consumer against odestep installed (find_package), added with
# add_subdirectory, and fetched with FetchContent; in the last two, odestep's own tests must not build. Where
# arm-none-eabi-g++ is installed, also cross-compiles tests/package/firmware_consumer for Cortex-M4F the
# same three ways, with the project's toolchain file, and find_package once more under a toolchain that
# searches packages only in its sysroot (CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY), with odestep_DIR given;
# with qemu-system-arm, docs/cortex-m.md's recipe for a user's own image (tests/package/board_consumer).
# Usage: check_consumers.sh SOURCE_DIR WORK_DIR CXX_COMPILER
# After the install, the consumers build side by side (JOBS at a time, default nproc), each into its own log;
# a failure prints its log.
set -euo pipefail
src=$1 work=$2 cxx=$3
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
rm -rf "$work" && mkdir -p "$work"
consumer="$src/tests/package/consumer"

cmake -S "$src" -B "$work/odestep-build" -DCMAKE_CXX_COMPILER="$cxx" -DODESTEP_BUILD_TESTS=OFF \
      -DODESTEP_BUILD_EXAMPLES=OFF -DODESTEP_INSTALL=ON >/dev/null
cmake --build "$work/odestep-build" --parallel "$jobs" >/dev/null  # the C API's static library (odestep::odestep_c)
cmake --install "$work/odestep-build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/odestep/odestep.hpp"
test -f "$work/prefix/share/cmake/odestep/odestepConfig.cmake"
test -f "$work/prefix/include/odestep/odestep.h"
ls "$work"/prefix/lib*/libodestep_c.a >/dev/null

host_consumer() {  # host_consumer MODE
  local mode=$1 build="$work/$1"
  cmake -S "$consumer" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DODESTEP_MODE="$mode" \
        -DODESTEP_SOURCE="$src" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  cmake --build "$build" >/dev/null
  "$build/consumer"
  "$build/c_consumer"
  if [ "$mode" != find_package ] && cmake --build "$build" --target help | grep -q odestep_tests; then
    echo "FAIL: $mode builds odestep's tests although odestep is not the top-level project"
    exit 1
  fi
  echo "ok: $mode"
}

# The README's FetchContent snippet, as written: the first ```cmake block under "## Getting it", in a project
# whose executable is `app`, fetched from this repository by branch and then pinned to its commit.
readme_snippet() {
  local readme="$work/readme" snippet pins pin
  mkdir -p "$readme"
  snippet=$(awk '/^## Getting it/ { on = 1 } on && /^```cmake$/ { grab = 1; next } grab && /^```$/ { exit } grab' "$src/README.md")
  [ -n "$snippet" ] || { echo "FAIL: no cmake block under '## Getting it' in README.md"; exit 1; }
  cp "$consumer/main.cpp" "$readme/main.cpp"
  pins=("$(git -C "$src" rev-parse HEAD)")
  git -C "$src" rev-parse --verify -q main >/dev/null && pins=(main "${pins[@]}")
  for pin in "${pins[@]}"; do
    { echo "cmake_minimum_required(VERSION 3.14)"; echo "project(readme_snippet LANGUAGES CXX)";
      echo "add_executable(app main.cpp)"; echo "$snippet" | sed "s/GIT_TAG        main/GIT_TAG        $pin/"; } > "$readme/CMakeLists.txt"
    rm -rf "$readme/build"
    cmake -S "$readme" -B "$readme/build" -DCMAKE_CXX_COMPILER="$cxx" -DODESTEP_REPOSITORY="$src" >/dev/null
    cmake --build "$readme/build" >/dev/null
    "$readme/build/app" >/dev/null
    echo "ok: the README's FetchContent snippet, GIT_TAG $pin"
  done
}

firmware="$src/tests/package/firmware_consumer"
toolchain="$src/toolchains/cortex-m4f.cmake"
firmware_consumer() {  # firmware_consumer MODE
  local mode=$1 build="$work/firmware-$1"
  cmake --no-warn-unused-cli -S "$firmware" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DODESTEP_MODE="$mode" \
        -DODESTEP_SOURCE="$src" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  cmake --build "$build" >/dev/null
  test -f "$build/libfirmware.a"
  echo "ok: cross-compiled firmware, $mode"
}
# A user's toolchain file that keeps package search in its sysroot: odestep_DIR points at the package.
firmware_strict() {
  local strict="$work/strict-toolchain.cmake" build
  printf 'include(%s)\nset(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)\n' "$toolchain" > "$strict"
  build="$work/firmware-strict"
  cmake -S "$firmware" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$strict" -DODESTEP_MODE=find_package \
        -Dodestep_DIR="$work/prefix/share/cmake/odestep" >/dev/null
  cmake --build "$build" >/dev/null
  echo "ok: cross-compiled firmware, find_package with odestep_DIR under CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY"
}

# docs/cortex-m.md's recipe "Your own image under QEMU" from the installed package, for a core and its QEMU
# board: the installed toolchain file and board support, an image from C and C++ sources built with the
# user's own -fstack-usage in CMAKE_C_FLAGS and CMAKE_CXX_FLAGS (every compile must still carry the core's
# flags, FLAGS...), run with the recipe's QEMU command as the doc prints it, its output compared with the doc's.
board_image() {  # board_image TOOLCHAIN MACHINE FLAGS...
  local core=$1 machine=$2 build="$work/board-$1/build" doc="$src/docs/cortex-m.md" run expected output
  shift 2
  cmake -S "$src/tests/package/board_consumer" -B "$build" -DCMAKE_PREFIX_PATH="$work/prefix" \
        -DCMAKE_TOOLCHAIN_FILE="$work/prefix/share/odestep/toolchains/$core.cmake" \
        -DCMAKE_C_FLAGS=-fstack-usage -DCMAKE_CXX_FLAGS=-fstack-usage -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
  cmake --build "$build" >/dev/null
  python3 - "$build/compile_commands.json" -fstack-usage "$@" <<'PY'
import json, sys
entries = json.load(open(sys.argv[1]))
bad = [e["file"] for e in entries if not all(f in e["command"].split() for f in sys.argv[2:])]
if len(entries) < 4 or bad:
    sys.exit(f"FAIL: compiles without {sys.argv[2:]}: {bad or entries}")
PY
  test -f "$build/CMakeFiles/app.dir/closed_form.c.su"  # the user's C flag reached the C compile
  run=$(grep -m1 "^qemu-system-arm -M $machine .* -kernel build/app\$" "$doc") ||
    { echo "FAIL: no QEMU command for $machine and build/app in $doc"; exit 1; }
  expected=$(awk '/^<!-- board image output -->$/ { on = 1; next } on == 1 && /^```/ { on = 2; next }
                  on == 2 && /^```$/ { exit } on == 2' "$doc")
  output=$(cd "$work/board-$core" && timeout 60 ${run})
  [ "$output" = "$expected" ] || { echo "FAIL: the image printed '$output', $doc shows '$expected'"; exit 1; }
  echo "ok: docs/cortex-m.md's own image under QEMU $machine from the installed package ($core, the user's flags kept)"
}

checks=("host_consumer find_package" "host_consumer add_subdirectory" "host_consumer FetchContent" readme_snippet)
if command -v arm-none-eabi-g++ >/dev/null; then
  checks+=("firmware_consumer find_package" "firmware_consumer add_subdirectory" "firmware_consumer FetchContent"
           firmware_strict)
  if command -v qemu-system-arm >/dev/null; then
    checks+=("board_image cortex-m4f mps2-an386 -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
             "board_image cortex-m0 microbit -mcpu=cortex-m0 -mthumb -mfloat-abi=soft")
  else
    echo "skipped: the recipe's own image under QEMU (no qemu-system-arm)"
  fi
else
  echo "skipped: the cross-compiled consumer (no arm-none-eabi-g++)"
fi
pids=() logs=()
for i in "${!checks[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  logs[i]="$work/check-$i.log"
  (set -e; ${checks[i]}) > "${logs[i]}" 2>&1 &
  pids[i]=$!
done
failed=0
for i in "${!checks[@]}"; do
  if wait "${pids[i]}"; then cat "${logs[i]}"; else echo "FAIL: ${checks[i]}:"; cat "${logs[i]}"; failed=1; fi
done
exit $failed
