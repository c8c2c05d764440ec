#!/usr/bin/env bash
# The main job on the bundled default surface: meshes Data/bracket.stl (a
# CAD-like part: a plate with a boss, a through hole, a slot and a rib) with
# 2 MPI ranks and writes out/bracket.pvtu (+ out/bracket_boundary.pvtp and
# the summary out/bracket.json). Extra arguments go to Scripts/tetmesh.py,
# e.g. --subdomains 8. Usage: bash Scripts/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source Scripts/prepare.sh # packages, the plugin's build, mpiexec's environment
mpiexec -n 2 --oversubscribe pvbatch Scripts/tetmesh.py Data/bracket.stl \
  -o out/bracket.pvtu --json out/bracket.json "$@"
