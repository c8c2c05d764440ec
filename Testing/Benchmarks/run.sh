#!/usr/bin/env bash
# The benchmark in one command: builds the plugin and serial_tetgen in their
# own tree (build-bench, so it never disturbs build/), then runs bench.py.
#
#   bash Testing/Benchmarks/run.sh            # full run, under 15 minutes on 2 cores
#   bash Testing/Benchmarks/run.sh --quick    # small cases, about 2 minutes
#   bash Testing/Benchmarks/run.sh --largest  # the largest mesh with 2 ranks (2 x 10^7 tetrahedra)
#
# Output: out/bench/bench.json, out/bench/*.png, out/bench/measured.md, the
# tables on stdout. Needs paraview (pvbatch), openmpi, gmsh, tetgen,
# python3-meshio and python3-matplotlib (Scripts/install-deps.sh installs them).
# Set PTM_BENCH_BUILD to use another build tree.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${PTM_BENCH_BUILD:-build-bench}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
# Release build of just what the benchmark runs (a no-op when up to date)
cmake --build "$build" -j2 --target ParallelTetMesher serial_tetgen > "$build/bench-build.log" 2>&1 ||
  { tail -20 "$build/bench-build.log"; exit 1; }
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_rmaps_base_oversubscribe=1
# /usr/bin/python3: Debian's numpy, meshio and matplotlib (not a pyenv python3)
exec /usr/bin/python3 Testing/Benchmarks/bench.py \
  --plugin "$build/lib/paraview-plugins/ParallelTetMesher/ParallelTetMesher.so" \
  --serial-tetgen "$build/bin/serial_tetgen" "$@"
