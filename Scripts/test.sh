#!/usr/bin/env bash
# Builds the plugin and runs the whole test suite (GoogleTest unit tests of
# the core, and pvbatch tests under mpiexec with 1 and 2 ranks).
# Usage: bash Scripts/test.sh            (from a fresh Debian bookworm machine)
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON
cmake --build build -j"$(nproc)"
cd build
ctest --output-on-failure -j"$(nproc)"
