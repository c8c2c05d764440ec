#!/usr/bin/env bash
# The main job on the bundled default surface: meshes Data/bracket.stl (a
# CAD-like part: a plate with a boss, a through hole, a slot and a rib) with
# 2 MPI ranks and writes out/bracket.pvtu (+ out/bracket_boundary.pvtp and
# the summary out/bracket.json). Extra arguments go to Scripts/tetmesh.py,
# e.g. --subdomains 8. Usage: bash Scripts/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh
cmake -S . -B build -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j2 --target ParallelTetMesher
# mpiexec as root, and 2 ranks even on a 1-core machine
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p out
mpiexec -n 2 --oversubscribe pvbatch Scripts/tetmesh.py Data/bracket.stl \
  -o out/bracket.pvtu --json out/bracket.json "$@"
