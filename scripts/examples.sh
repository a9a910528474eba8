#!/usr/bin/env bash
# Installs what is missing, builds the examples and runs them; each run's numbers are then checked
# against closed forms by the example's checker (examples/check/*.awk).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh examples
cmake --preset examples >/dev/null
cmake --build --preset examples -j"$(nproc)"
for example in quickstart harmonic_oscillator radioactive_decay euler_table earth_orbit pendulum kepler_orbits crossed_fields \
               pebble projectile bouncing_ball coffee; do
  echo "== $example"
  "build/examples/examples/$example"
done
echo "== checking the printed numbers against closed forms"
ctest --preset examples
