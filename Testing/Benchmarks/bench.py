"""Benchmark driver: the parallel pipeline against serial TetGen and Gmsh HXT
on the same surfaces, a stage breakdown, a scaling projection and the
project's goals. Run it through run.sh, which builds what it needs:

    bash Testing/Benchmarks/run.sh [--quick] [--largest] [--reps N]

Writes OUT/bench.json, OUT/*.png and prints the tables (OUT: out/bench).
Figures, not pass/fail: the exit status is non-zero only if a peer fails.
"""
import argparse
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time

import cases as casemod
import mesh_quality
import peers
import projection

# The peers, in the order of the first repetition; later repetitions rotate
# the order so no peer always runs first (cold caches) or last (a warm machine).
PEERS = [
    {"name": "serial TetGen", "kind": "serial"},
    {"name": "pipeline 1 rank K=1", "kind": "pipeline", "ranks": 1, "subdomains": 1},
    {"name": "pipeline 1 rank K=4", "kind": "pipeline", "ranks": 1, "subdomains": 4},
    {"name": "pipeline 2 ranks K=2", "kind": "pipeline", "ranks": 2, "subdomains": 2},
    {"name": "pipeline 2 ranks K=8", "kind": "pipeline", "ranks": 2, "subdomains": 8},
    {"name": "Gmsh HXT 2 threads", "kind": "gmsh", "threads": 2},
]
PROJECTION_KS = [8, 16, 32, 64]
# Gmsh's size bound on the first case starts at this fraction of H and is
# corrected once from the tetrahedron count (calibrated_gmsh_size): with the
# same H, HXT makes about a third of TetGen's tetrahedra, since TetGen's -a
# bound is a maximum volume and Gmsh's a target edge length. Each later case
# starts from the factor the previous one ended with.
GMSH_FIRST_SIZE_FACTOR = 0.6
GMSH_COUNT_TOLERANCE = 0.10
LARGEST_TARGET = 2e7


def parse_arguments(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="small cases (about 2 minutes), for development")
    p.add_argument("--largest", action="store_true",
                   help="only the largest mesh with 2 ranks (about 2 x 10^7 tetrahedra; not in the default run)")
    p.add_argument("--largest-target", type=float, default=LARGEST_TARGET, help="tetrahedra wanted by --largest")
    p.add_argument("--reps", type=int, default=None,
                   help="repetitions per peer (default: 2, and 1 for the 5 M ball to stay within 15 minutes)")
    p.add_argument("--out", default=os.path.join(casemod.ROOT, "out", "bench"))
    p.add_argument("--plugin", required=True)
    p.add_argument("--serial-tetgen", required=True)
    p.add_argument("--keep-meshes", action="store_true", help="keep every output mesh (large)")
    p.add_argument("--no-projection", action="store_true")
    args = p.parse_args(argv)
    # peers run in their own folders
    args.plugin, args.serial_tetgen, args.out = map(os.path.abspath, (args.plugin, args.serial_tetgen, args.out))
    return args


class Log:
    def __init__(self, path):
        self.start = time.perf_counter()
        self.file = open(path, "w")

    def __call__(self, text):
        line = "[%6.1f s] %s" % (time.perf_counter() - self.start, text)
        print(line, flush=True)
        self.file.write(line + "\n")
        self.file.flush()


def machine():
    load = os.getloadavg()
    return {
        "cpus": os.cpu_count(),
        "processor": next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")),
                          platform.processor()),
        "memory_gb": os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 1e9,
        "load_average_at_start": load,
        "gmsh": subprocess.run(["gmsh", "--version"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True).stdout.strip(),
        # the build is of the working tree, so uncommitted changes count
        "commit": _git("rev-parse", "--short", "HEAD"),
        "uncommitted_source_files": len(_git("status", "--porcelain", "--", "Filters", "CMakeLists.txt").splitlines()),
    }


def _git(*arguments):
    p = subprocess.run(["git", "-C", casemod.ROOT] + list(arguments), stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL, text=True)
    return p.stdout.strip()


def calibrated_gmsh_size(first_size, first_count, target):
    """One correction of Gmsh's size bound towards target tetrahedra: the count
    grows as the inverse cube of the bound in the interior."""
    return first_size * (first_count / float(target)) ** (1.0 / 3.0)


def run_peer(peer, case, folder, args, gmsh_size):
    if peer["kind"] == "serial":
        return peers.run_serial_tetgen(case, folder, args.serial_tetgen)
    if peer["kind"] == "pipeline":
        return peers.run_pipeline(case, peer["ranks"], peer["subdomains"], folder, args.plugin)
    r = peers.run_gmsh_hxt(case, folder, gmsh_size, peer["threads"])
    r["tetrahedra"] = mesh_quality.count_tetrahedra(r["output"])
    return r


def finish_run(run, args, with_quality):
    """Quality from the output (same code for every peer), then the mesh goes."""
    if with_quality:
        run["quality"] = mesh_quality.mesh_quality(run["output"])
        if run["tetrahedra"] != run["quality"]["tetrahedra"]:
            raise peers.PeerFailed("%s: the file holds %d tetrahedra, the mesher reported %d" % (
                run["output"], run["quality"]["tetrahedra"], run["tetrahedra"]))
    if not args.keep_meshes:
        folder = os.path.dirname(run["output"])
        for name in os.listdir(folder):
            path = os.path.join(folder, name)
            if name.startswith("mesh"):
                shutil.rmtree(path) if os.path.isdir(path) else os.remove(path)
    return run


def benchmark_case(case, reps, args, say, gmsh_factor):
    runs = []
    gmsh_size = gmsh_factor * case.size
    serial_tets = None
    calibration = None
    for rep in range(reps):
        order = PEERS[rep % len(PEERS):] + PEERS[:rep % len(PEERS)]
        for peer in order:
            folder = os.path.join(args.out, "runs", case.name, "%s_rep%d" % (peer["name"].replace(" ", "_"), rep))
            r = run_peer(peer, case, folder, args, gmsh_size)
            if peer["kind"] == "gmsh" and calibration is None:
                # the first Gmsh run calibrates its size bound; it counts as a
                # repetition if its count is already close to TetGen's
                calibration = {"mesh_size_max": gmsh_size, "tetrahedra": r["tetrahedra"],
                               "serial_tetrahedra": serial_tets}
                if abs(r["tetrahedra"] / float(serial_tets) - 1) > GMSH_COUNT_TOLERANCE:
                    finish_run(r, args, False)
                    gmsh_size = calibrated_gmsh_size(gmsh_size, r["tetrahedra"], serial_tets)
                    say("  Gmsh calibration: %d tets at MeshSizeMax %.4g (%.2f H) against TetGen's %d; "
                        "now %.4g (%.2f H)" % (r["tetrahedra"], r["mesh_size_max"], r["mesh_size_max"] / case.size,
                                               serial_tets, gmsh_size, gmsh_size / case.size))
                    r = run_peer(peer, case, folder, args, gmsh_size)
                calibration["used_mesh_size_max"] = gmsh_size
            if peer["kind"] == "serial":
                serial_tets = r["tetrahedra"]
            r.update(peer=peer["name"], kind=peer["kind"], ranks=peer.get("ranks", 1),
                     subdomains=peer.get("subdomains", 1), threads=peer.get("threads", 1), rep=rep)
            finish_run(r, args, rep == 0)
            runs.append(r)
            say("  %-22s rep %d: %9d tets, %7.2f s read to written (meshing %6.2f s), peak RSS %s MB" % (
                peer["name"], rep, r["tetrahedra"], r["seconds"], r["meshing_seconds"],
                "/".join("%.0f" % m for m in r["peak_rss_mb"])))
    return runs, calibration


def summarize_peer(runs):
    """Medians over the repetitions of one peer on one case (quality from the first)."""
    first = runs[0]
    seconds = [r["seconds"] for r in runs]
    s = {
        "peer": first["peer"], "kind": first["kind"], "ranks": first["ranks"], "subdomains": first["subdomains"],
        "repetitions": len(runs),
        "tetrahedra": first["tetrahedra"],
        "seconds": statistics.median(seconds), "seconds_min": min(seconds), "seconds_max": max(seconds),
        "meshing_seconds": statistics.median(r["meshing_seconds"] for r in runs),
        "process_seconds": statistics.median(r["process_seconds"] for r in runs),
        "peak_rss_mb_per_rank": [max(r["peak_rss_mb"][i] for r in runs) for i in range(len(first["peak_rss_mb"]))],
        "quality": first.get("quality"),
    }
    s["tetrahedra_per_second"] = s["tetrahedra"] / s["seconds"]
    if first["kind"] == "pipeline":
        stages = {k: statistics.median(r["stages"][k] for r in runs) for k in first["stages"]}
        tetgen = statistics.median(max(r["rank_meshing_seconds"]) for r in runs)
        mean_tetgen = statistics.median(sum(r["rank_meshing_seconds"]) / len(r["rank_meshing_seconds"]) for r in runs)
        s.update(
            stages=stages,
            surface_seconds=stages["cut"] + stages["interface"] + stages["relax"],
            tetgen_slowest_rank_seconds=tetgen,
            # the rest of the volume meshing stage: extracting subdomain
            # surfaces, numbering, owner all-reduce and assembling the output
            assemble_seconds=max(stages["volume meshing"] - tetgen, 0.0),
            rank_meshing_seconds=first["rank_meshing_seconds"],
            time_balance_max_over_mean=tetgen / mean_tetgen if mean_tetgen > 0 else 0.0,
            tetrahedra_per_rank=first["tetrahedra_per_rank"],
            tetrahedra_balance_max_over_mean=first["balance_max_over_mean"],
            paraview_quality=first["paraview_quality"])
        s["surface_share"] = s["surface_seconds"] / s["seconds"]
    if first["kind"] == "gmsh":
        s["mesh_size_max"] = first["mesh_size_max"]
    return s


def summarize_case(case, runs, calibration):
    by_peer = {}
    for r in runs:
        by_peer.setdefault(r["peer"], []).append(r)
    peers_ = [summarize_peer(by_peer[p["name"]]) for p in PEERS if p["name"] in by_peer]
    serial = next(p for p in peers_ if p["kind"] == "serial")
    gmsh = next(p for p in peers_ if p["kind"] == "gmsh")
    for p in peers_:
        p["speedup_vs_serial"] = serial["seconds"] / p["seconds"]
        p["meshing_speedup_vs_serial"] = serial["meshing_seconds"] / p["meshing_seconds"]
        p["rate_vs_gmsh"] = p["tetrahedra_per_second"] / gmsh["tetrahedra_per_second"]
    return {
        "case": case.name, "shape": case.shape, "description": case.description, "size": case.size,
        "maximum_volume": case.maximum_volume, "surface": case.stl, "surface_triangles": case.surface_triangles,
        "volume": case.volume, "target_tetrahedra": case.target, "gmsh_calibration": calibration,
        "peers": peers_,
    }


def run_largest(args, say):
    case = casemod.Case("ball_largest", "ball", args.largest_target, "unit ball, the largest mesh with 2 ranks")
    casemod.prepare(case, os.path.join(args.out, "inputs"))
    say("largest: %s, H = %.5f, %d surface triangles" % (case.name, case.size, case.surface_triangles))
    r = peers.run_pipeline(case, 2, 2, os.path.join(args.out, "runs", case.name, "pipeline_2_ranks_K=2"), args.plugin)
    r.update(peer="pipeline 2 ranks K=2", kind="pipeline", ranks=2, subdomains=2, rep=0)
    finish_run(r, args, True)
    result = {"case": case.name, "size": case.size, "surface_triangles": case.surface_triangles,
              "machine": machine(), "run": r}
    with open(os.path.join(args.out, "largest.json"), "w") as f:
        json.dump(result, f, indent=1)
    return result


def main(argv):
    args = parse_arguments(argv)
    os.makedirs(args.out, exist_ok=True)
    say = Log(os.path.join(args.out, "largest.log" if args.largest else "bench.log"))
    import report

    if args.largest:
        result = run_largest(args, say)
        report.print_largest(result)
        return 0

    info = machine()
    say("machine: %d CPUs, %.0f GB, load %.2f %.2f %.2f; %s" % (
        info["cpus"], info["memory_gb"], *info["load_average_at_start"], "quick mode" if args.quick else "full mode"))
    suite = casemod.default_cases(args.quick)
    for c in suite:
        casemod.prepare(c, os.path.join(args.out, "inputs"))
        say("case %s: %s, H = %.5f, %d surface triangles, volume %.3f" % (
            c.name, c.description, c.size, c.surface_triangles, c.volume))
    large = suite[1]  # the 5 M ball: goals and projection

    results = {"mode": "quick" if args.quick else "full", "machine": info, "cases": []}
    runs_file = os.path.join(args.out, "runs.json")  # every single run, one line per case
    if os.path.exists(runs_file):
        os.remove(runs_file)
    gmsh_factor = GMSH_FIRST_SIZE_FACTOR
    for c in suite:
        reps = args.reps if args.reps else (1 if c is large and not args.quick else 2)
        say("case %s, %d repetition(s) of %d peers" % (c.name, reps, len(PEERS)))
        runs, calibration = benchmark_case(c, reps, args, say, gmsh_factor)
        gmsh_factor = calibration["used_mesh_size_max"] / c.size
        results["cases"].append(summarize_case(c, runs, calibration))
        with open(runs_file, "a") as f:
            f.write(json.dumps({"case": c.name, "runs": runs}) + "\n")

    if not args.no_projection:
        large_summary = next(s for s in results["cases"] if s["case"] == large.name)
        serial_seconds = next(p for p in large_summary["peers"] if p["kind"] == "serial")["meshing_seconds"]
        say("projection on %s (serial TetGen %.2f s): K = %s on one rank" % (large.name, serial_seconds, PROJECTION_KS))
        results["projection"] = {
            "case": large.name, "serial_tetgen_seconds": serial_seconds,
            "records": projection.run_projection(large, PROJECTION_KS, os.path.join(args.out, "projection"),
                                                 args.plugin, args.serial_tetgen, serial_seconds, say)}

    results["machine"]["load_average_at_end"] = os.getloadavg()
    results["goals"] = report.goals(results, large.name)
    with open(os.path.join(args.out, "bench.json"), "w") as f:
        json.dump(results, f, indent=1)
    import plots

    results["plots"] = plots.all_plots(results, args.out)
    with open(os.path.join(args.out, "bench.json"), "w") as f:
        json.dump(results, f, indent=1)
    report.write_markdown(results, args.out)
    report.print_report(results)
    say("wrote %s and %d plots" % (os.path.join(args.out, "bench.json"), len(results["plots"])))
    return 0


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    try:
        sys.exit(main(sys.argv[1:]))
    except peers.PeerFailed as e:
        sys.stderr.write("bench: a peer failed: %s\n" % e)
        sys.exit(1)
