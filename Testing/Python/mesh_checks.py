"""Independent checks of the plugin's outputs, in numpy only: what a solver
writer would verify before trusting the pieces."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes


def enclosed_volume(points, triangles):
    # about a corner of the surface, not (0, 0, 0): far from the origin the
    # terms would grow as the cube of the distance and swamp the volume
    p = points[triangles] - points[triangles[0, 0]]
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0


def canonical_triangles(tris):
    """Each triangle rotated to start at its smallest id (orientation kept)."""
    tris = np.asarray(tris)
    k = np.argmin(tris, axis=1)
    rows = np.arange(len(tris))[:, None]
    return tris[rows, (k[:, None] + np.arange(3)) % 3]


def cells_of(dataset, size):
    """Connectivity of a dataset whose cells all have `size` points."""
    if dataset.GetNumberOfCells() == 0:
        return np.zeros((0, size), dtype=np.int64)
    offsets = vtk_to_numpy(dataset.GetCells().GetOffsetsArray()) if hasattr(dataset, "GetCells") else None
    if offsets is not None:
        conn = vtk_to_numpy(dataset.GetCells().GetConnectivityArray())
    else:
        conn = vtk_to_numpy(dataset.GetPolys().GetConnectivityArray())
        offsets = vtk_to_numpy(dataset.GetPolys().GetOffsetsArray())
    assert np.all(np.diff(offsets) == size), "cells of other sizes found"
    return conn.reshape(-1, size).astype(np.int64)


def global_points(dataset):
    """(global ids, coordinates) of a dataset's points."""
    ids = dataset.GetPointData().GetGlobalIds()
    assert ids is not None, "no global point ids"
    return vtk_to_numpy(ids).astype(np.int64), vtk_to_numpy(dataset.GetPoints().GetData()).astype(np.float64)


def unify(gids, coords):
    """Coordinates indexed by global id; asserts that the same id always has
    bit-identical coordinates and that ids are contiguous 0..P-1."""
    order = np.argsort(gids, kind="stable")
    g, c = gids[order], coords[order]
    same = g[1:] == g[:-1]
    assert np.array_equal(c[1:][same].view(np.uint64), c[:-1][same].view(np.uint64)), \
        "a global point id has different coordinates in different places"
    unique_ids = np.unique(g)
    assert unique_ids[0] == 0 and unique_ids[-1] == len(unique_ids) - 1, "point ids are not contiguous"
    table = np.empty((len(unique_ids), 3))
    table[g] = c
    return table


def check_volume_mesh(grid, boundary_reference):
    """The assembled volume mesh (all pieces in one vtkUnstructuredGrid, points
    repeated per piece). boundary_reference: (n,3) global-id triangles the
    mesh boundary must equal, oriented outward. Returns a summary dict."""
    gids, coords = global_points(grid)
    table = unify(gids, coords)
    ghosts = grid.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName())
    assert ghosts is not None, "no vtkGhostType point array"
    owned = (vtk_to_numpy(ghosts) & vtkDataSetAttributes.DUPLICATEPOINT) == 0
    counts = np.bincount(gids[owned], minlength=len(table))
    assert np.all(counts == 1), "points owned %s times" % np.unique(counts)
    tets = gids[cells_of(grid, 4)]
    cell_ids = vtk_to_numpy(grid.GetCellData().GetGlobalIds()).astype(np.int64)
    assert np.array_equal(np.sort(cell_ids), np.arange(len(tets))), "cell ids not 0..T-1 once each"
    p = table[tets]
    volumes = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0
    assert volumes.min() > 0, "a tetrahedron has non-positive volume %g" % volumes.min()
    faces = np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 3]], tets[:, [1, 2, 3]]])
    keys, use = np.unique(np.sort(faces, axis=1), axis=0, return_counts=True)
    assert use.max() <= 2, "a face is shared by more than two tetrahedra"
    once = keys[use == 1]
    reference = np.unique(np.sort(boundary_reference, axis=1), axis=0)
    assert once.shape == reference.shape and np.array_equal(once, reference), \
        "mesh boundary (%d faces) differs from the surface (%d faces)" % (len(once), len(reference))
    surface_volume = enclosed_volume(table, boundary_reference)
    assert abs(volumes.sum() / surface_volume - 1) < 1e-9, (volumes.sum(), surface_volume)
    dihedral = min_dihedral_angles(p)
    return {"tets": len(tets), "points": len(table), "volume": float(volumes.sum()),
            "min_dihedral": float(dihedral.min()), "share_below_10": float((dihedral < 10).mean())}


def min_dihedral_angles(p):
    """Smallest dihedral angle (degrees) of every tetrahedron (n,4,3)."""
    normals = []
    for a, b, c in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
        n = np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
    angles = []
    for i in range(4):
        for j in range(i + 1, 4):
            cosine = np.clip(-np.einsum("ij,ij->i", normals[i], normals[j]), -1, 1)
            angles.append(np.degrees(np.arccos(cosine)))
    # with consistently computed face normals, interior angle = pi - angle between normals
    a = np.array(angles)
    a = np.minimum(a, 180 - a)
    return a.min(axis=0)


def check_complex(complex_data):
    """The triangulated labeled complex gathered from all pieces: returns
    (points by global id, triangles by global id, pairs, planes)."""
    gids, coords = global_points(complex_data)
    table = unify(gids, coords)
    tris = gids[cells_of(complex_data, 3)]
    cd = complex_data.GetCellData()
    pairs = vtk_to_numpy(cd.GetArray("SubdomainPair")).reshape(-1, 2)
    planes = vtk_to_numpy(cd.GetArray("PlaneId"))
    assert complex_data.GetNumberOfLines() == 0, "interface loops left"
    # interface triangles appear on both owners' pieces: keep one copy
    key = np.concatenate([canonical_triangles(tris), pairs], axis=1)
    key, first = np.unique(key, axis=0, return_index=True)
    return table, key[:, :3], key[:, 3:], planes[first]


def subdomain_surfaces_closed(table, tris, pairs, count):
    """Every subdomain closed, edge-manifold, outward; returns its volumes."""
    volumes = []
    for s in range(count):
        mine = np.concatenate([tris[pairs[:, 0] == s], tris[pairs[:, 1] == s][:, [0, 2, 1]]])
        assert len(mine) > 0, "subdomain %d has no triangles" % s
        edges = np.concatenate([mine[:, [0, 1]], mine[:, [1, 2]], mine[:, [2, 0]]])
        forward, fc = np.unique(edges, axis=0, return_counts=True)
        assert fc.max() == 1, "subdomain %d: an edge used twice in the same direction" % s
        backward = set(map(tuple, edges[:, ::-1]))
        assert all(tuple(e) in backward for e in forward), "subdomain %d is not closed" % s
        v = enclosed_volume(table, mine)
        assert v > 0, "subdomain %d has non-positive volume" % s
        volumes.append(v)
    return np.array(volumes)


def interface_exceptions(table, tris, pairs, planes, bound):
    """Interface triangles under `bound` degrees, and how many of them are
    away from their region's boundary: no point on it and a circumcircle
    that reaches none of its segments. A region is one plane between one
    pair; its boundary segments are the edges only one of its triangles
    uses. Returns (under the bound, of them away from the boundary)."""
    below = away = 0
    interface = pairs[:, 1] >= 0
    for key in np.unique(np.column_stack([planes[interface], pairs[interface]]), axis=0):
        mine = tris[interface & (planes == key[0]) & (pairs[:, 0] == key[1]) & (pairs[:, 1] == key[2])]
        edges = np.sort(np.concatenate([mine[:, [0, 1]], mine[:, [1, 2]], mine[:, [2, 0]]]), axis=1)
        keys, use = np.unique(edges, axis=0, return_counts=True)
        segments = keys[use == 1]
        on_boundary = np.zeros(len(table), dtype=bool)
        on_boundary[segments.ravel()] = True
        p = table[mine]
        angles = []
        for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
            u, v = p[:, b] - p[:, a], p[:, c] - p[:, a]
            angles.append(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), np.einsum("ij,ij->i", u, v))))
        bad = np.min(angles, axis=0) < bound
        below += int(bad.sum())
        s0, s1 = table[segments[:, 0]], table[segments[:, 1]]
        for t in np.where(bad & ~on_boundary[mine].any(axis=1))[0]:
            a, u, v = p[t, 0], p[t, 1] - p[t, 0], p[t, 2] - p[t, 0]
            w = np.cross(u, v)
            centre = a + (np.dot(u, u) * np.cross(v, w) + np.dot(v, v) * np.cross(w, u)) / (2 * np.dot(w, w))
            d = s1 - s0
            s = np.clip(np.einsum("ij,ij->i", centre - s0, d) / np.einsum("ij,ij->i", d, d), 0, 1)
            if np.linalg.norm(centre - (s0 + s[:, None] * d), axis=1).min() >= np.linalg.norm(centre - a):
                away += 1
    return below, away
