#!/usr/bin/env bash
# Builds and runs tests/package/consumer against odestep installed (find_package), added with
# add_subdirectory, and fetched with FetchContent; in the last two, odestep's own tests must not build.
# Usage: check_consumers.sh SOURCE_DIR WORK_DIR CXX_COMPILER
set -euo pipefail
src=$1 work=$2 cxx=$3
rm -rf "$work" && mkdir -p "$work"
consumer="$src/tests/package/consumer"

cmake -S "$src" -B "$work/odestep-build" -DCMAKE_CXX_COMPILER="$cxx" -DODESTEP_BUILD_TESTS=OFF \
      -DODESTEP_BUILD_EXAMPLES=OFF -DODESTEP_INSTALL=ON >/dev/null
cmake --install "$work/odestep-build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/odestep/odestep.hpp"
test -f "$work/prefix/share/cmake/odestep/odestepConfig.cmake"

for mode in find_package add_subdirectory FetchContent; do
  build="$work/$mode"
  cmake -S "$consumer" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DODESTEP_MODE="$mode" \
        -DODESTEP_SOURCE="$src" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
  cmake --build "$build" >/dev/null
  "$build/consumer"
  if [ "$mode" != find_package ] && cmake --build "$build" --target help | grep -q odestep_tests; then
    echo "FAIL: $mode builds odestep's tests although odestep is not the top-level project"
    exit 1
  fi
  echo "ok: $mode"
done
