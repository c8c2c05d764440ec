"""CAD files and dirty surfaces through the whole pipeline on 2 ranks.

    /usr/bin/python3 test_cad_and_wrap.py CASE PLUGIN OUTPUT_DIR

Runs Scripts/tetmesh.py (mpiexec -n 2 pvbatch) on real files that Debian's
occt-misc ships in /usr/share/opencascade/data (LGPL-2.1 with the OCCT
exception; see Testing/Corpus/MANIFEST.md), then checks the result with the
independent conformity check (Testing/Corpus/conformity.py: numpy, meshio and
VTK's XML reader only) against the surface tetmesh meshed (--save-surface):

  step, iges, brep   a CAD solid: conforming, and CADFaceId on the boundary
                     port names a face of the file for every triangle and
                     every face of the file appears;
  wrap-self-intersecting, wrap-non-manifold
                     a model the cutter refuses (the message must name the
                     problem and say --wrap), then meshed with --wrap:
                     conforming, the wrap's distances reported and plausible;
                     the self-intersecting one also on 1 rank, whose wrapped
                     surface must be the same bit for bit.
"""
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Corpus"))
import conformity  # noqa: E402
import surface_tool  # noqa: E402

DATA = "/usr/share/opencascade/data"
# file, extra tetmesh arguments, faces in the file (CAD cases)
CASES = {
    "step": ("step/screw.step", [], 10),
    "iges": ("iges/hammer.iges", [], 45),
    "brep": ("occ/Pump_Nut.brep", [], 25),
    # the OCCT bottle tessellated coarsely (1/200 of the diagonal, as the
    # corpus does): two triangles of the thread cross
    "wrap-self-intersecting": ("occ/bottle.brep", ["--cad-deflection", "0.005"], "the surface intersects itself"),
    # the bearing axis: solids that share faces, so non-manifold edges
    "wrap-non-manifold": ("occ/Axis_of_bearing.brep", [], "non-manifold edge"),
}
# alpha 1/50 of the diagonal keeps each wrap under 10 s on 2 cores
WRAP_ARGUMENTS = ["--wrap", "--wrap-alpha", "0.02"]


def tetmesh(ranks, source, output, extra, plugin):
    command = ["mpiexec", "-n", str(ranks), "--oversubscribe", "pvbatch", "--force-offscreen-rendering",
               os.path.join(ROOT, "Scripts", "tetmesh.py"), source, "-o", output + ".pvtu",
               "--json", output + ".json", "--save-surface", output + "_surface.off",
               "--plugin", plugin] + extra
    print("+ " + " ".join(command), flush=True)
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=240)
    print(run.stdout[-3000:], flush=True)
    return run


def check_conforming(output):
    result = conformity.check(output + ".pvtu", surface_tool.stats(output + "_surface.off"))
    print("conformity: " + json.dumps(result), flush=True)
    assert result["conforming"], result["problems"]
    return result


def boundary_cell_array(output, name):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPPolyDataReader

    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(output + "_boundary.pvtp")
    reader.Update()
    array = reader.GetOutput().GetCellData().GetArray(name)
    assert array is not None, "the boundary port has no %s" % name
    return vtk_to_numpy(array)


def cad_case(name, plugin, out):
    path, extra, faces = CASES[name]
    output = os.path.join(out, name)
    run = tetmesh(2, os.path.join(DATA, path), output, extra, plugin)
    assert run.returncode == 0, "tetmesh failed"
    check_conforming(output)
    ids = boundary_cell_array(output, "CADFaceId")
    used = np.unique(ids)
    print("CADFaceId on %d boundary triangles: %d distinct, from %d to %d" % (
        len(ids), len(used), used.min(), used.max()))
    assert used.min() >= 0, "a boundary triangle without a CAD face"
    assert len(used) == faces and used.max() == faces - 1, "expected every one of the %d faces" % faces


def wrap_case(name, plugin, out):
    path, extra, problem = CASES[name]
    source = os.path.join(DATA, path)
    refused = tetmesh(2, source, os.path.join(out, name + "_refused"), extra, plugin)
    assert refused.returncode != 0, "the dirty model was not refused"
    assert problem in refused.stdout and "--wrap" in refused.stdout, "the refusal must name %r and --wrap" % problem

    output = os.path.join(out, name)
    run = tetmesh(2, source, output, extra + WRAP_ARGUMENTS, plugin)
    assert run.returncode == 0, "tetmesh --wrap failed"
    check_conforming(output)
    wrap = json.load(open(output + ".json"))["wrap"]
    # the wrap stays within about alpha of the input (offset where it hugs
    # it, up to alpha where it bridges a concave crease) ...
    assert wrap["offset"] * 0.5 < wrap["largest_distance_wrap_to_input"] < wrap["alpha"] + wrap["sample_spacing"], wrap
    # ... and the input within a few alpha of the wrap, except inner walls
    assert wrap["largest_distance_input_to_wrap"] > 0, wrap
    if name == "wrap-self-intersecting":
        one = tetmesh(1, source, os.path.join(out, name + "_np1"), extra + WRAP_ARGUMENTS, plugin)
        assert one.returncode == 0, "tetmesh --wrap on 1 rank failed"
        with open(output + "_surface.off", "rb") as a, open(os.path.join(out, name + "_np1_surface.off"), "rb") as b:
            assert a.read() == b.read(), "the wrap differs between 1 and 2 ranks"


def main(argv):
    name, plugin, out = argv
    if not os.path.isdir(DATA):
        print("SKIP: %s is missing (install occt-misc: Scripts/install-deps.sh)" % DATA)
        return 77
    os.makedirs(out, exist_ok=True)
    (wrap_case if name.startswith("wrap") else cad_case)(name, plugin, out)
    print("PASS " + name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
