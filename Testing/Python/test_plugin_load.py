"""The plugin loads on every rank of `mpiexec -n N pvbatch --symmetric`, its
proxies exist, ParaView's reader factory gives *.off files to the OFF reader,
and reading the bundled surfaces gives the right counts in total (rank 0
reads, the other ranks hold empty pieces). Every rank checks; the results are
reduced so that a failure on any rank fails the test on all of them.

    mpiexec -n N pvbatch --symmetric test_plugin_load.py PLUGIN DATA_DIR N
"""
import os
import sys

import ptm_testing as t
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (LoadPlugin defines the proxies here)

from vtkmodules.util.numpy_support import vtk_to_numpy

# file -> (points, triangles, polygons of the file): counts from the headers;
# the 6 quads of cube.off become 12 triangles
EXPECTED = {
    "cube.off": (8, 12, 6),
    "ball.off": (1136, 2268, 2268),
    "bracket.off": (2483, 4970, 4970),
}


def main():
    expected_ranks = t.use_arguments(sys.argv[1:])
    # really one MPI job of N ranks, not N serial runs
    assert t.size() == expected_ranks, "%d ranks, expected %s" % (t.size(), expected_ranks)
    partitions = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    assert partitions == expected_ranks, "servermanager sees %d partitions" % partitions

    LoadPlugin(t.PLUGIN, remote=False, ns=globals())  # noqa: F405
    assert "OFFSurfaceReader" in globals(), "LoadPlugin did not define OFFSurfaceReader"
    pxm = servermanager.ProxyManager()
    assert pxm.GetPrototypeProxy("sources", "OFFSurfaceReader") is not None, "no OFFSurfaceReader proxy"
    for name in ("VolumeBalancedCutter", "InterfaceTriangulator", "SurfaceRelaxer", "ParallelTetMesher", "AlphaWrap",
                 "SurfaceRemesher"):
        assert pxm.GetPrototypeProxy("filters", name) is not None, "no %s proxy" % name

    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    cube = os.path.join(t.DATA, "cube.off")
    assert factory.CanReadFile(cube, servermanager.ActiveConnection.Session), "no reader for *.off"
    assert factory.GetReaderName() == "OFFSurfaceReader", factory.GetReaderName()

    for name, (points, triangles, polygons) in EXPECTED.items():
        reader = OpenDataFile(os.path.join(t.DATA, name))  # noqa: F405
        assert reader is not None and reader.GetXMLName() == "OFFSurfaceReader", name
        reader.UpdatePipeline()
        local = reader.GetClientSideObject().GetOutputDataObject(0)
        got = (local.GetNumberOfPoints(), local.GetNumberOfCells())
        want = (points, triangles) if t.rank() == 0 else (0, 0)
        assert got == want, "%s: rank %d holds %s, expected %s" % (name, t.rank(), got, want)
        # totals over the ranks, by an MPI reduction and by ParaView's data information
        totals = (t.all_ranks_sum(got[0]), t.all_ranks_sum(got[1]))
        assert totals == (points, triangles), "%s: totals %s" % (name, totals)
        if t.rank() == 0:  # ParaView gathers the data information of all ranks on rank 0
            info = reader.GetDataInformation()
            assert (info.GetNumberOfPoints(), info.GetNumberOfCells()) == (points, triangles), name
        assert local.GetPolys().GetNumberOfConnectivityIds() == 3 * got[1], "%s: not all triangles" % name
        if t.rank() == 0:
            source = local.GetCellData().GetArray("SourcePolygonId")
            assert source is not None, "%s: no SourcePolygonId" % name
            ids = vtk_to_numpy(source)
            assert ids.min() == 0 and ids.max() == polygons - 1, name
            assert (ids[1:] >= ids[:-1]).all(), "%s: SourcePolygonId not in file order" % name
        Delete(reader)  # noqa: F405

    # the cube's geometry survives the trip through the proxy
    reader = OFFSurfaceReader(FileName=cube)  # noqa: F405
    reader.UpdatePipeline()
    if t.rank() == 0:
        bounds = reader.GetDataInformation().GetBounds()
        assert tuple(bounds) == (0, 1, 0, 1, 0, 1), bounds


t.run_checks(main)
