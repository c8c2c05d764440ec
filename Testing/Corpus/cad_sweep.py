"""Robustness of the whole pipeline on CAD files read as CAD (not through the
corpus' OFF surfaces): tetmesh.py on each file of OCCT's samples at several
K, both strategies, on R ranks; every mesh checked by the independent
conformity check against the surface tetmesh meshed (--save-surface).

    /usr/bin/python3 Testing/Corpus/cad_sweep.py occ/fuse.brep,occ/Ball.brep 24,48 [RANKS] [OUT]

Files are relative to /usr/share/opencascade/data (Debian's occt-misc). One
JSON line per run: return code, seconds, tetrahedra, conformity, minimum
dihedral angle, volume error, or the error lines of a failed run. A figure
command, not a test (runs at K = 48 can take minutes to fail).
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import conformity  # noqa: E402
import surface_tool  # noqa: E402

DATA = "/usr/share/opencascade/data"


def run(source, k, strategy, ranks, out):
    stem = os.path.join(out, "%s_K%d_%s_np%d" % (os.path.basename(source).split(".")[0], k, strategy, ranks))
    command = ["mpiexec", "-n", str(ranks), "--oversubscribe", "pvbatch", os.path.join(ROOT, "Scripts", "tetmesh.py"),
               os.path.join(DATA, source), "-o", stem + ".pvtu", "--subdomains", str(k), "--strategy", strategy,
               "--json", stem + ".json", "--save-surface", stem + "_surface.off"]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=1800,
                              env=env)
        code, text = done.returncode, done.stdout
    except subprocess.TimeoutExpired:
        code, text = "timeout", ""
    row = {"file": source, "k": k, "strategy": strategy, "ranks": ranks, "rc": code,
           "seconds": round(time.time() - start, 1)}
    if code == 0:
        with open(stem + ".json") as f:
            summary = json.load(f)
        check = conformity.check(stem + ".pvtu", surface_tool.stats(stem + "_surface.off"))
        row.update(tetrahedra=summary["tetrahedra"], conforming=check["conforming"], problems=check["problems"][:2],
                   minimum_dihedral=summary["quality"]["minimum_dihedral_angle_degrees"],
                   volume_error=check.get("volume_error"))
    else:
        row["error"] = [line for line in text.splitlines() if "error" in line.lower()][:3]
    return row


def main(argv):
    if len(argv) < 2:
        raise SystemExit(__doc__)
    ranks = int(argv[2]) if len(argv) > 2 else 2
    out = argv[3] if len(argv) > 3 else os.path.join(ROOT, "out", "cad_sweep")
    os.makedirs(out, exist_ok=True)
    for source in argv[0].split(","):
        for k in (int(k) for k in argv[1].split(",")):
            for strategy in ("RecursiveBisection", "ParallelPlanes"):
                print(json.dumps(run(source, k, strategy, ranks, out)), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
