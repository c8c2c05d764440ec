#!/usr/bin/env bash
# The paper's elastic ball, meshed and solved on 2 MPI ranks: Data/ball.stl is
# meshed into K = 4 subdomains (out/ball.pvtu, one piece per rank), then each
# rank hands its own piece only to dolfinx (cells kept in place) and solves
# linear elasticity on it (UFL, PETSc CG + GAMG):
# points below zmin + 0.1 R held, a downward traction of 1 per unit area on the
# boundary triangles above zmax - 0.5 R, E = 1000, nu = 0.3. Prints the applied
# load and the support reaction, writes out/ball_solution.pvtu (displacement,
# von Mises stress) and out/ball_solution.png (pvbatch render in Xvfb).
# Usage: bash Scripts/solve_demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source Scripts/prepare.sh # packages, the plugin's build, mpiexec's environment
mpiexec -n 2 --oversubscribe pvbatch Scripts/tetmesh.py Data/ball.stl \
  -o out/ball.pvtu --subdomains 4 --size 0.1
# the solver runs in the system Python, where dolfinx and petsc4py live
mpiexec -n 2 --oversubscribe /usr/bin/python3 Scripts/solve_elasticity.py out/ball.pvtu \
  --E 1000 --nu 0.3 --fix-below 0.1 --traction-above 0.5 --traction 0,0,-1 \
  --check-equilibrium 1e-8 -o out/ball_solution.pvtu --json out/ball_solution.json
xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch Scripts/render_solution.py \
  out/ball_solution.pvtu out/ball_solution.png
