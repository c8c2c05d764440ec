"""Runs the user example Scripts/examples/mesh_in_paraview.py (a tidied GUI
trace) with pvbatch on N ranks and checks its screenshot.

    pvpython --no-mpi test_example_screenshot.py RANKS OUT.png

The example is run as a user would on a machine without a display:
`mpiexec -n RANKS pvbatch Scripts/examples/mesh_in_paraview.py OUT.png` in a
virtual X server (OUT.png is removed first, so an old image cannot pass).
The X server is this script's own `Xvfb -displayfd`, which takes the first
display number it can really listen on; `xvfb-run -a` only looks for lock
files in /tmp and sometimes handed out a display that another X server
answered ("bad X server connection"). Xvfb, mpiexec and pvbatch run in one
process group that is killed at the end and on a timeout. The image must exist, be 1200 x 800, not be
blank (more than 10 % of the pixels differ from the white background), and
show the clipped mesh coloured by subdomain: each of the four subdomain
colours of the 'Brewer Qualitative Set2' preset (by hue; lighting changes
brightness, not hue) covers at least 1 % of the image, far more than its
swatch in the legend (0.2 %).
"""
import colorsys
import os
import signal
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "Scripts", "examples", "mesh_in_paraview.py")
SIZE = (1200, 800)
# the first four colours of ParaView's 'Brewer Qualitative Set2' preset
SUBDOMAIN_COLOURS = [(102, 194, 165), (252, 141, 98), (141, 160, 203), (231, 138, 195)]


def environment():
    """Without what an MPI singleton or an enclosing mpiexec put in the
    environment (a child mpiexec would take itself for an MPI process)."""
    launched = ("PMIX_", "ORTE_", "OMPI_COMM_WORLD_", "OMPI_UNIVERSE_", "OMPI_APP_CTX_", "OMPI_ARGV",
                "OMPI_COMMAND", "OMPI_MCA_ess", "OMPI_MCA_orte_", "OMPI_MCA_pmix", "OMPI_FIRST_RANKS",
                "OMPI_FILE_LOCATION", "OMPI_NUM_APP_CTX", "OMPI_MCA_initial_wdir")
    return {k: v for k, v in os.environ.items() if not k.startswith(launched)}


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    pixels = vtk_to_numpy(scalars).reshape(height, width, scalars.GetNumberOfComponents())
    return width, height, pixels[:, :, :3].astype(np.float64) / 255.0


def hue_degrees(rgb):
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    hi, lo = rgb.max(axis=-1), rgb.min(axis=-1)
    span = np.where(hi > lo, hi - lo, 1.0)
    h = np.where(hi == r, (g - b) / span % 6, np.where(hi == g, (b - r) / span + 2, (r - g) / span + 4))
    saturation = np.where(hi > 0, (hi - lo) / np.where(hi > 0, hi, 1.0), 0.0)
    return 60.0 * h, saturation


def check_image(path):
    assert os.path.isfile(path), "no screenshot %s" % path
    width, height, rgb = read_png(path)
    assert (width, height) == SIZE, "screenshot is %dx%d, expected %dx%d" % ((width, height) + SIZE)
    drawn = np.any(np.abs(rgb - 1.0) > 0.02, axis=-1).mean()
    print("example: %dx%d, %.1f %% of the pixels differ from the background" % (width, height, 100 * drawn))
    assert drawn > 0.10, "the screenshot is blank (%.2f %% drawn)" % (100 * drawn)
    hue, saturation = hue_degrees(rgb)
    for s, colour in enumerate(SUBDOMAIN_COLOURS):
        target = 360.0 * colorsys.rgb_to_hsv(*[c / 255.0 for c in colour])[0]
        distance = np.abs((hue - target + 180.0) % 360.0 - 180.0)
        share = ((distance < 10.0) & (saturation > 0.15)).mean()
        print("example: subdomain %d colour (hue %.0f) on %.2f %% of the image" % (s, target, 100 * share))
        assert share > 0.01, "subdomain %d's colour covers only %.2f %% of the image" % (s, 100 * share)


def start_xvfb():
    """Xvfb on the first free display; returns (process, ":N")."""
    read_end, write_end = os.pipe()
    # -noreset: by default Xvfb resets whenever its last client disconnects and
    # refuses connections meanwhile, so one rank closing its probe connection
    # made the other rank's XOpenDisplay fail ("bad X server connection")
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1280x1024x24",
                             "-noreset", "-nolisten", "tcp"], pass_fds=(write_end,), stdin=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    os.close(write_end)
    number = b""
    while not number.endswith(b"\n"):
        chunk = os.read(read_end, 16)  # Xvfb writes the number once it listens
        if not chunk:
            raise RuntimeError("Xvfb did not start (exit code %s)" % xvfb.wait())
        number += chunk
    os.close(read_end)
    return xvfb, ":" + number.decode().strip()


def kill_group(process):
    for sig in (signal.SIGTERM, signal.SIGKILL):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(5)
        except subprocess.TimeoutExpired:
            pass


def main(argv):
    if len(argv) != 2:
        raise SystemExit(__doc__)
    ranks, out = int(argv[0]), os.path.abspath(argv[1])
    os.makedirs(os.path.dirname(out), exist_ok=True)
    if os.path.exists(out):
        os.remove(out)
    xvfb, display = start_xvfb()
    try:
        command = [os.environ.get("PTM_MPIEXEC", "mpiexec"), "-n", str(ranks), "--oversubscribe",
                   os.environ.get("PTM_PVBATCH", "pvbatch"), os.path.abspath(EXAMPLE), out]
        print("example: DISPLAY=%s %s" % (display, " ".join(command)))
        sys.stdout.flush()
        env = environment()
        env["DISPLAY"] = display
        env.pop("XAUTHORITY", None)
        # the example finds the plugin through PTM_PLUGIN (set by CTest) or the build tree
        run = subprocess.Popen(command, stdin=subprocess.DEVNULL, env=env, start_new_session=True)
        try:
            code = run.wait(240)
        except subprocess.TimeoutExpired:
            code = None
        kill_group(run)
        assert code is not None, "the example did not finish in 240 s"
        assert code == 0, "the example failed with exit code %d" % code
    finally:
        kill_group(xvfb)
    check_image(out)
    print("example: passed")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--check"]:
        check_image(sys.argv[2])
    else:
        main(sys.argv[1:])
