"""The batch command's .pvtu read by a third-party reader (meshio), as a
solver writer would read it, without VTK or ParaView.

    /usr/bin/python3 test_meshio_pvtu.py OUT.pvtu SUMMARY.json INPUT_SURFACE.stl

OUT.pvtu and SUMMARY.json are written by
`mpiexec -n 2 pvbatch Scripts/tetmesh.py INPUT -o OUT.pvtu --json SUMMARY.json`
(the CTest fixture tetmesh_bracket_np2). meshio (Debian bookworm's
python3-meshio, meshio.__version__ 5.0.0) reads .vtu but not .pvtu,
so the pieces are taken from the .pvtu's <Piece Source=...> entries and read
one by one. Checks:

* one piece per rank, every cell block is "tetra";
* tetrahedra per piece = the JSON's tetrahedra_per_rank, their sum = tetrahedra;
* GlobalPointIds (point data): the ids of all pieces are exactly 0..P-1 with
  P = the JSON's points, i.e. sum of piece points - interface copies = P;
  copies of one id have bit-identical coordinates; vtkGhostType marks all
  copies but one, so the owned points sum to P;
* GlobalCellIds are 0..T-1 once each, SubdomainId covers 0..K-1;
* geometry: every tetrahedron has positive volume, no face is shared by more
  than two tetrahedra (the pieces conform across ranks), and the volume of the
  mesh and the area of its boundary equal those of the input surface (read
  with meshio as well) within 1e-4: snapping near the cuts and relaxation move
  surface nodes slightly (2e-5 on the bracket), one missing tetrahedron adds
  about 3e-4 of boundary area.

meshio's field data are not used: for these appended-format pieces it
returned GlobalCellCount with SubdomainTetrahedra's four values and the other
way round (VTK's reader reads them correctly).
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def pieces_of(pvtu):
    root = ET.parse(pvtu).getroot()
    assert root.get("type") == "PUnstructuredGrid", root.get("type")
    base = os.path.dirname(os.path.abspath(pvtu))
    return [os.path.join(base, p.get("Source")) for p in root.iter("Piece")]


def tet_volumes(p):
    return np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0


def surface_volume_and_area(points, triangles):
    p = points[triangles]
    volume = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    return volume, area


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    pvtu, summary_file, surface_file = argv
    with open(summary_file) as f:
        summary = json.load(f)
    T, P, K, ranks = summary["tetrahedra"], summary["points"], summary["subdomains"], summary["ranks"]
    print("meshio %s; summary: %d tetrahedra, %d points, %d subdomains, %d ranks" % (
        meshio.__version__, T, P, K, ranks))

    files = pieces_of(pvtu)
    assert len(files) == ranks, "%d pieces in %s for %d ranks" % (len(files), pvtu, ranks)
    gids, coords, owned, tets, cell_ids, subdomains = [], [], [], [], [], []
    for rank, name in enumerate(files):
        mesh = meshio.read(name)
        types = [block.type for block in mesh.cells]
        assert types and set(types) == {"tetra"}, "%s: cell types %s, expected tetra only" % (name, types)
        connectivity = np.concatenate([block.data for block in mesh.cells]).astype(np.int64)
        expected = summary["tetrahedra_per_rank"][rank]
        assert len(connectivity) == expected, "%s: %d tetrahedra, the summary says %d for rank %d" % (
            name, len(connectivity), expected, rank)
        assert "GlobalPointIds" in mesh.point_data, "%s: no GlobalPointIds point data" % name
        ids = mesh.point_data["GlobalPointIds"].astype(np.int64).ravel()
        ghost = mesh.point_data["vtkGhostType"].ravel()
        gids.append(ids)
        coords.append(np.asarray(mesh.points, dtype=np.float64))
        owned.append((ghost & 1) == 0)  # 1 = DUPLICATEPOINT
        tets.append(ids[connectivity])
        cell_ids.append(np.concatenate(mesh.cell_data["GlobalCellIds"]).astype(np.int64))
        subdomains.append(np.concatenate(mesh.cell_data["SubdomainId"]).astype(np.int64))
        print("piece %d: %s: %d points, %d tetrahedra, subdomains %s" % (
            rank, os.path.basename(name), len(ids), len(connectivity), np.unique(subdomains[-1]).tolist()))

    tets = np.concatenate(tets)
    assert len(tets) == T, "%d tetrahedra in the pieces, the summary says %d" % (len(tets), T)

    gids, coords, owned = np.concatenate(gids), np.concatenate(coords), np.concatenate(owned)
    unique = np.unique(gids)
    copies = len(gids) - len(unique)
    print("points: %d in the pieces - %d interface copies = %d (summary %d)" % (len(gids), copies, len(unique), P))
    assert len(unique) == P and unique[0] == 0 and unique[-1] == P - 1, \
        "GlobalPointIds are not 0..%d (%d distinct ids from %d to %d)" % (P - 1, len(unique), unique[0], unique[-1])
    assert copies > 0 or ranks == 1, "no point is shared between the pieces"
    table = np.empty((P, 3))
    table[gids] = coords
    assert np.array_equal(table[gids].view(np.uint64), coords.view(np.uint64)), \
        "one global point id has different coordinates in different pieces"
    counts = np.bincount(gids[owned], minlength=P)
    assert np.all(counts == 1), "points owned %s times (vtkGhostType)" % np.unique(counts).tolist()

    cell_ids = np.concatenate(cell_ids)
    assert np.array_equal(np.sort(cell_ids), np.arange(T)), "GlobalCellIds are not 0..T-1 once each"
    subdomains = np.concatenate(subdomains)
    assert np.array_equal(np.unique(subdomains), np.arange(K)), np.unique(subdomains)

    volumes = tet_volumes(table[tets])
    assert volumes.min() > 0, "a tetrahedron has non-positive volume %g" % volumes.min()
    faces = np.sort(np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 3]],
                                    tets[:, [1, 2, 3]]]), axis=1)
    keys, use = np.unique(faces, axis=0, return_counts=True)
    assert use.max() <= 2, "a face is shared by more than two tetrahedra"
    boundary = keys[use == 1]
    area = 0.5 * np.linalg.norm(np.cross(table[boundary[:, 1]] - table[boundary[:, 0]],
                                         table[boundary[:, 2]] - table[boundary[:, 0]]), axis=1).sum()

    surface = meshio.read(surface_file)
    triangles = np.concatenate([b.data for b in surface.cells if b.type == "triangle"]).astype(np.int64)
    surface_volume, surface_area = surface_volume_and_area(np.asarray(surface.points, dtype=np.float64), triangles)
    print("volume %.9g (surface %.9g), boundary area %.9g (surface %.9g), %d boundary faces" % (
        volumes.sum(), abs(surface_volume), area, surface_area, len(boundary)))
    assert abs(volumes.sum() / abs(surface_volume) - 1) < 1e-4, "the mesh volume differs from the surface's"
    assert abs(area / surface_area - 1) < 1e-4, "the mesh boundary area differs from the surface's"
    print("meshio_pvtu: passed")


if __name__ == "__main__":
    main(sys.argv[1:])
