#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Turns the examples' CSV files into the pictures of the gallery (docs/gallery.md): one gnuplot script per
# picture in scripts/plots/, each PNG checked to be a non-empty PNG file.
#   scripts/plots.sh [--update-docs] [CSV directory [PNG directory]]
# The CSV files are read from where `scripts/examples.sh` leaves them (build/examples/examples/data). The
# pictures go to build/gallery, so that a run leaves the work tree as it found it; --update-docs writes them
# into docs/gallery instead (then commit them). Needs gnuplot (scripts/install-deps.sh examples installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
default_out=build/gallery
if [ "${1:-}" = --update-docs ]; then
  default_out=docs/gallery
  shift
fi
data=${1:-build/examples/examples/data}
out=${2:-$default_out}
command -v gnuplot >/dev/null || { echo "plots: gnuplot is missing (scripts/install-deps.sh examples)"; exit 1; }
[ -d "$data" ] || { echo "plots: no CSV directory $data (run the examples first: scripts/examples.sh)"; exit 1; }
mkdir -p "$out"
pictures=(pendulum_phase sho_phase kepler_energy convergence pebble curveball bouncing_ball dipole_orbit
          dipole_invariants coffee_filter nuclear_decay euler_stability two_objects stiff_rc stiff_robertson)
png_magic=89504e470d0a1a0a
for picture in "${pictures[@]}"; do
  png="$out/$picture.png"
  rm -f "$png"
  gnuplot -e "data='$data'; out='$out'" "scripts/plots/$picture.gp"
  if [ ! -s "$png" ] || [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != "$png_magic" ]; then
    echo "plots: $png was not produced"
    exit 1
  fi
  echo "plots: $png ($(wc -c < "$png") bytes)"
done
