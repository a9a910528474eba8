#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The work-precision diagrams (bench/work_precision.cpp, bench/RESULTS.md "Work-precision (adaptive)") from its
# CSV: docs/gallery/wp_<problem>_evals.png and wp_<problem>_time.png for arenstorf, lorenz and pleiades, each
# checked to be a non-empty PNG file.
#   scripts/work_precision_plot.sh [CSV [PNG directory]]
# Defaults: bench/work_precision.csv (the committed data of the figures; `scripts/bench.sh --work-precision`
# rewrites it) and docs/gallery. Needs gnuplot (scripts/install-deps.sh examples installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
csv=${1:-bench/work_precision.csv}
out=${2:-docs/gallery}
command -v gnuplot > /dev/null || {
  echo "work_precision_plot: gnuplot is missing (scripts/install-deps.sh examples)"
  exit 1
}
[ -s "$csv" ] || {
  echo "work_precision_plot: no CSV $csv (run scripts/bench.sh --work-precision)"
  exit 1
}
mkdir -p "$out"
split=$(mktemp -d)
trap 'rm -rf "$split"' EXIT
# One file per problem and solver: <problem>_<solver>.csv.
awk -F, -v dir="$split" '/^#/ || NF < 5 { next } { print > (dir "/" $1 "_" $2 ".csv") }' "$csv"
png_magic=89504e470d0a1a0a
for problem in arenstorf lorenz pleiades; do
  rm -f "$out/wp_${problem}_evals.png" "$out/wp_${problem}_time.png"
  gnuplot -e "data='$split'; out='$out'; problem='$problem'" scripts/plots/work_precision.gp
  for png in "$out/wp_${problem}_evals.png" "$out/wp_${problem}_time.png"; do
    if [ ! -s "$png" ] || [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != "$png_magic" ]; then
      echo "work_precision_plot: $png was not produced"
      exit 1
    fi
    echo "work_precision_plot: $png ($(wc -c < "$png") bytes)"
  done
done
