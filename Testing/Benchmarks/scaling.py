"""Scaling of the real pipeline with P = 1 ... 64 MPI ranks, measured per rank
and per phase, and the wall time it predicts on P cores (issue #19).

    /usr/bin/python3 Testing/Benchmarks/scaling.py [--ranks 1,2,4,8,16,32,64]
        [--strong 2e6] [--weak 2.5e5] [--weak-ranks 1,2,4,8,16] [--out out/scaling]

This machine has 2 cores, so P > 2 runs oversubscribed and its wall time
means nothing. Instead every rank logs its processor time between the
pipeline's collectives (Filters/PhaseLog.h, PTM_PHASE_LOG): all ranks make
the same collective calls in the same order, so stretch i of every rank ends
at the same synchronisation. On P real cores the wall time is then about

    sum over stretches i of (max over ranks of the processor time in i)
      + sum over collectives of (latency x ceil(log2 P) + bytes moved / bandwidth)
      + sum over exchanges of (latency x (P - 1) + largest bytes a rank sends / bandwidth)

with `bytes moved` the bytes every rank receives (an all-gather delivers all
ranks' contributions to each; an all-reduce about twice the vector). The
first stretch holds pvbatch's start-up and the reading; the last (after the
last collective) the writing and teardown. Peers, per problem:

* serial TetGen: `serial_tetgen` (the same library call and switches) on the
  same surface with the same volume bound, whole process, processor time;
* efficiency at P = serial TetGen time / (P x predicted wall time).

Problems: a ball (Data/geo/ball.geo via gmsh, surface meshed at the same
size as the volume) of --strong tetrahedra for every P (strong scaling), and
of --weak tetrahedra per rank (weak scaling, K = P subdomains each time).
Prints a table per problem and writes OUT/scaling.json and OUT/scaling.png.
"""
import argparse
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cases  # noqa: E402
import peers  # noqa: E402

ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))


def parse_arguments(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--ranks", default="1,2,4,8,16,32,64")
    p.add_argument("--strong", type=float, default=2e6, help="tetrahedra of the strong-scaling ball")
    p.add_argument("--weak", type=float, default=2.5e5,
                   help="tetrahedra per rank of the weak-scaling ball (0: no weak scaling)")
    p.add_argument("--weak-ranks", default=None, help="rank counts of the weak scaling (default: --ranks)")
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--out", default=os.path.join(ROOT, "out", "scaling"))
    p.add_argument("--latency", type=float, default=5e-6, help="seconds per message hop (default 5 us)")
    p.add_argument("--bandwidth", type=float, default=5e9, help="bytes per second (default 5 GB/s)")
    return p.parse_args(argv)


def read_phase_logs(folder, ranks):
    """Per rank, the lines of its log: (phase, processor seconds, bytes, kind)."""
    logs = []
    for r in range(ranks):
        with open(os.path.join(folder, "rank-%d.tsv" % r)) as f:
            logs.append([(cols[1], float(cols[2]), int(cols[3]), cols[4])
                         for cols in (line.rstrip("\n").split("\t") for line in f)])
    counts = {len(log) for log in logs}
    if len(counts) != 1:
        raise RuntimeError("the ranks logged %s lines: not the same collectives" % sorted(counts))
    return logs


def predict(logs, latency, bandwidth):
    """Predicted wall seconds on P cores, per phase, and the bytes each rank sent."""
    ranks = len(logs)
    hops = math.ceil(math.log2(ranks)) if ranks > 1 else 0
    phases, communication, sent = {}, 0.0, [0] * ranks
    for i in range(len(logs[0])):
        name, kind = logs[0][i][0], logs[0][i][3]
        slowest = max(log[i][1] - (log[i - 1][1] if i else 0.0) for log in logs)
        phases[name] = phases.get(name, 0.0) + slowest
        contributed = [log[i][2] for log in logs]
        for r, b in enumerate(contributed):
            sent[r] += b
        if ranks > 1 and kind in ("allgather", "allreduce", "agree", "abort"):
            moved = sum(contributed) if kind == "allgather" else 2 * max(contributed)
            communication += latency * hops + moved / bandwidth
        elif ranks > 1 and kind == "exchange":
            # pairs of ranks in P - 1 rounds; a rank sends what it logged
            communication += latency * (ranks - 1) + max(contributed) / bandwidth
    return {"phases": phases, "communication": communication,
            "predicted_wall": sum(phases.values()) + communication, "bytes_sent": sent,
            "processor_seconds": [log[-1][1] for log in logs]}


def run_pipeline(case, ranks, folder, plugin):
    folder = peers._fresh(folder)
    env = peers.mpi_environment()
    env["PTM_PHASE_LOG"] = folder
    summary = os.path.join(folder, "summary.json")
    command = ["mpiexec", "-n", str(ranks), "pvbatch", peers.TETMESH, case.stl, "-o",
               os.path.join(folder, "mesh.pvtu"), "--subdomains", str(ranks), "--size", repr(case.size),
               "--json", summary, "--plugin", plugin]
    elapsed, _ = peers._run(command, folder, env)
    with open(summary) as f:
        s = json.load(f)
    return {"tetrahedra": s["tetrahedra"], "wall": elapsed, "logs": read_phase_logs(folder, ranks)}


def serial_processor_seconds(case, folder, executable):
    """Processor seconds of the whole serial_tetgen process (read to meshed)."""
    folder = peers._fresh(folder)
    before = os.times()
    subprocess.run([executable, case.off, "2.0", repr(case.maximum_volume)], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL)
    after = os.times()
    return (after.children_user - before.children_user) + (after.children_system - before.children_system)


def measure(case, ranks, args, plugin, serial_seconds, tag):
    rows = []
    for P in ranks:
        run = run_pipeline(case(P), P, os.path.join(args.out, "%s_P%d" % (tag, P)), plugin)
        model = predict(run["logs"], args.latency, args.bandwidth)
        serial = serial_seconds(P)
        row = {"ranks": P, "tetrahedra": run["tetrahedra"], "wall_oversubscribed": run["wall"],
               "serial_tetgen_seconds": serial,
               "efficiency": serial / (P * model["predicted_wall"]), **model}
        rows.append(row)
        print_row(tag, row)
    return rows


def print_row(tag, row):
    surface = sum(row["phases"].get(p, 0.0) for p in ("cut", "interface", "relax"))
    print("%s P=%3d  %10d tets  predicted %7.2f s (start+read %.2f, surface %.2f, meshing %.2f, "
          "numbering %.2f, writing %.2f, comm %.3f)  serial TetGen %.2f s  efficiency %5.1f %%  "
          "max sent %.1f MB  wall here %.1f s"
          % (tag, row["ranks"], row["tetrahedra"], row["predicted_wall"], row["phases"].get("start", 0.0),
             surface, row["phases"].get("volume meshing", 0.0), row["phases"].get("numbering and assembly", 0.0),
             row["phases"].get("end", 0.0), row["communication"], row["serial_tetgen_seconds"],
             100 * row["efficiency"], max(row["bytes_sent"]) / 1e6, row["wall_oversubscribed"]), flush=True)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for tag, rows in results.items():
        P = [r["ranks"] for r in rows]
        axes[0].plot(P, [100 * r["efficiency"] for r in rows], "o-", label=tag)
        meshing = [r["phases"].get("volume meshing", 0.0) for r in rows]
        other = [r["predicted_wall"] - m for r, m in zip(rows, meshing)]
        axes[1].plot(P, meshing, "o-", label="%s: volume meshing" % tag)
        axes[1].plot(P, other, "s--", label="%s: everything else" % tag)
    for ax in axes:
        ax.set_xscale("log", base=2)
        ax.set_xlabel("MPI ranks P")
        ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("predicted efficiency vs serial TetGen (%)")
    axes[1].set_ylabel("predicted wall seconds on P cores")
    axes[1].set_yscale("log")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv):
    args = parse_arguments(argv)
    args.out = os.path.abspath(args.out)  # the runs start in folders of their own
    ranks = [int(r) for r in args.ranks.split(",")]
    plugin = os.path.join(args.build, "lib", "paraview-plugins", "ParallelTetMesher", "ParallelTetMesher.so")
    tetgen = os.path.join(args.build, "bin", "serial_tetgen")
    surfaces = os.path.join(args.out, "surfaces")
    serial_cache = {}

    def ball(target):
        return cases.prepare(cases.Case("ball_%d" % target, "ball", target, "unit ball"), surfaces)

    def serial(case):
        if case.name not in serial_cache:
            serial_cache[case.name] = serial_processor_seconds(case, os.path.join(args.out, "serial"), tetgen)
        return serial_cache[case.name]

    strong = ball(int(args.strong))
    results = {"strong": measure(lambda P: strong, ranks, args, plugin, lambda P: serial(strong), "strong")}
    if args.weak > 0:
        weak_ranks = [int(r) for r in (args.weak_ranks or args.ranks).split(",")]
        results["weak"] = measure(lambda P: ball(int(args.weak * P)), weak_ranks, args, plugin,
                                  lambda P: serial(ball(int(args.weak * P))), "weak")
    with open(os.path.join(args.out, "scaling.json"), "w") as f:
        json.dump({"latency": args.latency, "bandwidth": args.bandwidth,
                   "results": {tag: [{k: v for k, v in r.items()} for r in rows] for tag, rows in results.items()}},
                  f, indent=1)
    plot(results, os.path.join(args.out, "scaling.png"))
    print("wrote %s" % os.path.join(args.out, "scaling.json"))


if __name__ == "__main__":
    main(sys.argv[1:])
