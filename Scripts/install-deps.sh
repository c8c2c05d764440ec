#!/usr/bin/env bash
# Installs every Debian bookworm package the build, the tests and the demo need.
# Idempotent: when everything is already present it returns in about a second.
set -euo pipefail

PACKAGES=(
  # build
  cmake g++ make ninja-build pkg-config git
  # ParaView with its development files (bundled VTK 9.2) and the Python side
  paraview paraview-dev python3-paraview python3-numpy
  # the libraries ParaView's CMake config insists on finding
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
  libdouble-conversion-dev liblz4-dev libutfcpp-dev libhdf5-openmpi-dev
  libnetcdf-dev libexpat1-dev libjsoncpp-dev libpugixml-dev libglew-dev
  libfreetype-dev libtiff-dev libjpeg-dev libxml2-dev libogg-dev libtheora-dev
  libgl2ps-dev libprotobuf-dev protobuf-compiler libfmt-dev nlohmann-json3-dev
  # geometry and meshing
  libtet1.5-dev libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev
  # MPI
  libopenmpi-dev openmpi-bin
  # tests; clang for libFuzzer and the sanitizer build; Xvfb for the GUI screenshot
  libgtest-dev clang libclang-rt-14-dev xvfb xauth
  # comparison peers and test geometry
  gmsh tetgen python3-meshio python3-matplotlib time
  # the FEM solver on the pieces (Scripts/solve_elasticity.py): dolfinx 0.5 (FEniCSx:
  # UFL, FFCx's JIT with gcc) on PETSc with MUMPS and GAMG
  python3-dolfinx python3-petsc4py python3-mpi4py
  # CAD input (STEP, IGES, BREP) through OpenCASCADE 7.6, and its sample
  # files (occt-misc: /usr/share/opencascade/data), which the CAD tests read
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev occt-misc
  # OCCT's CMake targets name libtbb.so (TKernel is built with TBB)
  libtbb-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "install-deps: done"
