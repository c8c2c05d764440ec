# Sourced by the demo scripts (demo.sh, solve_demo.sh) from the project's
# root: installs the packages, builds the plugin into build/, lets mpiexec
# run as root and run 2 ranks even on a 1-core machine, and makes out/.
bash Scripts/install-deps.sh
cmake -S . -B build -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j2 --target ParallelTetMesher
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p out
