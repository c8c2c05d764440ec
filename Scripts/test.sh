#!/usr/bin/env bash
# Builds the plugin and runs the whole test suite: GoogleTest unit tests of
# the core and pvbatch tests under mpiexec with 1 and 2 ranks, all in CTest.
# Before that, Scripts/sanitize.sh runs the core's unit tests under
# AddressSanitizer + UBSan and a short run of each fuzzer (./build-sanitize).
# Usage (from a fresh Debian bookworm machine): bash Scripts/test.sh
# Exits non-zero if either suite fails; the main CTest summary is the last
# thing printed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh

# The sanitizer suite first, so that its long output does not bury the main
# summary; its failure is remembered, not fatal, so the main suite still runs.
sanitize_status=0
bash Scripts/sanitize.sh || sanitize_status=$?
if [ "$sanitize_status" -ne 0 ]; then
  echo "test.sh: Scripts/sanitize.sh FAILED with status $sanitize_status (see above); running the main suite anyway"
fi

cmake -S . -B build -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
# mpiexec as root (CTest sets these for its MPI tests too)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
status=0
ctest --test-dir build --output-on-failure || status=$?
if [ "$status" -eq 0 ]; then
  status=$sanitize_status
fi
exit "$status"
