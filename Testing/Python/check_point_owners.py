"""Checks which rank owns each point of a written mesh, independently of the
mesher: every global point is owned (vtkGhostType without DUPLICATEPOINT) by
exactly one piece, the rank of the lowest subdomain with a tetrahedron on the
point. Ownership is settled by a rendezvous between ranks
(minimumOverHolders in Filters/RankCollectives.h); a point whose lowest
subdomain is known to one of its ranks only is the case this catches.

    pvbatch check_point_owners.py MESH.pvtu
"""
import os
import sys
from xml.etree import ElementTree

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def pieces(pvtu):
    """The piece files of a .pvtu, in piece (rank) order."""
    folder = os.path.dirname(os.path.abspath(pvtu))
    return [os.path.join(folder, piece.get("Source")) for piece in ElementTree.parse(pvtu).iter("Piece")]


def main(pvtu):
    lowest, owners, rank_of_subdomain = {}, {}, {}
    for rank, name in enumerate(pieces(pvtu)):
        if not os.path.exists(name):
            print("missing piece %s" % name)
            return 1
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(name)
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfCells() == 0:
            continue
        gids = vtk_to_numpy(grid.GetPointData().GetGlobalIds()).astype(np.int64)
        ghosts = vtk_to_numpy(grid.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName()))
        tets = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
        subdomains = vtk_to_numpy(grid.GetCellData().GetArray("SubdomainId")).astype(np.int64)
        for s in np.unique(subdomains):
            assert rank_of_subdomain.setdefault(int(s), rank) == rank, "subdomain %d in two pieces" % s
        here = np.full(len(gids), np.iinfo(np.int64).max)
        np.minimum.at(here, tets.ravel(), np.repeat(subdomains, 4))
        for gid, s, ghost in zip(gids.tolist(), here.tolist(), ghosts.tolist()):
            lowest[gid] = min(lowest.get(gid, s), s)
            if not ghost & vtkDataSetAttributes.DUPLICATEPOINT:
                owners.setdefault(gid, []).append(rank)
    if not lowest:
        print("no tetrahedra read from %s" % pvtu)
        return 1
    wrong = [g for g, s in lowest.items() if owners.get(g, []) != [rank_of_subdomain[s]]]
    print("%d points in %d subdomains, %d owned by another rank than their lowest subdomain's (or not once)"
          % (len(lowest), len(rank_of_subdomain), len(wrong)))
    for g in wrong[:5]:
        print("  point %d: lowest subdomain %d (rank %d), owned by %s"
              % (g, lowest[g], rank_of_subdomain[lowest[g]], owners.get(g, [])))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
