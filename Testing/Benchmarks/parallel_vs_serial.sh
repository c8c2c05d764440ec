#!/usr/bin/env bash
# Figures for the ParallelTetMesher against serial TetGen through the same
# library call and switches, on a ball meshed to a few million tetrahedra.
# Not a test: it prints wall time, tetrahedra, peak memory and quality.
#
#   bash Testing/Benchmarks/parallel_vs_serial.sh [mesh-size] [ranks] [subdomains]
#
# Needs a build (bash Scripts/test.sh or the manual build in README.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
size=${1:-0.025}
ranks=${2:-2}
subdomains=${3:-$ranks}
out=out/bench
mkdir -p "$out"
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
surface="$out/ball_$size"
if [ ! -f "$surface.stl" ]; then
  # ball.geo sets a 0.12 size; -clscale scales it
  gmsh -2 Data/geo/ball.geo -clscale "$(/usr/bin/python3 -c "print($size / 0.12)")" -format stl -bin -o "$surface.stl" > "$out/gmsh.log"
  /usr/bin/python3 - "$surface" <<'PY'
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1] + ".stl")
points, inverse = np.unique(m.points, axis=0, return_inverse=True)
meshio.write(sys.argv[1] + ".off", meshio.Mesh(points, [("triangle", inverse[m.cells_dict["triangle"]])]))
PY
fi
echo "surface: $surface.stl ($(/usr/bin/python3 -c "import meshio;print(len(meshio.read('$surface.stl').cells_dict['triangle']))") triangles)"

echo "== serial TetGen (one process, same library call and switches)"
/usr/bin/time -f "wall %e s, peak RSS %M KB" build/bin/serial_tetgen "$surface.off" 2>&1 | tee "$out/serial.txt"

echo "== pipeline, $ranks ranks, $subdomains subdomains"
mpiexec -n "$ranks" --oversubscribe /usr/bin/time -f "rank wall %e s, peak RSS %M KB" \
  pvbatch Scripts/tetmesh.py "$surface.stl" -o "$out/ball.pvtu" --subdomains "$subdomains" \
  --json "$out/parallel.json" 2>&1 | grep -E "tetmesh|rank wall" | tee "$out/parallel.txt"
