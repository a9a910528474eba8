#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Instructions per step of the steps with Phi on the emulated Cortex-M4F (bench/m4f/sensitivity.cpp's rows,
# run by bench/m4f/main.cpp, with the flags of scripts/bench-m4f.sh), at -O2 and -Os. Prints the runner's
# ROW lines. Usage: bench/m4f/sensitivity.sh (from anywhere; needs arm-none-eabi-g++ and qemu-system-arm).
set -euo pipefail
cd "$(dirname "$0")/../.."
read -r -a cpu <<< "$(sed -n 's/^set(ODESTEP_TARGET_CPU_FLAGS "\([^"]*\)").*/\1/p' toolchains/cortex-m4f.cmake)"
dir=$(mktemp -d "${TMPDIR:-/tmp}/odestep-m4f-sens.XXXXXX")
trap 'rm -rf "$dir"' EXIT
flags=("${cpu[@]}" -std=c++17 -DNDEBUG -Wall -Wextra -Wdouble-promotion -fno-exceptions -fno-rtti
       -ffunction-sections -fdata-sections -Iinclude -Ibench)
for opt in -O2 -Os; do
  objects=()
  for k in $(seq 50 63); do
    arm-none-eabi-g++ "${flags[@]}" "$opt" -DM4F_UNIT="$k" -c bench/m4f/sensitivity.cpp -o "$dir/row$k$opt.o"
    objects+=("$dir/row$k$opt.o")
  done
  arm-none-eabi-g++ "${flags[@]}" "$opt" -c bench/m4f/main.cpp -o "$dir/main$opt.o"
  arm-none-eabi-g++ "${cpu[@]}" "$dir/main$opt.o" "${objects[@]}" toolchains/board/startup.cpp \
    toolchains/board/syscalls.cpp -nostartfiles -Ltoolchains/board -Ttoolchains/board/mps2.ld \
    --specs=rdimon.specs -Wl,--gc-sections -o "$dir/sens$opt.elf"
  echo "=== Cortex-M4F (QEMU mps2-an386, -icount shift=0) $opt, float"
  timeout 120 qemu-system-arm -M mps2-an386 -nographic -monitor none \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$dir/sens$opt.elf"
done
