"""Every class of bad input, as a real malformed file of Data/bad/, through
the whole pipeline (reader, VolumeBalancedCutter, InterfaceTriangulator,
SurfaceRelaxer, ParallelTetMesher): refused inputs give, on every rank, an
error naming the problem and empty outputs; repairable inputs are repaired
with a warning and meshed. The open box, wrapped (AlphaWrap) with an alpha
narrower than its hole, is a hollow skin: refused on every rank by name,
and with AllowSkin output with a warning. The ball cut in parallel slabs
under a quarter of the size thick is refused before any cut, on every rank,
with the largest K that is not, and cut with MinimumSlabThickness 0. A hang
fails the test by CTest's timeout.

    mpiexec -n N pvbatch --symmetric test_bad_input.py PLUGIN DATA_DIR N
"""
import os
import sys
import time

import ptm_testing as t
from paraview import simple

# file -> the words the error must contain (every rank)
REFUSED = {
    "open_box.stl": "the surface is open: 3 boundary edges (used by one triangle), e.g. from (",
    "cubes_sharing_edge.stl": "1 non-manifold edge (used by more than two triangles, up to 4), e.g. from (1, 1, 0) to (1, 1, 1)",
    "cubes_sharing_vertex.stl": "1 non-manifold vertex (where separate sheets of the surface touch in a point), e.g. at (1, 1, 1)",
    "overlapping_boxes.stl": "the surface intersects itself:",
    "nan_coordinate.stl": "NaN or infinite coordinate",
    "empty.stl": "the input has no triangles",
    "zero_area_sliver.off": "cannot be removed without opening the surface",
}
# file -> the words the cutter's warning must contain (rank 0), the mesh is made
REPAIRED = {
    "inside_out_sphere.stl": "1 inside-out shell inverted",
    "flipped_triangles.off": "triangles flipped to agree with their neighbours",
    "duplicate_and_zero_area.off": "removed 2 duplicated triangles",
}


def check_skin_refused():
    """AlphaWrap of the open box at the default alpha (0.017, the hole is a
    half face): refused as a hollow skin on every rank, empty output; with
    AllowSkin, a closed wrap about 2 x the offset thick, with a warning."""
    reader = simple.OpenDataFile(os.path.join(t.DATA, "bad", "open_box.stl"))
    wrap = simple.AlphaWrap(Input=reader)
    catcher = t.ErrorCatcher(wrap.GetClientSideObject(), warnings=True)
    wrap.UpdatePipeline()
    assert "the wrap is a hollow skin, not a solid" in catcher.errors_text, \
        "rank %d: AlphaWrap of the open box did not refuse the skin: %r" % (t.rank(), catcher.text)
    assert wrap.GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells() == 0
    wrap.AllowSkin = 1
    catcher = t.ErrorCatcher(wrap.GetClientSideObject(), warnings=True)
    wrap.UpdatePipeline()
    out = wrap.GetClientSideObject().GetOutputDataObject(0)
    thickness = out.GetFieldData().GetArray("WrapMeanThickness").GetValue(0)
    offset = out.GetFieldData().GetArray("WrapOffset").GetValue(0)
    assert catcher.errors_text == "", "rank %d: %r" % (t.rank(), catcher.text)
    # piece 0 of the request holds the whole wrap (WholeSurfaceStage.h)
    assert t.all_ranks_sum(out.GetNumberOfCells()) > 0, "the allowed skin came out empty"
    assert 1.8 * offset < thickness < 10 * offset, (thickness, offset)
    if t.rank() == 0:
        assert "hollow skin" in catcher.text, catcher.text
        print("open_box.stl wrapped: a skin %.4g thick (%.2f x the offset), refused, and allowed with a warning"
              % (thickness, thickness / offset))
    for p in (wrap, reader):
        simple.Delete(p)


def check_thin_slabs_refused():
    """The unit ball in 16 parallel slabs at size 0.5: the middle slabs are
    about 0.08 thick, 0.17 x the size, under MinimumSlabThickness (0.25):
    the whole pipeline refuses before cutting, on every rank, naming the
    largest K whose slabs are thick enough; with 0 the cutter cuts them,
    warning."""
    proxies = pipeline(os.path.join(t.DATA, "ball.off"))
    cutter = proxies[1]
    cutter.Strategy = "ParallelPlanes"
    cutter.NumberOfSubdomains = 16
    cutter.MaximumSize = 0.5
    catchers = [t.ErrorCatcher(p.GetClientSideObject(), warnings=True) for p in proxies]
    proxies[-1].UpdatePipeline()
    errors = "\n".join(c.errors_text for c in catchers)
    for words in ("the cut is refused: ParallelPlanes with 16 subdomains cuts slabs as thin as",
                  "refused before cutting",
                  "Use at most "):
        assert words in errors, "rank %d: the thin slabs were not refused with %r: %r" % (t.rank(), words, errors)
    largest = int(errors.split("Use at most ")[1].split()[0])
    assert 1 <= largest < 16, errors
    assert t.all_ranks_sum(proxies[-1].GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells()) == 0
    cutter.MinimumSlabThickness = 0
    catcher = t.ErrorCatcher(cutter.GetClientSideObject(), warnings=True)
    cutter.UpdatePipeline()
    assert catcher.errors_text == "", "rank %d: %r" % (t.rank(), catcher.text)
    cut = cutter.GetClientSideObject().GetOutputDataObject(0)
    assert t.all_ranks_sum(cut.GetNumberOfCells()) > 0, "the thin slabs allowed came out empty"
    if t.rank() == 0:
        assert "slabs as thin as" in catcher.text, catcher.text
        print("ball.off in 16 slabs at size 0.5: refused (at most %d), cut with MinimumSlabThickness 0" % largest)
    for p in reversed(proxies):
        simple.Delete(p)


def pipeline(path):
    reader = simple.OpenDataFile(path)
    cutter = simple.VolumeBalancedCutter(Input=reader, NumberOfSubdomains=2)
    interfaces = simple.InterfaceTriangulator(Input=cutter)
    relaxed = simple.SurfaceRelaxer(Input=interfaces)
    mesher = simple.ParallelTetMesher(Input=relaxed)
    return [reader, cutter, interfaces, relaxed, mesher]


def main():
    expected_ranks = t.use_arguments(sys.argv[1:])
    assert t.size() == expected_ranks, "%d ranks, expected %s" % (t.size(), expected_ranks)
    t.load_plugin()
    bad = os.path.join(t.DATA, "bad")
    for name, expected in sorted(REFUSED.items()):
        start = time.time()
        proxies = pipeline(os.path.join(bad, name))
        catchers = [t.ErrorCatcher(p.GetClientSideObject(), warnings=True) for p in proxies]
        proxies[-1].UpdatePipeline()
        errors = "\n".join(c.text for c in catchers)
        assert expected in errors, "%s: rank %d: the errors do not say %r:\n%s" % (name, t.rank(), expected, errors)
        for port in (0, 1):
            out = proxies[-1].GetClientSideObject().GetOutputDataObject(port)
            assert out.GetNumberOfPoints() == 0 and out.GetNumberOfCells() == 0, \
                "%s: rank %d: port %d is not empty after the error" % (name, t.rank(), port)
        assert t.all_ranks_true(True)
        if t.rank() == 0:
            print("%-28s refused in %.2f s: %s" % (name, time.time() - start,
                                                 [m for m in errors.split("\n") if expected in m][0][-160:]))
        for p in reversed(proxies):
            simple.Delete(p)

    for name, expected in sorted(REPAIRED.items()):
        proxies = pipeline(os.path.join(bad, name))
        catchers = [t.ErrorCatcher(p.GetClientSideObject(), warnings=True) for p in proxies]
        proxies[-1].UpdatePipeline()
        errors = "\n".join(c.errors_text for c in catchers if c.errors)
        assert errors == "", "%s: rank %d: unexpected errors: %r" % (name, t.rank(), [c.errors for c in catchers])
        if t.rank() == 0:
            warnings = catchers[1].text
            assert expected in warnings, "%s: the cutter's warnings do not say %r: %r" % (name, expected, warnings)
        cutter = proxies[1].GetClientSideObject().GetOutputDataObject(0)
        repairs = cutter.GetFieldData().GetAbstractArray("InputRepairs")
        assert repairs is not None and any(expected in repairs.GetValue(i) for i in range(repairs.GetNumberOfValues())), \
            "%s: rank %d: InputRepairs field data misses %r" % (name, t.rank(), expected)
        tets = t.all_ranks_sum(proxies[-1].GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells())
        assert tets > 0, "%s: no tetrahedra" % name
        if t.rank() == 0:
            print("%-28s repaired and meshed: %d tetrahedra (%s)" % (name, tets, expected))
        for p in reversed(proxies):
            simple.Delete(p)
    check_skin_refused()
    check_thin_slabs_refused()


t.run_checks(main)
