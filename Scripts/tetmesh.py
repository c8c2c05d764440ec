"""Parallel tetrahedral meshing of a closed surface, as one MPI command.

    mpiexec -n N pvbatch Scripts/tetmesh.py INPUT -o OUT.pvtu [--subdomains K]
        [--size H] [--strategy RecursiveBisection|ParallelPlanes]
        [--direction Inertia|LongestExtent|X|Y|Z] [--json SUMMARY.json]
        [--wrap [--wrap-alpha A] [--wrap-offset D] [--wrap-allow-skin]]
        [--remesh [--remesh-edge-length L] [--remesh-feature-angle DEG] [--remesh-max-deviation F]
                  [--remesh-max-volume-change F]]
        [--solid I] [--cad-deflection F]
        [--cad-angular-deflection A] [--save-surface SURFACE.off]

Reads any surface ParaView reads (STL, OFF, PLY, OBJ, VTP...) or the solids
of a CAD file (STEP, IGES, BREP: the plugin's CAD Surface Reader, whose
CADFaceId reaches OUT_boundary.pvtp), optionally wraps a dirty surface
(open, non-manifold, self-intersecting) into a closed one (--wrap: Alpha
Wrap, reporting how far the wrap strays from the input), optionally
remeshes it into triangles of about one edge length keeping its sharp edges
(--remesh: Surface Remesher, for CAD exports with long thin triangles; it
moves the surface, and reports and bounds by how much), runs
VolumeBalancedCutter, InterfaceTriangulator, SurfaceRelaxer and
ParallelTetMesher, writes the pieces with ParaView's parallel writer
(OUT.pvtu plus OUT_boundary.pvtp with the outer boundary triangles) and
prints a summary: tetrahedra, points, subdomains per rank, balance, time per
stage and the mesh quality the mesher measured (smallest dihedral angle,
share of tetrahedra under 10 degrees). Errors exit non-zero
with the message.
"""
import argparse
import json
import math
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def parse_arguments(argv):
    p = argparse.ArgumentParser(prog="tetmesh.py", description=__doc__.split("\n\n")[0])
    p.add_argument("input", help="closed surface file (STL, OFF, PLY, OBJ, VTP, ...)")
    p.add_argument("-o", "--output", required=True, help="output .pvtu file")
    p.add_argument("--subdomains", type=int, default=0, help="number of subdomains K (0: one per rank)")
    p.add_argument("--size", type=float, default=0.0,
                   help="target edge length for interfaces and tetrahedra (0: the surface's own resolution)")
    p.add_argument("--size-expression", default="",
                   help="size field: the edge length wanted at x, y, z, in the syntax of ParaView's Calculator "
                        "(e.g. '0.02 + 0.1 * abs(z)'); --size, when given, caps it")
    p.add_argument("--size-array", default="",
                   help="size field from samples: a point array of the input surface, or of --size-source; "
                        "interpolated between its points; --size, when given, caps it")
    p.add_argument("--size-source", default=None,
                   help="a data set any ParaView reader opens (a background mesh, an earlier solution) "
                        "whose point array --size-array gives the size")
    p.add_argument("--balance", default="PredictedCost", choices=["Volume", "PredictedCost", "BoundaryFacets", "Nodes"],
                   help="what the cuts make equal (default PredictedCost: the tetrahedra TetGen is predicted to make, "
                   "for the size field or, without one, from the size and the input's triangles)")
    p.add_argument("--strategy", default="RecursiveBisection", choices=["RecursiveBisection", "ParallelPlanes"])
    p.add_argument("--direction", default="Inertia", choices=["Inertia", "LongestExtent", "X", "Y", "Z"])
    p.add_argument("--radius-edge-ratio", type=float, default=2.0, help="TetGen quality bound (default 2.0)")
    p.add_argument("--min-dihedral", type=float, default=10.0,
                   help="smallest dihedral angle TetGen aims for, the second -q value (default 10; 0: none, "
                   "as serial tetgen -pq2.0)")
    p.add_argument("--sliver-repair-angle", type=float, default=5.0,
                   help="mesh again around a subdomain's flat tetrahedra on or held by its surface, under this "
                   "dihedral angle, with a point above or inside each (degrees; default 5, 0: off)")
    p.add_argument("--tetgen-time-limit", type=float, default=0.0,
                   help="processor seconds one TetGen run may use (default 0: automatic, about 6x TetGen's "
                   "speed); all runs of a subdomain together may use 4x this, then the run fails naming it")
    p.add_argument("--relax-iterations", type=int, default=10, help="surface relaxation sweeps (default 10)")
    p.add_argument("--no-contour-subdivision", action="store_true",
                   help="keep the contours as the cut made them (default: their long edges are split at the size "
                   "before the interfaces are triangulated)")
    p.add_argument("--keep-flat-crossings", action="store_true",
                   help="keep every contour point of the cuts, also those inside planar faces (default: they "
                   "are taken out, and the run is made again keeping them if TetGen fails)")
    p.add_argument("--minimum-slab-thickness", type=float, default=None,
                   help="ParallelPlanes: refuse before cutting a K whose thinnest slab is under this fraction of the "
                   "size, naming the largest K that is not (default 0.25, the cutter's MinimumSlabThickness; 0: "
                   "never refuse)")
    p.add_argument("--recut-attempts", type=int, default=5,
                   help="where a stage after the cut fails on a subdomain or an interface (one crossing itself, TetGen "
                   "failing on one), "
                   "cut again at most this many times, otherwise (keeping flat crossings, untilted planes, "
                   "planes not turned to earlier lines, no thickness size, and for ParallelPlanes last recursive "
                   "bisection), with a warning; 0 fails at once (default 5)")
    p.add_argument("--no-thickness-size", action="store_true",
                   help="size the boundary by --size alone (default: edges no longer than the part is thick "
                   "where a wall is thinner than the size, measured by rays along the inward normals)")
    p.add_argument("--no-boundary-refinement", action="store_true",
                   help="mesh the subdomain surfaces as they are (TetGen keeps every input sliver)")
    p.add_argument("--boundary-spacing-floor", type=float, default=0.125,
                   help="shortest spacing, as a fraction of the local size, at which the boundary refinement "
                        "splits an input edge beside a thin input triangle (default 1/8; lower follows thin "
                        "strips of CAD exports, with better and many more tetrahedra)")
    p.add_argument("--coplanar-tolerance", type=float, default=0.0,
                   help="degrees: boundary refinement merges input triangles this close to coplanar "
                        "(changes the surface slightly; default 0 keeps it exactly)")
    p.add_argument("--relax-mode", default="KeepSurface", choices=["KeepSurface", "SmoothSurface"],
                   help="KeepSurface (default): the surface stays exactly the same; SmoothSurface: may move it")
    p.add_argument("--max-surface-deviation", type=float, default=0.01,
                   help="SmoothSurface: largest surface move, relative to the bounding-box diagonal (default 0.01)")
    p.add_argument("--wrap", action="store_true",
                   help="mesh a closed alpha wrap of the surface (for open, non-manifold or self-intersecting input)")
    p.add_argument("--wrap-alpha", type=float, default=0.01,
                   help="--wrap: alpha, as a fraction of the bounding-box diagonal (default 0.01)")
    p.add_argument("--wrap-offset", type=float, default=1.0 / 3000,
                   help="--wrap: offset from the input, as a fraction of the diagonal (default 1/3000)")
    p.add_argument("--wrap-allow-skin", action="store_true",
                   help="--wrap: mesh a wrap that is a hollow skin (an open surface with holes wider than alpha, "
                        "wrapped from both sides) as a thin solid, instead of failing")
    p.add_argument("--remesh", action="store_true",
                   help="remesh the surface first into triangles of about --remesh-edge-length (CGAL isotropic "
                        "remeshing, sharp edges kept): for CAD exports with long thin triangles; moves the surface "
                        "(reported, and bounded by --remesh-max-deviation)")
    p.add_argument("--remesh-edge-length", type=float, default=0.0,
                   help="--remesh: the edge length wanted (default: --size if given, else the input's "
                        "mean edge length)")
    p.add_argument("--remesh-feature-angle", type=float, default=30.0,
                   help="--remesh: edges whose faces' normals differ by more (degrees) are kept (default 30)")
    p.add_argument("--remesh-max-deviation", type=float, default=0.005,
                   help="--remesh: largest distance allowed between the remeshed surface and the input, as a "
                        "fraction of the bounding-box diagonal (default 0.005; 0: not bounded); beyond it, or where "
                        "the result crosses itself, the edge length is halved, at most 6 times")
    p.add_argument("--remesh-max-volume-change", type=float, default=0.002,
                   help="--remesh: largest change of the enclosed volume allowed, relative (default 0.002; 0: not "
                        "bounded); beyond it the edge length is halved too")
    p.add_argument("--solid", type=int, default=-1,
                   help="CAD input: the solid to mesh, 0-based (default -1: all, as separate shells)")
    p.add_argument("--cad-deflection", type=float, default=1e-3,
                   help="CAD input: tessellation deflection as a fraction of the diagonal (default 0.001)")
    p.add_argument("--cad-angular-deflection", type=float, default=0.5,
                   help="CAD input: tessellation angular deflection in radians (default 0.5)")
    p.add_argument("--save-surface", default=None,
                   help="also write the surface that was meshed (after reading and wrapping) as OFF")
    p.add_argument("--plugin", default=None, help="path of ParallelTetMesher.so (default: from the build tree)")
    p.add_argument("--json", default=None, help="also write the summary as JSON")
    return p.parse_args(argv)


def find_plugin(explicit):
    # a path the user named is used or refused, never silently replaced by
    # the build tree's plugin (which may be another version)
    if explicit:
        if not os.path.isfile(explicit):
            fail("--plugin %s: no such file" % explicit)
        return os.path.abspath(explicit)
    candidates = [os.environ.get("PTM_PLUGIN", ""),
                   os.path.join(HERE, "..", "build", "lib", "paraview-plugins", "ParallelTetMesher",
                                "ParallelTetMesher.so")]
    for c in candidates:
        if c and os.path.isfile(c):
            return os.path.abspath(c)
    fail("ParallelTetMesher.so not found; build the project or pass --plugin")


class Failure(Exception):
    """A refused request or a failed stage, with its reason."""


def fail(message):
    # Raised, not sys.exit(): under mpiexec, pvbatch's rank 0 leaving by
    # exit() skips the finalizing barrier the other ranks wait in, so
    # mpiexec killed them and a clean, agreed failure printed a SIGTERM stack
    # trace from every other rank. An exception ends the script normally:
    # every rank finalizes and pvbatch exits with 1 (report_failure prints
    # the reason without a traceback).
    raise Failure(message)


def report_failure(kind, value, traceback):
    if issubclass(kind, Failure):
        sys.stderr.write("tetmesh: error: %s\n" % value)
        sys.stderr.flush()
    else:
        sys.__excepthook__(kind, value, traceback)


class ErrorLog:
    """Collects the error messages of the filters' VTK objects (every rank
    reports a failure of the plugin's filters, so rank 0 sees it too)."""

    def __init__(self):
        self.messages = []
        self._callbacks = []

    def watch(self, proxy):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            # VTK's message is "ERROR: In file, line N" then "class (address): text"
            lines = [l.strip() for l in str(message).splitlines() if l.strip()]
            text = lines[-1] if lines else ""
            self.messages.append(text.split("): ", 1)[-1])

        self._callbacks.append(on_error)
        proxy.GetClientSideObject().AddObserver("ErrorEvent", on_error)
        return proxy


CAD_EXTENSIONS = (".step", ".stp", ".iges", ".igs", ".brep")


def write_off(polydata, path):
    """The triangles of a vtkPolyData (rank 0's whole surface) as OFF, 17 digits."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    points = vtk_to_numpy(polydata.GetPoints().GetData())
    triangles = vtk_to_numpy(polydata.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in triangles:
            f.write("3 %d %d %d\n" % tuple(t))


def field_value(polydata, name):
    array = polydata.GetFieldData().GetArray(name)
    return float(array.GetValue(0)) if array is not None and array.GetNumberOfTuples() else None


def recut_changes(strategy, tilt, alignment, removed, thin_walls):
    """The other cuts tried, in order, after a stage following the cut as
    asked failed, as (cutter settings changed, description); each is the
    cut as asked with that change. `removed` is the number of contour points
    the cut took out of planar faces, `thin_walls` whether the cutter
    measured walls thinner than the size (SizeByThickness on, with samples).

    1. Keeping the flat crossings (TetGen may fail on the thin slabs their
       removal leaves and mesh them with the crossings kept: OCCT's Top and
       Bottom at 32 parallel planes).
    2. Recursive bisection's planes untilted, then 3. planes neither tilted
       nor turned towards lines already drawn: for a subdomain a cut leaves
       crossing itself where the cutter's own check does not see it
       (FreeCAD's TCMT1107_4 at K = 16 by bisection was such a case until
       session 20 fixed the check, and meshed with untilted planes).
    4. The boundary sized by the size alone, the flat crossings kept:
       Cura's BIQU_SSS bed at K = 64 with parallel planes crashed TetGen
       (add_steinerpt_in_segment) on subdomain 35 or 7 in every order after
       each cut above, stalled it on subdomain 32 without the thickness size
       alone, and meshed with the crossings kept as well.
    5. Parallel planes only: recursive bisection instead, the last resort,
       as it changes the kind of decomposition asked for. CUI's barrel jack
       (KiCad) at K = 64 has steps 1.1e-6 high running along the planes'
       normal, so every plane crosses them, and TetGen aborted on a slab
       0.22 thick between two such crossings after every cut above;
       bisection, whose parts are thicker and cut across, meshed it at
       every K tried."""
    attempts = []
    if removed:
        attempts.append(({"RemoveFlatCrossings": 0},
                         "the cut had taken %d contour points out of planar faces: cutting again keeping them "
                         "(--keep-flat-crossings)" % removed))
    if strategy == "RecursiveBisection" and tilt != 0:
        attempts.append(({"PlaneTiltAngle": 0}, "cutting again with untilted planes"))
    if alignment != 0:
        attempts.append(({"PlaneTiltAngle": 0, "PlaneAlignmentAngle": 0},
                         "cutting again with planes neither tilted nor turned towards earlier lines"))
    if thin_walls:
        change = {"SizeByThickness": 0}
        if removed:
            change["RemoveFlatCrossings"] = 0
        attempts.append((change, "cutting again without sizing the boundary by the wall thickness "
                         "(--no-thickness-size%s): walls thinner than the size get coarser tetrahedra across them"
                         % (", --keep-flat-crossings" if removed else "")))
    if strategy == "ParallelPlanes":
        attempts.append(({"Strategy": "RecursiveBisection"},
                         "cutting by recursive bisection instead of parallel planes (--strategy "
                         "RecursiveBisection): its parts are thicker and are cut in more than one direction"))
    return attempts


def recut_attempts(cutter, strategy):
    """recut_changes for the cut the cutter proxy made."""
    cut = cutter.GetClientSideObject().GetOutputDataObject(0)
    samples = cut.GetFieldData().GetArray("ThicknessSamples")
    thin_walls = bool(cutter.SizeByThickness) and samples is not None and samples.GetNumberOfTuples() > 0
    return recut_changes(strategy, cutter.PlaneTiltAngle, cutter.PlaneAlignmentAngle,
                         field_value(cut, "FlatCrossingsRemoved"), thin_walls)


def recut_if_stages_fail(run, errors, times, cutter, stages, strategy, most_recuts):
    """Runs the stages after the cut. Where one of them fails on a subdomain
    or an interface, a cut made otherwise (recut_attempts) may succeed, as a
    user would try by hand: the stages run again from each of at most most_recuts other cuts, each
    beginning from the cutter's settings as asked, with a warning naming the
    failure and the change. times["failed attempts"] sums the seconds of the
    cuts and stages that failed. Returns the list of {"failure", "change",
    "settings"} (the cutter properties the next attempt changed) of the
    attempts that failed (empty when the first cut succeeded);
    raises the last failure if every attempt failed."""
    asked = {name: cutter.GetPropertyValue(name)
             for name in ("RemoveFlatCrossings", "PlaneTiltAngle", "PlaneAlignmentAngle", "SizeByThickness")}
    # the name asked for: GetPropertyValue gives an enumeration as a live
    # property, which would restore the value last set
    asked["Strategy"] = strategy
    failed = []
    attempts = None
    while True:
        try:
            for stage, proxy in stages:
                run(stage, proxy)
            return failed
        except Failure as failure:
            if attempts is None:
                attempts = recut_attempts(cutter, strategy)[:max(most_recuts, 0)]
            # only what a cut can cause: a failure naming a subdomain or an
            # interface (not, say, a size that cannot fit in memory, whose
            # message begins "the requested size")
            if len(failed) == len(attempts) or not re.search(r"subdomain|interface", str(failure), re.I) \
                    or "the requested size" in str(failure):
                raise
            change, description = attempts[len(failed)]
            failed.append({"failure": str(failure), "change": description, "settings": change})
            sys.stderr.write("tetmesh: warning: %s; %s\n" % (failure, description))
            sys.stderr.flush()
            del errors.messages[:]
            times["failed attempts"] = times.get("failed attempts", 0.0) + times.get("cut", 0.0) + sum(
                times.pop(stage, 0.0) for stage, _ in stages)
            for name, value in asked.items():
                setattr(cutter, name, change.get(name, value))
            run("cut", cutter)


def open_reader(path):
    """ParaView's reader of `path`, or fail() saying why there is none."""
    from paraview import simple
    try:
        reader = simple.OpenDataFile(path)
    except RuntimeError as e:  # ParaView 5.11 raises where no reader can read the file
        reader, why = None, str(e).strip()
    else:
        why = "no reader for it"
    if reader is None:
        fail("ParaView cannot read '%s' (%s)" % (path, why))
    return reader


def main(argv):
    args = parse_arguments(argv)
    if not os.path.isfile(args.input):
        fail("input file '%s' does not exist" % args.input)
    if args.subdomains < 0 or args.size < 0:
        fail("--subdomains and --size must not be negative")
    if args.size_source and not args.size_array:
        fail("--size-source needs --size-array, the name of its point array that gives the size")
    if args.size_source and not os.path.isfile(args.size_source):
        fail("size source '%s' does not exist" % args.size_source)
    from paraview import servermanager, simple

    # without ns the proxies become functions of paraview.simple
    simple.LoadPlugin(find_plugin(args.plugin), remote=False)
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    errors = ErrorLog()
    times = {}

    def run(stage, proxy):
        errors.watch(proxy)
        start = time.perf_counter()
        proxy.UpdatePipeline()
        times[stage] = time.perf_counter() - start
        if errors.messages:
            fail("%s failed: %s" % (stage, errors.messages[0]))
        return proxy

    reader = open_reader(args.input)
    if args.input.lower().endswith(CAD_EXTENSIONS) and "SolidIndex" in reader.ListProperties():
        reader.SolidIndex = args.solid
        reader.RelativeLinearDeflection = args.cad_deflection
        reader.AngularDeflection = args.cad_angular_deflection
    run("read", reader)
    surface = reader
    wrapper = remesher = None
    if args.wrap:
        surface = wrapper = run("wrap", simple.AlphaWrap(Input=reader, RelativeAlpha=args.wrap_alpha,
                                                         RelativeOffset=args.wrap_offset,
                                                         AllowSkin=1 if args.wrap_allow_skin else 0))
    if args.remesh:
        surface = remesher = run("remesh", simple.SurfaceRemesher(
            Input=surface, TargetEdgeLength=args.remesh_edge_length or max(args.size, 0.0),
            FeatureAngle=args.remesh_feature_angle, MaximumDeviation=args.remesh_max_deviation,
            MaximumVolumeChange=args.remesh_max_volume_change))
    size_source = None
    if args.size_source:
        size_source = open_reader(args.size_source)
        run("read size source", size_source)
    # only when given: the default is the filter's own
    slabs = {} if args.minimum_slab_thickness is None else {"MinimumSlabThickness": args.minimum_slab_thickness}
    cutter = run("cut", simple.VolumeBalancedCutter(
        Input=surface, NumberOfSubdomains=args.subdomains, Strategy=args.strategy, Direction=args.direction,
        BalanceCriterion=args.balance,
        SizeExpression=args.size_expression, SizeArray=args.size_array, SizeSource=size_source,
        MaximumSize=args.size, RemoveFlatCrossings=0 if args.keep_flat_crossings else 1,
        SizeByThickness=0 if args.no_thickness_size else 1, **slabs))
    # rank 0's copy of the surface the cutter took (every rank asked for the whole)
    meshed = surface.GetClientSideObject().GetOutputDataObject(0)
    wrap_report = remesh_report = None
    if wrapper is not None:
        wrapped = wrapper.GetClientSideObject().GetOutputDataObject(0)
        wrap_report = {name: field_value(wrapped, field) for name, field in (
            ("alpha", "WrapAlpha"), ("offset", "WrapOffset"),
            ("largest_distance_wrap_to_input", "WrapToInputDistance"),
            ("largest_distance_input_to_wrap", "InputToWrapDistance"),
            ("sample_spacing", "WrapSampleSpacing"), ("seconds", "WrapSeconds"),
            ("mean_thickness", "WrapMeanThickness"))}
        wrap_report["triangles"] = int(wrapped.GetNumberOfPolys())
    if remesher is not None:
        remesh_report = {name: field_value(meshed, field) for name, field in (
            ("edge_length", "RemeshEdgeLength"),
            ("largest_distance_remeshed_to_input", "RemeshToInputDistance"),
            ("largest_distance_input_to_remeshed", "InputToRemeshDistance"),
            ("sample_spacing", "RemeshSampleSpacing"), ("volume_change_relative", "RemeshVolumeChange"),
            ("feature_edges", "RemeshFeatureEdges"), ("corners", "RemeshCorners"), ("seconds", "RemeshSeconds"))}
        remesh_report["triangles"] = int(meshed.GetNumberOfPolys())
    if args.save_surface:
        write_off(meshed, args.save_surface)
    interfaces = simple.InterfaceTriangulator(Input=cutter, MaximumEdgeLength=args.size,
                                              SizeExpression=args.size_expression,
                                              SubdivideContours=0 if args.no_contour_subdivision else 1)
    relaxed = simple.SurfaceRelaxer(Input=interfaces, NumberOfIterations=args.relax_iterations, Mode=args.relax_mode,
                                    MaximumSurfaceDeviation=args.max_surface_deviation)
    volume = args.size ** 3 / (6 * math.sqrt(2)) if args.size > 0 else 0.0
    mesher = simple.ParallelTetMesher(
        Input=relaxed, RadiusEdgeRatio=args.radius_edge_ratio, MinimumDihedralAngle=args.min_dihedral,
        SliverRepairAngle=args.sliver_repair_angle,
        TetGenTimeLimit=args.tetgen_time_limit,
        MaximumVolume=volume,
        BoundaryRefinement=0 if args.no_boundary_refinement else 1,
        BoundarySpacingFloor=args.boundary_spacing_floor,
        CoplanarTolerance=args.coplanar_tolerance, SizeExpression=args.size_expression)
    recuts = recut_if_stages_fail(
        run, errors, times, cutter, [("interface", interfaces), ("relax", relaxed), ("volume meshing", mesher)],
        args.strategy, args.recut_attempts)

    start = time.perf_counter()
    output = os.path.abspath(args.output)
    os.makedirs(os.path.dirname(output), exist_ok=True)
    # Appended raw arrays (not base64, not compressed): on the 2.4 M ball at
    # 2 ranks writing took 0.53-0.60 s against 1.48-1.61 s for inline base64,
    # in files a quarter smaller (143 against 190 MB). ParaView's default,
    # base64 appended, is not used: meshio 5.0 misreads it on some array sizes
    # (a 2,457-point piece: "len(points) = 2457, but len(point_data[...]) = 1");
    # it reads raw appended data by encoding each array whole.
    raw = dict(DataMode="Appended", EncodeAppendedData=0)
    simple.SaveData(output, proxy=simple.OutputPort(mesher, 0), **raw)
    boundary_file = os.path.splitext(output)[0] + "_boundary.pvtp"
    simple.SaveData(boundary_file, proxy=simple.OutputPort(mesher, 1), **raw)
    times["write"] = time.perf_counter() - start

    # the totals (the same on every rank), from rank 0's piece of the small
    # boundary port: fetching port 0 would gather the whole volume mesh onto
    # rank 0 (with 4 x 10^7 tetrahedra that gather passes MPI's 2 GB message
    # limit and never ends)
    fd = servermanager.Fetch(mesher, 0, idx=1).GetFieldData()
    tets = int(fd.GetArray("GlobalCellCount").GetValue(0))
    # quality measured by the mesher on every rank's tetrahedra as it made them
    minimum_dihedral = float(fd.GetArray("MinimumDihedralAngle").GetValue(0))
    below_10 = int(fd.GetArray("TetrahedraBelow10Degrees").GetValue(0))
    per_subdomain = [int(fd.GetArray("SubdomainTetrahedra").GetValue(i))
                     for i in range(fd.GetArray("SubdomainTetrahedra").GetNumberOfTuples())]
    owner = [int(fd.GetArray("SubdomainRank").GetValue(i))
             for i in range(fd.GetArray("SubdomainRank").GetNumberOfTuples())]
    per_rank = [0] * ranks
    subdomains_per_rank = [0] * ranks
    for s, n in enumerate(per_subdomain):
        per_rank[owner[s]] += n
        subdomains_per_rank[owner[s]] += 1
    mean = sum(per_rank) / float(ranks)
    summary = {
        "input": os.path.abspath(args.input),
        "output": output,
        "boundary_output": boundary_file,
        "ranks": ranks,
        "subdomains": len(per_subdomain),
        "subdomains_per_rank": subdomains_per_rank,
        "tetrahedra": int(tets),
        "points": int(fd.GetArray("GlobalPointCount").GetValue(0)),
        "tetrahedra_per_rank": per_rank,
        "balance_max_over_mean": max(per_rank) / mean if mean > 0 else 0.0,
        "seconds": times,
        "flat_crossings_removed": int(field_value(cutter.GetClientSideObject().GetOutputDataObject(0),
                                                  "FlatCrossingsRemoved") or 0),
        "recuts": recuts,
        "kept_flat_crossings_after_failure": next(
            (r["failure"] for r in recuts if r["settings"].get("RemoveFlatCrossings") == 0), None),
        "interfaces": {name: int(field_value(interfaces.GetClientSideObject().GetOutputDataObject(0), field) or 0)
                       for name, field in (("contour_points_added", "ContourPointsAdded"),
                                           ("subdivision_retries", "ContourSubdivisionRetries"),
                                           ("regions_kept_whole", "InterfacesKeptWhole"),
                                           ("regions_triangulated_again", "InterfacesTriangulatedAgain"),
                                           ("new_points", "InterfaceNewPoints"))},
        "quality": {
            "minimum_dihedral_angle_degrees": minimum_dihedral,
            "share_below_10_degrees": below_10 / float(max(tets, 1)),
            "sliver_repair_points": int(fd.GetArray("SliverRepairPoints").GetValue(0)),
        },
        "boundary_refinement": {
            "points_added": int(fd.GetArray("BoundaryPointsAdded").GetValue(0)),
            "volume_change_relative": float(fd.GetArray("BoundaryVolumeChange").GetValue(0)),
            "largest_deviation": float(fd.GetArray("BoundaryLargestDeviation").GetValue(0)),
        },
    }
    if wrap_report is not None:
        summary["wrap"] = wrap_report
        print("tetmesh: wrapped (alpha %.4g, offset %.4g) into %d triangles; largest distance wrap to input "
              "%.4g, input to wrap %.4g (sampled every %.3g); mean thickness %.4g" % (
                  wrap_report["alpha"], wrap_report["offset"], wrap_report["triangles"],
                  wrap_report["largest_distance_wrap_to_input"], wrap_report["largest_distance_input_to_wrap"],
                  wrap_report["sample_spacing"], wrap_report["mean_thickness"]))
    if remesh_report is not None:
        summary["remesh"] = remesh_report
        print("tetmesh: remeshed at edge length %.4g into %d triangles (%d feature edges kept, %d corners); "
              "largest distance remeshed to input %.4g, input to remeshed %.4g (sampled every %.3g), "
              "volume change %.3g" % (
                  remesh_report["edge_length"], remesh_report["triangles"], remesh_report["feature_edges"],
                  remesh_report["corners"], remesh_report["largest_distance_remeshed_to_input"],
                  remesh_report["largest_distance_input_to_remeshed"], remesh_report["sample_spacing"],
                  remesh_report["volume_change_relative"]))
    print("tetmesh: %d tetrahedra, %d points, %d subdomains on %d ranks (%s per rank)" % (
        summary["tetrahedra"], summary["points"], summary["subdomains"], ranks, subdomains_per_rank))
    print("tetmesh: balance max/mean tetrahedra per rank %.3f" % summary["balance_max_over_mean"])
    print("tetmesh: seconds " + ", ".join("%s %.2f" % (k, v) for k, v in times.items()))
    print("tetmesh: minimum dihedral angle %.2f degrees, %.4f%% of tetrahedra under 10 degrees "
          "(%d points put in by the sliver repair)" % (
              minimum_dihedral, 100 * summary["quality"]["share_below_10_degrees"],
              summary["quality"]["sliver_repair_points"]))
    print("tetmesh: wrote %s and %s" % (output, boundary_file))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(summary, f, indent=1)
    return summary


if __name__ == "__main__":
    # The script ends normally, so pvbatch finalizes MPI on every rank; a
    # failure ends it by the exception fail() raises, printed as one line
    # "tetmesh: error: ...", and pvbatch exits with 1.
    sys.excepthook = report_failure
    main(sys.argv[1:])
