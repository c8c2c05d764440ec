#!/usr/bin/python3
"""Linear elasticity with FEniCSx (dolfinx 0.5, PETSc CG+GAMG or MUMPS) on the
mesher's pieces, in place: rank r reads only piece r of the .pvtu (and of
*_boundary.pvtp), hands exactly those tetrahedra to dolfinx and keeps them.

  mpiexec -n P /usr/bin/python3 Scripts/solve_elasticity.py out/ball.pvtu \
      --pressure 1 --check-exact 1e-8                  # the exact test
  mpiexec -n P /usr/bin/python3 Scripts/solve_elasticity.py out/ball.pvtu \
      --fix-below 0.1 --traction-above 0.5 --traction 0,0,-1 -o out/ball_solution.pvtu

The engine is dolfinx: the mesh is built by dolfinx.mesh.create_mesh from each
rank's own tetrahedra (a cell partitioner that keeps every cell on its rank,
see keep_cells_partitioner), the problem is written in UFL (P1 vector
elements, pressure and traction as ds terms on the boundary facets tagged from
the boundary piece), assembled by dolfinx and solved by PETSc.

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
    """New vertex numbers, contiguous per owning rank: dolfinx's create_mesh
    takes global node i from row i - offset_r of rank r's coordinate block
    (blocks in rank order), so rank r passes the points it owns, numbered
    offset_r, offset_r + 1, ..., and its cells in these numbers. Owned points (vtkGhostType 0) are numbered in GlobalPointIds
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


def owned_coordinates(comm, piece, new, n_owned):
    """The coordinates of the points this rank owns, row k = number offset + k."""
    offset = comm.exscan(n_owned) or 0
    owned = (piece["ghost"] & 1) == 0
    x = np.empty((n_owned, 3))
    x[new[owned] - offset] = piece["x"][owned]
    return x


def tet_volumes(x, tets):
    t = x[tets]
    vol = np.abs(np.linalg.det(t[:, 1:] - t[:, :1])) / 6.0
    if np.any(vol <= 0):
        raise SolveError(f"{int(np.sum(vol <= 0))} tetrahedra of zero volume")
    return vol


# ---------------------------------------------------------------- the dolfinx mesh

def keep_cells_partitioner(comm, n_cells):
    """A cell partitioner for dolfinx.mesh.create_mesh that moves no cell.

    dolfinx 0.5.2 finds the vertices shared between ranks only among the
    vertices that touch both an owned and a ghost cell (Topology.cpp,
    vertex_ownerhip_groups), and the ghost cells come from the partitioner:
    destination ranks after the first. So every cell goes to this rank (its
    first destination) and, as a ghost, to the ranks holding a cell across
    one of its facets (from the distributed dual graph, whose off-rank
    neighbours are global cell numbers: exscan of the cell counts + local
    index). create_mesh asks for facet ghosts, matches the vertices, and with
    GhostMode.none drops the ghost cells again: each rank keeps exactly its
    own cells. Returning the rank alone makes dolfinx share no vertex."""
    from dolfinx.cpp.graph import AdjacencyList_int32
    from dolfinx.cpp.mesh import create_cell_partitioner
    rank = comm.Get_rank()
    starts = np.r_[0, np.cumsum(comm.allgather(n_cells))]

    def destinations(_comm, _nparts, dual, _ghosting):
        nbr, off = np.asarray(dual.array), np.asarray(dual.offsets)
        owner = np.searchsorted(starts, nbr, side="right") - 1
        cell = np.repeat(np.arange(dual.num_nodes), np.diff(off))
        other = owner != rank
        pairs = np.unique(np.column_stack([cell[other], owner[other]]), axis=0)
        offsets = np.r_[0, np.cumsum(np.bincount(pairs[:, 0], minlength=dual.num_nodes) + 1)]
        data = np.empty(offsets[-1], dtype=np.int32)
        data[offsets[:-1]] = rank
        nth = np.arange(len(pairs)) - np.searchsorted(pairs[:, 0], pairs[:, 0])
        data[offsets[pairs[:, 0]] + 1 + nth] = pairs[:, 1]
        return AdjacencyList_int32(data, offsets.astype(np.int32))

    return create_cell_partitioner(destinations)


def create_mesh(comm, piece, new, n_owned):
    """The dolfinx mesh of all ranks' pieces, each rank's cells in place.
    Returns the mesh, the piece tetrahedron of every dolfinx cell and the
    piece point of every dolfinx geometry node; fails unless dolfinx kept
    exactly this rank's tetrahedra and every point of the mesh once."""
    import dolfinx.mesh
    import ufl
    tets = piece["tets"]
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.tetrahedron, 1))
    msh = dolfinx.mesh.create_mesh(comm, new[tets].astype(np.int64),
                                   owned_coordinates(comm, piece, new, n_owned), domain,
                                   ghost_mode=dolfinx.mesh.GhostMode.none,
                                   partitioner=keep_cells_partitioner(comm, len(tets)))
    cells = msh.topology.index_map(3)
    tet_of_cell = np.asarray(msh.topology.original_cell_index) - (comm.exscan(len(tets)) or 0)
    kept = (cells.size_local == len(tets) and cells.num_ghosts == 0
            and np.array_equal(np.sort(tet_of_cell), np.arange(len(tets))))
    order = np.argsort(new)
    gi = np.asarray(msh.geometry.input_global_indices)
    pos = np.clip(np.searchsorted(new[order], gi), 0, len(order) - 1)
    point_of_node = order[pos]
    nodes_ok = (len(gi) == len(new) and np.array_equal(new[point_of_node], gi)
                and np.array_equal(msh.geometry.x, piece["x"][point_of_node]))
    n_points = comm.allreduce(n_owned)
    if not comm.allreduce(kept, op=MPI.LAND):
        raise SolveError("dolfinx did not keep every rank's tetrahedra in place")
    if not comm.allreduce(nodes_ok, op=MPI.LAND) or msh.topology.index_map(0).size_global != n_points:
        raise SolveError(f"dolfinx's mesh has {msh.topology.index_map(0).size_global} vertices, "
                         f"the pieces {n_points} points (shared points not matched)")
    return msh, tet_of_cell, point_of_node


def piece_dofs(msh, V, point_of_node, n_points):
    """The block dof of V (P1 vector) at every piece point: through the
    cells, whose geometry nodes and dofs are listed in the same order."""
    nodes = msh.geometry.dofmap.array.reshape(-1, 4)
    dofs = V.dofmap.list.array.reshape(-1, 4)
    dof_of_point = np.full(n_points, -1, dtype=np.int32)
    dof_of_point[point_of_node[nodes]] = dofs
    imap = V.dofmap.index_map
    if np.any(dof_of_point < 0) or imap.size_local + imap.num_ghosts != n_points:
        raise SolveError("the P1 dofs are not the piece's points one to one")
    return dof_of_point


def boundary_tags(comm, msh, point_of_node, btri, select):
    """Facet tags from the boundary piece: 1 on every boundary triangle, 2 on
    the loaded ones. Each boundary triangle must be an exterior facet of
    dolfinx's mesh (owned by this rank: the boundary piece of rank r only has
    faces of rank r's tetrahedra), and the counts must agree."""
    import dolfinx.mesh
    top = msh.topology
    top.create_connectivity(2, 3)
    top.create_connectivity(2, 0)
    exterior = np.asarray(dolfinx.mesh.exterior_facet_indices(top), dtype=np.int32)
    point_of_vertex = np.empty(top.index_map(0).size_local + top.index_map(0).num_ghosts, dtype=np.int64)
    point_of_vertex[top.connectivity(3, 0).array.reshape(-1, 4)] = \
        point_of_node[msh.geometry.dofmap.array.reshape(-1, 4)]
    facet_points = point_of_vertex[top.connectivity(2, 0).array.reshape(-1, 3)[exterior]]
    both = np.vstack([np.sort(facet_points, axis=1), np.sort(btri, axis=1)])
    _, key = np.unique(both, axis=0, return_inverse=True)
    key = key.ravel()
    facet_key, tri_key = key[:len(exterior)], key[len(exterior):]
    where = np.full(len(both), -1, dtype=np.int64)
    where[facet_key] = np.arange(len(exterior))
    facet_of_tri = where[tri_key]
    matched = bool(np.all(facet_of_tri >= 0)) and len(np.unique(facet_of_tri)) == len(btri)
    n_ext, n_tri = comm.allreduce(len(exterior)), comm.allreduce(len(btri))
    if not comm.allreduce(matched, op=MPI.LAND) or n_ext != n_tri:
        raise SolveError(f"the boundary piece's triangles ({n_tri}) are not dolfinx's exterior "
                         f"facets ({n_ext})")
    facets = exterior[facet_of_tri]
    values = np.where(select, 2, 1).astype(np.int32)
    order = np.argsort(facets)
    return dolfinx.mesh.meshtags(msh, 2, facets[order], values[order])


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


def loaded_triangles(args, piece, btri, lo, hi):
    """The boundary triangles the traction acts on (by SourceFaceId or by
    height) and their area."""
    p = piece["x"][btri]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    select = np.zeros(len(btri), dtype=bool)
    if args.traction_faces is not None:
        select |= np.isin(piece["bface"], args.traction_faces)
    if args.traction_above is not None:
        half = 0.5 * (hi[2] - lo[2])
        select |= p[:, :, 2].mean(axis=1) > hi[2] - args.traction_above * half
    return select, float(area[select].sum())


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
    largest in (B-A)x(C-A), the direction C moves under rotation about AB).
    Returns (global id, components, coordinates), known on every rank."""
    x, gid = piece["x"], piece["gid"]
    ga, a = argmax_global(comm, (gid == 0).astype(float), gid, x)
    gb, b = argmax_global(comm, np.linalg.norm(x - a, axis=1), gid, x)
    d = (b - a) / np.linalg.norm(b - a)
    r = x - a
    gc, c = argmax_global(comm, np.linalg.norm(r - np.outer(r @ d, d), axis=1), gid, x)
    kb = int(np.argmax(np.abs(b - a)))
    kc = int(np.argmax(np.abs(np.cross(b - a, c - a))))
    return [(ga, [0, 1, 2], a), (gb, [k for k in range(3) if k != kb], b), (gc, [kc], c)]


def supported_points(args, piece, btri, lo, hi):
    """Piece points held at zero (all three components)."""
    fixed = np.zeros(len(piece["x"]), dtype=bool)
    if args.fix_below is not None:
        half = 0.5 * (hi[2] - lo[2])
        fixed |= piece["x"][:, 2] < lo[2] + args.fix_below * half
    if args.fix_faces is not None:
        fixed[btri[np.isin(piece["bface"], args.fix_faces)].ravel()] = True
    return fixed


def consistent_blocks(V, blocks):
    """The given block dofs together with those any other rank gave for the
    same points: a point of a fixed face (--fix-faces) is also on ranks whose
    boundary piece does not have that face, and a Dirichlet dof must be
    marked on every rank that has it (dolfinx zeroes rows and columns cell by
    cell)."""
    from dolfinx import fem
    from petsc4py import PETSc
    mark = fem.Function(V)
    mark.x.array[:] = 0.0
    mark.x.array.reshape(-1, 3)[blocks] = 1.0
    mark.vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    mark.vector.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
    return np.flatnonzero(mark.x.array.reshape(-1, 3)[:, 0] > 0).astype(np.int32)


def dirichlet_conditions(args, comm, piece, V, dof_of_point, btri, lo, hi):
    """dolfinx Dirichlet conditions: the supports at zero, or, without
    supports, the three pinned points at the exact pressure solution's
    values. Returns the conditions and the pins (None with supports)."""
    from dolfinx import fem
    from petsc4py import PETSc
    bcs = []
    if args.fix_below is None and args.fix_faces is None:
        pins = pin_points(comm, piece)
        for g, comps, xp in pins:
            blocks = dof_of_point[piece["gid"] == g]
            for k in comps:
                value = exact_displacement(args, xp)[k]
                bcs.append(fem.dirichletbc(PETSc.ScalarType(value), (3 * blocks + k).astype(np.int32), V.sub(k)))
        pins = [(int(g), comps) for g, comps, _ in pins]
    else:
        pins = None
        fixed = consistent_blocks(V, dof_of_point[supported_points(args, piece, btri, lo, hi)])
        if comm.allreduce(len(fixed)) == 0:
            raise SolveError("no supported point: --fix-below/--fix-faces selected nothing")
        for k in range(3):
            bcs.append(fem.dirichletbc(PETSc.ScalarType(0.0), (3 * fixed + k).astype(np.int32), V.sub(k)))
    return bcs, pins


def exact_displacement(args, x):
    """Uniform pressure p on a closed body: u = -p(1-2nu)/E x (+ rigid motion)."""
    return -args.pressure * (1 - 2 * args.nu) / args.E * x


# ---------------------------------------------------------------- the problem in UFL

def elasticity_forms(args, msh, V, tags):
    """a(u, v) = (sigma(u), eps(v)), L(v) = -p (n, v) on all boundary facets
    + (t, v) on the loaded ones; E, nu, p, t are Constants, so the compiled
    forms do not depend on the values (one JIT compilation, then the cache)."""
    import ufl
    from dolfinx import fem
    from petsc4py import PETSc
    E = fem.Constant(msh, PETSc.ScalarType(args.E))
    nu = fem.Constant(msh, PETSc.ScalarType(args.nu))
    p = fem.Constant(msh, PETSc.ScalarType(args.pressure))
    t = fem.Constant(msh, np.asarray(args.traction, dtype=PETSc.ScalarType))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    ds = ufl.Measure("ds", domain=msh, subdomain_data=tags)
    n = ufl.FacetNormal(msh)
    a = ufl.inner(stress(u, E, nu), ufl.sym(ufl.grad(v))) * ufl.dx
    L = -p * ufl.inner(n, v) * ds((1, 2)) + ufl.inner(t, v) * ds(2)
    return fem.form(a), fem.form(L), (E, nu)


def stress(u, E, nu):
    import ufl
    mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
    eps = ufl.sym(ufl.grad(u))
    return 2 * mu * eps + lmbda * ufl.tr(eps) * ufl.Identity(3)


def von_mises(msh, u, E, nu, tet_of_cell):
    """Per tetrahedron (P1: constant stress), interpolated by dolfinx into
    DG0 and put in the piece's cell order."""
    import ufl
    from dolfinx import fem
    s = stress(u, E, nu)
    dev = s - ufl.tr(s) / 3 * ufl.Identity(3)
    W = fem.FunctionSpace(msh, ("DG", 0))
    w = fem.Function(W)
    w.interpolate(fem.Expression(ufl.sqrt(1.5 * ufl.inner(dev, dev)), W.element.interpolation_points()))
    vm = np.empty(len(tet_of_cell))
    vm[tet_of_cell] = w.x.array[W.dofmap.list.array]
    return vm


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
    """The six rigid motions on the owned dofs (x: their points), for GAMG's
    coarse spaces."""
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


# ---------------------------------------------------------------- driver

def setup(args, comm, t):
    """Reading, numbering, the dolfinx mesh, forms, assembly, conditions:
    everything before the solve. Returns the state the solve and the report
    need."""
    from dolfinx import fem
    from dolfinx.fem import petsc as fem_petsc
    from petsc4py import PETSc
    rank, size = comm.Get_rank(), comm.Get_size()
    piece = collective(comm, "reading", read_own_pieces, args.mesh, rank, size)
    t["read"] = time.perf_counter()
    new, n_owned, _, recv_bytes = contiguous_numbering(comm, piece)
    t["numbering"] = time.perf_counter()
    vol = collective(comm, "tetrahedra", tet_volumes, piece["x"], piece["tets"])
    msh, tet_of_cell, point_of_node = create_mesh(comm, piece, new, n_owned)
    V = fem.VectorFunctionSpace(msh, ("Lagrange", 1))
    dof_of_point = collective(comm, "dofs", piece_dofs, msh, V, point_of_node, len(new))
    lo, hi = global_bounds(comm, piece["x"])
    btri = collective(comm, "boundary", boundary_to_piece, piece)
    select, area = loaded_triangles(args, piece, btri, lo, hi)
    area = comm.allreduce(area)
    if args.pressure == 0 and area == 0:
        raise SolveError("no load: --traction-faces/--traction-above selected no boundary triangle")
    if args.pressure == 0 and not np.any(args.traction):
        raise SolveError("no load: the traction is zero (give --traction tx,ty,tz)")
    tags = boundary_tags(comm, msh, point_of_node, btri, select)
    bcs, pins = dirichlet_conditions(args, comm, piece, V, dof_of_point, btri, lo, hi)
    t["mesh"] = time.perf_counter()
    a, L, material = elasticity_forms(args, msh, V, tags)
    t["forms"] = time.perf_counter()
    A = fem_petsc.assemble_matrix(a, bcs=bcs)
    A.assemble()
    b = fem_petsc.assemble_vector(L)
    fem_petsc.apply_lifting(b, [a], bcs=[bcs])
    b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    fem_petsc.set_bc(b, bcs)
    # without conditions, for the support reaction K0 u - f
    A0 = fem_petsc.assemble_matrix(a)
    A0.assemble()
    b0 = fem_petsc.assemble_vector(L)
    b0.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    start = A.getOwnershipRange()[0]
    rows = []
    for bc in bcs:
        dofs, n_owned_dofs = bc.dof_indices()
        rows.append(np.asarray(dofs[:n_owned_dofs]) + start)
    rows = np.unique(np.concatenate(rows)).astype(np.int64)
    t["assemble"] = time.perf_counter()
    imap_c, imap_v = msh.topology.index_map(3), msh.topology.index_map(0)
    n_dofs_owned = V.dofmap.index_map.size_local
    return dict(piece=piece, msh=msh, V=V, material=material, tet_of_cell=tet_of_cell,
                dof_of_point=dof_of_point, x_owned=V.tabulate_dof_coordinates()[:n_dofs_owned],
                A=A, b=b, A0=A0, b0=b0, rows=rows, pins=pins, area=area,
                volume=comm.allreduce(float(vol.sum())), recv_bytes=recv_bytes,
                ghost_nodes=len(new) - n_owned,
                dolfinx={"cells": imap_c.size_local, "ghost_cells": imap_c.num_ghosts,
                         "owned_vertices": imap_v.size_local, "ghost_vertices": imap_v.num_ghosts,
                         "global_vertices": imap_v.size_global})


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
    import dolfinx
    from dolfinx import fem
    t = {"start": time.perf_counter()}
    s = setup(args, comm, t)
    ksp = make_solver(args, s["A"], s["x_owned"])
    uh = fem.Function(s["V"])
    ksp.solve(s["b"], uh.vector)
    uh.x.scatter_forward()
    t["solve"] = time.perf_counter()
    res = s["b"].copy()
    s["A"].mult(uh.vector, res)
    res.axpy(-1.0, s["b"])
    piece = s["piece"]
    u = uh.x.array.reshape(-1, 3)[s["dof_of_point"]]
    load, reaction, magnitude = forces(comm, s, uh.vector)
    # a pressure on a closed body has no resultant: compare with the nodal forces' size
    scale = max(np.linalg.norm(load), 1e-12 * magnitude)
    out = {"ranks": comm.Get_size(), "points": comm.allreduce(int(np.sum((piece["ghost"] & 1) == 0))),
           "tetrahedra": comm.allreduce(len(piece["tets"])), "E": args.E, "nu": args.nu,
           "engine": f"dolfinx {dolfinx.__version__}",
           "solver": args.solver, "iterations": ksp.getIterationNumber(),
           "converged_reason": ksp.getConvergedReason(),
           "relative_residual": res.norm() / max(s["b"].norm(), 1e-300),
           "load": load.tolist(), "reaction": reaction.tolist(),
           "equilibrium_error": float(np.linalg.norm(load + reaction) / scale),
           "self_equilibrated_load": bool(np.linalg.norm(load) < 1e-12 * magnitude),
           "loaded_area": s["area"], "volume": s["volume"], "pins": s["pins"]}
    vm = von_mises(s["msh"], uh, *s["material"], s["tet_of_cell"])
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
    phases = ["read", "numbering", "mesh", "forms", "assemble", "solve", "post"]
    prev, sec = t["start"], {}
    for p in phases:
        sec[p] = round(t[p] - prev, 4)
        prev = t[p]
    return {"file_bytes_read": piece["file_bytes"], "numbering_bytes_received": s["recv_bytes"],
            "tetrahedra": len(piece["tets"]), "points": len(piece["x"]),
            "copies_of_other_ranks_points": s["ghost_nodes"], "dolfinx": s["dolfinx"],
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
        d = pr["dolfinx"]
        print(f"solve: rank {r}: {pr['tetrahedra']} tetrahedra in the piece, {d['cells']} cells in "
              f"{out['engine']} ({d['ghost_cells']} ghost cells), vertices {d['owned_vertices']} owned + "
              f"{d['ghost_vertices']} ghosts of {d['global_vertices']}")
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
    import logging
    # dolfinx's JIT (cffi, setuptools) logs every compiler call at INFO on the root logger
    logging.getLogger().addFilter(lambda record: record.levelno >= logging.WARNING)
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
