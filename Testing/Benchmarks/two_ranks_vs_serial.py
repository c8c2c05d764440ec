"""2 ranks (K = 2) against serial TetGen on balls of given sizes: whole
processes as a user runs them, the peers alternating, figures not tests.

    /usr/bin/python3 Testing/Benchmarks/two_ranks_vs_serial.py PLUGIN SERIAL_TETGEN \
        2.4e6,5e6,1e7 [REPS] [OUT]

PLUGIN is ParallelTetMesher.so, SERIAL_TETGEN the serial_tetgen of the same
build (run.sh builds both; so does `cmake --build build`). Prints one JSON line
per run and a table of the medians; writes OUT/two_ranks.json (OUT:
out/two_ranks). Needs OMPI_MCA_rmaps_base_oversubscribe=1 on 2 cores, and
OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM)=1 as root.
"""
import json
import os
import shutil
import statistics
import sys

import cases as casemod
import peers


def main(argv):
    plugin, serial = os.path.abspath(argv[0]), os.path.abspath(argv[1])  # the runs start in their folders
    targets = [float(t) for t in argv[2].split(",")]
    reps = int(argv[3]) if len(argv) > 3 else 2
    out = argv[4] if len(argv) > 4 else os.path.join(casemod.ROOT, "out", "two_ranks")
    rows = []
    for target in targets:
        case = casemod.Case("ball_%g" % target, "ball", target, "unit ball")
        casemod.prepare(case, os.path.join(out, "inputs"))
        for rep in range(reps):
            for peer in (["serial", "pipeline"] if rep % 2 == 0 else ["pipeline", "serial"]):
                folder = os.path.join(out, "runs", case.name, peer)
                r = (peers.run_serial_tetgen(case, folder, serial) if peer == "serial"
                     else peers.run_pipeline(case, 2, 2, folder, plugin))
                row = {"target": target, "surface_triangles": case.surface_triangles, "peer": peer, "rep": rep}
                row.update({k: r[k] for k in ("tetrahedra", "seconds", "process_seconds", "peak_rss_mb")})
                if peer == "pipeline":
                    row["stages"] = r["stages"]
                    row["tetrahedra_per_rank"] = r["tetrahedra_per_rank"]
                print(json.dumps(row), flush=True)
                rows.append(row)
                shutil.rmtree(folder, ignore_errors=True)
    with open(os.path.join(out, "two_ranks.json"), "w") as f:
        json.dump(rows, f, indent=1)
    # The ceiling: the wall ratio if each rank did nothing but run TetGen, at
    # serial TetGen's own time per tetrahedron, and every other step of both
    # peers took no time: serial tetrahedra over the largest rank's. Each
    # rank meshes about half of a mesh some 7 % larger than serial TetGen's
    # (the interfaces), so this is about 1.87x on the balls, and 1.8x leaves
    # 4 % of serial TetGen's time for everything else.
    print("| target | serial tets | serial s | 2 ranks tets | 2 ranks s | wall ratio | ceiling | rate ratio "
          "| surface stages | peak MB serial / per rank |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for target in targets:
        def pick(peer):
            return [r for r in rows if r["target"] == target and r["peer"] == peer]
        s, p = pick("serial"), pick("pipeline")
        ts, tp = statistics.median(r["process_seconds"] for r in s), statistics.median(r["process_seconds"] for r in p)
        surface = statistics.median(sum(r["stages"][k] for k in ("cut", "interface", "relax")) for r in p)
        ceiling = s[0]["tetrahedra"] / float(max(p[0]["tetrahedra_per_rank"]))
        print("| %.3g | %d | %.2f | %d | %.2f | %.2fx | %.2fx | %.2fx | %.1f s (%.0f %%) | %.0f / %s |" % (
            target, s[0]["tetrahedra"], ts, p[0]["tetrahedra"], tp, ts / tp, ceiling,
            (p[0]["tetrahedra"] / tp) / (s[0]["tetrahedra"] / ts), surface, 100 * surface / tp,
            max(r["peak_rss_mb"][0] for r in s), " / ".join("%.0f" % m for m in p[0]["peak_rss_mb"])))


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main(sys.argv[1:])
