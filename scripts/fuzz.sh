#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Builds odestep's fuzz targets (tests/fuzz/*.cpp: clang's libFuzzer with AddressSanitizer and
# UndefinedBehaviorSanitizer) in their own build directory, build/fuzz/, and runs them. Each target checks the
# README's promises as properties and aborts on a broken one (docs/hardening.md lists them).
#
#   scripts/fuzz.sh --quick     the gate: every target (JOBS at a time) on the committed corpus,
#                               tests/fuzz/corpus/<target>/, whose regression-* inputs are the defects found so
#                               far, then a fixed number of new inputs from a fixed seed (about 4.5 s a target on
#                               an idle core; at most 120 s), without comparison-guided mutation (its dictionary
#                               holds addresses, which change from run to run): nearly the same inputs on every
#                               machine (libFuzzer's schedule still varies a little), so that a clone's gate
#                               and CI's agree; fails on any finding. The search for new defects is the timed
#                               mode below (random seeds, every mutation).
#   scripts/fuzz.sh SECONDS     all targets for SECONDS in all (split evenly, one after the other), going on past
#                               a finding; prints the executions per target and where the findings are
#   scripts/fuzz.sh --known     replays tests/fuzz/known/<target>/: findings not fixed yet (each is expected to
#                               fail until its fix lands; then it moves to the corpus as a regression-* input)
#   scripts/fuzz.sh --build     builds only
# Every mode ends with the line "fuzz: N passed, M failed". A finding is written to build/fuzz/findings/<target>/
# (replay it: build/fuzz/<target> FILE; ODESTEP_FUZZ_TRACE=1 prints what the checks saw). New inputs that
# widen coverage go to build/fuzz/corpus/<target>/, never into the committed corpus.
#
# Environment: CXX_FUZZ (default clang++), FUZZ_BUILD_DIR (default build/fuzz), FUZZ_TIMEOUT (seconds one input may
# take before it is a hang, default 10), FUZZ_TARGETS (a space-separated subset of the targets), JOBS (--quick: targets
# fuzzed at a time, and compilations at a time; default nproc). Needs clang++ and its libFuzzer runtime (Debian: clang, libclang-rt-dev).
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD

read -r -a targets <<< "${FUZZ_TARGETS:-fuzz_loops fuzz_loops_newtonian fuzz_steps fuzz_events fuzz_free_events fuzz_adaptive fuzz_c_api}"
jobs=${JOBS:-$(nproc 2> /dev/null || echo 2)}
quick_seed=20261127  # the gate's fixed seed
quick_cap=120        # the gate's cap in seconds a target (its runs take about 4.5 s on an idle core)
# The gate's new inputs a target: about 4.5 s of each on an idle core (rates of 2-minute runs on this project's
# 2-core machine: fuzz_events 1,000 a second, fuzz_free_events 4,400, fuzz_c_api 8,300, fuzz_adaptive 33,000,
# fuzz_loops 49,000, fuzz_loops_newtonian 53,000, fuzz_steps 76,000).
quick_runs() {
  case "$1" in
    fuzz_events) echo 5000 ;;
    fuzz_free_events) echo 20000 ;;
    fuzz_c_api) echo 40000 ;;
    fuzz_adaptive) echo 150000 ;;
    fuzz_loops) echo 220000 ;;
    fuzz_loops_newtonian) echo 240000 ;;
    *) echo 340000 ;;
  esac
}
cxx=${CXX_FUZZ:-clang++}
dir=${FUZZ_BUILD_DIR:-$root/build/fuzz}
timeout_s=${FUZZ_TIMEOUT:-10}

mode=${1:-}
case "$mode" in
  --quick | --known | --build) ;;
  '' | -h | --help)
    sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'
    [ -n "$mode" ] && exit 0
    exit 2
    ;;
  *)
    if ! [[ "$mode" =~ ^[0-9]+$ ]] || [ "$mode" -lt 1 ]; then
      echo "fuzz: unknown argument '$mode' (--quick, --known, --build or a number of seconds)" >&2
      exit 2
    fi
    ;;
esac

summary() { echo "fuzz: $1 passed, $2 failed"; }

# --- build -----------------------------------------------------------------------------------------------
if ! command -v "$cxx" > /dev/null 2>&1; then
  echo "fuzz: $cxx is missing (scripts/install-deps.sh test)" >&2
  summary 0 1
  exit 1
fi
mkdir -p "$dir"
probe=$dir/probe.cpp
printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' > "$probe"
if ! "$cxx" -fsanitize=fuzzer "$probe" -o "$dir/probe" > "$dir/probe.log" 2>&1; then
  echo "fuzz: $cxx cannot link a libFuzzer target (Debian: apt-get install libclang-rt-dev):" >&2
  cat "$dir/probe.log" >&2
  summary 0 1
  exit 1
fi
# Line tables only: a finding's stack trace keeps every frame's file and line, and the targets compile in about a
# sixth less CPU time than with -g (fuzz_free_events.cpp: 35.5 s against 29.4 s, user + sys).
flags=(-std=c++17 -gline-tables-only -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
  -fno-omit-frame-pointer -Wall -Wextra -Werror -I"$root/include")
# Every translation unit on its own (fuzz_c_api's nine, the library's sources in src/ and its target, would
# otherwise compile one after the other), JOBS at a time, the longest first; then each target is linked.
stale=()
for t in "${targets[@]}"; do
  # Rebuild when the target, the shared checks or any header is newer than the binary.
  if [ -x "$dir/$t" ] && [ -z "$(find "$root/tests/fuzz/$t.cpp" "$root/tests/fuzz/fuzz_support.hpp" "$root/include" \
    "$root/src" -newer "$dir/$t" -print -quit)" ]; then
    continue
  fi
  stale+=("$t")
done
objects_of() {  # objects_of TARGET: the target's source and, for fuzz_c_api (it calls the C API), src/*.cpp
  local s
  echo "$1"
  if [ "$1" = fuzz_c_api ]; then for s in "$root"/src/*.cpp; do echo "src_$(basename "$s" .cpp)"; done; fi
}
source_of() {  # source_of OBJECT
  case "$1" in src_*) echo "$root/src/${1#src_}.cpp" ;; *) echo "$root/tests/fuzz/$1.cpp" ;; esac
}
units=()
for t in "${stale[@]}"; do [ "$t" = fuzz_c_api ] && mapfile -t units < <(objects_of "$t"); done
for t in "${stale[@]}"; do [ "$t" = fuzz_c_api ] || units+=("$t"); done
mkdir -p "$dir/obj"
for u in "${units[@]}"; do
  rm -f "$dir/obj/$u.o"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  ("$cxx" "${flags[@]}" -c "$(source_of "$u")" -o "$dir/obj/$u.o.new" > "$dir/obj/$u.log" 2>&1 &&
    mv "$dir/obj/$u.o.new" "$dir/obj/$u.o") &
done
wait
built=0
for t in "${stale[@]}"; do
  objects=()
  : > "$dir/$t.build.log"
  for u in $(objects_of "$t"); do
    [ -f "$dir/obj/$u.o" ] || cat "$dir/obj/$u.log" >> "$dir/$t.build.log"
    objects+=("$dir/obj/$u.o")
  done
  if [ -s "$dir/$t.build.log" ] || ! "$cxx" "${flags[@]}" "${objects[@]}" -o "$dir/$t.new" >> "$dir/$t.build.log" 2>&1; then
    built=1
  else
    mv "$dir/$t.new" "$dir/$t"
  fi
done
if [ $built -ne 0 ]; then
  for t in "${targets[@]}"; do
    [ -s "$dir/$t.build.log" ] && { echo "fuzz: building $t:" >&2; cat "$dir/$t.build.log" >&2; }
  done
  summary 0 1
  exit 1
fi
[ "$mode" = --build ] && { echo "fuzz: built ${targets[*]} in $dir"; summary ${#targets[@]} 0; exit 0; }

# --- run ---------------------------------------------------------------------------------------------------
passed=0
failed=0
# fuzz_one TARGET SECONDS [OPTIONS...]: one libFuzzer run on the working corpus and the committed one (the gate:
# the committed one alone, so that every machine runs the same inputs); returns libFuzzer's status and appends
# its executions to $dir/<target>.runs.
fuzz_one() {
  local t=$1 seconds=$2 log=$dir/$1.log
  shift 2
  local corpora=("$dir/corpus/$t" "$root/tests/fuzz/corpus/$t")
  [ "$mode" = --quick ] && corpora=("$dir/gate/$t" "$root/tests/fuzz/corpus/$t")
  mkdir -p "$dir/corpus/$t" "$dir/findings/$t"
  [ "$mode" = --quick ] && rm -rf "$dir/gate/$t" && mkdir -p "$dir/gate/$t"
  "$dir/$t" -max_total_time="$seconds" -timeout="$timeout_s" -rss_limit_mb=2048 -print_final_stats=1 "$@" \
    -artifact_prefix="$dir/findings/$t/" "${corpora[@]}" > "$log" 2>&1
  local status=$?
  sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1 >> "$dir/$t.runs"
  return $status
}

if [ "$mode" = --known ]; then
  for t in "${targets[@]}"; do
    for f in "$root"/tests/fuzz/known/"$t"/*; do
      [ -f "$f" ] || continue
      if "$dir/$t" -timeout="$timeout_s" "$f" > "$dir/known.log" 2>&1; then
        echo "fuzz: known finding $t/$(basename "$f") passes now: move it to tests/fuzz/corpus/$t/"
        passed=$((passed + 1))
      else
        echo "fuzz: known finding $t/$(basename "$f") still fails:"
        grep -E 'property violated|ERROR: libFuzzer|SUMMARY' "$dir/known.log" | head -n 2 | sed 's/^/  /'
        failed=$((failed + 1))
      fi
    done
  done
  summary $passed $failed
  [ $failed -eq 0 ]
  exit $?
fi

if [ "$mode" = --quick ]; then
  # The gate skips the checks of properties with an open finding (tests/fuzz/known/; fuzz_support.hpp).
  export ODESTEP_FUZZ_SKIP_OPEN=1
  # The targets run side by side, as many at a time as there are cores (each fuzzes on one core), and are
  # reported in order once all have ended.
  for t in "${targets[@]}"; do
    : > "$dir/$t.runs"
    rm -f "$dir/$t.status"
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
    (fuzz_one "$t" "$quick_cap" -seed="$quick_seed" -reload=0 -use_cmp=0 -runs="$(quick_runs "$t")"; echo $? > "$dir/$t.status") &
  done
  wait
  for t in "${targets[@]}"; do
    if [ "$(cat "$dir/$t.status" 2> /dev/null)" = 0 ]; then
      echo "fuzz: ok   $t: $(cat "$dir/$t.runs") executions (seed $quick_seed), no finding"
      passed=$((passed + 1))
    else
      echo "fuzz: FAIL $t: a finding (see $dir/$t.log; inputs in $dir/findings/$t/):"
      grep -E 'property violated|ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|runtime error|SUMMARY' \
        "$dir/$t.log" | head -n 3 | sed 's/^/  /'
      failed=$((failed + 1))
    fi
  done
  summary $passed $failed
  [ $failed -eq 0 ]
  exit $?
fi

# A long run: SECONDS in all, split evenly; after a finding the target starts again with the time it has left.
per=$((mode / ${#targets[@]}))
[ $per -lt 1 ] && per=1
for t in "${targets[@]}"; do
  : > "$dir/$t.runs"
  start=$SECONDS
  findings=0
  while :; do
    left=$((per - (SECONDS - start)))
    [ $left -ge 1 ] || break
    if ! fuzz_one "$t" "$left"; then
      findings=$((findings + 1))
      grep -E 'property violated|ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|runtime error' \
        "$dir/$t.log" | head -n 1 | sed "s/^/fuzz: $t finding: /"
      cp "$dir/$t.log" "$dir/findings/$t/log-$findings.txt"
    fi
  done
  runs=$(awk '{ n += $1 } END { print n + 0 }' "$dir/$t.runs")
  if [ $findings -eq 0 ]; then
    echo "fuzz: ok   $t: $runs executions in $((SECONDS - start)) s, no finding"
    passed=$((passed + 1))
  else
    echo "fuzz: FAIL $t: $runs executions in $((SECONDS - start)) s, $findings findings in $dir/findings/$t/"
    failed=$((failed + 1))
  fi
done
summary $passed $failed
[ $failed -eq 0 ]
