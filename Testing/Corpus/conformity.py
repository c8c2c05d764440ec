"""Independent conformity check of a pipeline result (numpy and VTK's XML
readers only; nothing of the plugin is used).

    /usr/bin/python3 conformity.py MESH.pvtu SURFACE.off

check(pvtu, input_stats) reads every .vtu piece of the .pvtu, merges the
points by their GlobalPointIds (the same id must carry bit-identical
coordinates in every piece) and checks:

* every tetrahedron has positive volume (exactly, where floats cannot
  tell; no tetrahedron appears twice);
* every face is shared by at most 2 tetrahedra, lying on its two sides (once
  in each orientation); the faces used once (the
  boundary) form a closed surface: every boundary edge in exactly 2 of them;
* those boundary faces are exactly the triangles of OUT_boundary.pvtp (by ids);
* the boundary area equals the input surface's area (relative 1e-6: the
  boundary must lie on the input surface; moving a node within a flat face
  keeps the area, moving it off a curved one does not).

conforming is true when none of these fails. It also returns the relative
volume error |V_mesh - V_input| / V_input (the goal is 1e-9, reported apart)
and the relative area error.
"""
import os
import sys
from fractions import Fraction

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Benchmarks"))
from mesh_quality import piece_files, read_vtu  # noqa: E402

AREA_TOLERANCE = 1e-6


def read_polydata(path):
    """(points, GlobalPointIds, triangles) of a .vtp piece."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    gids = data.GetPointData().GetArray("GlobalPointIds")
    if data.GetNumberOfPolys() == 0:
        return None, (None if gids is None else vtk_to_numpy(gids).astype(np.int64)), np.zeros((0, 3), np.int64)
    offsets = vtk_to_numpy(data.GetPolys().GetOffsetsArray())
    conn = vtk_to_numpy(data.GetPolys().GetConnectivityArray()).astype(np.int64)
    if not (np.diff(offsets) == 3).all():
        raise ValueError("%s: boundary cells that are not triangles" % path)
    return None, (None if gids is None else vtk_to_numpy(gids).astype(np.int64)), conn.reshape(-1, 3)


def read_piece(path, cell_type):
    """(points, GlobalPointIds, cells of cell_type) of a .vtu or .vtp piece,
    read with VTK's own XML readers (mesh_quality.read_vtu: meshio misreads
    the pieces' arrays)."""
    if path.endswith(".vtp"):
        return read_polydata(path)
    return read_vtu(path, cell_type)


def exact_signs(p, volumes):
    """The sign of every tetrahedron's volume: the float one, except where it
    is within the float's round-off (|volume| <= 1e-12 of the cube of the
    tetrahedron's extent), where it is computed exactly with fractions. A
    nearly flat tetrahedron of exact volume +2.7e-16 came out -8.1e-16 in
    floats (OCCT's Top, K = 32, parallel planes)."""
    signs = np.sign(volumes)
    extent = (p.max(axis=1) - p.min(axis=1)).max(axis=1)
    for t in np.where(np.abs(volumes) <= 1e-12 * extent ** 3)[0]:
        q = [[Fraction(float(x)) for x in corner] for corner in p[t]]
        a, b, c = ([q[k][i] - q[0][i] for i in range(3)] for k in (1, 2, 3))
        det = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
               + a[2] * (b[0] * c[1] - b[1] * c[0]))
        signs[t] = (det > 0) - (det < 0)
    return signs


def check(pvtu, input_stats):
    problems = []
    all_gids, all_coords, tets = [], [], []
    for piece in piece_files(pvtu):
        points, gids, cells = read_piece(piece, "tetra")
        if gids is None:
            if len(cells):
                problems.append("%s has no GlobalPointIds" % os.path.basename(piece))
            continue
        all_gids.append(gids)
        all_coords.append(points)
        tets.append(gids[cells])
    if problems:
        return {"conforming": False, "problems": problems}
    gids = np.concatenate(all_gids)
    coords = np.concatenate(all_coords)
    tets = np.concatenate(tets)
    order = np.argsort(gids, kind="stable")
    g, c = gids[order], coords[order]
    same = g[1:] == g[:-1]
    if not np.array_equal(c[1:][same].view(np.uint64), c[:-1][same].view(np.uint64)):
        problems.append("a global point id has different coordinates in different pieces")
    table = np.zeros((g.max() + 1, 3))
    table[g] = c
    p = table[tets]
    volumes = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0
    signs = exact_signs(p, volumes)
    if (signs <= 0).any():
        problems.append("%d tetrahedra with non-positive volume (min %.3g)" % ((signs <= 0).sum(), volumes[signs <= 0].min()))
    dup = len(tets) - len(np.unique(np.sort(tets, axis=1), axis=0))
    if dup:
        problems.append("%d tetrahedra appear twice" % dup)
    faces = np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 3, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 1]]])
    keys, inverse, use = np.unique(np.sort(faces, axis=1), axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()
    if use.max() > 2:
        problems.append("%d faces shared by more than 2 tetrahedra" % (use > 2).sum())
    # a face shared by 2 tetrahedra must come once in each orientation (else the
    # two lie on the same side of it: the mesh folds over itself)
    rot = np.argmin(faces, axis=1)
    oriented = faces[np.arange(len(faces))[:, None], (rot[:, None] + np.arange(3)) % 3]
    _, oriented_use = np.unique(oriented, axis=0, return_counts=True)
    if (oriented_use > 1).any():
        problems.append("%d interior faces have both tetrahedra on the same side (the mesh folds)" % (
            (oriented_use > 1).sum()))
    boundary = faces[use[inverse] == 1]  # oriented outward (faces are written with outward normals)
    edges = np.sort(np.concatenate([boundary[:, [0, 1]], boundary[:, [1, 2]], boundary[:, [2, 0]]]), axis=1)
    _, edge_use = np.unique(edges, axis=0, return_counts=True)
    if (edge_use != 2).any():
        problems.append("the boundary is not closed: %d edges not in exactly 2 boundary faces" % (edge_use != 2).sum())
    bfile = os.path.splitext(pvtu)[0] + "_boundary.pvtp"
    if os.path.isfile(bfile):
        ref = []
        for piece in piece_files(bfile):
            _, bg, tri = read_piece(piece, "triangle")
            if bg is not None and len(tri):
                ref.append(bg[tri])
        ref = np.unique(np.sort(np.concatenate(ref), axis=1), axis=0) if ref else np.zeros((0, 3), dtype=np.int64)
        mine = np.unique(np.sort(boundary, axis=1), axis=0)
        if mine.shape != ref.shape or not np.array_equal(mine, ref):
            problems.append("boundary faces (%d) differ from %s (%d)" % (len(mine), os.path.basename(bfile), len(ref)))
    bp = table[boundary]
    area = 0.5 * np.linalg.norm(np.cross(bp[:, 1] - bp[:, 0], bp[:, 2] - bp[:, 0]), axis=1).sum()
    bo = bp - bp[0, 0]  # about a corner: far from (0, 0, 0) the terms would swamp the volume
    enclosed = np.einsum("ij,ij->i", bo[:, 0], np.cross(bo[:, 1], bo[:, 2])).sum() / 6.0
    volume = volumes.sum()
    area_error = abs(area - input_stats["area"]) / input_stats["area"]
    if area_error > AREA_TOLERANCE:
        problems.append("boundary area differs from the input's by %.2e (relative)" % area_error)
    if abs(enclosed - volume) > 1e-9 * abs(volume):
        problems.append("tetrahedra volume %.12g differs from the volume the boundary encloses %.12g" % (
            volume, enclosed))
    return {"conforming": not problems, "problems": problems, "tetrahedra": int(len(tets)),
            "points": int(len(np.unique(g))), "volume": float(volume),
            "volume_error": float(abs(volume - input_stats["volume"]) / abs(input_stats["volume"])),
            "area_error": float(area_error), "boundary_faces": int(len(boundary))}


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import json

    import surface_tool

    print(json.dumps(check(sys.argv[1], surface_tool.stats(sys.argv[2]))))


def check_summary_mesh(summary_json, surface_stats, largest_volume_error=1e-9):
    """The check of the .pvtu beside a tetmesh.py --json summary, and what a
    regression test counts as failures: not conforming, or the volume off by
    more than largest_volume_error (relative)."""
    result = check(os.path.splitext(summary_json)[0] + ".pvtu", surface_stats)
    failures = []
    if not result["conforming"]:
        failures.append("the mesh does not conform: %s" % result["problems"])
    if result.get("volume_error", 1) > largest_volume_error:
        failures.append("volume error %.3g" % result.get("volume_error", 1))
    return result, failures
