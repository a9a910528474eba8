#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs the Debian packages the benchmarks need, only those that are missing: scripts/bench.sh's (g++,
# valgrind, Boost, GSL; scripts/install-deps.sh test installs those too) and SUNDIALS for the ARKODE variants
# of the stiff cases (bench/stiff_*.cpp, bench/sundials.hpp). libsundials-dev pulls in OpenMPI, PETSc, hypre
# and gfortran (140 new packages on the Debian 12 image the figures come from), which is why it is installed
# here and not by scripts/install-deps.sh's test profile; the stiff cases build without it (their ARKODE
# variants are left out). Usage: bench/install-deps.sh
set -euo pipefail
packages=(g++ valgrind libboost-dev libgsl-dev libsundials-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
