"""The benchmark inputs: closed surfaces made here, never downloaded.

A case is a surface and a target edge length H. H is chosen so that the
mesh has about the case's target number of tetrahedra: TetGen's quality mesh
with the volume bound of a regular tetrahedron of edge H has about
2 x volume / bound tetrahedra (the estimate in TetGenSubdomainMesher.h), so
H = (2 x volume x 6 sqrt(2) / target)^(1/3). The surface is then meshed with
the same H, so surface and interior have one resolution. The real counts
differ from the target by up to about 20 % and are what the report shows.

Every surface is written as binary STL (read by ParaView and Gmsh) and as
OFF with coincident points merged (read by serial_tetgen).
"""
import math
import os
import subprocess
from dataclasses import dataclass

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
BALL_GEO = os.path.join(ROOT, "Data", "geo", "ball.geo")
BALL_GEO_SIZE = 0.12  # the size ball.geo sets; -clscale scales it
FLANGE_GEO = os.path.join(HERE, "flange.geo")
TETRAHEDRA_PER_BOUND_VOLUME = 2.0


@dataclass
class Case:
    name: str           # e.g. ball_5M
    shape: str          # ball, flange, organic
    target: float       # tetrahedra wanted
    description: str
    size: float = 0.0   # H, set by prepare()
    stl: str = ""
    off: str = ""
    surface_triangles: int = 0
    volume: float = 0.0

    @property
    def maximum_volume(self):
        """TetGen's -a bound: a regular tetrahedron of edge H, as tetmesh.py --size H."""
        return regular_tetrahedron_volume(self.size)


def regular_tetrahedron_volume(edge):
    return edge ** 3 / (6.0 * math.sqrt(2.0))


def size_for(volume, target):
    return (TETRAHEDRA_PER_BOUND_VOLUME * volume * 6.0 * math.sqrt(2.0) / target) ** (1.0 / 3.0)


def default_cases(quick):
    """The four cases; quick mode keeps the shapes and shrinks the meshes
    about tenfold so a whole run takes a couple of minutes."""
    scale = 0.1 if quick else 1.0
    return [
        Case("ball_1M" if not quick else "ball_100k", "ball", 1e6 * scale, "unit ball"),
        Case("ball_5M" if not quick else "ball_400k", "ball", (5e6 if not quick else 4e5),
             "unit ball, the large case"),
        Case("flange_1M" if not quick else "flange_100k", "flange", 1e6 * scale,
             "CAD-like flange (flange.geo, OpenCASCADE booleans)"),
        Case("organic_1M" if not quick else "organic_100k", "organic", 1e6 * scale,
             "scanned-like organic surface (organic_surface.py)"),
    ]


def _gmsh_surface(geo, out_stl, size, log):
    if geo == BALL_GEO:
        options = ["-clscale", repr(size / BALL_GEO_SIZE)]
    else:
        options = ["-setnumber", "h", repr(size)]
    subprocess.run(["gmsh", "-2", geo] + options + ["-format", "stl", "-bin", "-o", out_stl],
                   check=True, stdout=log, stderr=subprocess.STDOUT)


def _make_surface(shape, size, out_stl, log):
    if shape == "ball":
        _gmsh_surface(BALL_GEO, out_stl, size, log)
    elif shape == "flange":
        _gmsh_surface(FLANGE_GEO, out_stl, size, log)
    elif shape == "organic":
        import organic_surface

        sphere = out_stl[:-4] + "_sphere.stl"
        _gmsh_surface(BALL_GEO, sphere, size, log)
        organic_surface.main(sphere, out_stl)
        os.remove(sphere)
    else:
        raise ValueError(shape)


def _merged(stl):
    import meshio

    m = meshio.read(stl)
    points, inverse = np.unique(m.points.astype(np.float64), axis=0, return_inverse=True)
    return points, inverse.reshape(-1)[m.cells_dict["triangle"]]


def enclosed_volume(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    return abs(float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6.0)


def prepare(case, folder):
    """Makes the case's surface (cached in folder) and sets its size."""
    import meshio

    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "surfaces.log"), "a") as log:
        # the volume from a coarse version of the same shape fixes H
        coarse = os.path.join(folder, "%s_coarse.stl" % case.shape)
        if not os.path.isfile(coarse):
            _make_surface(case.shape, 0.1, coarse, log)
        case.size = size_for(enclosed_volume(*_merged(coarse)), case.target)
        stem = os.path.join(folder, "%s_h%.5f" % (case.shape, case.size))
        case.stl, case.off = stem + ".stl", stem + ".off"
        if not (os.path.isfile(case.stl) and os.path.isfile(case.off)):
            _make_surface(case.shape, case.size, case.stl, log)
            points, triangles = _merged(case.stl)
            meshio.write(case.off, meshio.Mesh(points, [("triangle", triangles)]))
    points, triangles = _merged(case.stl)
    case.surface_triangles = len(triangles)
    case.volume = enclosed_volume(points, triangles)
    return case
