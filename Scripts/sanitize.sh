#!/usr/bin/env bash
# Builds the geometry core with AddressSanitizer + UBSan and libFuzzer in
# ./build-sanitize (clang, no plugin) and runs its CTest: every core unit test
# under the sanitizers, then a short run of each fuzzer (Testing/Fuzz).
# Usage: bash Scripts/sanitize.sh   (deps: Scripts/install-deps.sh)
# Exits with CTest's status. Takes about 10 minutes from clean on 2 cores
# (10.5 min in a fresh clone at e5c7390, with the two 2-minute fuzz runs).
set -euo pipefail
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ cmake -S . -B build-sanitize \
  -DPTM_BUILD_PLUGIN=OFF -DPTM_SANITIZE=ON -DPTM_BUILD_FUZZERS=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build-sanitize -j2
status=0
ctest --test-dir build-sanitize --output-on-failure -j2 || status=$?
exit "$status"
