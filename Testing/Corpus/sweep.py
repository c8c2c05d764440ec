"""Sweep the real pipeline over the corpus (issue #18).

    /usr/bin/python3 Testing/Corpus/sweep.py --plugin PATH/ParallelTetMesher.so
        [--corpus out/corpus] [--out out/corpus-sweep] [--quick]
        [--surfaces a,b] [--ks 2,4,8,16,32,64] [--strategies RecursiveBisection,ParallelPlanes]
        [--timeout 300] [--jobs 1] [--ranks 2] [--target-tets 75000]

For every corpus surface (OUT_DIR/NAME.off of fetch.sh), every K and strategy
it runs `mpiexec -n 2 --oversubscribe pvbatch Scripts/tetmesh.py SURF -o
OUT.pvtu --subdomains K --strategy S --size H --json J` in its own process
group, with a timeout (the whole group is killed; a timeout is a failure),
and checks the result independently of the plugin (conformity.py: the .pvtu
pieces read with VTK's XML readers, merged by GlobalPointIds, numpy). Beside each
surface it runs serial TetGen (Debian's `tetgen` binary) with `-pq2.0a<bound>`
and the same volume bound; Testing/Benchmarks/mesh_quality.py measures both.

The size H of a surface: the volume bound a is chosen so that serial TetGen
makes 50,000-100,000 tetrahedra: first a = V / N (V the enclosed volume, N =
--target-tets), then, as long as TetGen's count T lies outside that range,
a := a * T / N (at most 4 tries; a surface finer than the range allows stays
above it). H is the edge of the regular tetrahedron of volume a
(a = H^3 / (6 sqrt 2), the bound tetmesh.py gives TetGen for --size H), so
the pipeline and serial TetGen get the same bound.

Writes OUT/results.json (every run and serial reference), OUT/results.md (the
table and the summary) and prints both as it goes.
"""
import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "Testing", "Benchmarks"))

import conformity  # noqa: E402
import surface_tool  # noqa: E402
from mesh_quality import mesh_quality  # noqa: E402

ALL_KS = [2, 4, 8, 16, 32, 64]
ALL_STRATEGIES = ["RecursiveBisection", "ParallelPlanes"]
QUICK_SURFACES = ["3torus", "fandisk", "occt-Pump_Nut", "scad-example001"]
GOAL_UNDER10_RATIO = 1.5
GOAL_DIHEDRAL_RATIO = 0.5
GOAL_VOLUME_ERROR = 1e-9


def parse_arguments(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--plugin", help="ParallelTetMesher.so (default: BUILD/lib/paraview-plugins/...)")
    p.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory holding the plugin")
    p.add_argument("--corpus", default=os.path.join(ROOT, "out", "corpus"))
    p.add_argument("--out", default=os.path.join(ROOT, "out", "corpus-sweep"))
    p.add_argument("--quick", action="store_true", help="a few surfaces, K = 2, 8")
    p.add_argument("--surfaces", default="", help="comma-separated names (default: every NAME.off of the corpus)")
    p.add_argument("--ks", default="", help="comma-separated K (default 2,4,8,16,32,64)")
    p.add_argument("--strategies", default="", help="comma-separated (default both)")
    p.add_argument("--timeout", type=float, default=300.0, help="seconds per pipeline run")
    p.add_argument("--jobs", type=int, default=1, help="pipeline runs at the same time")
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--target-tets", type=int, default=75000)
    p.add_argument("--serial-switches", default="pq2.0", help="serial TetGen switches before a<bound>")
    p.add_argument("--keep-meshes", action="store_true", help="keep the .pvtu of every run")
    p.add_argument("--report-only", action="store_true", help="rewrite OUT/results.md from OUT/results.json, run nothing")
    p.add_argument("--relax-iterations", type=int, default=None,
                   help="pass --relax-iterations to tetmesh.py (default: its own, 10; 0 shows what relaxation does)")
    p.add_argument("--coplanar-tolerance", type=float, default=None,
                   help="pass --coplanar-tolerance to tetmesh.py: the boundary refinement merges nearly coplanar "
                   "input triangles as TetGen -p does (0.1 degrees is TetGen's own merge angle); the volume may "
                   "then change (reported), so the 1e-9 volume goal applies to the default (exact) mode only")
    p.add_argument("--no-thickness-size", action="store_true",
                   help="pass --no-thickness-size to tetmesh.py: the boundary spaced by the size alone, as before "
                   "session 21 (for comparisons with the thickness cap)")
    p.add_argument("--remesh", action="store_true",
                   help="pass --remesh to tetmesh.py: the surface is remeshed at the run's size first (CGAL isotropic "
                   "remeshing, sharp edges kept); it moves the surface, so the volume goal does not apply")
    return p.parse_args(argv)


def run_group(command, timeout, cwd=None, env=None):
    """Run in a new process group; on timeout kill the whole group.
    Returns (returncode or None on timeout, stdout+stderr text, seconds)."""
    start = time.perf_counter()
    proc = subprocess.Popen(command, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        code = None
    return code, out.decode("utf-8", "replace"), time.perf_counter() - start


def serial_tetgen(surface, bound, workdir, switches, timeout):
    os.makedirs(workdir, exist_ok=True)
    local = os.path.join(workdir, "surface.off")
    shutil.copyfile(surface, local)
    for f in os.listdir(workdir):
        if f.startswith("surface.1."):
            os.remove(os.path.join(workdir, f))
    command = ["tetgen", "-%sa%.17gkQ" % (switches, bound), "surface.off"]
    code, text, seconds = run_group(command, timeout, cwd=workdir)
    vtk = os.path.join(workdir, "surface.1.vtk")
    result = {"switches": command[1], "seconds": seconds, "ok": code == 0 and os.path.isfile(vtk)}
    if result["ok"]:
        q = mesh_quality(vtk)
        q.pop("smallest_dihedral_histogram", None)
        result.update(q)
    else:
        result["error"] = "timeout" if code is None else last_error_line(text)
    return result


def calibrate(name, surface, stats, args, workdir):
    """The volume bound that gives serial TetGen 50-100k tetrahedra, and serial TetGen's result there."""
    target = args.target_tets
    bound = stats["volume"] / target
    # never coarser than about 1000 tetrahedra of the bound in the volume: on
    # a thin sheet (Prusa's aq_bed) serial TetGen's count is its boundary's
    # and hardly moves with the bound, which grew 77 x per try to a size
    # larger than the part
    largest = stats["volume"] / 1000.0
    tried = []
    for attempt in range(4):
        ref = serial_tetgen(surface, bound, workdir, args.serial_switches, args.timeout)
        tried.append((bound, ref.get("tetrahedra")))
        if not ref["ok"] or 50000 <= ref["tetrahedra"] <= 100000 or attempt == 3:
            break  # the last try's bound stays: serial and the pipeline get the same one
        scaled = min(bound * ref["tetrahedra"] / float(target), largest)
        if scaled == bound:
            break
        bound = scaled
    ref["calibration"] = tried
    ref["bound"] = bound
    ref["size"] = (6 * math.sqrt(2) * bound) ** (1.0 / 3.0)
    # for context: the same bound with the surface kept exactly (-Y), as the
    # pipeline's TetGen runs (pYzQq2.0a); a coarse surface then gets far fewer
    # tetrahedra, since TetGen may not refine next to it
    ref["with_Y"] = serial_tetgen(surface, bound, workdir + "-Y", args.serial_switches.replace("p", "pY", 1),
                                  args.timeout)
    return ref


def last_error_line(text):
    lines = [l.strip() for l in text.splitlines() if l.strip()]
    for pattern in ("tetmesh: error", "Error", "error", "ERROR", "Traceback", "Abort", "Segmentation", "signal"):
        hits = [l for l in lines if pattern in l]
        if hits:
            return hits[-1 if pattern != "Traceback" else 0][:400]
    return lines[-1][:400] if lines else "no output"


def pipeline_run(surface, name, k, strategy, size, stats, args, plugin):
    tag = "%s_K%d_%s" % (name, k, "RB" if strategy == "RecursiveBisection" else "PP")
    rundir = os.path.join(args.out, "runs", tag)
    shutil.rmtree(rundir, ignore_errors=True)
    os.makedirs(rundir)
    out = os.path.join(rundir, "mesh.pvtu")
    summary = os.path.join(rundir, "summary.json")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    command = ["mpiexec", "-n", str(args.ranks), "--oversubscribe", "pvbatch",
               os.path.join(ROOT, "Scripts", "tetmesh.py"), surface, "-o", out, "--subdomains", str(k),
               "--strategy", strategy, "--size", "%.17g" % size, "--json", summary, "--plugin", plugin]
    if args.relax_iterations is not None:
        command += ["--relax-iterations", str(args.relax_iterations)]
    if args.coplanar_tolerance is not None:
        command += ["--coplanar-tolerance", "%g" % args.coplanar_tolerance]
    if args.no_thickness_size:
        command += ["--no-thickness-size"]
    if args.remesh:
        command += ["--remesh"]
    code, text, seconds = run_group(command, args.timeout, env=env)
    with open(os.path.join(rundir, "log.txt"), "w") as f:
        f.write(" ".join(command) + "\n" + text)
    result = {"surface": name, "k": k, "strategy": strategy, "size": size, "seconds": seconds,
              "command": " ".join(command)}
    if code is None:
        result.update(ok=False, error="timeout after %.0f s" % args.timeout)
    elif code != 0 or not os.path.isfile(out):
        # refused up front (a K the part cannot hold at the size, with the
        # largest K that can), as issue #18 allows: not a failure half-way
        result.update(ok=False, error=last_error_line(text), refused=REFUSED_UP_FRONT in text)
    else:
        result["ok"] = True
        result["warnings"] = sorted(set(l.strip()[:300] for l in text.splitlines() if "Warning" in l
                                        or "warning" in l))[:5]
        try:
            result["pipeline"] = json.load(open(summary))
        except (OSError, ValueError):
            pass
        try:
            result["conformity"] = conformity.check(out, stats)
        except Exception as e:  # noqa: BLE001 - every failure of the check is a finding
            result["conformity"] = {"conforming": False, "problems": ["check failed: %r" % e]}
        try:
            q = mesh_quality(out)
            q.pop("smallest_dihedral_histogram", None)
            result["quality"] = q
        except Exception as e:  # noqa: BLE001
            result["quality"] = {"error": repr(e)}
    if not args.keep_meshes:
        for f in os.listdir(rundir):
            if f.endswith((".vtu", ".pvtu", ".vtp", ".pvtp")) or os.path.isdir(os.path.join(rundir, f)):
                p = os.path.join(rundir, f)
                shutil.rmtree(p) if os.path.isdir(p) else os.remove(p)
    return result


# The words of the cutter's refusal of parallel slabs under MinimumSlabThickness.
REFUSED_UP_FRONT = "refused before cutting"


def classify(error):
    e = error.lower()
    if "timeout" in e:
        return "timeout"
    if "intersect" in e:
        return "self-intersecting subdomain"
    if "boundary differs" in e:
        return "TetGen changed a subdomain's boundary"
    if "tetgen" in e:
        return "TetGen crash/stall"
    return "other"


# The share under 10 degrees with its count beside it: a share falls as
# good tetrahedra are added, so a mesh finer than serial's can meet the goal
# with more bad tetrahedra (session 22's graded interfaces).
RUN_TABLE_HEADER = ["| surface | K | strategy | run | conforming | tetrahedra | volume error | min dihedral | "
                    "under 10 deg (count) | wall s | error / problems |",
                    "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]


def under10(share, tetrahedra):
    """The share under 10 degrees and, where the tetrahedra are known, their count."""
    if share is None:
        return "-"
    if tetrahedra is None:
        return "%.3f%%" % (100 * share)
    return "%.3f%% (%d)" % (100 * share, round(share * tetrahedra))


def fmt(x, spec):
    return "-" if x is None else spec % x


def row(r, serial):
    c = r.get("conformity", {})
    q = r.get("quality", {})
    if not r["ok"]:
        return "| %s | %d | %s | %s | - | - | - | - | - | %.1f | %s |" % (
            r["surface"], r["k"], r["strategy"], "refused" if r.get("refused") else "**fail**", r["seconds"],
            r["error"].replace("|", "/"))
    return "| %s | %d | %s | ok | %s | %s | %s | %s | %s | %.1f | %s |" % (
        r["surface"], r["k"], r["strategy"], "yes" if c.get("conforming") else "**no**",
        fmt(q.get("tetrahedra"), "%d"), fmt(c.get("volume_error"), "%.1e"),
        fmt(q.get("minimum_dihedral_angle_degrees"), "%.2f"),
        under10(q.get("share_below_10_degrees"), q.get("tetrahedra")),
        r["seconds"], "; ".join(c.get("problems", []))[:300].replace("|", "/"))


def serial_row(name, s, label="serial TetGen", note=None):
    if not s.get("ok"):
        return "| %s | - | %s | **fail** | - | - | - | - | - | %.1f | %s |" % (
            name, label, s["seconds"], s.get("error", ""))
    return "| %s | - | %s `%s` | ok | - | %d | - | %.2f | %s | %.1f | %s |" % (
        name, label, s["switches"].split("a")[0], s["tetrahedra"], s["minimum_dihedral_angle_degrees"],
        under10(s["share_below_10_degrees"], s["tetrahedra"]), s["seconds"],
        note if note is not None else "H = %.4g, bound a = %.4g" % (s["size"], s["bound"]))


def topologically_conforming(r):
    """Conforming but perhaps for the boundary area: every problem is the area one."""
    c = r.get("conformity", {})
    return r["ok"] and "tetrahedra" in c and all(p.startswith("boundary area") for p in c.get("problems", []))


def ratios(good, s):
    """(worst under-10 share over the runs / serial's, worst minimum dihedral / serial's)."""
    if not good or not s.get("ok"):
        return None, None
    su = max(r["quality"]["share_below_10_degrees"] for r in good)
    sd = min(r["quality"]["minimum_dihedral_angle_degrees"] for r in good)
    ref_u = s["share_below_10_degrees"]
    under = su / ref_u if ref_u > 0 else (0.0 if su == 0 else float("inf"))
    dih = sd / s["minimum_dihedral_angle_degrees"] if s["minimum_dihedral_angle_degrees"] > 0 else None
    return under, dih


def count_ratio(good, s):
    """Worst count of tetrahedra under 10 degrees over the runs / serial's (not a goal: serial -pq
    refines the boundary to many more tetrahedra, which lowers its share, not its count)."""
    if not good or not s.get("ok") or not s.get("tetrahedra"):
        return None
    ref = s["share_below_10_degrees"] * s["tetrahedra"]
    worst = max(r["quality"]["share_below_10_degrees"] * r["quality"]["tetrahedra"] for r in good)
    return worst / ref if ref > 0 else (0.0 if worst == 0 else float("inf"))


def mode_name(arguments):
    """The non-exact mode of a sweep, in words."""
    if arguments.get("remesh"):
        return "the surface remeshed at the run's size first (--remesh)"
    return "nearly coplanar input triangles merged (--coplanar-tolerance)"


def summarize(results, serial, names, exact=True, mode="nearly coplanar input triangles merged (--coplanar-tolerance)"):
    """exact: the runs were in the default (exact-geometry) mode, where the volume goal applies."""
    lines = []
    if not exact:
        lines.append("Mode: %s; the volume goal "
                     "(1e-9) is for the default mode only, so \"goals met\" here counts success, conformity "
                     "and quality, and the volume error column shows what the mode changed." % mode)
    refused = [r for r in results if r.get("refused")]
    if refused:
        lines.append("Refused up front, before any cut, with the largest K the part can hold at the size "
                     "(MinimumSlabThickness; not counted below): %d of %d runs: %s." % (
                         len(refused), len(results), "; ".join(
                             "%s K=%d %s" % (r["surface"], r["k"], r["strategy"]) for r in refused)))
        results = [r for r in results if not r.get("refused")]
    runs = len(results)
    ok = [r for r in results if r["ok"]]
    conform = [r for r in ok if r.get("conformity", {}).get("conforming")]
    topo = [r for r in ok if topologically_conforming(r)]
    lines.append("Runs: %d; succeeded %d (%.1f %%); succeeded and conformed %d (%.1f %%); succeeded and "
                 "conformed but for the boundary area (boundary nodes moved off the input surface) %d (%.1f %%)." % (
                     runs, len(ok), 100.0 * len(ok) / max(runs, 1), len(conform), 100.0 * len(conform) / max(runs, 1),
                     len(topo), 100.0 * len(topo) / max(runs, 1)))
    errors = [r["conformity"]["volume_error"] for r in ok if r.get("conformity", {}).get("volume_error") is not None]
    if errors:
        worst = max(ok, key=lambda r: r.get("conformity", {}).get("volume_error") or 0)
        lines.append("Max relative volume error %.2e (%s K=%d %s; goal <= %.0e); runs above the goal: %d of %d." % (
            max(errors), worst["surface"], worst["k"], worst["strategy"], GOAL_VOLUME_ERROR,
            sum(e > GOAL_VOLUME_ERROR for e in errors), len(errors)))
    lines.append("")
    lines.append("| surface | runs ok / all | conform | max under-10 share ratio vs serial -pq (goal <= %.1f) | "
                 "min dihedral ratio vs serial -pq (goal >= %.1f) | same two vs serial -pYq | max volume error | "
                 "goals met | max under-10 count ratio vs serial -pq (not a goal) |" % (
                     GOAL_UNDER10_RATIO, GOAL_DIHEDRAL_RATIO))
    lines.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for name in names:
        rs = [r for r in results if r["surface"] == name]
        if not rs:
            continue
        # ran: the runs that meshed; good: those whose quality was measured
        # too (all of them, unless reading a mesh failed)
        ran = [r for r in rs if r["ok"]]
        good = [r for r in ran if "tetrahedra" in r.get("quality", {})]
        s = serial.get(name, {})
        under, dih = ratios(good, s)
        under_y, dih_y = ratios(good, s.get("with_Y", {}))
        vols = [r["conformity"].get("volume_error") for r in ran if r.get("conformity", {}).get("volume_error") is not None]
        vmax = max(vols) if vols else None
        # a mode that moves the surface is checked against its own surface:
        # the boundary area no longer equals the input's
        nconf = sum(1 for r in ran if (r.get("conformity", {}).get("conforming") if exact
                                       else topologically_conforming(r)))
        met = (len(good) == len(rs) and nconf == len(rs) and under is not None and under <= GOAL_UNDER10_RATIO
               and dih is not None and dih >= GOAL_DIHEDRAL_RATIO and vmax is not None
               and (vmax <= GOAL_VOLUME_ERROR or not exact))
        lines.append("| %s | %d / %d | %d | %s | %s | %s / %s | %s | %s | %s |" % (
            name, len(ran), len(rs), nconf, fmt(under, "%.2f"), fmt(dih, "%.2f"), fmt(under_y, "%.2f"),
            fmt(dih_y, "%.2f"), fmt(vmax, "%.1e"), "yes" if met else "no", fmt(count_ratio(good, s), "%.2f")))
    failures = [r for r in results if not r["ok"]]
    if failures:
        lines.append("")
        lines.append("Failures by class:")
        lines.append("")
        by = {}
        for r in failures:
            by.setdefault(classify(r["error"]), []).append(r)
        for cls in sorted(by):
            lines.append("* **%s** (%d): %s" % (cls, len(by[cls]), "; ".join(
                "%s K=%d %s" % (r["surface"], r["k"], r["strategy"]) for r in by[cls])))
    noconf = [r for r in ok if not topologically_conforming(r)]
    if noconf:
        lines.append("")
        lines.append("Succeeded but not conforming (other than the boundary area): " + "; ".join(
            "%s K=%d %s (%s)" % (r["surface"], r["k"], r["strategy"],
                                 "; ".join(r.get("conformity", {}).get("problems", []))[:200]) for r in noconf))
    return lines


def report_only(args):
    saved = json.load(open(os.path.join(args.out, "results.json")))
    results, serial = saved["runs"], saved["serial"]
    names = list(serial)
    table = list(RUN_TABLE_HEADER)
    for name in names:
        table.append(serial_row(name, serial[name]))
        table.append(serial_row(name, serial[name]["with_Y"], "serial TetGen, surface kept", "same bound"))
        table += [row(r, serial[name]) for r in results if r["surface"] == name]
    saved_args = saved.get("arguments", {})
    exact = saved_args.get("coplanar_tolerance") is None and not saved_args.get("remesh")
    text = "\n".join(table + [""] + summarize(results, serial, names, exact, mode_name(saved_args))) + "\n"
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write(text)
    print(text)


def main(argv):
    args = parse_arguments(argv)
    args.out = os.path.abspath(args.out)
    plugin = args.plugin or os.path.join(args.build, "lib", "paraview-plugins", "ParallelTetMesher",
                                         "ParallelTetMesher.so")
    if not os.path.isfile(plugin):
        raise SystemExit("sweep: plugin %s not found (pass --plugin or --build)" % plugin)
    plugin = os.path.abspath(plugin)
    if not os.path.isdir(args.corpus):
        raise SystemExit("sweep: corpus %s not found: run Testing/Corpus/fetch.sh first" % args.corpus)
    names = sorted(f[:-4] for f in os.listdir(args.corpus) if f.endswith(".off"))
    ks = [int(k) for k in args.ks.split(",") if k] or ([2, 8] if args.quick else ALL_KS)
    strategies = [s for s in args.strategies.split(",") if s] or ALL_STRATEGIES
    if args.surfaces:
        wanted = args.surfaces.split(",")
        unknown = [w for w in wanted if w not in names]
        if unknown:
            raise SystemExit("sweep: not in the corpus: %s" % ", ".join(unknown))
        names = wanted
    elif args.quick:
        names = [n for n in QUICK_SURFACES if n in names]
    os.makedirs(args.out, exist_ok=True)
    if args.report_only:
        report_only(args)
        return
    print("sweep: %d surfaces, K %s, %s, %d ranks, timeout %.0f s, plugin %s" % (
        len(names), ks, strategies, args.ranks, args.timeout, plugin), flush=True)

    results, serial = [], {}
    exact = args.coplanar_tolerance is None and not args.remesh
    json_path = os.path.join(args.out, "results.json")
    md_path = os.path.join(args.out, "results.md")
    header = RUN_TABLE_HEADER
    table = list(header)
    print("\n".join(header), flush=True)

    def save():
        with open(json_path, "w") as f:
            json.dump({"arguments": vars(args), "plugin": plugin, "serial": serial, "runs": results}, f, indent=1)
        with open(md_path, "w") as f:
            f.write("\n".join(table + [""] + summarize(results, serial, names, exact, mode_name(vars(args)))) + "\n")

    for name in names:
        surface = os.path.join(os.path.abspath(args.corpus), name + ".off")
        stats = surface_tool.stats(surface)
        ref = calibrate(name, surface, stats, args, os.path.join(args.out, "serial", name))
        ref["input"] = stats
        serial[name] = ref
        table.append(serial_row(name, ref))
        table.append(serial_row(name, ref["with_Y"], "serial TetGen, surface kept", "same bound"))
        print("\n".join(table[-2:]), flush=True)
        size = ref["size"]
        jobs = [(k, s) for k in ks for s in strategies]
        with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            futures = [pool.submit(pipeline_run, surface, name, k, s, size, stats, args, plugin) for k, s in jobs]
            for fut in futures:
                r = fut.result()
                results.append(r)
                table.append(row(r, ref))
                print(table[-1], flush=True)
                save()
        save()
    print("")
    print("\n".join(summarize(results, serial, names, exact, mode_name(vars(args)))))
    print("\nsweep: wrote %s and %s" % (md_path, json_path))


if __name__ == "__main__":
    main(sys.argv[1:])
