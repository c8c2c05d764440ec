#!/usr/bin/env bash
# The dirty corpus (open, non-manifold, self-intersecting real models kept
# apart by fetch.sh in OUT/dirty) through the pipeline on 2 ranks, K = 4:
# first as they are, which must end in a refusal that names the problem and
# the wrap; then with --wrap, checked by conformity.py against the wrapped
# surface. Prints one table row per model. Not CI (minutes).
#
#   bash Testing/Corpus/wrap_sweep.sh --build build [--corpus out/corpus] [--out out/wrap-sweep]
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD=build CORPUS=out/corpus OUT=out/wrap-sweep
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD="$2"; shift 2 ;;
    --corpus) CORPUS="$2"; shift 2 ;;
    --out) OUT="$2"; shift 2 ;;
    *) echo "wrap_sweep.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
PLUGIN="$BUILD/lib/paraview-plugins/ParallelTetMesher/ParallelTetMesher.so"
[ -f "$PLUGIN" ] || { echo "wrap_sweep.sh: no plugin at $PLUGIN (build first)" >&2; exit 2; }
[ -d "$CORPUS/dirty" ] || { echo "wrap_sweep.sh: no $CORPUS/dirty (bash Testing/Corpus/fetch.sh)" >&2; exit 2; }
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p "$OUT"
echo "| model | without --wrap | with --wrap | tetrahedra | conforming | wrap -> input, input -> wrap (of the diagonal) | seconds |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for surface in "$CORPUS"/dirty/*.off; do
  name=$(basename "$surface" .off)
  dir="$OUT/$name"; mkdir -p "$dir"
  timeout 300 mpiexec -n 2 pvbatch "$ROOT/Scripts/tetmesh.py" "$surface" -o "$dir/plain.pvtu" \
    --subdomains 4 --plugin "$PLUGIN" > "$dir/plain.log" 2>&1
  plain_status=$?
  refusal=$(grep -o "tetmesh: error: .*" "$dir/plain.log" | head -1 | cut -c1-90)
  if [ $plain_status -eq 0 ]; then plain="meshed"; elif grep -q -- "--wrap" "$dir/plain.log"; then plain="refused, names the wrap"; else plain="failed: $refusal"; fi
  start=$(date +%s.%N)
  timeout 600 mpiexec -n 2 pvbatch "$ROOT/Scripts/tetmesh.py" "$surface" -o "$dir/wrapped.pvtu" \
    --subdomains 4 --wrap --save-surface "$dir/wrapped.off" --json "$dir/wrapped.json" \
    --plugin "$PLUGIN" > "$dir/wrapped.log" 2>&1
  status=$?
  seconds=$(echo "$(date +%s.%N) - $start" | bc)
  if [ $status -ne 0 ]; then
    echo "| $name | $plain | **failed** ($(grep -o 'tetmesh: error: .*' "$dir/wrapped.log" | head -1 | cut -c1-80)) | - | - | - | $seconds |"
    continue
  fi
  /usr/bin/python3 - "$dir" "$seconds" "$name" "$plain" "$ROOT" <<'PY'
import json, sys
import numpy as np
d, seconds, name, plain, root = sys.argv[1:6]
sys.path.insert(0, root + "/Testing/Corpus")
import conformity
import surface_tool
stats = surface_tool.stats(d + "/wrapped.off")
r = conformity.check(d + "/wrapped.pvtu", stats)
w = json.load(open(d + "/wrapped.json")).get("wrap", {})
points = np.loadtxt(d + "/wrapped.off", skiprows=2, max_rows=int(open(d + "/wrapped.off").readlines()[1].split()[0]))
diag = float(np.linalg.norm(points.max(0) - points.min(0)))
def rel(x):
    return "%.2g" % (x / diag) if x is not None else "-"
print("| %s | %s | meshed | %d | %s (volume error %.1e) | %s, %s | %.1f |" % (
    name, plain, r["tetrahedra"], "yes" if r["conforming"] else "**no**: " + "; ".join(r["problems"])[:80],
    r["volume_error"], rel(w.get("largest_distance_wrap_to_input")), rel(w.get("largest_distance_input_to_wrap")),
    float(seconds)))
PY
done
