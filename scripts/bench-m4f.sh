#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Instructions per step of every odestep stepper on the emulated Cortex-M4F, float, at -O2 and -Os, against
# the scalar hand loops (plain and with odestep's NaN/Inf guarantee) where written: bench/m4f/ (the method
# is in bench/m4f/main.cpp). Each row of bench/m4f/steppers.cpp is compiled as its own translation unit;
# all of them and the runner are linked into one image per -O, run under QEMU mps2-an386 with
# -icount shift=0 (1 ns of virtual time per instruction; the board's 25 MHz timer ticks every 40).
#
# Prints the image's raw output and a markdown table. Exits 1 if a build or a run fails, or a row fails
# its check (a step that did not return ok, or odestep and the hand loops ending in different states);
# never because of a ratio: the figures are reported, not asserted.
#
# Usage: scripts/bench-m4f.sh [--report FILE] [--docs FILE] [extra compiler flags...]
#        scripts/bench-m4f.sh --c-api   the C API's RK4 step instead (bench/m4f/c_api.cpp: odestep_step_f, n = 4
#                                       of ODESTEP_C_MAX_STATES 8, against the C++ step with the same f pointer),
#                                       the library built with ODESTEP_C_EXACT_STATES 0 and 8, at -O2 and -Os
#   --report FILE  also write the table (with its heading) to FILE (scripts/audit.sh: build/audit/)
#   --docs FILE    replace the lines between "<!-- bench-m4f:begin -->" and "<!-- bench-m4f:end -->" in
#                  FILE with the table (docs/cortex-m.md), if every build, run and check passed
#   flags          e.g. -DODESTEP_STEP_FLATTEN= -DODESTEP_STEP_UNROLL_ALWAYS= (the library's -Os form before issue 18)
# Environment: JOBS (parallel compiles, default 2).
# Needs arm-none-eabi-g++ with newlib and qemu-system-arm (Debian: gcc-arm-none-eabi libnewlib-arm-none-eabi
# libstdc++-arm-none-eabi-newlib qemu-system-arm).
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
report_file="" docs_file=""
if [[ ${1:-} == --c-api ]]; then
  read -r -a cpu <<< "$(sed -n 's/^set(ODESTEP_TARGET_CPU_FLAGS "\([^"]*\)").*/\1/p' toolchains/cortex-m4f.cmake)"
  dir=$(mktemp -d "${TMPDIR:-/tmp}/odestep-m4f-capi.XXXXXX")
  trap 'rm -rf "$dir"' EXIT
  status=0
  echo "| ODESTEP_C_EXACT_STATES | -O | odestep_step_f | C++ step, f by pointer | ratio | largest difference | check |"
  echo "|--:|---|--:|--:|--:|--:|---|"
  for exact in 0 8; do
    for opt in -O2 -Os; do
      common=("${cpu[@]}" "$opt" -std=c++17 -DNDEBUG -fno-exceptions -fno-rtti -ffp-contract=off -ffunction-sections
              -fdata-sections -Iinclude)
      if ! { arm-none-eabi-g++ "${common[@]}" -DODESTEP_C_EXACT_STATES=$exact -c src/capi.cpp -o "$dir/capi.o" &&
             arm-none-eabi-g++ "${common[@]}" -DODESTEP_C_EXACT_STATES=$exact -c src/capi_float.cpp -o "$dir/capi_float.o" &&
             arm-none-eabi-g++ "${common[@]}" -Wall -Wextra -Wdouble-promotion -c bench/m4f/c_api.cpp -o "$dir/main.o" &&
             arm-none-eabi-g++ "${cpu[@]}" "$dir/main.o" "$dir/capi.o" "$dir/capi_float.o" toolchains/board/startup.cpp \
               toolchains/board/syscalls.cpp -nostartfiles -Ltoolchains/board -Ttoolchains/board/mps2.ld \
               --specs=rdimon.specs -Wl,--gc-sections -o "$dir/c_api.elf"; }; then
        echo "bench-m4f: the C API build (E $exact, $opt) failed" >&2
        status=1
        continue
      fi
      line=$(timeout 120 qemu-system-arm -M mps2-an386 -nographic -monitor none \
               -semihosting-config enable=on,target=native -icount shift=0 -kernel "$dir/c_api.elf") || status=1
      # C_API <odestep> <cpp_fnptr> <ratio> <difference> <ok | FAIL>
      awk -F'\t' -v e="$exact" -v o="$opt" '$1 == "C_API" { printf "| %s | %s | %s | %s | %s | %s | %s |\n", e, o, $2, $3, $4, $5, $6 }' <<< "$line"
      grep -q 'ok$' <<< "$line" || status=1
    done
  done
  exit $status
fi
while (($# > 0)); do
  case $1 in
    --report) report_file=$2; shift 2 ;;
    --docs) docs_file=$2; shift 2 ;;
    *) break ;;
  esac
done
for tool in arm-none-eabi-g++ qemu-system-arm awk; do
  command -v "$tool" > /dev/null 2>&1 || { echo "bench-m4f: missing $tool" >&2; exit 2; }
done
dir=$(mktemp -d "${TMPDIR:-/tmp}/odestep-m4f.XXXXXX")
trap 'rm -rf "$dir"' EXIT
jobs=${JOBS:-2}

# The core's flags, from its toolchain file (as scripts/audit.sh reads them).
read -r -a cpu <<< "$(sed -n 's/^set(ODESTEP_TARGET_CPU_FLAGS "\([^"]*\)").*/\1/p' toolchains/cortex-m4f.cmake)"
units=$(sed -n 's/^#if M4F_UNIT == \([0-9]*\).*/\1/p' bench/m4f/steppers.cpp)
flags=("${cpu[@]}" -std=c++17 -DNDEBUG -Wall -Wextra -Wdouble-promotion -fno-exceptions -fno-rtti
       -ffunction-sections -fdata-sections -Iinclude -Ibench)
# The rows also get their call graphs (rowK.ci), for the flash and stack of each step (scripts/callgraph.awk).
row_flags=(-fcallgraph-info=su)
failed=0
touch "$dir/out-O2" "$dir/out-Os"
for opt in -O2 -Os; do
  objects=$dir/objects$opt
  mkdir -p "$objects" "$dir/pch$opt/m4f"
  # The units' common header precompiled (GCC takes pch$opt/m4f/units.hpp.gch, first on the include path,
  # for bench/m4f/units.hpp when it was built with the same flags), then one object per row, JOBS at a time.
  # shellcheck disable=SC2016  # expanded by the inner shell
  if ! arm-none-eabi-g++ "${flags[@]}" "$opt" "$@" -x c++-header bench/m4f/units.hpp \
         -o "$dir/pch$opt/m4f/units.hpp.gch" ||
     ! xargs -P "$jobs" -I{} sh -c 'exec "$@" -DM4F_UNIT={} -c bench/m4f/steppers.cpp -o "'"$objects"'/row{}.o"' \
         sh arm-none-eabi-g++ -I"$dir/pch$opt" -Winvalid-pch "${flags[@]}" "${row_flags[@]}" "$opt" "$@" <<< "$units" ||
     ! arm-none-eabi-g++ "${flags[@]}" "$opt" "$@" -c bench/m4f/main.cpp -o "$objects/main.o"; then
    echo "bench-m4f: the build at $opt failed" >&2
    failed=1
    continue
  fi
  # FLASH <-O> <unit> <odestep|hand|checked> <text> <stack>: each step function of each row (its name in namespace m4f
  # or the row's anonymous namespace, step_...) with what it reaches in its row's object.
  for k in $units; do
    awk -v sizes_cmd="arm-none-eabi-nm -S $objects/row$k.o" -v roots='^_ZN(3m4f|12_GLOBAL__N_1)[0-9]+step_' \
      -f scripts/callgraph.awk "$objects/row$k.ci" |
      awk -v unit="$k" -v opt="$opt" '{
        kind = $1 ~ /_hand_checked/ ? "checked" : ($1 ~ /_hand/ ? "hand" : "odestep")
        print "FLASH\t" opt "\t" unit "\t" kind "\t" $2 "\t" $3
      }'
  done > "$dir/flash$opt"
  elf=$dir/steppers$opt.elf
  # The rows' objects in table order (their static registrations fill the table by index in any order).
  mapfile -t row_objects < <(for k in $units; do echo "$objects/row$k.o"; done)
  if ! arm-none-eabi-g++ "${cpu[@]}" "$objects/main.o" "${row_objects[@]}" toolchains/board/startup.cpp \
       toolchains/board/syscalls.cpp -nostartfiles -Ltoolchains/board -Ttoolchains/board/mps2.ld \
       --specs=rdimon.specs -Wl,--gc-sections -o "$elf"; then
    echo "bench-m4f: the link at $opt failed" >&2
    failed=1
    continue
  fi
  echo "=== Cortex-M4F (QEMU mps2-an386, -icount shift=0) $opt $*"
  if ! timeout 120 qemu-system-arm -M mps2-an386 -nographic -monitor none \
       -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf" | tee "$dir/out$opt"; then
    echo "bench-m4f: the run at $opt failed (or a row failed its check)" >&2
    failed=1
  fi
done

# The table: one line per row, -O2 and -Os side by side.
table=$dir/table.md
{
  echo "arm-none-eabi-g++ $(arm-none-eabi-g++ -dumpversion) \`${cpu[*]}\`${*:+ \`$*\`}, float;"
  echo "QEMU $(qemu-system-arm --version | awk 'NR == 1 { print $4 }') mps2-an386 \`-icount shift=0\`: instructions per step, 1000 steps timed"
  echo "after 4 untimed, the empty step's loop subtracted (+-0.04). \`hand\`: the scalar hand loop; \`checked\`:"
  echo "the same with odestep's guarantee (NaN/Inf test, state kept on failure); \`-\`: none written."
  echo "x hand, x chk: odestep's figure divided by the hand loop's, by the checked hand loop's."
  echo
  echo "| stepper | -O2 odestep | hand | checked | x hand | x chk | -Os odestep | hand | checked | x hand | x chk |"
  echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  awk -F'\t' '
    function ratio(a, b) { return (a == "-" || b == "-" || b + 0 == 0) ? "-" : sprintf("%.2f", a / b) }
    function cells(r) {
      split(r, c, SUBSEP)
      return sprintf("%s | %s | %s | %s | %s", c[1], c[2], c[3], ratio(c[1], c[2]), ratio(c[1], c[3]))
    }
    { file = FILENAME ~ /-O2$/ ? 1 : 2 }
    $1 == "ROW" {
      if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 }
      value[$2, file] = $3 SUBSEP $4 SUBSEP $5
      if ($7 != "ok") verdict[$2] = verdict[$2] (file == 1 ? " -O2 " : " -Os ") $7
    }
    END {
      for (i = 1; i <= n; i++) {
        s = order[i]
        o2 = ((s, 1) in value) ? cells(value[s, 1]) : "- | - | - | - | -"
        os = ((s, 2) in value) ? cells(value[s, 2]) : "- | - | - | - | -"
        printf "| %s%s | %s | %s |\n", s, (s in verdict) ? " **" substr(verdict[s], 2) "**" : "", o2, os
      }
    }' "$dir/out-O2" "$dir/out-Os" 2> /dev/null
  echo
  echo "Flash and stack of each step (the same rows' objects, bytes of text reachable from the step function /"
  echo "the deepest stack on a call path from it: scripts/callgraph.awk; the float oscillator's f is inlined)."
  echo
  echo "| stepper | -O2 odestep | hand | checked | text x hand | text x chk | -Os odestep | hand | checked | text x hand | text x chk |"
  echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  sed -n 's/^#if M4F_UNIT == \([0-9]*\) *\/\/ *\(.*\)$/NAME\t\1\t\2/p' bench/m4f/steppers.cpp |
    cat - "$dir/flash-O2" "$dir/flash-Os" |
    awk -F'\t' '
      function ratio(a, b) { return (a == "" || b == "" || b + 0 == 0) ? "-" : sprintf("%.2f", a / b) }
      function cell(u, kind, o) { return ((u, kind, o) in text) ? text[u, kind, o] " / " stack[u, kind, o] : "-" }
      function half(u, o) {
        return sprintf("%s | %s | %s | %s | %s", cell(u, "odestep", o), cell(u, "hand", o), cell(u, "checked", o),
                       ratio(text[u, "odestep", o], text[u, "hand", o]), ratio(text[u, "odestep", o], text[u, "checked", o]))
      }
      $1 == "NAME" { name[$2] = $3; order[++n] = $2; next }
      $1 == "FLASH" { o = $2 == "-O2" ? 1 : 2; text[$3, $4, o] = $5; stack[$3, $4, o] = $6 }
      END { for (i = 1; i <= n; i++) printf "| %s | %s | %s |\n", name[order[i]], half(order[i], 1), half(order[i], 2) }'
} > "$table"
echo
cat "$table"
if [[ -n "$report_file" ]]; then
  cp "$table" "$report_file"
fi
# The docs take the table only from a run that passed.
if [[ -n "$docs_file" && $failed == 0 ]]; then
  if grep -q '^<!-- bench-m4f:begin -->$' "$docs_file" && grep -q '^<!-- bench-m4f:end -->$' "$docs_file"; then
    awk -v table="$table" '
      /^<!-- bench-m4f:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
      /^<!-- bench-m4f:end -->$/ { skip = 0 }
      !skip' "$docs_file" > "$dir/docs" && cat "$dir/docs" > "$docs_file"
  else
    echo "bench-m4f: $docs_file has no <!-- bench-m4f:begin --> / <!-- bench-m4f:end --> lines" >&2
    failed=1
  fi
fi
exit $failed
