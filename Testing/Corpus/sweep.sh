#!/usr/bin/env bash
# Run the corpus sweep against an existing build (builds nothing).
#
#   bash Testing/Corpus/sweep.sh --build build [sweep.py options]
#   bash Testing/Corpus/sweep.sh --plugin PATH/ParallelTetMesher.so [sweep.py options]
#
# Needs the corpus (bash Testing/Corpus/fetch.sh) and Debian's tetgen, pvbatch,
# mpiexec, python3-numpy and python3-paraview (VTK's readers). Every option of sweep.py passes
# through: --quick, --surfaces a,b, --ks 2,8, --strategies S, --timeout S,
# --jobs N, --corpus DIR, --out DIR.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
for tool in tetgen pvbatch mpiexec; do
    command -v "$tool" >/dev/null || { echo "sweep.sh: $tool is missing (apt-get install tetgen paraview ...)" >&2; exit 2; }
done
if [ "$(id -u)" = 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# numpy and VTK come from Debian's python3, not from a virtualenv's
exec /usr/bin/python3 "$HERE/sweep.py" "$@"
