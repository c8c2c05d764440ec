"""The benchmark's tables and the project's goals, from bench.json's results.

The goals are printed next to the figures as MET or MISSED; they are targets
of the project, not tests, and the driver's exit status ignores them.
"""
import os


def table(headers, rows, align=None):
    """Plain-text table, columns padded; align is a string of l/r per column."""
    cells = [[str(h) for h in headers]] + [[str(c) for c in r] for r in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(headers))]
    align = align or "l" + "r" * (len(headers) - 1)
    lines = []
    for n, r in enumerate(cells):
        lines.append("  ".join(c.ljust(w) if a == "l" else c.rjust(w) for c, w, a in zip(r, widths, align)))
        if n == 0:
            lines.append("  ".join("-" * w for w in widths))
    return "\n".join(lines)


def markdown_table(headers, rows):
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join(" --- " for _ in headers) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def _q(p, key, fmt):
    q = p.get("quality")
    return fmt % q[key] if q else "-"


def peer_rows(case):
    rows = []
    for p in case["peers"]:
        rows.append([
            p["peer"],
            "{:,}".format(p["tetrahedra"]),
            "%.2f" % p["seconds"] + (" (%.2f-%.2f)" % (p["seconds_min"], p["seconds_max"]) if p["repetitions"] > 1 else ""),
            "%.2f" % p["meshing_seconds"],
            "{:,.0f}".format(p["tetrahedra_per_second"]),
            "%.2fx" % p["speedup_vs_serial"],
            "%.2fx" % p["rate_vs_gmsh"],
            "/".join("%.0f" % m for m in p["peak_rss_mb_per_rank"]),
            _q(p, "minimum_dihedral_angle_degrees", "%.2f"),
            "%.4f" % (100 * p["quality"]["share_below_10_degrees"]) if p.get("quality") else "-",
            _q(p, "maximum_radius_edge_ratio", "%.2f"),
        ])
    return rows


PEER_HEADERS = ["peer", "tets", "s read->written", "meshing s", "tets/s", "vs serial", "rate vs Gmsh",
                "peak RSS MB/rank", "min dih deg", "% <10 deg", "max R/e"]

STAGE_HEADERS = ["case", "peer", "read", "cut+gather", "interface", "relax", "TetGen slowest rank",
                 "extract+number+assemble", "write", "total", "surface %", "TetGen s max/mean",
                 "tets max/mean", "tets per rank"]


def stage_rows(results):
    rows = []
    for case in results["cases"]:
        for p in case["peers"]:
            if p["kind"] != "pipeline":
                continue
            st = p["stages"]
            rows.append([case["case"], p["peer"], "%.2f" % st["read"], "%.2f" % st["cut"], "%.2f" % st["interface"],
                         "%.2f" % st["relax"], "%.2f" % p["tetgen_slowest_rank_seconds"], "%.2f" % p["assemble_seconds"],
                         "%.2f" % st["write"], "%.2f" % p["seconds"], "%.1f" % (100 * p["surface_share"]),
                         "%.3f" % p["time_balance_max_over_mean"], "%.3f" % p["tetrahedra_balance_max_over_mean"],
                         "/".join("{:,}".format(t) for t in p["tetrahedra_per_rank"])])
    return rows


PROJECTION_HEADERS = ["K", "tets", "cut s", "interface s", "relax s", "surface s", "interface area",
                      "subdomain s sum", "largest subdomain s", "P=K makespan s", "eff P=K", "P=K/4",
                      "P=K/4 makespan s", "eff P=K/4", "eff P=K meshing only"]


def projection_rows(results):
    rows = []
    for r in results["projection"]["records"]:
        if "error" in r:
            rows.append([r["subdomains"], "FAILED"] + ["-"] * (len(PROJECTION_HEADERS) - 2))
            continue
        pk, pq = r["predictions"]["P=K"], r["predictions"]["P=K/4"]
        st = r["stage_seconds"]
        rows.append([r["subdomains"], "{:,}".format(r["tetrahedra"]), "%.2f" % st["cut"], "%.2f" % st["interface"],
                     "%.2f" % st["relax"], "%.2f" % r["surface_stage_seconds"], "%.2f" % r["interface_area"],
                     "%.2f" % r["meshing_seconds_sum"], "%.2f" % max(r["subdomain_seconds"]),
                     "%.2f" % pk["makespan_seconds"], "%.0f%%" % (100 * pk["efficiency"]), pq["ranks"],
                     "%.2f" % pq["makespan_seconds"], "%.0f%%" % (100 * pq["efficiency"]),
                     "%.0f%%" % (100 * pk["efficiency_meshing_only"])])
    return rows


def goals(results, large_name):
    """The five goals with the figure each is judged on."""
    large = next(c for c in results["cases"] if c["case"] == large_name)
    serial = next(p for p in large["peers"] if p["kind"] == "serial")
    gmsh = next(p for p in large["peers"] if p["kind"] == "gmsh")
    two = [p for p in large["peers"] if p["kind"] == "pipeline" and p["ranks"] == 2]
    best = min(two, key=lambda p: p["seconds"])
    out = []

    def goal(name, value, met, figure, note):
        out.append({"goal": name, "value": value, "met": bool(met), "figure": figure, "note": note})

    speedup = serial["seconds"] / best["seconds"]
    goal("2 ranks >= 1.8x faster than serial TetGen on the %s case" % large_name, speedup, speedup >= 1.8,
         "%.2fx" % speedup,
         "%s, read to written %.2f s against %.2f s; volume meshing alone %.2fx" % (
             best["peer"], best["seconds"], serial["seconds"], serial["meshing_seconds"] / best["meshing_seconds"]))
    rate = best["tetrahedra_per_second"] / gmsh["tetrahedra_per_second"]
    goal(">= 1.5x Gmsh HXT's tetrahedra per second", rate, rate >= 1.5, "%.2fx" % rate,
         "%s %s tets/s against Gmsh HXT (2 threads) %s tets/s on %s; other cases: %s" % (
             best["peer"], "{:,.0f}".format(best["tetrahedra_per_second"]),
             "{:,.0f}".format(gmsh["tetrahedra_per_second"]), large_name,
             ", ".join("%s %.2fx" % (c["case"], max(p["rate_vs_gmsh"] for p in c["peers"]
                                                     if p["kind"] == "pipeline" and p["ranks"] == 2))
                       for c in results["cases"] if c is not large)))
    share = best["surface_share"]
    goal("surface stages < 5% of the total", share, share < 0.05, "%.1f%%" % (100 * share),
         "%s: cut+gather %.2f s, interface %.2f s, relax %.2f s of %.2f s; worst over all pipeline runs %.1f%%" % (
             best["peer"], best["stages"]["cut"], best["stages"]["interface"], best["stages"]["relax"],
             best["seconds"], 100 * max(p["surface_share"] for c in results["cases"] for p in c["peers"]
                                        if p["kind"] == "pipeline")))
    if results.get("projection"):
        rec = next((r for r in results["projection"]["records"] if r["subdomains"] == 64), None)
        if rec and "error" in rec:
            goal("predicted parallel efficiency >= 80% at 64 ranks", None, False, "no figure",
                 "the K = 64 projection failed: " + rec["error"].splitlines()[-1])
        elif rec:
            e = rec["predictions"]["P=K"]["efficiency"]
            goal("predicted parallel efficiency >= 80% at 64 ranks", e, e >= 0.8, "%.0f%%" % (100 * e),
                 "K = 64 on 64 ranks: makespan %.2f s (surface stages %.2f s + largest subdomain %.2f s) against "
                 "serial TetGen %.2f s; meshing alone %.0f%%; K = 64 on 16 ranks %.0f%%" % (
                     rec["predictions"]["P=K"]["makespan_seconds"], rec["surface_stage_seconds"],
                     rec["predictions"]["P=K"]["meshing_makespan_seconds"], results["projection"]["serial_tetgen_seconds"],
                     100 * rec["predictions"]["P=K"]["efficiency_meshing_only"],
                     100 * rec["predictions"]["P=K/4"]["efficiency"]))
    # quality: every pipeline run on every case against serial TetGen on the same case
    measures = [("minimum_dihedral_angle_degrees", "min dihedral", -1, "%.2f deg"),
                ("share_below_10_degrees", "share under 10 deg", 1, "%.4f%%"),
                ("maximum_radius_edge_ratio", "max radius-edge", 1, "%.2f")]
    worse = {label: [] for _, label, _, _ in measures}
    runs = 0
    for c in results["cases"]:
        s = next(p for p in c["peers"] if p["kind"] == "serial")["quality"]
        for p in c["peers"]:
            if p["kind"] != "pipeline":
                continue
            runs += 1
            for key, label, sign, fmt in measures:
                if sign * (p["quality"][key] - s[key]) > 0:
                    scale = 100 if fmt.endswith("%%") else 1
                    worse[label].append("%s %s %s vs %s" % (c["case"], p["peer"].replace("pipeline ", ""),
                                                          fmt % (scale * p["quality"][key]), fmt % (scale * s[key])))
    count = sum(len(v) for v in worse.values())
    goal("quality no worse than serial TetGen", count, count == 0,
         "%d of %d comparisons worse" % (count, 3 * runs),
         "; ".join("%s worse in %d of %d runs (e.g. %s)" % (label, len(v), runs, v[0]) for label, v in worse.items() if v)
         or "every pipeline run on every case")
    return out


def print_report(results):
    m = results["machine"]
    print()
    print("== Benchmark (%s mode) on %d CPUs (%s), %.0f GB; load %.2f at start, %.2f at end; "
          "commit %s with %d uncommitted source files" % (
              results["mode"], m["cpus"], m["processor"], m["memory_gb"], m["load_average_at_start"][0],
              m["load_average_at_end"][0], m["commit"], m["uncommitted_source_files"]))
    for case in results["cases"]:
        cal = case["gmsh_calibration"]
        print()
        print("-- %s: %s; H = %.4f (TetGen -a %.3g), %s surface triangles; Gmsh MeshSizeMax %.4g (%.2f H)" % (
            case["case"], case["description"], case["size"], case["maximum_volume"],
            "{:,}".format(case["surface_triangles"]), cal["used_mesh_size_max"], cal["used_mesh_size_max"] / case["size"]))
        print(table(PEER_HEADERS, peer_rows(case)))
    print()
    print("-- Stage breakdown of the pipeline (seconds; median over repetitions)")
    print(table(STAGE_HEADERS, stage_rows(results), "ll" + "r" * (len(STAGE_HEADERS) - 2)))
    print()
    print("-- Cross-check: tetmesh.py's quality (ParaView Mesh Quality) against mesh_quality.py on the same meshes")
    print(table(["case", "peer", "min dih ParaView", "min dih here", "% <10 ParaView", "% <10 here"],
                [[c["case"], p["peer"], "%.2f" % p["paraview_quality"]["minimum_dihedral_angle_degrees"],
                  "%.2f" % p["quality"]["minimum_dihedral_angle_degrees"],
                  "%.4f" % (100 * p["paraview_quality"]["share_below_10_degrees"]),
                  "%.4f" % (100 * p["quality"]["share_below_10_degrees"])]
                 for c in results["cases"] for p in c["peers"] if p["kind"] == "pipeline"], "llrrrr"))
    if results.get("projection"):
        print()
        print("-- Scaling projection on %s: every subdomain meshed alone on one rank; serial TetGen %.2f s" % (
            results["projection"]["case"], results["projection"]["serial_tetgen_seconds"]))
        print(table(PROJECTION_HEADERS, projection_rows(results)))
        for r in results["projection"]["records"]:
            if "error" in r:
                print("K=%d FAILED: %s" % (r["subdomains"], r["error"]))
    print()
    print("-- Goals (targets, not tests)")
    print(table(["goal", "figure", ""], [[g["goal"], g["figure"], "MET" if g["met"] else "MISSED"]
                                         for g in results["goals"]], "lrl"))
    for n, g in enumerate(results["goals"], 1):
        print("  (%d) %s" % (n, g["note"]))
    if results.get("plots"):
        print()
        print("plots: " + ", ".join(results["plots"]))


def print_largest(result):
    r = result["run"]
    q = r["quality"]
    print()
    print("== Largest mesh with 2 ranks (K = 2): %s tetrahedra, H = %.4f, %s surface triangles" % (
        "{:,}".format(r["tetrahedra"]), result["size"], "{:,}".format(result["surface_triangles"])))
    print("read to written %.1f s (volume meshing %.1f s; TetGen per rank %s s), whole command %.1f s" % (
        r["seconds"], r["meshing_seconds"], "/".join("%.1f" % t for t in r["rank_meshing_seconds"]),
        r["process_seconds"]))
    print("peak RSS per rank %s MB; stages %s" % ("/".join("%.0f" % m for m in r["peak_rss_mb"]),
                                                 ", ".join("%s %.2f" % kv for kv in r["stages"].items())))
    print("quality: min dihedral %.2f deg, %.4f%% under 10 deg, max radius-edge %.2f" % (
        q["minimum_dihedral_angle_degrees"], 100 * q["share_below_10_degrees"], q["maximum_radius_edge_ratio"]))


def markdown(results):
    """The README section, from the figures of this run."""
    m = results["machine"]
    lines = ["## Measured performance", "",
             "All on one machine (%d CPUs, %s, %.0f GB), all peers in the same run and alternating, on the same "
             "surface with the same size bound; %s mode. Reproduce with" % (m["cpus"], m["processor"], m["memory_gb"],
                                                                            results["mode"]),
             "", "```sh", "bash Testing/Benchmarks/run.sh%s   # writes out/bench/bench.json and out/bench/*.png" % (
                 " --quick" if results["mode"] == "quick" else ""), "```", ""]
    for case in results["cases"]:
        lines += ["**%s** (%s, %s surface triangles, H = %.4f):" % (
            case["case"], case["description"], "{:,}".format(case["surface_triangles"]), case["size"]), "",
                  markdown_table(PEER_HEADERS, peer_rows(case)), ""]
    lines += ["Stage breakdown (seconds):", "", markdown_table(STAGE_HEADERS, stage_rows(results)), ""]
    if results.get("projection"):
        lines += ["Scaling projection on %s (every subdomain meshed alone, the plugin's rank assignment, "
                  "efficiency = T_serial / (P x makespan including the surface stages)):" % results["projection"]["case"],
                  "", markdown_table(PROJECTION_HEADERS, projection_rows(results)), ""]
        lines += ["K = %d failed: %s" % (r["subdomains"], r["error"]) for r in results["projection"]["records"]
                  if "error" in r]
        lines += [""]
    lines += ["Goals:", "", markdown_table(["goal", "figure", "", "how"],
                                            [[g["goal"], g["figure"], "MET" if g["met"] else "MISSED", g["note"]]
                                             for g in results["goals"]]), ""]
    return "\n".join(lines)


def write_markdown(results, folder):
    path = os.path.join(folder, "measured.md")
    with open(path, "w") as f:
        f.write(markdown(results))
    return path
