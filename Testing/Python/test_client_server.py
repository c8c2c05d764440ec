"""Client-server: the plugin as a pvserver user meets it.

    pvpython --no-mpi test_client_server.py PLUGIN DATA_DIR RANKS [SURFACE] [K]

This process is the driver. It starts `mpiexec -n RANKS pvserver
--server-port=<free port>` on localhost in its own process group, waits until
it listens, and runs the client, `pvpython --no-mpi test_client_server.py
--client PORT ...` (this file again), which connects, loads the plugin on the
server only (LoadPlugin(remote=True)), runs VolumeBalancedCutter ->
InterfaceTriangulator -> SurfaceRelaxer -> ParallelTetMesher on SURFACE
(default bracket.stl) with K = 4 subdomains, checks what it sees and
disconnects:

* the connection has RANKS data partitions, and every server rank holds a
  non-empty piece (fetched piece by piece; ProcessIdScalars, a ParaView
  filter independent of the plugin, agrees with the plugin's Rank array);
* the data information's cell count equals the field data GlobalCellCount and
  the cells of the gathered pieces; GlobalCellIds are 0..T-1 once each,
  GlobalPointIds 0..P-1, every point owned once, all subdomains 0..K-1
  present, every tetrahedron positive, and the mesh boundary equals the
  boundary port (mesh_checks.check_volume_mesh, numpy only).

The client is a separate process because pvpython closes its server
connection only when it exits (simple.Disconnect() alone leaves pvserver
waiting). After the client has ended, the server must exit by itself with
code 0; it is killed in every case (normal end, failure, SIGTERM/SIGINT,
the watchdog after WATCHDOG_SECONDS), and mpiexec gets SIGTERM if the driver
dies.
"""
import ctypes
import os
import signal
import socket
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

WATCHDOG_SECONDS = 270          # CTest's TIMEOUT is 300: end (and clean up) before it
LISTEN_TIMEOUT_SECONDS = 60     # pvserver under mpiexec usually listens within 2 s
CLIENT_TIMEOUT_SECONDS = 180    # the client's whole run; about 10 s here
SERVER_EXIT_SECONDS = 30        # pvserver ends within a second of the client


def free_port():
    """A TCP port that is free right now (the kernel picks it for port 0)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def _die_with_parent():
    """In a child before exec: SIGTERM it when the driver dies (mpiexec then
    terminates its pvserver ranks)."""
    try:
        libc = ctypes.CDLL("libc.so.6", use_errno=True)
        libc.prctl(1, signal.SIGTERM)  # 1 = PR_SET_PDEATHSIG
    except OSError:
        pass


def _server_group():
    """In the server's child before exec: a new process group, so that the
    whole server can be killed at once, and SIGTERM when the driver dies."""
    os.setsid()
    _die_with_parent()


def server_environment():
    """This process's environment without what MPI_Init of a singleton
    (pvpython without --no-mpi) or an enclosing mpiexec put there: with it, a
    child mpiexec believes it is itself an MPI process and exits with 1."""
    keep = ("OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "OMPI_MCA_rmaps_base_oversubscribe")
    launched = ("PMIX_", "ORTE_", "OMPI_COMM_WORLD_", "OMPI_UNIVERSE_", "OMPI_FIRST_RANKS", "OMPI_FILE_LOCATION",
                "OMPI_APP_CTX_", "OMPI_ARGV", "OMPI_COMMAND", "OMPI_MCA_ess", "OMPI_MCA_orte_", "OMPI_MCA_pmix",
                "OMPI_MCA_initial_wdir", "OMPI_MCA_mpi_oversubscribe", "OMPI_NUM_APP_CTX", "OMPI_MCA_shmem_RUNTIME_QUERY_hint")
    return {k: v for k, v in os.environ.items() if k in keep or not k.startswith(launched)}


class Server:
    """`mpiexec -n ranks pvserver` in its own process group, its output
    collected by a thread."""

    def __init__(self, ranks, port):
        self.port = port
        mpiexec = os.environ.get("PTM_MPIEXEC", "mpiexec")
        pvserver = os.environ.get("PTM_PVSERVER", "pvserver")
        self.command = [mpiexec, "-n", str(ranks), "--oversubscribe", pvserver,
                        "--server-port=%d" % port, "--force-offscreen-rendering",
                        "--disable-xdisplay-test"]
        print("client-server: starting", " ".join(self.command))
        sys.stdout.flush()
        self.lines = []
        self.listening = threading.Event()
        self.process = subprocess.Popen(self.command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        stdin=subprocess.DEVNULL, env=server_environment(), preexec_fn=_server_group)
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for raw in self.process.stdout:
            line = raw.decode(errors="replace").rstrip()
            self.lines.append(line)
            print("pvserver|", line)
            sys.stdout.flush()
            if "Accepting connection(s)" in line and line.endswith(":%d" % self.port):
                self.listening.set()

    def wait_listening(self, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if self.listening.wait(0.2):
                return True
            if self.process.poll() is not None:
                return False
        return False

    def kill(self):
        """SIGTERM to mpiexec (it ends its ranks and reaps them), then
        SIGKILL to whatever is left of the process group; returns mpiexec's
        exit code."""
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                pass
        try:
            os.killpg(self.process.pid, signal.SIGKILL)  # ranks that outlived mpiexec
        except ProcessLookupError:
            pass
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            pass
        self.reader.join(5)
        return self.process.poll()


def start_server(ranks):
    """A listening server; a new port if the first was taken meanwhile."""
    for attempt in range(3):
        server = Server(ranks, free_port())
        if server.wait_listening(LISTEN_TIMEOUT_SECONDS):
            return server
        server.kill()
        print("client-server: pvserver did not listen (attempt %d)" % (attempt + 1))
    raise RuntimeError("pvserver did not start listening:\n" + "\n".join(server.lines[-30:]))


def run_client(port, plugin, surface_path, ranks, K):
    import numpy as np
    from paraview import servermanager, simple
    from vtkmodules.util.numpy_support import vtk_to_numpy

    from mesh_checks import cells_of, check_volume_mesh

    connection = simple.Connect("localhost", port, timeout=60)
    assert connection is not None, "could not connect to localhost:%d" % port
    try:
        partitions = servermanager.ActiveConnection.GetNumberOfDataPartitions()
        assert partitions == ranks, "the server has %d partitions, expected %d" % (partitions, ranks)

        # the plugin lives on the server; the client only learns the proxies
        simple.LoadPlugin(plugin, remote=True, ns=globals())
        for name in ("VolumeBalancedCutter", "InterfaceTriangulator", "SurfaceRelaxer", "ParallelTetMesher"):
            assert name in globals(), "%s not defined after LoadPlugin(remote=True)" % name

        reader = simple.OpenDataFile(surface_path)  # the path is read by the server
        assert reader is not None, "no reader for %s on the server" % surface_path
        cutter = VolumeBalancedCutter(Input=reader, NumberOfSubdomains=K)  # noqa: F821
        interfaces = InterfaceTriangulator(Input=cutter)  # noqa: F821
        relaxed = SurfaceRelaxer(Input=interfaces)  # noqa: F821
        mesher = ParallelTetMesher(Input=relaxed)  # noqa: F821
        start = time.perf_counter()
        mesher.UpdatePipeline()
        seconds = time.perf_counter() - start

        info = mesher.GetDataInformation(0)
        cells = info.GetNumberOfCells()
        print("client-server: %d tetrahedra, %d points (with copies) in %.2f s on %d server ranks" % (
            cells, info.GetNumberOfPoints(), seconds, partitions))
        assert info.GetDataClassName() == "vtkUnstructuredGrid", info.GetDataClassName()
        assert cells > 0, "the mesh is empty"
        arrays = set(info.GetCellDataInformation().GetArrayInformation(i).GetName()
                     for i in range(info.GetCellDataInformation().GetNumberOfArrays()))
        assert {"GlobalCellIds", "SubdomainId", "Rank"} <= arrays, arrays
        subdomain_range = mesher.CellData["SubdomainId"].GetRange()
        assert subdomain_range == (0.0, K - 1.0), subdomain_range
        rank_range = mesher.CellData["Rank"].GetRange()
        assert rank_range == (0.0, ranks - 1.0), rank_range

        # every server rank holds a non-empty piece, and its cells say so
        pieces = []
        for r in range(ranks):
            piece = servermanager.Fetch(mesher, r)
            n = piece.GetNumberOfCells()
            assert n > 0, "server rank %d holds no tetrahedra" % r
            own = vtk_to_numpy(piece.GetCellData().GetArray("Rank"))
            assert np.all(own == r), "piece of rank %d has cells with Rank %s" % (r, np.unique(own))
            pieces.append(n)
        print("client-server: tetrahedra per server rank", pieces)
        assert sum(pieces) == cells, (pieces, cells)

        # ParaView's own process ids (not the plugin's) agree
        pids = simple.ProcessIdScalars(Input=simple.OutputPort(mesher, 0))
        pids.UpdatePipeline()
        assert pids.PointData["ProcessId"].GetRange() == (0.0, ranks - 1.0), \
            pids.PointData["ProcessId"].GetRange()
        for r in range(ranks):
            piece = servermanager.Fetch(pids, r)
            process = vtk_to_numpy(piece.GetPointData().GetArray("ProcessId"))
            assert len(process) > 0 and np.all(process == r), (r, np.unique(process))

        # the whole mesh on the client: global numbering and geometry.
        # servermanager.Fetch(mesher) is not used: with this ParaView 5.11 in
        # client-server mode it returned rank 0's piece only (also for
        # Wavelet + Tetrahedralize: 20000 of 40000 cells); an explicit
        # ReductionFilter gathers every piece on server rank 0, and fetching
        # rank 0's piece of it brings the whole mesh.
        def gathered(port):
            reduction = simple.ReductionFilter(Input=simple.OutputPort(mesher, port))
            reduction.PostGatherHelperName = "vtkAppendFilter" if port == 0 else "vtkAppendPolyData"
            reduction.UpdatePipeline()
            data = servermanager.Fetch(reduction, 0)
            simple.Delete(reduction)
            return data

        grid = gathered(0)
        assert grid.GetNumberOfCells() == cells, (grid.GetNumberOfCells(), cells)
        fd = grid.GetFieldData()
        total_cells = int(fd.GetArray("GlobalCellCount").GetValue(0))
        total_points = int(fd.GetArray("GlobalPointCount").GetValue(0))
        subdomains = int(fd.GetArray("NumberOfSubdomains").GetValue(0))
        per_subdomain = vtk_to_numpy(fd.GetArray("SubdomainTetrahedra")).astype(np.int64)
        assert total_cells == cells, "GlobalCellCount %d, cells %d" % (total_cells, cells)
        assert subdomains == K, "NumberOfSubdomains %d, expected %d" % (subdomains, K)
        assert per_subdomain.sum() == cells and len(per_subdomain) == K, per_subdomain
        cell_ids = vtk_to_numpy(grid.GetCellData().GetArray("GlobalCellIds")).astype(np.int64)
        assert np.array_equal(np.sort(cell_ids), np.arange(cells)), "GlobalCellIds are not 0..T-1 once each"
        subdomain_of_cell = vtk_to_numpy(grid.GetCellData().GetArray("SubdomainId"))
        assert np.array_equal(np.bincount(subdomain_of_cell, minlength=K), per_subdomain), \
            "SubdomainTetrahedra does not count the cells per SubdomainId"
        boundary = gathered(1)
        boundary_gids = vtk_to_numpy(boundary.GetPointData().GetArray("GlobalPointIds")).astype(np.int64)
        figures = check_volume_mesh(grid, boundary_gids[cells_of(boundary, 3)])
        assert figures["points"] == total_points, (figures["points"], total_points)
        print("client-server: checked", figures)
    finally:
        simple.Disconnect()


def client_main(argv):
    port, plugin, data, ranks, surface, K = argv
    run_client(int(port), plugin, os.path.join(data, surface), int(ranks), int(K))
    print("client-server: client passed")
    sys.stdout.flush()


def pvpython():
    for candidate in (os.environ.get("PTM_PVPYTHON", ""), sys.executable):
        if candidate and os.path.basename(candidate).startswith("pvpython"):
            return candidate
    return "pvpython"


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    plugin, data, ranks = os.path.abspath(argv[0]), os.path.abspath(argv[1]), int(argv[2])
    surface = argv[3] if len(argv) > 3 else "bracket.stl"
    K = int(argv[4]) if len(argv) > 4 else 4
    if not os.path.isfile(plugin):
        raise SystemExit("plugin not found: %s" % plugin)

    server = None
    client = None

    def cleanup_and_exit(code, why):
        if client is not None and client.poll() is None:
            client.kill()
        if server is not None:
            server.kill()
        print("client-server:", why)
        sys.stdout.flush()
        os._exit(code)

    # SIGTERM/SIGINT (CTest, Ctrl-C) and the watchdog take the server along
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(sig, lambda s, f: cleanup_and_exit(1, "FAILED: signal %d" % s))
    watchdog = threading.Timer(WATCHDOG_SECONDS,
                               lambda: cleanup_and_exit(1, "FAILED: no result after %d s" % WATCHDOG_SECONDS))
    watchdog.daemon = True
    watchdog.start()

    failures = []
    try:
        server = start_server(ranks)
        command = [pvpython(), "--no-mpi", os.path.abspath(__file__), "--client", str(server.port),
                   plugin, data, str(ranks), surface, str(K)]
        print("client-server: client", " ".join(command))
        sys.stdout.flush()
        client = subprocess.Popen(command, stdin=subprocess.DEVNULL, env=server_environment(),
                                  preexec_fn=_die_with_parent)
        try:
            code = client.wait(CLIENT_TIMEOUT_SECONDS)
            if code != 0:
                failures.append("the client failed with exit code %d" % code)
        except subprocess.TimeoutExpired:
            client.kill()
            client.wait()
            failures.append("the client did not finish in %d s" % CLIENT_TIMEOUT_SECONDS)
        # the client has gone: the server must notice and end by itself
        try:
            code = server.process.wait(SERVER_EXIT_SECONDS)
            if code != 0:
                failures.append("pvserver exited with code %d after the client disconnected" % code)
        except subprocess.TimeoutExpired:
            failures.append("pvserver still running %d s after the client disconnected" % SERVER_EXIT_SECONDS)
    except Exception as e:
        failures.append("%s: %s" % (type(e).__name__, e))
    finally:
        watchdog.cancel()
        if server is not None:
            server.kill()
            leftover = subprocess.run(["pgrep", "-g", str(server.process.pid)], capture_output=True, text=True).stdout.split()
            if leftover:
                failures.append("processes of the server's group survived the kill: %s" % leftover)
    for f in failures:
        print("client-server: FAILED:", f)
    print("client-server: %s" % ("FAILED" if failures else "passed"))
    sys.stdout.flush()
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--client"]:
        client_main(sys.argv[2:])
    else:
        main(sys.argv[1:])
