"""The exact test of the FEM solver on the mesher's pieces (issue #20).

A closed elastic body under uniform pressure p deforms as u = -p(1-2nu)/E x
(plus a rigid motion, removed by the solver's three pinned points), and linear
tetrahedra reproduce it exactly. For the ball and the bracket: mesh with RANKS
ranks into more subdomains than ranks, solve on the same ranks, then check
independently of the solver, from the written .pvtu pieces, that
  - every rank's solution piece holds exactly the mesher's tetrahedra (no repartitioning),
    and the solver reports that dolfinx's mesh has exactly those cells on that rank
    and shares the points between ranks (ghost vertices = the pieces' copies),
  - max|u - u_exact| / max|u_exact| <= 1e-8,
  - the check can fail: a solve with E 1% off is 1e-2 away from the exact field.
With RANKS = 2 it also checks that solving a 2-piece mesh on 1 rank fails with
a message. Run it with the system Python (it starts mpiexec itself):

  /usr/bin/python3 Testing/Python/test_fem_exact.py RANKS PLUGIN DATA_DIR OUT_DIR
"""
import json
import os
import subprocess
import sys

import numpy as np

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "Scripts"))
import ptm_pieces  # noqa: E402

MPIEXEC = os.environ.get("PTM_MPIEXEC", "mpiexec")
PVBATCH = os.environ.get("PTM_PVBATCH", "pvbatch")
SOLVER = os.path.join(REPO, "Scripts", "solve_elasticity.py")
NU, P, TOL = 0.3, 1.0, 1e-8


def run(cmd, expect_ok=True):
    print("+ " + " ".join(cmd), flush=True)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=240)
    sys.stdout.write(r.stdout[-3000:])
    sys.stderr.write(r.stderr[-3000:])
    if expect_ok and r.returncode != 0:
        raise SystemExit(f"FAILED (exit {r.returncode}): {' '.join(cmd)}")
    return r


def mesh(ranks, plugin, surface, out, subdomains, size):
    run([MPIEXEC, "-n", str(ranks), "--oversubscribe", PVBATCH, "--force-offscreen-rendering",
         os.path.join(REPO, "Scripts", "tetmesh.py"), surface, "-o", out,
         "--subdomains", str(subdomains), "--size", str(size), "--plugin", plugin])


def solve(ranks, mesh_file, out, E, extra=(), expect_ok=True):
    return run([MPIEXEC, "-n", str(ranks), "--oversubscribe", sys.executable, SOLVER, mesh_file,
                "--pressure", str(P), "--E", str(E), "--nu", str(NU), "-o", out,
                "--json", out[:-5] + ".json", *extra], expect_ok)


def exact_error(solution, E):
    """max|u - u_exact| / max|u_exact| over all pieces, from the files."""
    num, den = 0.0, 0.0
    for src in ptm_pieces.piece_sources(solution):
        piece = ptm_pieces.read_piece(src)
        ex = -P * (1 - 2 * NU) / E * piece["points"]
        num = max(num, np.abs(piece["point_data"]["Displacement"] - ex).max())
        den = max(den, np.abs(ex).max())
    return num / den


def same_tetrahedra(mesh_file, solution):
    for m, s in zip(ptm_pieces.piece_sources(mesh_file), ptm_pieces.piece_sources(solution)):
        a, b = ptm_pieces.read_piece(m), ptm_pieces.read_piece(s)
        if not np.array_equal(a["cell_data"]["GlobalCellIds"], b["cell_data"]["GlobalCellIds"]):
            raise SystemExit(f"FAILED: {s} does not hold exactly the tetrahedra of {m}")


def engine_kept_pieces(name, summary):
    """The solver's own report of dolfinx's mesh: every rank's cells are its
    piece's tetrahedra (none moved, no ghost cells), the shared points are
    shared vertices (the global vertex count is the mesh's point count, and
    the ghost vertices are as many as the pieces' copies of other ranks'
    points)."""
    ranks = summary["per_rank"]
    for r, pr in enumerate(ranks):
        d = pr["dolfinx"]
        if d["cells"] != pr["tetrahedra"] or d["ghost_cells"] != 0:
            raise SystemExit(f"FAILED: {name}: rank {r} has {d['cells']} cells (+{d['ghost_cells']} "
                             f"ghosts) in dolfinx, {pr['tetrahedra']} tetrahedra in its piece")
        if d["global_vertices"] != summary["points"]:
            raise SystemExit(f"FAILED: {name}: dolfinx has {d['global_vertices']} vertices, "
                             f"the mesh {summary['points']} points")
    ghosts = sum(pr["dolfinx"]["ghost_vertices"] for pr in ranks)
    copies = sum(pr["copies_of_other_ranks_points"] for pr in ranks)
    if ghosts != copies or (len(ranks) > 1 and ghosts == 0):
        raise SystemExit(f"FAILED: {name}: {ghosts} ghost vertices in dolfinx, {copies} shared copies in the pieces")
    print(f"{name}: {summary['engine']} kept the cells per rank {[pr['tetrahedra'] for pr in ranks]}, "
          f"ghost vertices {[pr['dolfinx']['ghost_vertices'] for pr in ranks]}")


def check_surface(ranks, plugin, surface, out, size, wrong_E):
    name = os.path.splitext(os.path.basename(surface))[0]
    mesh_file = os.path.join(out, f"{name}.pvtu")
    solution = os.path.join(out, f"{name}_pressure.pvtu")
    mesh(ranks, plugin, surface, mesh_file, 2 * ranks + 2, size)
    solve(ranks, mesh_file, solution, 1.0, ["--check-exact", str(TOL)])
    same_tetrahedra(mesh_file, solution)
    err = exact_error(solution, 1.0)
    err_wrong_formula = exact_error(solution, 1.01)
    summary = json.load(open(solution[:-5] + ".json"))
    engine_kept_pieces(name, summary)
    print(f"{name} on {ranks} ranks: exact error {err:.3e} (solver says "
          f"{summary['exact_relative_error']:.3e}); against E = 1.01: {err_wrong_formula:.3e}")
    if not err <= TOL:
        raise SystemExit(f"FAILED: {name}: error {err:.3e} > {TOL}")
    if not err_wrong_formula > 1e-3:
        raise SystemExit(f"FAILED: {name}: the check does not tell E = 1 from E = 1.01")
    if wrong_E:
        bad = os.path.join(out, f"{name}_wrongE.pvtu")
        solve(ranks, mesh_file, bad, 1.01)
        e = exact_error(bad, 1.0)
        print(f"{name}: a solve with E = 1.01 is {e:.3e} from the E = 1 field")
        if not e > 1e-3:
            raise SystemExit("FAILED: a wrong Young's modulus passes the exact check")
    return mesh_file


def main():
    ranks, plugin, data, out = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
    os.makedirs(out, exist_ok=True)
    ball = check_surface(ranks, plugin, os.path.join(data, "ball.stl"), out, 0.15, wrong_E=True)
    check_surface(ranks, plugin, os.path.join(data, "bracket.stl"), out, 0.0, wrong_E=False)
    if ranks >= 2:
        r = solve(ranks - 1, ball, os.path.join(out, "mismatch.pvtu"), 1.0, expect_ok=False)
        if r.returncode == 0 or "pieces" not in r.stderr:
            raise SystemExit("FAILED: solving on fewer ranks than pieces did not fail with a message")
        print("rank-count mismatch refused:", r.stderr.strip().splitlines()[0])
    print("fem exact test passed")


if __name__ == "__main__":
    main()
