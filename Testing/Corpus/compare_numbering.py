"""Do two pipeline meshes of one input have the same tetrahedra and the same global numbering?

    /usr/bin/python3 Testing/Corpus/compare_numbering.py A.pvtu B.pvtu

The pieces of a .pvtu depend on the rank count (which subdomains a piece
holds, the order of its points, the interface points it repeats), so
comparing the arrays of two runs on 2 and 3 ranks says nothing. This takes
each mesh's owned tetrahedra (vtkGhostType 0) in GlobalCellIds order, each as
the GlobalPointIds of its corners, and every global point id with its
coordinates, and compares those. Exit status 0 when both are equal.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy as v2n
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader


def load(path):
    reader = vtkXMLPUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    points = v2n(grid.GetPoints().GetData())
    cells = v2n(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    point_ids = v2n(grid.GetPointData().GetArray("GlobalPointIds"))
    cell_ids = v2n(grid.GetCellData().GetArray("GlobalCellIds"))
    ghost = grid.GetCellData().GetArray("vtkGhostType")
    owned = np.ones(len(cells), bool) if ghost is None else v2n(ghost) == 0
    tets = point_ids[cells[owned]][np.argsort(cell_ids[owned], kind="stable")]
    coordinates = {}
    for i, gid in enumerate(point_ids):
        coordinates.setdefault(int(gid), tuple(points[i]))
    return tets, coordinates


def main():
    a_tets, a_points = load(sys.argv[1])
    b_tets, b_points = load(sys.argv[2])
    same_tets = np.array_equal(a_tets, b_tets)
    same_points = a_points == b_points
    print("tetrahedra %d and %d; same tetrahedra by global ids: %s; same coordinates per global point id: %s"
          % (len(a_tets), len(b_tets), same_tets, same_points))
    sys.exit(0 if same_tets and same_points else 1)


if __name__ == "__main__":
    main()
