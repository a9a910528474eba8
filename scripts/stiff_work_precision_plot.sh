#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The stiff work-precision diagrams (bench/stiff_work_precision.cpp and .py, bench/RESULTS.md "Work-precision
# (stiff)") from its CSV: <dir>/swp_<problem>_evals.png and swp_<problem>_time.png for robertson, vdpol, hires, pollu,
# each checked to be a non-empty PNG file. Failed runs (error inf) are left out of the curves.
#   scripts/stiff_work_precision_plot.sh [CSV [PNG directory]]
# Defaults: bench/stiff_work_precision.csv (the committed data; `scripts/bench.sh --stiff-work-precision` rewrites
# it) and build/bench/swp (the pictures are not committed). Needs gnuplot (scripts/install-deps.sh examples).
set -euo pipefail
cd "$(dirname "$0")/.."
csv=${1:-bench/stiff_work_precision.csv}
out=${2:-build/bench/swp}
command -v gnuplot > /dev/null || {
  echo "stiff_work_precision_plot: gnuplot is missing (scripts/install-deps.sh examples)"
  exit 1
}
[ -s "$csv" ] || {
  echo "stiff_work_precision_plot: no CSV $csv (run scripts/bench.sh --stiff-work-precision)"
  exit 1
}
mkdir -p "$out"
split=$(mktemp -d)
trap 'rm -rf "$split"' EXIT
# One file per problem and solver: <problem>_<solver>.csv, finite errors only.
awk -F, -v dir="$split" '/^#/ || NF < 11 || $4 == "inf" { next } { print > (dir "/" $1 "_" $2 ".csv") }' "$csv"
png_magic=89504e470d0a1a0a
for problem in robertson vdpol hires pollu; do
  rm -f "$out/swp_${problem}_evals.png" "$out/swp_${problem}_time.png"
  gnuplot -e "data='$split'; out='$out'; problem='$problem'" scripts/plots/stiff_work_precision.gp
  for png in "$out/swp_${problem}_evals.png" "$out/swp_${problem}_time.png"; do
    if [ ! -s "$png" ] || [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != "$png_magic" ]; then
      echo "stiff_work_precision_plot: $png was not produced"
      exit 1
    fi
    echo "stiff_work_precision_plot: $png ($(wc -c < "$png") bytes)"
  done
done
