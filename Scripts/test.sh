#!/usr/bin/env bash
# Builds the plugin and runs the whole test suite: GoogleTest unit tests of
# the core and pvbatch tests under mpiexec with 1 and 2 ranks, all in CTest.
# Usage (from a fresh Debian bookworm machine): bash Scripts/test.sh
# Exits with CTest's status; CTest's summary is the last thing printed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh
cmake -S . -B build -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
# mpiexec as root (CTest sets these for its MPI tests too)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
status=0
ctest --test-dir build --output-on-failure || status=$?
exit "$status"
