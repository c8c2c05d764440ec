"""The benchmark's plots (matplotlib, PNG, no display needed)."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLORS = {"serial": "#7f7f7f", "gmsh": "#2ca02c"}
PIPELINE_COLORS = ["#aec7e8", "#6baed6", "#3182bd", "#08519c"]


def _peer_colors(case):
    colors, k = [], 0
    for p in case["peers"]:
        if p["kind"] == "pipeline":
            colors.append(PIPELINE_COLORS[k % len(PIPELINE_COLORS)])
            k += 1
        else:
            colors.append(COLORS[p["kind"]])
    return colors


def _grouped_bars(ax, results, value, error=None):
    cases = results["cases"]
    names = [p["peer"] for p in cases[0]["peers"]]
    width = 0.8 / len(names)
    x = np.arange(len(cases))
    colors = _peer_colors(cases[0])
    for i, name in enumerate(names):
        values = [value(next(p for p in c["peers"] if p["peer"] == name)) for c in cases]
        yerr = None
        if error:
            bounds = [error(next(p for p in c["peers"] if p["peer"] == name)) for c in cases]
            yerr = np.array([[v - lo for v, (lo, hi) in zip(values, bounds)], [hi - v for v, (lo, hi) in zip(values, bounds)]])
        ax.bar(x + (i - (len(names) - 1) / 2) * width, values, width, yerr=yerr, capsize=2, label=name,
               color=colors[i])
    ax.set_xticks(x)
    ax.set_xticklabels([c["case"] for c in cases])


def wall_time(results, folder):
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.5))
    _grouped_bars(a, results, lambda p: p["seconds"], lambda p: (p["seconds_min"], p["seconds_max"]))
    a.set_ylabel("seconds, read to written (median, min-max)")
    a.set_title("Wall time per peer")
    _grouped_bars(b, results, lambda p: p["tetrahedra_per_second"] / 1e3)
    b.set_ylabel("thousand tetrahedra per second")
    b.set_title("Throughput per peer")
    b.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(folder, "wall_time.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


STAGES = [("read", lambda p: p["stages"]["read"]), ("cut + gather", lambda p: p["stages"]["cut"]),
          ("interface", lambda p: p["stages"]["interface"]), ("relax", lambda p: p["stages"]["relax"]),
          ("TetGen (slowest rank)", lambda p: p["tetgen_slowest_rank_seconds"]),
          ("extract, number, assemble", lambda p: p["assemble_seconds"]), ("write", lambda p: p["stages"]["write"])]


def stage_breakdown(results, folder):
    cases = results["cases"]
    fig, axes = plt.subplots(1, len(cases), figsize=(4 * len(cases), 4.5), squeeze=False)
    colors = plt.get_cmap("tab10").colors
    for ax, case in zip(axes[0], cases):
        runs = [p for p in case["peers"] if p["kind"] == "pipeline"]
        bottom = np.zeros(len(runs))
        for k, (label, get) in enumerate(STAGES):
            v = np.array([get(p) for p in runs])
            ax.bar(range(len(runs)), v, bottom=bottom, label=label, color=colors[k])
            bottom += v
        ax.set_xticks(range(len(runs)))
        ax.set_xticklabels([p["peer"].replace("pipeline ", "").replace(" K=", "\nK=") for p in runs], fontsize=8)
        ax.set_title(case["case"])
        ax.set_ylabel("seconds")
    axes[0][-1].legend(fontsize=7)
    fig.suptitle("Pipeline stages (median over repetitions)")
    fig.tight_layout()
    path = os.path.join(folder, "stages.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def scaling(results, folder):
    proj = results["projection"]
    recs = [r for r in proj["records"] if "error" not in r]
    K = [r["subdomains"] for r in recs]
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for label, style, color in (("P=K", "o-", "C0"), ("P=K/4", "s-", "C1")):
        a.plot(K, [100 * r["predictions"][label]["efficiency"] for r in recs], style, color=color,
               label="%s, with surface stages" % label)
        a.plot(K, [100 * r["predictions"][label]["efficiency_meshing_only"] for r in recs], style[0] + "--",
               color=color, alpha=0.6, label="%s, volume meshing only" % label)
    a.axhline(80, color="gray", lw=0.8, ls=":", label="goal 80 %")
    a.set_xscale("log", base=2)
    a.set_xticks(K)
    a.set_xticklabels(K)
    a.set_xlabel("subdomains K")
    a.set_ylabel("predicted parallel efficiency, %")
    a.set_title("Projection on %s (serial TetGen %.1f s)" % (proj["case"], proj["serial_tetgen_seconds"]))
    a.legend(fontsize=8)
    b.plot(K, [r["surface_stage_seconds"] for r in recs], "o-", color="C3", label="surface stages, s")
    b.plot(K, [max(r["subdomain_seconds"]) for r in recs], "s-", color="C0", label="largest subdomain, s")
    b.set_xscale("log", base=2)
    b.set_yscale("log")
    b.set_xticks(K)
    b.set_xticklabels(K)
    b.set_xlabel("subdomains K")
    b.set_ylabel("seconds")
    c = b.twinx()
    c.plot(K, [r["interface_area"] for r in recs], "^-", color="C2", label="interface area")
    c.set_ylabel("interface area")
    lines = b.get_lines() + c.get_lines()
    b.legend(lines, [l.get_label() for l in lines], fontsize=8)
    b.set_title("Growth with K")
    fig.tight_layout()
    path = os.path.join(folder, "scaling.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def quality(results, folder):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for ax, (key, label, scale) in zip(axes, [
            ("minimum_dihedral_angle_degrees", "minimum dihedral angle, degrees", 1),
            ("share_below_10_degrees", "tetrahedra under 10 degrees, %", 100),
            ("maximum_radius_edge_ratio", "maximum radius-edge ratio", 1)]):
        _grouped_bars(ax, results, lambda p: scale * p["quality"][key])
        ax.set_title(label)
    axes[2].set_yscale("log")
    axes[0].legend(fontsize=7)
    fig.suptitle("Quality, computed the same way for every peer (mesh_quality.py)")
    fig.tight_layout()
    path = os.path.join(folder, "quality.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def all_plots(results, folder):
    paths = [wall_time(results, folder), stage_breakdown(results, folder), quality(results, folder)]
    if results.get("projection"):
        paths.append(scaling(results, folder))
    return paths
