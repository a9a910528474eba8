#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs what is missing, builds the examples and runs them; each run's numbers are then checked
# against closed forms by the example's checker (examples/check/*.awk). The examples write CSV files into
# build/examples/examples/data, which scripts/plots.sh turns into the gallery's pictures (build/gallery/;
# `scripts/plots.sh --update-docs` replaces docs/gallery/'s).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh examples
cmake --preset examples >/dev/null
cmake --build --preset examples -j"$(nproc)"
for example in quickstart harmonic_oscillator radioactive_decay euler_table earth_orbit pendulum kepler_orbits crossed_fields \
               pebble projectile bouncing_ball coffee euler_accuracy position_force phase_space nuclear_decay coffee_filter \
               convergence kepler_energy curveball dipole steel_ball stiff; do
  echo "== $example"
  "build/examples/examples/$example" build/examples/examples/data
done
echo "== checking the printed numbers against closed forms"
ctest --preset examples
echo "== the gallery's pictures"
scripts/plots.sh build/examples/examples/data build/gallery
