#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Instructions per step on the emulated Cortex-M4F: bench/m4f/rk4_float4.cpp (float RK4, 4 states: odestep
# against the unrolled hand loops of bench/hand.hpp, plain and checked) built with arm-none-eabi-g++ at -O2
# and -Os and run under QEMU mps2-an386 with -icount shift=0 (1 ns of virtual time per instruction; the
# board's 25 MHz timer then ticks every 40 instructions). Prints one line per variant and -O, and each
# step function's size in bytes. Exits non-zero if a build, a run or the agreement check fails.
#
# Usage: scripts/bench-m4f.sh [extra compiler flags...]    e.g. -DODESTEP_STEP_FLATTEN= -DODESTEP_STEP_UNROLL=
# Needs arm-none-eabi-g++ with newlib and qemu-system-arm (Debian: gcc-arm-none-eabi libnewlib-arm-none-eabi
# libstdc++-arm-none-eabi-newlib qemu-system-arm).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
for tool in arm-none-eabi-g++ arm-none-eabi-nm qemu-system-arm; do
  command -v "$tool" > /dev/null 2>&1 || { echo "bench-m4f: missing $tool" >&2; exit 2; }
done
dir=$(mktemp -d "${TMPDIR:-/tmp}/odestep-m4f.XXXXXX")
trap 'rm -rf "$dir"' EXIT
cpu=(-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard)
failed=0
for opt in -O2 -Os; do
  elf=$dir/rk4_float4${opt}.elf
  if ! arm-none-eabi-g++ "${cpu[@]}" -std=c++17 -DNDEBUG "$opt" "$@" -Wall -Wextra -Wdouble-promotion -fno-exceptions \
    -fno-rtti -ffunction-sections -fdata-sections -Iinclude -Ibench bench/m4f/rk4_float4.cpp \
    toolchains/board/startup.cpp toolchains/board/syscalls.cpp -nostartfiles -Ltoolchains/board \
    -Ttoolchains/board/mps2.ld --specs=rdimon.specs -Wl,--gc-sections -o "$elf"; then
    echo "bench-m4f: build at $opt failed" >&2
    failed=1
    continue
  fi
  echo "=== Cortex-M4F (QEMU mps2-an386, -icount shift=0) $opt $*"
  if ! timeout 300 qemu-system-arm -M mps2-an386 -nographic -monitor none \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf"; then
    echo "bench-m4f: the run at $opt failed" >&2
    failed=1
  fi
  arm-none-eabi-nm -S "$elf" | awk '$4 ~ /^step_(odestep|hand|hand_checked)$/ { printf "size\t%s\t%d bytes\n", $4, ("0x" $2) + 0 }'
done
exit $failed
