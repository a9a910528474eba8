#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The Cortex-M0 runner (tests/m0/runner.cpp): builds it for QEMU's `microbit` (nRF51, Armv6-M, 256 KiB
# flash, 16 KiB RAM) and for the host, runs both, and fails unless every BITS line of the M0 run (the final
# float states of RK4, velocity Verlet, the C API's RK4 step and an event loop, as bit patterns) equals the
# host's, and both runs end with "END 0" (the host's also checks its results against closed forms). Prints
# the M0's instructions per step (COUNT lines: QEMU -icount shift=0, SysTick at 16 MHz, 62.5 instructions
# per tick) and the images' flash and RAM (arm-none-eabi-size). A few seconds to a minute, mostly compiling.
#
# Usage: scripts/test-m0.sh [--m4f] [-O...]
#   -O...   the images' optimisation levels (default -O2; e.g. -O2 -Os)
#   --m4f   also build and run the same runner on the Cortex-M4F (QEMU mps2-an386, SysTick at 25 MHz: 40
#           instructions per tick), checked the same way, for figures beside the M0's (docs/cortex-m.md)
# Builds in build/m0/. Needs g++, arm-none-eabi-g++ with newlib and qemu-system-arm (Debian:
# gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2

targets=(m0)
opts=()
for arg in "$@"; do
  case $arg in
    --m4f) targets+=(m4f) ;;
    -O*) opts+=("$arg") ;;
    *) echo "test-m0: unknown argument '$arg' (--m4f, -O...)" >&2; exit 2 ;;
  esac
done
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
failed=0

# The host's run, in the background while the target images compile.
(g++ -O2 "${common[@]}" "${sources[@]}" -o "$out/runner-host" && "$out/runner-host" > "$out/host.txt") &
host_pid=$!

runs=()
for target in "${targets[@]}"; do
  for opt in "${opts[@]}"; do
    if [[ $target == m0 ]]; then
      cpu=(-mcpu=cortex-m0 -mthumb -mfloat-abi=soft) clock=() board=(microbit microbit.ld)
    else
      cpu=(-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard) clock=(-DRUNNER_TENTHS_PER_TICK=400u)
      board=(mps2-an386 mps2.ld)
    fi
    run=$target$opt
    runs+=("$run")
    dir=$out/obj-$run
    mkdir -p "$dir"
    rm -f "$out/$run.txt" "$out/runner-$run.elf"
    pids=()
    for src in "${sources[@]}"; do
      name=$(basename "${src%.cpp}")
      arm-none-eabi-g++ "${cpu[@]}" "$opt" "${common[@]}" "${clock[@]}" -ffunction-sections -fdata-sections \
        -c "$src" -o "$dir/$name.o" &
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
    elf=$out/runner-$run.elf
    if ((ok == 0)) || ! arm-none-eabi-g++ "${cpu[@]}" "$dir"/*.o -nostartfiles -Ltoolchains/board \
         -Ttoolchains/board/"${board[1]}" -Wl,--gc-sections -o "$elf"; then
      echo "test-m0: the $target image at $opt does not build" >&2
      failed=1
      continue
    fi
    echo "=== $target image $opt on ${board[0]} (text: flash; data: flash and RAM; bss: RAM; and a 4 KiB stack)"
    arm-none-eabi-size "$elf"
    timeout 120 qemu-system-arm -M "${board[0]}" -nographic -monitor none -icount shift=0 \
      -semihosting-config enable=on,target=native -kernel "$elf" > "$out/$run.txt" 2>&1
    status=$?
    grep '^COUNT' "$out/$run.txt"
    # The clock's check: a loop of 201 instructions must read 201 (the board's clock: 62.5 or 40 instructions a tick).
    if ! awk '$1 == "COUNT" && $2 == "calibration" { found = 1; bad = $3 < 200.9 || $3 > 201.1 }
              END { exit !(found && !bad) }' "$out/$run.txt"; then
      echo "test-m0: the clock's calibration of $run is not 201 instructions" >&2
      failed=1
    fi
    if ((status != 0)) || ! grep -qx 'END 0' "$out/$run.txt"; then
      echo "test-m0: the run $run failed (exit $status):" >&2
      cat "$out/$run.txt" >&2
      failed=1
    fi
  done
done

if ! wait "$host_pid" || ! grep -qx 'END 0' "$out/host.txt"; then
  echo "test-m0: the host run failed:" >&2
  cat "$out/host.txt" >&2
  exit 1
fi
for run in "${runs[@]}"; do
  [[ -f "$out/$run.txt" ]] || continue
  if ! diff <(grep '^BITS' "$out/host.txt") <(grep '^BITS' "$out/$run.txt"); then
    echo "test-m0: the results of $run differ from the host's (< host, > target)" >&2
    failed=1
  else
    echo "=== $run: $(grep -c '^BITS' "$out/host.txt") results bit for bit the host's"
  fi
done
exit $failed
