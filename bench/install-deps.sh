#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs the Debian packages the benchmarks need, only those that are missing: scripts/bench.sh's (g++,
# valgrind, Boost, GSL; scripts/install-deps.sh test installs those too) and SUNDIALS for the ARKODE variants
# (bench/sundials.hpp). libsundials-dev pulls in OpenMPI, PETSc, hypre and gfortran (140 new packages on the
# Debian 12 image the figures come from), which is why scripts/install-deps.sh's test profile leaves it out;
# the cases build without it (their ARKODE variants are left out). Usage: bench/install-deps.sh
set -euo pipefail
exec "$(dirname "$0")/../scripts/install-deps.sh" bench
