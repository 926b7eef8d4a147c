#!/usr/bin/env bash
# Shared by tests/run_tests.sh and parameters/run_comparison.sh: install the
# Debian packages that are missing (needs root or sudo) and build
# nitsche-contact in Release in ./build. Source it from the repository root.
set -euo pipefail

# libopenblas0-serial: an optimised BLAS for the sparse direct solvers (MUMPS
# runs 3-4x faster than on the reference BLAS; doc/benchmarks.md). Debian
# selects it through update-alternatives; the exact-output tests keep the
# reference BLAS (tests/reference_blas.cmake).
packages="cmake g++ make libdeal.ii-dev libmumps-dev numdiff python3 python3-matplotlib openmpi-bin libopenblas0-serial"
missing=""
for p in $packages; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "Installing missing Debian packages:$missing"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

# OpenMPI refuses to run as root unless told otherwise (CI runs as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs"
