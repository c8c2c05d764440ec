"""CAD files and dirty surfaces through the whole pipeline on 2 ranks.

    /usr/bin/python3 test_cad_and_wrap.py CASE PLUGIN OUTPUT_DIR

Runs Scripts/tetmesh.py (mpiexec -n 2 pvbatch) on real files that Debian's
occt-misc ships in /usr/share/opencascade/data (LGPL-2.1 with the OCCT
exception; see Testing/Corpus/MANIFEST.md), then checks the result with the
independent conformity check (Testing/Corpus/conformity.py: numpy and
VTK's XML readers only) against the surface tetmesh meshed (--save-surface):

  step, iges, brep   a CAD solid: conforming, and CADFaceId on the boundary
                     port names a face of the file for every triangle and
                     every face of the file appears;
  wrap-self-intersecting, wrap-non-manifold
                     a model the cutter refuses (the message must name the
                     problem and say --wrap), then meshed with --wrap:
                     conforming, the wrap's distances reported and plausible;
                     the self-intersecting one also on 1 rank, whose wrapped
                     surface must be the same bit for bit;
  remesh             a CAD solid full of long thin triangles (Pump_Nut) meshed
                     exactly and with --remesh: the remeshed run conforms,
                     keeps its figures within the bound, reports the volume
                     change the two surfaces show, keeps every CAD face on the
                     boundary, and has far better tetrahedra than the exact run.
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
# K = 8 at size 2 (the part is about 51 across): both runs under 20 s on 2 cores
REMESH = ("occ/Pump_Nut.brep", ["--subdomains", "8", "--size", "2"])
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


def remesh_case(plugin, out):
    path, extra = REMESH
    source = os.path.join(DATA, path)
    runs = {}
    for mode, more in (("exact", []), ("remesh", ["--remesh"])):
        output = os.path.join(out, "remesh_" + mode)
        run = tetmesh(2, source, output, extra + more, plugin)
        assert run.returncode == 0, "tetmesh %s failed" % mode
        runs[mode] = (output, json.load(open(output + ".json")))
    output, summary = runs["remesh"]
    check_conforming(output)
    report = summary["remesh"]
    print("remesh report: " + json.dumps(report), flush=True)
    exact_surface = surface_tool.stats(runs["exact"][0] + "_surface.off")
    remeshed_surface = surface_tool.stats(output + "_surface.off")
    diagonal = exact_surface["bbox_diagonal"]
    # the bound (0.005 of the diagonal by default) holds on both figures, and
    # the edge length is the size or a halving of it
    assert max(report["largest_distance_remeshed_to_input"], report["largest_distance_input_to_remeshed"]) \
        <= 0.005 * diagonal, report
    assert report["edge_length"] in (2.0, 1.0, 0.5), report
    assert report["feature_edges"] > 0 and report["triangles"] == remeshed_surface["triangles"], report
    change = (remeshed_surface["volume"] - exact_surface["volume"]) / exact_surface["volume"]
    assert abs(change - report["volume_change_relative"]) < 1e-9 and abs(change) < 0.01, (change, report)
    exact_quality, remesh_quality = runs["exact"][1]["quality"], summary["quality"]
    print("exact: %.3f deg, %.3f %% under 10; remeshed: %.3f deg, %.3f %%" % (
        exact_quality["minimum_dihedral_angle_degrees"], 100 * exact_quality["share_below_10_degrees"],
        remesh_quality["minimum_dihedral_angle_degrees"], 100 * remesh_quality["share_below_10_degrees"]))
    # the CAD faces survive the remeshing: every one of the part's 25 names
    # boundary triangles
    ids = np.unique(boundary_cell_array(output, "CADFaceId"))
    assert ids.min() >= 0 and len(ids) == 25 and ids.max() == 24, ids
    # measured: 0.023 -> 0.026 degrees, 0.944 -> 0.759 % under 10 degrees
    # (the borders of the 25 CAD faces are kept, with their small corners;
    # without them, 0.23 degrees and 0.38 %)
    assert remesh_quality["minimum_dihedral_angle_degrees"] >= exact_quality["minimum_dihedral_angle_degrees"]
    assert remesh_quality["share_below_10_degrees"] < 0.9 * exact_quality["share_below_10_degrees"]


def main(argv):
    name, plugin, out = argv
    if not os.path.isdir(DATA):
        print("SKIP: %s is missing (install occt-misc: Scripts/install-deps.sh)" % DATA)
        return 77
    os.makedirs(out, exist_ok=True)
    if name == "remesh":
        remesh_case(plugin, out)
    else:
        (wrap_case if name.startswith("wrap") else cad_case)(name, plugin, out)
    print("PASS " + name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
