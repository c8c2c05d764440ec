"""The plugin loads on every rank, its proxies exist, and the OFF reader is
registered for *.off and reads the bundled cube with the right counts."""
import os

import ptm_testing as t
from paraview import simple, servermanager


def main():
    t.load_plugin()
    for group, name in [("sources", "OFFSurfaceReader"), ("filters", "VolumeBalancedCutter"),
                        ("filters", "InterfaceTriangulator"), ("filters", "SurfaceRelaxer"),
                        ("filters", "ParallelTetMesher")]:
        proxy = servermanager.ProxyManager().NewProxy(group, name)
        assert proxy is not None, "proxy %s/%s missing on rank %d" % (group, name, t.rank())
    reader = simple.OpenDataFile(os.path.join(t.DATA, "cube.off"))
    assert reader is not None, "OpenDataFile does not know *.off"
    assert reader.GetXMLName() == "OFFSurfaceReader", reader.GetXMLName()
    reader.UpdatePipeline()
    local = reader.GetClientSideObject().GetOutputDataObject(0)
    # rank 0 reads the file, the other ranks hold empty pieces
    expected = (8, 12) if t.rank() == 0 else (0, 0)
    got = (local.GetNumberOfPoints(), local.GetNumberOfCells())
    assert got == expected, "rank %d holds %s, expected %s" % (t.rank(), got, expected)
    # totals over all ranks: 8 points, 12 triangles from 6 quads
    assert t.all_ranks_sum(got[0]) == 8 and t.all_ranks_sum(got[1]) == 12
    if t.rank() == 0:
        assert local.GetCellData().GetArray("SourcePolygonId") is not None


t.run_checks(main)
