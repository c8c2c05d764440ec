"""Faults on one rank make every rank fail (or abort) from the same update,
with the message, never a hang and never a partial output that looks
complete. Run with 2 ranks (also passes with 1):

    mpiexec -n 2 pvbatch --symmetric test_rank_faults.py PLUGIN DATA_DIR 2

1. a TetGen-stage failure in one subdomain only: the bar of
   Data/bad/bar_with_crossing_box.stl crosses a small box at its far end;
   with the cutter's self-intersection check off, only the subdomain at that
   end (on the last rank) fails in ParallelTetMesher;
2. an abort asked on the last rank only, in the middle of ParallelTetMesher;
   the next update (without the abort) meshes normally;
3. impossible requests: a size whose mesh would not fit in memory (asked of
   the mesher, and of the cutter, which refuses it before cutting), an
   interface edge length far too short, and nonsense property values.
A hang fails the test by CTest's timeout; every case prints its time.
"""
import os
import shutil
import sys
import tempfile
import time

import ptm_testing as t
from paraview import simple


def outputs_empty(mesher):
    obj = mesher.GetClientSideObject()
    return all(obj.GetOutputDataObject(p).GetNumberOfCells() == 0 for p in (0, 1))


def expect_failure(label, proxies, expected, absent=None):
    start = time.time()
    catchers = [t.ErrorCatcher(p.GetClientSideObject()) for p in proxies]
    proxies[-1].UpdatePipeline()
    text = "\n".join(c.text for c in catchers if c.messages)
    assert expected in text, "%s: rank %d: no error saying %r:\n%s" % (label, t.rank(), expected, text)
    assert absent is None or absent not in text, "%s: the error also names %r, which is not wrong:\n%s" % (label, absent, text)
    assert outputs_empty(proxies[-1]), "%s: rank %d: output not empty" % (label, t.rank())
    assert t.all_ranks_true(True)
    if t.rank() == 0:
        line = [m for m in text.split("\n") if expected in m][0]
        print("%-34s every rank failed in %.2f s: ...%s" % (label, time.time() - start, line[-150:]))
        sys.stdout.flush()
    return text


def pipeline(path, K, **cutter_properties):
    reader = simple.OpenDataFile(path)
    cutter = simple.VolumeBalancedCutter(Input=reader, NumberOfSubdomains=K, **cutter_properties)
    interfaces = simple.InterfaceTriangulator(Input=cutter)
    relaxed = simple.SurfaceRelaxer(Input=interfaces)
    mesher = simple.ParallelTetMesher(Input=relaxed)
    return [reader, cutter, interfaces, relaxed, mesher]


def delete(proxies):
    for p in reversed(proxies):
        simple.Delete(p)


def main():
    expected_ranks = t.use_arguments(sys.argv[1:])
    assert t.size() == expected_ranks, "%d ranks, expected %s" % (t.size(), expected_ranks)
    t.load_plugin()
    last = t.size() - 1

    # 1. one subdomain fails, on one rank
    proxies = pipeline(os.path.join(t.DATA, "bad", "bar_with_crossing_box.stl"), 2,
                       Strategy="ParallelPlanes", Direction="X", CheckSelfIntersections=0)
    who = ("rank %d: " % last) if t.size() > 1 else ""
    # the failed subdomain's surface is kept where PTM_FAILED_SURFACE_DIR says
    keep = tempfile.mkdtemp(prefix="ptm_failed_")
    os.environ["PTM_FAILED_SURFACE_DIR"] = keep
    kept = os.path.join(keep, "subdomain-1.off")
    text = expect_failure("failure in subdomain 1 only", proxies, who + "subdomain 1: the surface intersects itself")
    del os.environ["PTM_FAILED_SURFACE_DIR"]
    if t.rank() == last:
        assert "(its surface: %s)" % kept in text, text
        with open(kept) as f:
            head = f.read().split("\n")[:2]
        triangles = int(head[1].split()[1])
        with open(os.path.join(keep, "subdomain-1.sides")) as f:
            sides = [int(x) for x in f.read().split()]
        assert head[0] == "OFF" and triangles > 0 and len(sides) == triangles and sides.count(0) > 0, (head, len(sides))
        print("the failed subdomain kept: %d triangles, %d on the interface" % (triangles, sides.count(0)))
    shutil.rmtree(keep)
    delete(proxies)

    # 2. abort on the last rank only, in the middle of the volume meshing
    proxies = pipeline(os.path.join(t.DATA, "ball.stl"), 2 * t.size())
    mesher = proxies[-1].GetClientSideObject()
    asked = []

    def ask_abort(obj, event):
        if t.rank() == last and not asked:
            asked.append(True)
            obj.SetAbortExecute(1)

    tag = mesher.AddObserver("ProgressEvent", ask_abort)
    start = time.time()
    proxies[-1].UpdatePipeline()
    assert outputs_empty(proxies[-1]), "rank %d: output not empty after the abort" % t.rank()
    assert t.all_ranks_sum(len(asked)) == 1
    if t.rank() == 0:
        print("%-34s every rank aborted in %.2f s" % ("abort asked on rank %d" % last, time.time() - start))
    mesher.RemoveObserver(tag)
    # an aborted update leaves empty outputs until the filter is modified
    proxies[-1].UpdatePipeline()
    assert t.all_ranks_sum(mesher.GetOutputDataObject(0).GetNumberOfCells()) == 0
    mesher.Modified()
    proxies[-1].MarkModified(proxies[-1])
    proxies[-1].UpdatePipeline()
    tets = t.all_ranks_sum(mesher.GetOutputDataObject(0).GetNumberOfCells())
    assert tets > 0, "no mesh after the abort was lifted"
    if t.rank() == 0:
        print("%-34s %d tetrahedra" % ("the next update", tets))

    # 3. impossible requests
    proxies[-1].MaximumVolume = 1e-13
    expect_failure("a mesh that cannot fit in memory", proxies, "would give about")
    proxies[-1].MaximumVolume = 0
    # the same for the cutter's size, refused before any cut (without that
    # check this pipeline, whose mesher sizes itself, meshed the ball in
    # 19 s and said nothing; tetmesh.py, which gives every stage the size,
    # spent minutes on the bracket's interfaces at --size 0.001)
    proxies[1].MaximumSize = 1e-4
    text = expect_failure("a size that cannot fit in memory", proxies, "the requested size (MaximumSize 0.0001)")
    assert "VolumeBalancedCutter failed" in text, text
    proxies[1].MaximumSize = 0
    # a size field is checked after the cuts, from the predicted tetrahedra
    # (the cutter's field is the one the mesher is to use; this pipeline's
    # mesher has none and, without the check, meshed at its own size;
    # tetmesh.py --size-expression 0.001, which gives every stage the
    # field, ran into the interface triangulations for minutes)
    proxies[1].SizeExpression = "0.001"
    expect_failure("a size field that cannot fit", proxies, "the requested size (SizeExpression '0.001') would give at least")
    proxies[1].SizeExpression = ""
    # and the triangulator's edge length, where an interface would need more
    # points than one may get (without the check: minutes, then edges
    # longer than asked)
    proxies[2].MaximumEdgeLength = 1e-4
    expect_failure("an interface edge far too short", proxies, "the requested size (MaximumEdgeLength 0.0001)")
    proxies[2].MaximumEdgeLength = 0
    proxies[-1].RadiusEdgeRatio = 0.5
    expect_failure("RadiusEdgeRatio 0.5", proxies, "ParallelTetMesher: RadiusEdgeRatio must lie in [1, 100], not 0.5")
    proxies[-1].RadiusEdgeRatio = 2
    proxies[-1].BoundarySpacingFloor = 0
    expect_failure("BoundarySpacingFloor 0", proxies,
                   "ParallelTetMesher: BoundarySpacingFloor must lie in [1/1024, 1] (a fraction of the local size), not 0")
    proxies[-1].BoundarySpacingFloor = 0.125
    proxies[2].MinimumAngle = 50
    expect_failure("MinimumAngle 50", proxies, "InterfaceTriangulator: MinimumAngle must lie in [1, 34] degrees, not 50",
                   absent="MaximumEdgeLength")
    proxies[2].MinimumAngle = 20.7
    proxies[3].RelaxationFactor = -1
    expect_failure("RelaxationFactor -1", proxies, "SurfaceRelaxer: RelaxationFactor must lie in [0.01, 1], not -1")
    proxies[3].RelaxationFactor = 0.5
    proxies[3].MaximumSurfaceDeviation = -1
    expect_failure("MaximumSurfaceDeviation -1", proxies, "SurfaceRelaxer: MaximumSurfaceDeviation must lie in [0, 1] "
                   "(relative to the bounding-box diagonal), not -1")
    proxies[3].MaximumSurfaceDeviation = 0.01
    proxies[1].NumberOfSubdomains = -3
    expect_failure("NumberOfSubdomains -3", proxies, "VolumeBalancedCutter: NumberOfSubdomains must be 0 (one per rank) or between 1 and 1000000, not -3")
    proxies[1].NumberOfSubdomains = 2
    proxies[1].BalanceTolerance = 2
    expect_failure("BalanceTolerance 2", proxies, "VolumeBalancedCutter: BalanceTolerance must lie in [1e-6, 0.5], not 2")
    delete(proxies)


t.run_checks(main)
