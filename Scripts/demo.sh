#!/usr/bin/env bash
# Meshes the bundled default surface (Data/bracket.stl, a CAD-like part) with
# 2 MPI ranks and writes out/bracket.pvtu (+ out/bracket_boundary.pvtp and a
# JSON summary). Extra arguments go to Scripts/tetmesh.py, e.g. --subdomains 8.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON > /dev/null
cmake --build build -j"$(nproc)" --target ParallelTetMesher
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
mkdir -p out
mpiexec -n 2 --oversubscribe pvbatch Scripts/tetmesh.py Data/bracket.stl \
  -o out/bracket.pvtu --json out/bracket.json "$@"
