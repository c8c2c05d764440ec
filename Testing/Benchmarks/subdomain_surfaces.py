"""The surface stages for K subdomains on one rank, and every subdomain's
closed surface written as OFF, so each can be meshed and timed on its own.

    pvbatch subdomain_surfaces.py SURFACE.stl K SIZE PLUGIN OUT_FOLDER

The ParallelTetMesher reports only one meshing time per rank
(RankMeshingSeconds), not one per subdomain; the scaling projection needs
each subdomain's time, so this runs the same three surface filters with the
same properties as Scripts/tetmesh.py, times them, and writes what
ParallelTetMesher would mesh: for subdomain s every triangle whose
SubdomainPair holds s, flipped where s is the second entry, in the canonical
order of ptm::extractSubdomainSurface (points by global id, each triangle
starting at its smallest id, triangles sorted), so TetGen sees the same input.
OUT_FOLDER/surfaces.json gets the stage seconds, the cutter's SubdomainMeasure
(what the rank assignment balances), the interface area and the files.
"""
import json
import os
import sys
import time

import numpy as np


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        np.savetxt(f, points, fmt="%.17g")
        np.savetxt(f, np.column_stack([np.full(len(triangles), 3), triangles]), fmt="%d")


def canonical_subdomain_surface(points, global_ids, triangles, pair, s):
    own = triangles[pair[:, 0] == s]
    flipped = triangles[pair[:, 1] == s][:, ::-1]
    tris = global_ids[np.concatenate([own, flipped])]
    # rotate each triangle to start at its smallest global id (keeps orientation)
    first = np.argmin(tris, axis=1)
    rows = np.arange(len(tris))[:, None]
    tris = tris[rows, (first[:, None] + np.arange(3)) % 3]
    tris = tris[np.lexsort((tris[:, 2], tris[:, 1], tris[:, 0]))]
    used = np.unique(tris)
    local = np.searchsorted(used, tris)
    order = np.argsort(global_ids)
    coordinates = points[order[np.searchsorted(global_ids[order], used)]]
    return coordinates, local


def main(stl, subdomains, size, plugin, folder):
    from paraview import servermanager, simple
    from vtkmodules.util.numpy_support import vtk_to_numpy

    simple.LoadPlugin(plugin, remote=False)
    os.makedirs(folder, exist_ok=True)
    seconds = {}
    errors = []

    def on_error(caller, event, message=None):
        errors.append(str(message or "").strip().splitlines()[-1].split("): ", 1)[-1])

    def run(stage, proxy):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING

        proxy.GetClientSideObject().AddObserver("ErrorEvent", calldata_type(VTK_STRING)(on_error))
        start = time.perf_counter()
        proxy.UpdatePipeline()
        seconds[stage] = time.perf_counter() - start
        if errors:
            sys.stderr.write("subdomain_surfaces: %s failed: %s\n" % (stage, errors[0]))
            sys.exit(1)
        return proxy

    # the same filters and properties as Scripts/tetmesh.py
    reader = run("read", simple.OpenDataFile(stl))
    cutter = run("cut", simple.VolumeBalancedCutter(Input=reader, NumberOfSubdomains=subdomains,
                                                    Strategy="RecursiveBisection", Direction="Inertia"))
    interfaces = run("interface", simple.InterfaceTriangulator(Input=cutter, MaximumEdgeLength=size))
    relaxed = run("relax", simple.SurfaceRelaxer(Input=interfaces, NumberOfIterations=10))

    complex_ = servermanager.Fetch(relaxed)
    fd = servermanager.Fetch(cutter).GetFieldData()
    measures = vtk_to_numpy(fd.GetArray("SubdomainMeasure")).tolist()
    volumes = vtk_to_numpy(fd.GetArray("SubdomainVolume")).tolist()
    points = vtk_to_numpy(complex_.GetPoints().GetData()).astype(np.float64)
    global_ids = vtk_to_numpy(complex_.GetPointData().GetArray("GlobalPointIds")).astype(np.int64)
    polys = vtk_to_numpy(complex_.GetPolys().GetConnectivityArray()).astype(np.int64)
    offsets = vtk_to_numpy(complex_.GetPolys().GetOffsetsArray())
    if not np.all(np.diff(offsets) == 3):
        raise SystemExit("subdomain_surfaces: the complex has non-triangle polygons")
    triangles = polys.reshape(-1, 3)
    # cell data runs over vertices, lines, then polygons
    first_poly = complex_.GetNumberOfVerts() + complex_.GetNumberOfLines()
    pair = vtk_to_numpy(complex_.GetCellData().GetArray("SubdomainPair"))[first_poly:first_poly + len(triangles)]

    a, b, c = (points[triangles[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    interface = pair[:, 1] >= 0  # both sides are subdomains
    files = []
    for s in range(subdomains):
        coordinates, local = canonical_subdomain_surface(points, global_ids, triangles, pair, s)
        path = os.path.join(folder, "subdomain_%03d.off" % s)
        write_off(path, coordinates, local)
        files.append(path)
    summary = {
        "subdomains": subdomains,
        "seconds": seconds,
        "surface_stage_seconds": seconds["cut"] + seconds["interface"] + seconds["relax"],
        "subdomain_measure": measures,
        "subdomain_volume": volumes,
        "interface_area": float(area[interface].sum()),
        "boundary_area": float(area[~interface].sum()),
        "interface_triangles": int(np.count_nonzero(interface)),
        "complex_triangles": int(len(triangles)),
        "files": files,
    }
    with open(os.path.join(folder, "surfaces.json"), "w") as f:
        json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5])
