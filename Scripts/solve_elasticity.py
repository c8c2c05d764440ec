#!/usr/bin/python3
"""Linear elasticity with PETSc (petsc4py, MUMPS or CG+GAMG) on the mesher's pieces,
in place: rank r reads only piece r of the .pvtu (and of *_boundary.pvtp) and
keeps exactly those tetrahedra.

  mpiexec -n P /usr/bin/python3 Scripts/solve_elasticity.py out/ball.pvtu \
      --pressure 1 --check-exact 1e-8                  # the exact test
  mpiexec -n P /usr/bin/python3 Scripts/solve_elasticity.py out/ball.pvtu \
      --fix-below 0.1 --traction-above 0.5 --traction 0,0,-1 -o out/ball_solution.pvtu

Boundary conditions: loads act on the mesher's boundary triangles (port 1), chosen
by SourceFaceId (--traction-faces) or by height (--traction-above); supports
are points chosen by height (--fix-below) or by SourceFaceId (--fix-faces).
With --pressure and no support the six rigid motions are removed by pinning
three points picked by global id (see pin_points), so the result does not
depend on the rank count.
"""
import argparse
import json
import os
import sys
import time

import numpy as np
from mpi4py import MPI

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import ptm_pieces  # noqa: E402


class SolveError(RuntimeError):
    pass


def collective(comm, what, fn, *args):
    """Runs a rank-local step; if it fails on any rank, every rank raises the
    same message, so no rank goes on into a collective call alone."""
    result, err = None, None
    try:
        result = fn(*args)
    except (ptm_pieces.PieceError, SolveError, ValueError, KeyError) as e:
        err = f"{what}: {e}"
    by_message = {}
    for r, e in enumerate(comm.allgather(err)):
        if e:
            by_message.setdefault(e, []).append(str(r))
    if by_message:
        raise SolveError("; ".join(f"rank{'s' if len(r) > 1 else ''} {','.join(r)}: {e}"
                                   for e, r in by_message.items()))
    return result


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mesh", help="the mesher's .pvtu (its *_boundary.pvtp must lie beside it)")
    p.add_argument("-o", "--output", help="write displacement and von Mises stress as .pvtu")
    p.add_argument("--json", help="write the summary (errors, forces, times, bytes) as JSON")
    p.add_argument("--E", type=float, default=1.0, help="Young's modulus (default 1)")
    p.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio (default 0.3)")
    p.add_argument("--pressure", type=float, default=0.0,
                   help="uniform pressure on the whole boundary (the exact test)")
    p.add_argument("--traction", default="0,0,0", help="traction vector tx,ty,tz per unit area")
    p.add_argument("--traction-above", type=float, default=None, metavar="F",
                   help="traction on boundary triangles whose centroid has z > zmax - F*R (R: half height)")
    p.add_argument("--traction-faces", default=None, metavar="IDS",
                   help="traction on boundary triangles with these SourceFaceIds, e.g. 3,7-12")
    p.add_argument("--fix-below", type=float, default=None, metavar="F",
                   help="fix points with z < zmin + F*R (R: half height)")
    p.add_argument("--fix-faces", default=None, metavar="IDS",
                   help="fix the points of boundary triangles with these SourceFaceIds")
    p.add_argument("--solver", choices=["lu", "cg"], default="cg",
                   help="cg: CG + GAMG with the rigid modes (default); lu: MUMPS direct")
    p.add_argument("--rtol", type=float, default=1e-12, help="cg relative tolerance")
    p.add_argument("--check-exact", type=float, default=None, metavar="TOL",
                   help="with --pressure: fail if max|u - u_exact|/max|u_exact| > TOL")
    p.add_argument("--check-equilibrium", type=float, default=None, metavar="TOL",
                   help="fail if |reaction + load| / |load| > TOL")
    a = p.parse_args(argv)
    try:
        a.traction = np.array([float(t) for t in a.traction.split(",")])
        assert a.traction.shape == (3,)
    except (ValueError, AssertionError):
        p.error(f"--traction must be three numbers tx,ty,tz, got '{a.traction}'")
    if not (a.E > 0 and -1 < a.nu < 0.5):
        p.error(f"need E > 0 and -1 < nu < 0.5, got E={a.E} nu={a.nu}")
    a.traction_faces = parse_ids(p, a.traction_faces, "--traction-faces")
    a.fix_faces = parse_ids(p, a.fix_faces, "--fix-faces")
    has_load = a.pressure != 0 or a.traction_above is not None or a.traction_faces is not None
    if not has_load:
        p.error("no load: give --pressure, or --traction with --traction-above/--traction-faces")
    if a.check_exact is not None and (a.pressure == 0 or a.fix_below is not None
                                      or a.fix_faces is not None or np.any(a.traction)):
        p.error("--check-exact needs --pressure alone (no supports, no traction)")
    return a


def parse_ids(p, text, flag):
    if text is None:
        return None
    ids = []
    try:
        for part in text.split(","):
            lo, _, hi = part.partition("-")
            ids.extend(range(int(lo), int(hi or lo) + 1))
    except ValueError:
        p.error(f"{flag}: expected ids like 3,7-12, got '{text}'")
    return np.array(ids, dtype=np.int64)


# ---------------------------------------------------------------- reading

def read_own_pieces(mesh_file, rank, size):
    """Rank r reads the two small index files and its own two pieces only."""
    if not mesh_file.endswith(".pvtu"):
        raise SolveError(f"{mesh_file}: expected the mesher's .pvtu")
    boundary_file = mesh_file[:-len(".pvtu")] + "_boundary.pvtp"
    sources = ptm_pieces.piece_sources(mesh_file)
    bsources = ptm_pieces.piece_sources(boundary_file)
    if len(sources) != size or len(bsources) != size:
        raise SolveError(f"{mesh_file} has {len(sources)} pieces and {boundary_file} "
                         f"{len(bsources)}, but {size} ranks run: mesh with "
                         f"`mpiexec -n {size}` or solve with `mpiexec -n {len(sources)}`")
    vol = ptm_pieces.read_piece(sources[rank])
    bnd = ptm_pieces.read_piece(bsources[rank])
    tets = ptm_pieces.fixed_size_cells(vol, 4, "volume cells", sources[rank])
    if vol["types"] is not None and np.any(vol["types"] != ptm_pieces.VTK_TETRA):
        raise SolveError(f"{sources[rank]}: cells other than linear tetrahedra")
    tris = ptm_pieces.fixed_size_cells(bnd, 3, "boundary polygons", bsources[rank])
    for name in ("GlobalPointIds", "vtkGhostType"):
        if name not in vol["point_data"]:
            raise SolveError(f"{sources[rank]}: no point array {name} (not the mesher's output?)")
    if "GlobalPointIds" not in bnd["point_data"] or "SourceFaceId" not in bnd["cell_data"]:
        raise SolveError(f"{bsources[rank]}: no GlobalPointIds/SourceFaceId")
    nbytes = sum(os.path.getsize(f) for f in (mesh_file, boundary_file)) \
        + vol["bytes"] + bnd["bytes"]
    meshing = vol["field_data"].get("RankMeshingSeconds", np.array([np.nan]))
    return {
        "x": vol["points"], "tets": tets,
        "gid": vol["point_data"]["GlobalPointIds"].astype(np.int64),
        "ghost": vol["point_data"]["vtkGhostType"].astype(np.uint8),
        "cell_data": vol["cell_data"],
        "bx": bnd["points"], "btris": tris,
        "bgid": bnd["point_data"]["GlobalPointIds"].astype(np.int64),
        "bface": bnd["cell_data"]["SourceFaceId"].astype(np.int64),
        "file_bytes": nbytes, "meshing_seconds": float(meshing.ravel()[0]),
    }


# ---------------------------------------------------------------- numbering

def exchange(comm, send_lists):
    """Alltoallv of int64 arrays (one per destination); returns the received
    arrays (one per source) and the bytes received."""
    size = comm.Get_size()
    counts = np.array([len(s) for s in send_lists], dtype=np.int64)
    rcounts = np.array(comm.alltoall(counts.tolist()), dtype=np.int64)
    sbuf = np.concatenate(send_lists).astype(np.int64) if counts.sum() else np.zeros(0, np.int64)
    rbuf = np.empty(rcounts.sum(), dtype=np.int64)
    comm.Alltoallv([sbuf, counts, np.r_[0, np.cumsum(counts)[:-1]], MPI.INT64_T],
                   [rbuf, rcounts, np.r_[0, np.cumsum(rcounts)[:-1]], MPI.INT64_T])
    splits = np.cumsum(rcounts)[:-1]
    return np.split(rbuf, splits) if size > 1 else [rbuf], int(rbuf.nbytes + 8 * size)


def contiguous_numbering(comm, piece):
    """New vertex numbers, contiguous per owning rank (PETSc's rows of
    rank r are one contiguous block). Owned points (vtkGhostType 0) are numbered in GlobalPointIds
    order after the prefix sum of the owned counts; a copy learns its number
    through a directory rank (gid mod P), since a rank does not know which
    other rank owns its copies."""
    rank, size = comm.Get_rank(), comm.Get_size()
    gid, owned = piece["gid"], (piece["ghost"] & 1) == 0
    own_idx = np.flatnonzero(owned)[np.argsort(gid[owned], kind="stable")]
    offset = comm.exscan(len(own_idx)) or 0
    new = np.full(len(gid), -1, dtype=np.int64)
    new[own_idx] = offset + np.arange(len(own_idx))
    copy_idx = np.flatnonzero(~owned)
    # one message per directory rank: [n_owned, owned (gid,new) pairs..., queried gids...]
    sends = []
    for d in range(size):
        o = own_idx[gid[own_idx] % size == d]
        q = copy_idx[gid[copy_idx] % size == d]
        sends.append(np.concatenate([[len(o)], np.column_stack([gid[o], new[o]]).ravel(), gid[q]]))
    received, nbytes = exchange(comm, sends)
    replies, err = directory_answers(received, size)
    answers, nbytes2 = exchange(comm, replies)
    err = comm.allreduce(err, op=MPI.MAX)
    if err:
        raise SolveError("numbering: a point is owned by two ranks or a copy has no owner "
                         "(vtkGhostType/GlobalPointIds inconsistent across the pieces)")
    for d in range(size):
        q = copy_idx[gid[copy_idx] % size == d]
        new[q] = answers[d]
    return new, len(own_idx), offset, nbytes + nbytes2


def directory_answers(received, size):
    """The directory rank's side: collects the owners' (gid, new) pairs and
    answers the copies' queries in the order asked; -1 and an error flag for
    a gid that has no owner or two."""
    pairs = np.concatenate([m[1:1 + 2 * m[0]] for m in received]).reshape(-1, 2)
    order = np.argsort(pairs[:, 0], kind="stable")
    keys, values = pairs[order, 0], pairs[order, 1]
    err = int(len(keys) > 1 and np.any(keys[1:] == keys[:-1]))
    replies = []
    for m in received:
        q = m[1 + 2 * m[0]:]
        pos = np.clip(np.searchsorted(keys, q), 0, max(len(keys) - 1, 0))
        ok = (len(keys) > 0) & (keys[pos] == q) if len(keys) else np.zeros(len(q), bool)
        err |= int(not np.all(ok))
        replies.append(np.where(ok, values[pos] if len(keys) else -1, -1))
    return replies, err


# ---------------------------------------------------------------- PETSc assembly

def element_stiffness(x, tets, E, nu):
    """P1 elasticity element matrices (m, 12, 12), dofs ordered (vertex,
    component): K[a i, b j] = V (lambda g_a,i g_b,j + mu g_a,j g_b,i
    + mu delta_ij g_a.g_b), g the constant barycentric gradients."""
    d = x[tets[:, 1:]] - x[tets[:, :1]]                       # edges as rows
    vol = np.abs(np.linalg.det(d)) / 6.0
    if np.any(vol <= 0):
        raise SolveError(f"{int(np.sum(vol <= 0))} tetrahedra of zero volume")
    g = np.empty((len(tets), 4, 3))
    g[:, 1:] = np.transpose(np.linalg.inv(d), (0, 2, 1))      # grad of xi_i = column i of D^-1
    g[:, 0] = -g[:, 1:].sum(axis=1)
    mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
    k = lmbda * np.einsum("kai,kbj->kaibj", g, g) + mu * np.einsum("kaj,kbi->kaibj", g, g)
    k += mu * np.einsum("kac,kbc->kab", g, g)[:, :, None, :, None] * np.eye(3)[None, None, :, None, :]
    return (vol[:, None, None, None, None] * k).reshape(-1, 12, 12)


def preallocation(piece, new, n_owned, offset):
    """Nonzeros per owned scalar row (diagonal and off-diagonal block) from
    the vertex graph of this rank's tetrahedra, doubled on vertices of the
    piece's surface, where other ranks may add columns; a low guess only
    costs PETSc a reallocation (allowed below)."""
    t = new[piece["tets"]]
    pairs = np.concatenate([t[:, [i, j]] for i in range(4) for j in range(4)])
    pairs = np.unique(pairs, axis=0)
    mine = (pairs[:, 0] >= offset) & (pairs[:, 0] < offset + n_owned)
    pairs = pairs[mine]
    row = pairs[:, 0] - offset
    diag = (pairs[:, 1] >= offset) & (pairs[:, 1] < offset + n_owned)
    d = np.bincount(row[diag], minlength=n_owned)
    o = np.bincount(row[~diag], minlength=n_owned)
    faces = np.sort(np.concatenate([t[:, [0, 1, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 3]], t[:, [1, 2, 3]]]), axis=1)
    uf, count = np.unique(faces, axis=0, return_counts=True)
    surf = np.unique(uf[count == 1])
    surf = surf[(surf >= offset) & (surf < offset + n_owned)] - offset
    d[surf] *= 2
    o[surf] = 2 * o[surf] + 8
    return np.repeat(np.minimum(3 * d, 3 * n_owned), 3).astype(np.int32), np.repeat(3 * o, 3).astype(np.int32)


def assemble_stiffness(comm, piece, new, n_owned, E, nu):
    """The global stiffness matrix, rows of the points this rank owns;
    each rank adds its own tetrahedra only (PETSc sends the entries of
    interface rows to their owners in assemble())."""
    from petsc4py import PETSc
    offset = comm.exscan(n_owned) or 0
    d_nnz, o_nnz = preallocation(piece, new, n_owned, offset)
    A = PETSc.Mat().createAIJ(((3 * n_owned, PETSc.DETERMINE), (3 * n_owned, PETSc.DETERMINE)),
                              bsize=3, nnz=(d_nnz, o_nnz), comm=comm)
    A.setOption(PETSc.Mat.Option.NEW_NONZERO_ALLOCATION_ERR, False)
    ke = collective(comm, "element matrices", element_stiffness, piece["x"], piece["tets"], E, nu)
    dofs = (3 * new[piece["tets"]][:, :, None] + np.arange(3)).reshape(-1, 12).astype(PETSc.IntType)
    for k in range(len(dofs)):
        A.setValues(dofs[k], dofs[k], ke[k], addv=PETSc.InsertMode.ADD_VALUES)
    A.assemble()
    return A


def owned_coordinates(comm, piece, new, n_owned):
    offset = comm.exscan(n_owned) or 0
    owned = (piece["ghost"] & 1) == 0
    x = np.empty((n_owned, 3))
    x[new[owned] - offset] = piece["x"][owned]
    return x


def gather_piece_values(u, rows):
    """The solution at every point of the piece, copies included (a PETSc
    scatter from the distributed vector)."""
    from petsc4py import PETSc
    local = PETSc.Vec().createSeq(len(rows), comm=PETSc.COMM_SELF)
    iset = PETSc.IS().createGeneral(rows.astype(PETSc.IntType), comm=PETSc.COMM_SELF)
    scatter = PETSc.Scatter().create(u, iset, local, None)
    scatter.scatter(u, local, addv=PETSc.InsertMode.INSERT_VALUES, mode=PETSc.ScatterMode.FORWARD)
    return local.getArray().copy()


# ---------------------------------------------------------------- loads and supports

def global_bounds(comm, x):
    lo = x.min(axis=0) if len(x) else np.full(3, np.inf)
    hi = x.max(axis=0) if len(x) else np.full(3, -np.inf)
    comm.Allreduce(MPI.IN_PLACE, lo, op=MPI.MIN)
    comm.Allreduce(MPI.IN_PLACE, hi, op=MPI.MAX)
    return lo, hi


def boundary_to_piece(piece):
    """Piece point index of every boundary triangle vertex: the boundary
    piece of rank r only has faces of rank r's tetrahedra."""
    order = np.argsort(piece["gid"])
    pos = np.clip(np.searchsorted(piece["gid"][order], piece["bgid"]), 0, len(order) - 1)
    if len(order) == 0 or not np.array_equal(piece["gid"][order][pos], piece["bgid"]):
        raise SolveError("a boundary triangle has a point that is not in this rank's volume piece")
    return order[pos][piece["btris"]]


def boundary_loads(args, piece, btri, lo, hi):
    """Consistent P1 nodal forces of a constant pressure / traction on each
    selected boundary triangle: a third of (traction x area) per vertex.
    Returns (piece point index, force) rows and the selected area."""
    p = piece["x"][btri]
    area_vec = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area = np.linalg.norm(area_vec, axis=1)
    force = -args.pressure * area_vec
    select = np.zeros(len(btri), dtype=bool)
    if args.traction_faces is not None:
        select |= np.isin(piece["bface"], args.traction_faces)
    if args.traction_above is not None:
        half = 0.5 * (hi[2] - lo[2])
        select |= p[:, :, 2].mean(axis=1) > hi[2] - args.traction_above * half
    force = force + select[:, None] * args.traction[None, :] * area[:, None]
    pts = btri.ravel()
    return pts, np.repeat(force / 3.0, 3, axis=0), float(area[select].sum())


def outward_check(comm, piece, btri):
    """Σ centroid·(area normal) over the boundary is 3·volume only if every
    boundary triangle faces outwards; a pressure load depends on it."""
    p = piece["x"][btri]
    flux = np.einsum("ij,ij->", p.mean(axis=1), 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]))
    t = piece["x"][piece["tets"]]
    vol = np.abs(np.linalg.det(t[:, 1:] - t[:, :1])).sum() / 6.0
    flux, vol = comm.allreduce(flux), comm.allreduce(vol)
    if abs(flux / 3.0 - vol) > 1e-8 * vol:
        raise SolveError(f"boundary triangles are not all outward: flux/3 = {flux / 3:.12g} "
                         f"but the tetrahedra's volume is {vol:.12g}")
    return vol


def argmax_global(comm, score, gid, x):
    """The point with the largest score over all ranks, ties to the lowest
    global id: the same point whatever the rank count."""
    if len(score):
        i = np.lexsort((gid, -score))[0]
        cand = (float(score[i]), -int(gid[i]), x[i].tolist())
    else:
        cand = (-np.inf, -sys.maxsize, [0.0, 0.0, 0.0])
    best = max(comm.allgather(cand))
    return -best[1], np.array(best[2])


def pin_points(comm, piece):
    """Three points and components that remove the six rigid motions:
    A = global id 0 (3 components); B = farthest from A (the 2 components
    other than B-A's largest); C = farthest from line AB (the component
    largest in (B-A)x(C-A), the direction C moves under rotation about AB)."""
    x, gid = piece["x"], piece["gid"]
    ga, a = argmax_global(comm, (gid == 0).astype(float), gid, x)
    gb, b = argmax_global(comm, np.linalg.norm(x - a, axis=1), gid, x)
    d = (b - a) / np.linalg.norm(b - a)
    r = x - a
    gc, c = argmax_global(comm, np.linalg.norm(r - np.outer(r @ d, d), axis=1), gid, x)
    kb = int(np.argmax(np.abs(b - a)))
    kc = int(np.argmax(np.abs(np.cross(b - a, c - a))))
    return [(ga, [0, 1, 2]), (gb, [k for k in range(3) if k != kb]), (gc, [kc])]


def support_points(args, comm, piece, btri, lo, hi):
    """(piece point index, component) pairs to hold at zero."""
    fixed = np.zeros(len(piece["x"]), dtype=bool)
    if args.fix_below is not None:
        half = 0.5 * (hi[2] - lo[2])
        fixed |= piece["x"][:, 2] < lo[2] + args.fix_below * half
    if args.fix_faces is not None:
        fixed[btri[np.isin(piece["bface"], args.fix_faces)].ravel()] = True
    idx = np.flatnonzero(fixed)
    return np.repeat(idx, 3), np.tile([0, 1, 2], len(idx))


# ---------------------------------------------------------------- solve

def petsc_rows(gblock, pts, comps):
    return (3 * gblock[pts] + comps).astype(np.int32)


def constrain(A, b, rows, values):
    """Holds the given global rows at the given values, symmetric (rows and
    columns), b corrected. Any rank may name any row, also one owned by
    another rank: a marker vector gathers them to their owners first."""
    from petsc4py import PETSc
    mark, xbc = A.createVecRight(), A.createVecRight()
    mark.setValues(rows, np.ones(len(rows)), addv=PETSc.InsertMode.INSERT_VALUES)
    xbc.setValues(rows, values, addv=PETSc.InsertMode.INSERT_VALUES)
    for v in (mark, xbc):
        v.assemblyBegin()
        v.assemblyEnd()
    start = mark.getOwnershipRange()[0]
    owned = (np.flatnonzero(mark.array == 1.0) + start).astype(np.int32)
    A.zeroRowsColumns(owned, 1.0, xbc, b)
    return owned


def make_solver(args, A, x_owned):
    from petsc4py import PETSc
    ksp = PETSc.KSP().create(A.getComm())
    ksp.setOperators(A)
    if args.solver == "lu":
        ksp.setType("preonly")
        ksp.getPC().setType("lu")
        ksp.getPC().setFactorSolverType("mumps")
    else:
        A.setNearNullSpace(rigid_modes(A, x_owned))
        ksp.setType("cg")
        ksp.getPC().setType("gamg")
        ksp.setTolerances(rtol=args.rtol, atol=0.0, max_it=5000)
    ksp.setFromOptions()
    return ksp


def rigid_modes(A, x):
    """The six rigid motions on the owned dofs, for GAMG's coarse spaces."""
    from petsc4py import PETSc
    modes = []
    for k in range(6):
        v = A.createVecRight()
        a = v.array.reshape(-1, 3)
        if k < 3:
            a[:, k] = 1.0
        else:
            i, j = [(0, 1), (1, 2), (2, 0)][k - 3]
            a[:, i], a[:, j] = -x[:, j], x[:, i]
        # Gram-Schmidt: PETSc's null spaces want orthonormal vectors
        for w in modes:
            v.axpy(-v.dot(w), w)
        v.normalize()
        modes.append(v)
    return PETSc.NullSpace().create(vectors=modes, comm=A.getComm())


def von_mises(x, tets, u, E, nu):
    """Per tetrahedron (P1: constant strain), from the displacement gradient."""
    d = x[tets[:, 1:]] - x[tets[:, :1]]
    du = u[tets[:, 1:]] - u[tets[:, :1]]
    grad = np.transpose(np.linalg.solve(d, du), (0, 2, 1))
    eps = 0.5 * (grad + np.transpose(grad, (0, 2, 1)))
    mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
    tr = np.trace(eps, axis1=1, axis2=2)
    s = 2 * mu * eps + (lmbda * tr)[:, None, None] * np.eye(3)
    dev = s - (np.trace(s, axis1=1, axis2=2) / 3)[:, None, None] * np.eye(3)
    return np.sqrt(1.5 * np.einsum("kij,kij->k", dev, dev))


# ---------------------------------------------------------------- driver

def setup(args, comm, t):
    """Reading, numbering, mesh, stiffness, loads and supports: everything
    before the solve. Returns the state the solve and the report need."""
    rank, size = comm.Get_rank(), comm.Get_size()
    piece = collective(comm, "reading", read_own_pieces, args.mesh, rank, size)
    t["read"] = time.perf_counter()
    new, n_owned, _, recv_bytes = contiguous_numbering(comm, piece)
    t["numbering"] = time.perf_counter()
    gblock = new
    A = assemble_stiffness(comm, piece, new, n_owned, args.E, args.nu)
    lo, hi = global_bounds(comm, piece["x"])
    btri = collective(comm, "boundary", boundary_to_piece, piece)
    volume = outward_check(comm, piece, btri)
    pts, forces, area = boundary_loads(args, piece, btri, lo, hi)
    if args.pressure == 0 and comm.allreduce(area) == 0:
        raise SolveError("no load: --traction-faces/--traction-above selected no boundary triangle")
    if args.pressure == 0 and not np.any(args.traction):
        raise SolveError("no load: the traction is zero (give --traction tx,ty,tz)")
    b = A.createVecLeft()
    b.setValues(petsc_rows(gblock, np.repeat(pts, 3), np.tile([0, 1, 2], len(pts))),
                forces.ravel(), addv=True)
    b.assemblyBegin()
    b.assemblyEnd()
    if args.fix_below is None and args.fix_faces is None:
        pins = pin_points(comm, piece)
        sel = [(np.flatnonzero(piece["gid"] == g), comps) for g, comps in pins]
        spts = np.concatenate([np.repeat(i, len(c)) for i, c in sel]).astype(np.int64)
        scomp = np.concatenate([np.tile(c, len(i)) for i, c in sel]).astype(np.int64)
        svals = exact_displacement(args, piece["x"][spts])[np.arange(len(spts)), scomp]
    else:
        pins = None
        spts, scomp = support_points(args, comm, piece, btri, lo, hi)
        svals = np.zeros(len(spts))
    if comm.allreduce(len(spts)) == 0:
        raise SolveError("no supported point: --fix-below/--fix-faces selected nothing")
    A0, b0 = A.copy(), b.copy()
    rows = constrain(A, b, petsc_rows(gblock, spts, scomp), svals)
    t["assemble"] = time.perf_counter()
    return dict(piece=piece, x_owned=owned_coordinates(comm, piece, new, n_owned), new=new, A=A, b=b, A0=A0, b0=b0, rows=rows, pins=pins,
                area=comm.allreduce(area), volume=volume, recv_bytes=recv_bytes,
                ghost_nodes=len(new) - n_owned)


def exact_displacement(args, x):
    """Uniform pressure p on a closed body: u = -p(1-2nu)/E x (+ rigid motion)."""
    return -args.pressure * (1 - 2 * args.nu) / args.E * x


def forces(comm, s, u):
    """Applied load (sum of the nodal forces) and support reaction K0 u - f
    on the constrained rows, summed per component over all ranks."""
    r = s["A0"].createVecLeft()
    s["A0"].mult(u, r)
    r.axpy(-1.0, s["b0"])
    start = r.getOwnershipRange()[0]
    reaction = np.zeros(3)
    np.add.at(reaction, s["rows"] % 3, r.array[s["rows"] - start])
    load = s["b0"].array.reshape(-1, 3).sum(axis=0)
    magnitude = comm.allreduce(float(np.abs(s["b0"].array).sum()))
    return comm.allreduce(load), comm.allreduce(reaction), magnitude


def solve(args, comm):
    t = {"start": time.perf_counter()}
    s = setup(args, comm, t)
    ksp = make_solver(args, s["A"], s["x_owned"])
    uvec = s["A"].createVecRight()
    ksp.solve(s["b"], uvec)
    t["solve"] = time.perf_counter()
    res = s["b"].copy()
    s["A"].mult(uvec, res)
    res.axpy(-1.0, s["b"])
    piece = s["piece"]
    n = len(piece["x"])
    u = gather_piece_values(uvec, petsc_rows(s["new"], np.repeat(np.arange(n), 3), np.tile([0, 1, 2], n))).reshape(-1, 3)
    load, reaction, magnitude = forces(comm, s, uvec)
    # a pressure on a closed body has no resultant: compare with the nodal forces' size
    scale = max(np.linalg.norm(load), 1e-12 * magnitude)
    out = {"ranks": comm.Get_size(), "points": comm.allreduce(int(np.sum((piece["ghost"] & 1) == 0))),
           "tetrahedra": comm.allreduce(len(piece["tets"])), "E": args.E, "nu": args.nu,
           "solver": args.solver, "iterations": ksp.getIterationNumber(),
           "converged_reason": ksp.getConvergedReason(),
           "relative_residual": res.norm() / max(s["b"].norm(), 1e-300),
           "load": load.tolist(), "reaction": reaction.tolist(),
           "equilibrium_error": float(np.linalg.norm(load + reaction) / scale),
           "self_equilibrated_load": bool(np.linalg.norm(load) < 1e-12 * magnitude),
           "loaded_area": s["area"], "volume": s["volume"], "pins": s["pins"]}
    vm = von_mises(piece["x"], piece["tets"], u, args.E, args.nu)
    if args.pressure != 0 and s["pins"] is not None:
        ex = exact_displacement(args, piece["x"])
        err = comm.allreduce(float(np.max(np.abs(u - ex), initial=0.0)), op=MPI.MAX)
        out["exact_relative_error"] = err / comm.allreduce(float(np.max(np.abs(ex), initial=0.0)), op=MPI.MAX)
        out["max_von_mises_over_p"] = comm.allreduce(float(vm.max(initial=0.0)), op=MPI.MAX) / abs(args.pressure)
    out["max_von_mises"] = comm.allreduce(float(vm.max(initial=0.0)), op=MPI.MAX)
    out["max_displacement"] = comm.allreduce(float(np.linalg.norm(u, axis=1).max(initial=0.0)), op=MPI.MAX)
    if args.output:
        write_solution(comm, args.output, piece, u, vm)
    t["post"] = time.perf_counter()
    out["per_rank"] = comm.gather(rank_report(piece, s, t), root=0)
    return out


def rank_report(piece, s, t):
    phases = ["read", "numbering", "assemble", "solve", "post"]
    prev, sec = t["start"], {}
    for p in phases:
        sec[p] = round(t[p] - prev, 4)
        prev = t[p]
    return {"file_bytes_read": piece["file_bytes"], "numbering_bytes_received": s["recv_bytes"],
            "tetrahedra": len(piece["tets"]), "points": len(piece["x"]),
            "copies_of_other_ranks_points": s["ghost_nodes"],
            "meshing_seconds": piece["meshing_seconds"], "seconds": sec,
            "solver_seconds_total": round(t["post"] - t["start"], 4)}


def write_solution(comm, output, piece, u, vm):
    """One .vtu per rank (the mesher's points, tetrahedra and ids, plus the
    displacement and von Mises stress) and the .pvtu on rank 0."""
    rank = comm.Get_rank()
    stem = os.path.splitext(os.path.basename(output))[0]
    folder = os.path.join(os.path.dirname(os.path.abspath(output)), stem)
    os.makedirs(folder, exist_ok=True)
    point_data = {"GlobalPointIds": piece["gid"], "vtkGhostType": piece["ghost"], "Displacement": u}
    cell_data = {"VonMises": vm}
    for name in ("GlobalCellIds", "SubdomainId", "Rank"):
        if name in piece["cell_data"]:
            cell_data[name] = piece["cell_data"][name]
    ptm_pieces.write_tetra_piece(os.path.join(folder, f"{stem}_{rank}.vtu"),
                                 piece["x"], piece["tets"], point_data, cell_data)
    if rank == 0:
        kinds = lambda d: {k: ({np.dtype(v): n for n, v in ptm_pieces.VTK_TYPES.items()}[np.asarray(a).dtype],  # noqa: E731
                               np.asarray(a).shape[1] if np.asarray(a).ndim == 2 else 1) for k, a in d.items()}
        ptm_pieces.write_pvtu(output, [f"{stem}/{stem}_{r}.vtu" for r in range(comm.Get_size())],
                              kinds(point_data), kinds(cell_data))
    comm.Barrier()


def print_summary(out):
    print(f"solve: {out['tetrahedra']} tetrahedra, {out['points']} points on {out['ranks']} ranks, "
          f"solver {out['solver']} ({out['iterations']} iterations), relative residual "
          f"{out['relative_residual']:.2e}")
    print("solve: applied load   F = [" + ", ".join(f"{v:+.10e}" for v in out["load"]) + "]")
    print("solve: reaction       R = [" + ", ".join(f"{v:+.10e}" for v in out["reaction"]) + "]")
    if out["self_equilibrated_load"]:
        print("solve: the load has no resultant (pressure on a closed body); |R + F| is round-off")
    else:
        print(f"solve: |R + F| / |F| = {out['equilibrium_error']:.2e}")
    if "exact_relative_error" in out:
        print(f"solve: max|u - u_exact| / max|u_exact| = {out['exact_relative_error']:.3e}, "
              f"max von Mises / p = {out['max_von_mises_over_p']:.2e}")
    print(f"solve: max |u| = {out['max_displacement']:.6e}, max von Mises = {out['max_von_mises']:.6e}")
    for r, pr in enumerate(out["per_rank"]):
        print(f"solve: rank {r}: read {pr['file_bytes_read']} B from files, "
              f"{pr['numbering_bytes_received']} B from the numbering exchange; meshing "
              f"{pr['meshing_seconds']:.2f} s, solver {pr['solver_seconds_total']:.2f} s {pr['seconds']}")


def release_petsc(comm):
    """Frees the PETSc objects now, on all ranks together: left to the
    interpreter's exit, petsc4py 3.18's garbage cleanup can hang in
    MPI_Comm_dup."""
    import gc
    from petsc4py import PETSc
    gc.collect()
    PETSc.garbage_cleanup(comm)
    comm.Barrier()


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    comm = MPI.COMM_WORLD
    try:
        out = solve(args, comm)
    except SolveError as e:
        if comm.Get_rank() == 0:
            print(f"solve_elasticity: error: {e}", file=sys.stderr, flush=True)
        return 1
    except Exception:  # a bug, on one rank maybe: end all ranks instead of hanging
        import traceback
        traceback.print_exc()
        sys.stderr.flush()
        comm.Abort(2)
    finally:
        release_petsc(comm)
    failed = []
    if args.check_exact is not None and not out["exact_relative_error"] <= args.check_exact:
        failed.append(f"exact error {out['exact_relative_error']:.3e} > {args.check_exact:g}")
    if args.check_equilibrium is not None and not out["equilibrium_error"] <= args.check_equilibrium:
        failed.append(f"equilibrium error {out['equilibrium_error']:.3e} > {args.check_equilibrium:g}")
    if out["converged_reason"] <= 0:
        failed.append(f"the linear solver did not converge (reason {out['converged_reason']})")
    if comm.Get_rank() == 0:
        print_summary(out)
        if args.json:
            with open(args.json, "w") as f:
                json.dump(out, f, indent=1)
        for msg in failed:
            print(f"solve_elasticity: FAILED: {msg}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
