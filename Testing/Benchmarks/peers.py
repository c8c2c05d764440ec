"""The meshers compared, each run as its own command on the same surface with
the same size bound, with wall time and peak resident memory per process.

* pipeline: `mpiexec -n P pvbatch Scripts/tetmesh.py` with K subdomains;
  every rank runs under /usr/bin/time, so each rank's own peak RSS is known
  (the largest of pvbatch and the TetGen processes it forks);
* serial TetGen: serial_tetgen, the project's own library call and switches on
  the whole surface (the reference);
* Gmsh HXT: `gmsh -3` with Mesh.Algorithm3D = 10 and 2 threads on the same STL,
  its size bound scaled so the tetrahedron count matches TetGen's (see
  calibrated_gmsh_size in bench.py).

A run returns a dict: seconds is the time from reading the surface to the
written mesh as the mesher itself measures it (pvbatch's start-up and
tetmesh.py's own Mesh Quality summary are not part of it; the whole command's
time is process_seconds), meshing_seconds the volume meshing alone.
"""
import os
import re
import shutil
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
TETMESH = os.path.join(ROOT, "Scripts", "tetmesh.py")
TIME_FORMAT = "%e %M"  # wall seconds, peak resident set in KB


def mpi_environment():
    env = dict(os.environ)
    if os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    return env


class PeerFailed(RuntimeError):
    pass


def _run(command, folder, env=None):
    """Runs command in folder, returns (elapsed seconds, stdout); stderr and
    stdout are kept in folder/log.txt."""
    start = time.perf_counter()
    p = subprocess.run(command, cwd=folder, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    elapsed = time.perf_counter() - start
    with open(os.path.join(folder, "log.txt"), "w") as log:
        log.write(" ".join(command) + "\n" + p.stdout)
    if p.returncode != 0:
        tail = "\n".join(p.stdout.strip().splitlines()[-5:])
        raise PeerFailed("%s exited with %d:\n%s" % (os.path.basename(command[0]), p.returncode, tail))
    return elapsed, p.stdout


def _time_file(path):
    """(wall seconds, peak RSS in MB) from a /usr/bin/time -o file (its last line)."""
    with open(path) as f:
        wall, kilobytes = f.read().strip().splitlines()[-1].split()
    return float(wall), float(kilobytes) / 1024.0


def _fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


def rank_meshing_seconds(piece_path):
    """RankMeshingSeconds of one piece (the TetGen seconds of its rank), read
    from the piece's XML header: the array has one value, so its RangeMin is
    the value. (meshio 5.0 assigns the appended field arrays to the wrong
    names, so it is not used for this.)"""
    with open(piece_path, "rb") as f:
        head = f.read(1 << 16).decode("latin-1")
    m = re.search(r'Name="RankMeshingSeconds"[^>]*RangeMin="([^"]+)"', head)
    return float(m.group(1)) if m else None


def run_pipeline(case, ranks, subdomains, folder, plugin):
    import json

    from mesh_quality import piece_files

    folder = _fresh(folder)
    output = os.path.join(folder, "mesh.pvtu")
    summary = os.path.join(folder, "summary.json")
    wrapper = 'exec /usr/bin/time -f "%s" -o "$0.$OMPI_COMM_WORLD_RANK" "$@"' % TIME_FORMAT
    command = ["mpiexec", "-n", str(ranks), "sh", "-c", wrapper, os.path.join(folder, "time"),
               "pvbatch", TETMESH, case.stl, "-o", output, "--subdomains", str(subdomains),
               "--size", repr(case.size), "--json", summary, "--plugin", plugin]
    elapsed, _ = _run(command, folder, mpi_environment())
    with open(summary) as f:
        s = json.load(f)
    per_rank = [_time_file(os.path.join(folder, "time.%d" % r)) for r in range(ranks)]
    pieces = piece_files(output)
    return {
        "tetrahedra": s["tetrahedra"],
        "seconds": sum(s["seconds"].values()),
        "meshing_seconds": s["seconds"]["volume meshing"],
        "process_seconds": elapsed,
        "peak_rss_mb": [rss for _, rss in per_rank],
        "stages": s["seconds"],
        "rank_meshing_seconds": [rank_meshing_seconds(p) for p in pieces],
        "tetrahedra_per_rank": s["tetrahedra_per_rank"],
        "subdomains_per_rank": s["subdomains_per_rank"],
        "balance_max_over_mean": s["balance_max_over_mean"],
        "paraview_quality": s["quality"],
        "output": output,
    }


def run_serial_tetgen(case, folder, executable):
    import json

    folder = _fresh(folder)
    output = os.path.join(folder, "mesh.vtk")
    timing = os.path.join(folder, "time.0")
    command = ["/usr/bin/time", "-f", TIME_FORMAT, "-o", timing, executable, case.off, "2.0",
               repr(case.maximum_volume), output]
    elapsed, stdout = _run(command, folder)
    s = json.loads(stdout.strip().splitlines()[-1])
    return {
        "tetrahedra": s["tetrahedra"],
        "seconds": s["read_seconds"] + s["orient_seconds"] + s["seconds"] + s["write_seconds"],
        "meshing_seconds": s["seconds"],
        "process_seconds": elapsed,
        "peak_rss_mb": [_time_file(timing)[1]],
        "switches": s["switches"],
        "output": output,
    }


GMSH_SCRIPT = """// the case's STL as one volume, meshed by HXT
Merge "{stl}";
Surface Loop(1) = {{1}};
Volume(1) = {{1}};
Mesh.Algorithm3D = 10;
Mesh.MeshSizeMax = {size!r};
"""


def run_gmsh_hxt(case, folder, size, threads=2):
    folder = _fresh(folder)
    script = os.path.join(folder, "hxt.geo")
    with open(script, "w") as f:
        f.write(GMSH_SCRIPT.format(stl=case.stl, size=size))
    output = os.path.join(folder, "mesh.msh")
    timing = os.path.join(folder, "time.0")
    command = ["/usr/bin/time", "-f", TIME_FORMAT, "-o", timing, "gmsh", script, "-3", "-nt", str(threads),
               "-bin", "-format", "msh4", "-o", output]
    elapsed, stdout = _run(command, folder)
    meshing = re.search(r"Done meshing 3D \(Wall ([0-9.eE+-]+)s", stdout)
    total = re.search(r"From start: Wall ([0-9.eE+-]+)s", stdout)
    if not meshing or "\nError   :" in stdout:
        raise PeerFailed("gmsh did not mesh the volume; see %s/log.txt" % folder)
    return {
        "tetrahedra": None,  # counted from the file by the caller (Gmsh's log counts before optimising)
        "seconds": float(total.group(1)) if total else elapsed,
        "meshing_seconds": float(meshing.group(1)),
        "process_seconds": elapsed,
        "peak_rss_mb": [_time_file(timing)[1]],
        "mesh_size_max": size,
        "output": output,
    }
