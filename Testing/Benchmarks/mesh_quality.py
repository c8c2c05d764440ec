"""Quality of a tetrahedral mesh, computed the same way for every peer.

Every mesher's output (the pipeline's .pvtu pieces with VTK's XML reader,
serial TetGen's legacy .vtk and Gmsh's .msh with meshio) is measured here
with numpy, so the
figures compare like with like instead of mixing ParaView's Mesh Quality,
TetGen's and Gmsh's own statistics:

* minimum dihedral angle (degrees) over all tetrahedra,
* share of tetrahedra whose smallest dihedral angle is under 10 degrees,
* maximum radius-edge ratio (circumradius over shortest edge; TetGen's -q
  bound is on this ratio, 2.0 by default).

    /usr/bin/python3 mesh_quality.py MESH [MESH ...]     # prints one JSON per mesh
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

# Tetrahedra are processed in chunks so a 20 M-tetrahedron mesh does not need
# tens of temporary arrays of its full length at once.
CHUNK = 1 << 20

# The six edges of a tetrahedron and, for each, the two faces meeting there
# (face f is the face opposite vertex f).
EDGES = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]


def _chunk_quality(points, tets):
    p = points[tets]  # (n, 4, 3)
    # outward normal of the face opposite each vertex
    normals = np.empty((len(tets), 4, 3))
    for f in range(4):
        a, b, c = [k for k in range(4) if k != f]
        n = np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
        inward = np.einsum("ij,ij->i", n, p[:, f] - p[:, a]) > 0
        n[inward] *= -1
        normals[:, f] = n
    lengths = np.linalg.norm(normals, axis=2)
    lengths[lengths == 0] = np.inf  # a degenerate face: its angles come out 90, the volume test below catches it
    normals /= lengths[:, :, None]
    # the dihedral angle at an edge is pi minus the angle between the outward
    # normals of the two faces that share it, i.e. the faces opposite the two
    # vertices not on the edge
    smallest = np.full(len(tets), np.pi)
    for i, j in EDGES:
        fi, fj = [k for k in range(4) if k not in (i, j)]
        cosine = -np.einsum("ij,ij->i", normals[:, fi], normals[:, fj])
        smallest = np.minimum(smallest, np.arccos(np.clip(cosine, -1.0, 1.0)))
    smallest = np.degrees(smallest)

    # circumradius from the vertex d: |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b) over 2 a.(b x c)
    a, b, c = p[:, 0] - p[:, 3], p[:, 1] - p[:, 3], p[:, 2] - p[:, 3]
    bc, ca, ab = np.cross(b, c), np.cross(c, a), np.cross(a, b)
    six_volume = np.einsum("ij,ij->i", a, bc)
    numerator = (np.einsum("ij,ij->i", a, a)[:, None] * bc + np.einsum("ij,ij->i", b, b)[:, None] * ca
                 + np.einsum("ij,ij->i", c, c)[:, None] * ab)
    with np.errstate(divide="ignore", invalid="ignore"):
        radius = np.linalg.norm(numerator, axis=1) / np.abs(2 * six_volume)
    shortest = np.min([np.linalg.norm(p[:, j] - p[:, i], axis=1) for i, j in EDGES], axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(six_volume != 0, radius / shortest, np.inf)
    smallest[six_volume == 0] = 0.0
    return smallest, ratio, int(np.count_nonzero(six_volume == 0))


class QualityAccumulator:
    """Quality over several pieces of one mesh (the pipeline writes one per rank)."""

    def __init__(self):
        self.tetrahedra = 0
        self.minimum_dihedral = 180.0
        self.below_10 = 0
        self.maximum_radius_edge = 0.0
        self.flat = 0
        self.histogram_edges = np.linspace(0, 90, 91)
        self.histogram = np.zeros(90, dtype=np.int64)

    def add(self, points, tets):
        points = np.asarray(points, dtype=np.float64)
        tets = np.asarray(tets, dtype=np.int64)
        for start in range(0, len(tets), CHUNK):
            dihedral, ratio, flat = _chunk_quality(points, tets[start:start + CHUNK])
            self.tetrahedra += len(dihedral)
            if len(dihedral):
                self.minimum_dihedral = min(self.minimum_dihedral, float(dihedral.min()))
                self.maximum_radius_edge = max(self.maximum_radius_edge, float(ratio.max()))
            self.below_10 += int(np.count_nonzero(dihedral < 10.0))
            self.flat += flat
            self.histogram += np.histogram(np.minimum(dihedral, 89.999), bins=self.histogram_edges)[0]

    def result(self):
        return {
            "tetrahedra": self.tetrahedra,
            "minimum_dihedral_angle_degrees": self.minimum_dihedral,
            "share_below_10_degrees": self.below_10 / float(max(self.tetrahedra, 1)),
            "maximum_radius_edge_ratio": self.maximum_radius_edge,
            "zero_volume_tetrahedra": self.flat,
            # smallest dihedral angle per tetrahedron, 1-degree bins from 0 to 90
            "smallest_dihedral_histogram": self.histogram.tolist(),
        }


def piece_files(path):
    """The files that hold a mesh: the pieces of a .pvtu or .pvtp, else the file itself."""
    if not path.endswith((".pvtu", ".pvtp")):
        return [path]
    root = ET.parse(path).getroot()
    folder = os.path.dirname(os.path.abspath(path))
    return [os.path.join(folder, piece.get("Source")) for piece in root.iter("Piece")]


def read_vtu(path, cell_type="tetra"):
    """(points, GlobalPointIds or None, cells of cell_type) of a .vtu piece,
    read with VTK's own XML reader. meshio 5.0 misreads the pieces' raw
    appended arrays (it looks them up by offset among those it has already
    renamed): on a K = 5 mesh it failed with "buffer size must be a multiple
    of element size", so until session 20 the sweeps measured no odd K."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    gids = grid.GetPointData().GetArray("GlobalPointIds")
    gids = None if gids is None else vtk_to_numpy(gids).astype(np.int64).ravel()
    size = 4 if cell_type == "tetra" else 3
    vtk_type = 10 if cell_type == "tetra" else 5  # VTK_TETRA, VTK_TRIANGLE
    if grid.GetNumberOfCells() == 0:
        return np.zeros((0, 3)), gids, np.zeros((0, size), dtype=np.int64)
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
    types = vtk_to_numpy(grid.GetCellTypesArray())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray()).astype(np.int64)
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).astype(np.int64)
    chosen = np.where(types == vtk_type)[0]
    if ((offsets[chosen + 1] - offsets[chosen]) != size).any():
        raise ValueError("%s: cells of type %d without %d points" % (path, vtk_type, size))
    return points, gids, conn[offsets[chosen][:, None] + np.arange(size)]


def read_tetrahedra(piece):
    """(points, tetrahedra) of one file: a .vtu piece with VTK's reader
    (read_vtu), the other peers' files with meshio, whose Gmsh reader prints
    blank lines to stdout, which would break the driver's tables, so it is
    silenced."""
    import contextlib
    import io

    if piece.endswith(".vtu"):
        points, _, tets = read_vtu(piece)
        return points, tets
    import meshio

    with contextlib.redirect_stdout(io.StringIO()):
        mesh = meshio.read(piece)
    tets = [block.data for block in mesh.cells if block.type == "tetra"]
    return mesh.points, (np.concatenate(tets) if tets else np.zeros((0, 4), dtype=np.int64))


def count_tetrahedra(path):
    return sum(len(read_tetrahedra(piece)[1]) for piece in piece_files(path))


def mesh_quality(path):
    accumulator = QualityAccumulator()
    for piece in piece_files(path):
        points, tets = read_tetrahedra(piece)
        accumulator.add(points, tets)
    return accumulator.result()


if __name__ == "__main__":
    for argument in sys.argv[1:]:
        q = mesh_quality(argument)
        q.pop("smallest_dihedral_histogram")
        print(json.dumps(dict(q, mesh=argument)))
