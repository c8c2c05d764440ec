"""The CAD reader in ParaView: the reader factory gives *.step, *.iges and
*.brep files to it, OpenDataFile reads them (rank 0 holds the surface, the
other ranks empty pieces) with CADFaceId on every triangle, and bad files
(unreadable, no solid, a solid index out of range) give an error naming the
file and the problem on every rank, through the cutter too, without hanging.
OpenCASCADE is loaded only by the first CAD file read (libptmcad.so, beside
the plugin), not by loading the plugin. Reads the sample files of Debian's occt-misc; skipped without them.

    mpiexec -n N pvbatch --symmetric test_cad_reader.py PLUGIN DATA_DIR N
"""
import os
import sys

import ptm_testing as t
from paraview import servermanager, simple

from vtkmodules.util.numpy_support import vtk_to_numpy

OCCT = "/usr/share/opencascade/data"
# file -> (triangles, faces) of the default tessellation (CADTessellationTest)
GOOD = {
    "step/screw.step": (1344, 10),
    "occ/Pump_Nut.brep": (2498, 25),
    "iges/hammer.iges": (2732, 45),
}


def occt_libraries_loaded():
    """OpenCASCADE's libraries mapped into this process."""
    with open("/proc/self/maps") as maps:
        return sorted({line.split()[-1] for line in maps if "/libTK" in line})


def read_good():
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    for name, (triangles, faces) in GOOD.items():
        path = os.path.join(OCCT, name)
        assert factory.CanReadFile(path, servermanager.ActiveConnection.Session), "no reader for " + name
        assert factory.GetReaderName() == "CADSurfaceReader", (name, factory.GetReaderName())
        reader = simple.OpenDataFile(path)
        assert reader is not None and reader.GetXMLName() == "CADSurfaceReader", name
        reader.UpdatePipeline()
        local = reader.GetClientSideObject().GetOutputDataObject(0)
        assert t.all_ranks_sum(local.GetNumberOfCells()) == triangles, name
        if t.rank() == 0:
            ids = vtk_to_numpy(local.GetCellData().GetArray("CADFaceId"))
            assert len(set(ids.tolist())) == faces and ids.min() == 0, (name, sorted(set(ids.tolist())))
        else:
            assert local.GetNumberOfCells() == 0, "rank %d holds a piece of %s" % (t.rank(), name)
        simple.Delete(reader)


def refuse_bad(directory):
    garbage = os.path.join(directory, "garbage.step")
    cases = [
        (garbage, -1, garbage + ": OpenCASCADE cannot read it as a STEP file"),
        (os.path.join(OCCT, "occ/face.brep"), -1, "no solid in the file"),
        (os.path.join(OCCT, "occ/Pump_Nut.brep"), 3, "solid 3 does not exist (the file has 1 solids"),
        (os.path.join(directory, "missing.igs"), -1, "cannot open the file"),
    ]
    for path, solid, expected in cases:
        reader = simple.CADSurfaceReader(FileName=path, SolidIndex=solid)
        cutter = simple.VolumeBalancedCutter(Input=reader)
        caught = t.ErrorCatcher(reader.GetClientSideObject())
        cutter.UpdatePipeline()
        local = cutter.GetClientSideObject().GetOutputDataObject(0)
        assert t.all_ranks_sum(local.GetNumberOfCells()) == 0, path
        # the cutter asks every rank for the whole surface: every rank reads and fails
        assert expected in caught.errors_text, "rank %d: %r lacks %r" % (t.rank(), caught.errors_text, expected)
        simple.Delete(cutter)
        simple.Delete(reader)


def main():
    expected_ranks = t.use_arguments(sys.argv[1:])
    assert t.size() == expected_ranks, "%d ranks, expected %s" % (t.size(), expected_ranks)
    if not os.path.isdir(OCCT):
        print("SKIP: %s is missing (install occt-misc)" % OCCT)
        return
    t.load_plugin()
    # every run of an STL or OFF file would pay 0.35-0.52 s and 18 MB per rank for them
    assert not occt_libraries_loaded(), "loading the plugin loaded %s" % occt_libraries_loaded()
    pxm = servermanager.ProxyManager()
    assert pxm.GetPrototypeProxy("sources", "CADSurfaceReader") is not None, "no CADSurfaceReader proxy"
    assert pxm.GetPrototypeProxy("filters", "AlphaWrap") is not None, "no AlphaWrap proxy"
    directory = os.path.join(t.OUTPUT, "cad_reader_np%d" % t.size())
    if t.rank() == 0:
        os.makedirs(directory, exist_ok=True)
        with open(os.path.join(directory, "garbage.step"), "w") as f:
            f.write("ISO-10303-21;\nthis is not a STEP file\n")
    t.barrier()
    read_good()
    refuse_bad(directory)  # through the cutter, which has every rank read
    assert occt_libraries_loaded(), "rank %d read CAD files without OpenCASCADE" % t.rank()


t.run_checks(main)
