#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The Cortex-M0 runner (tests/m0/runner.cpp): builds it for QEMU's `microbit` (nRF51, Armv6-M, 256 KiB
# flash, 16 KiB RAM) and for the host, runs both, and fails unless every BITS line of the M0 run (the final
# float states of RK4, velocity Verlet, the C API's RK4 step and an event loop, as bit patterns) equals the
# host's, and both runs end with "END 0" (the host's also checks its results against closed forms). Prints
# the M0's instructions per step (COUNT lines: QEMU -icount shift=0, SysTick at 16 MHz, 62.5 instructions
# per tick) and the images' flash and RAM (arm-none-eabi-size). A few seconds to a minute, mostly compiling.
#
# Usage: scripts/test-m0.sh [-O...]    the M0 images' optimisation levels (default -O2; e.g. -O2 -Os)
# Builds in build/m0/. Needs g++, arm-none-eabi-g++ with newlib and qemu-system-arm (Debian:
# gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2

opts=("$@")
((${#opts[@]} > 0)) || opts=(-O2)
for tool in g++ arm-none-eabi-g++ arm-none-eabi-size qemu-system-arm; do
  command -v "$tool" > /dev/null 2>&1 || { echo "test-m0: missing $tool" >&2; exit 2; }
done
out=build/m0
mkdir -p "$out"

warnings=(-Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror)
# The library's own flags for the C API (-ffp-contract=off: no fused multiply-add on the host either).
common=(-std=c++17 -ffp-contract=off -fno-exceptions -fno-rtti -Iinclude -Ibench "${warnings[@]}")
sources=(tests/m0/runner.cpp src/capi.cpp src/capi_float.cpp)
cpu=(-mcpu=cortex-m0 -mthumb -mfloat-abi=soft)
failed=0

# The host's run, in the background while the M0 images compile.
(g++ -O2 "${common[@]}" "${sources[@]}" -o "$out/runner-host" && "$out/runner-host" > "$out/host.txt") &
host_pid=$!

for opt in "${opts[@]}"; do
  dir=$out/obj$opt
  mkdir -p "$dir"
  rm -f "$out/m0$opt.txt" "$out/runner$opt.elf"
  pids=()
  for src in "${sources[@]}"; do
    name=$(basename "${src%.cpp}")
    arm-none-eabi-g++ "${cpu[@]}" "$opt" "${common[@]}" -ffunction-sections -fdata-sections -c "$src" \
      -o "$dir/$name.o" &
    pids+=($!)
  done
  # The bare board (toolchains/board/): no C library I/O, output through the runner's own semihosting calls.
  arm-none-eabi-g++ "${cpu[@]}" "$opt" -std=c++17 -fno-exceptions -fno-rtti -DODESTEP_BOARD_BARE=1 \
    -c toolchains/board/startup.cpp -o "$dir/startup.o" &
  pids+=($!)
  arm-none-eabi-g++ "${cpu[@]}" "$opt" -std=c++17 -c toolchains/board/syscalls.cpp -o "$dir/syscalls.o" &
  pids+=($!)
  ok=1
  for pid in "${pids[@]}"; do wait "$pid" || ok=0; done
  elf=$out/runner$opt.elf
  if ((ok == 0)) || ! arm-none-eabi-g++ "${cpu[@]}" "$dir"/*.o -nostartfiles -Ltoolchains/board \
       -Ttoolchains/board/microbit.ld -Wl,--gc-sections -o "$elf"; then
    echo "test-m0: the M0 image at $opt does not build" >&2
    failed=1
    continue
  fi
  echo "=== M0 image $opt (text: flash; data: flash and RAM; bss: RAM; the RAM also holds a 4 KiB stack)"
  arm-none-eabi-size "$elf"
  timeout 120 qemu-system-arm -M microbit -nographic -monitor none -icount shift=0 \
    -semihosting-config enable=on,target=native -kernel "$elf" > "$out/m0$opt.txt" 2>&1
  status=$?
  grep '^COUNT' "$out/m0$opt.txt"
  # The clock's check: a loop of 201 instructions must read 201 (62.5 instructions per SysTick tick).
  if ! awk '$1 == "COUNT" && $2 == "calibration" { found = 1; bad = $3 < 200.9 || $3 > 201.1 }
            END { exit !(found && !bad) }' "$out/m0$opt.txt"; then
    echo "test-m0: the clock's calibration at $opt is not 201 instructions" >&2
    failed=1
  fi
  if ((status != 0)) || ! grep -qx 'END 0' "$out/m0$opt.txt"; then
    echo "test-m0: the M0 run at $opt failed (exit $status):" >&2
    cat "$out/m0$opt.txt" >&2
    failed=1
  fi
done

if ! wait "$host_pid" || ! grep -qx 'END 0' "$out/host.txt"; then
  echo "test-m0: the host run failed:" >&2
  cat "$out/host.txt" >&2
  exit 1
fi
for opt in "${opts[@]}"; do
  [[ -f "$out/m0$opt.txt" ]] || continue
  if ! diff <(grep '^BITS' "$out/host.txt") <(grep '^BITS' "$out/m0$opt.txt"); then
    echo "test-m0: the M0 results at $opt differ from the host's (< host, > M0)" >&2
    failed=1
  else
    echo "=== M0 $opt: $(grep -c '^BITS' "$out/host.txt") results bit for bit the host's"
  fi
done
exit $failed
