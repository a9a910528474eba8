#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs the Debian packages a task needs, only those that are missing. Usage:
#   scripts/install-deps.sh examples   # compiler, CMake, gnuplot (the gallery's pictures)
#   scripts/install-deps.sh test       # + clang (and its libFuzzer and sanitizer runtimes, for scripts/fuzz.sh), cppcheck, doxygen, doctest,
#                                      #   valgrind, Boost/GSL (benchmarks), Cortex-M toolchain, QEMU
#   scripts/install-deps.sh bench      # the benchmarks alone (bench/install-deps.sh): valgrind, Boost, GSL, SciPy (the stiff
#                                      #   work-precision rows) and
#                                      #   SUNDIALS, which pulls in MPI (so the test profile leaves it out)
set -euo pipefail
profile=${1:-test}
packages=(g++ cmake make mawk)
# gnuplot-nox: Debian's gnuplot without a GUI (the metapackage `gnuplot` pulls in Qt); it has pngcairo.
packages+=(gnuplot-nox)
if [ "$profile" = test ]; then
  # libclang-rt-dev: clang's runtimes (libclang_rt.fuzzer, .asan, .ubsan; libclang-rt-14-dev on Debian 12), only
  # recommended by clang, so not installed with --no-install-recommends.
  packages+=(clang libclang-rt-dev clang-format cppcheck doxygen doctest-dev valgrind libboost-dev libgsl-dev binutils
             gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib libnewlib-arm-none-eabi qemu-system-arm)
fi
if [ "$profile" = bench ]; then
  packages+=(valgrind libboost-dev libgsl-dev libsundials-dev python3-scipy)
fi
case "$profile" in examples | test | bench) ;; *) echo "install-deps: unknown profile '$profile'" >&2; exit 2 ;; esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
