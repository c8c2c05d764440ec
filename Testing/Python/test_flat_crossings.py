"""The cutter's flat-crossing removal on and off, through the batch command.

    /usr/bin/python3 test_flat_crossings.py DEFAULT.json KEPT.json INPUT_SURFACE.stl

DEFAULT.json is the summary of `tetmesh.py bracket.stl` (the CTest fixture
tetmesh_bracket_np2), KEPT.json that of the same run with
--keep-flat-crossings, whose .pvtu lies beside it. Checks: the default cut
took contour points out of the bracket's planar faces and the kept one none,
neither run had to be made again, and the kept run's mesh passes every check
of test_meshio_pvtu.py (conforming pieces, global ids, volume and area of the
input).
"""
import json
import os
import subprocess
import sys


def main(default_json, kept_json, surface):
    with open(default_json) as f:
        default = json.load(f)
    with open(kept_json) as f:
        kept = json.load(f)
    failures = []
    if not default.get("flat_crossings_removed", 0) > 0:
        failures.append("the default cut took no crossing out of the bracket's planar faces")
    if kept.get("flat_crossings_removed") != 0:
        failures.append("--keep-flat-crossings still took %s out" % kept.get("flat_crossings_removed"))
    for name, summary in (("default", default), ("kept", kept)):
        if summary.get("kept_flat_crossings_after_failure") is not None:
            failures.append("the %s run was made again: %s" % (name, summary["kept_flat_crossings_after_failure"]))
    pvtu = os.path.splitext(kept_json)[0] + ".pvtu"
    checks = os.path.join(os.path.dirname(os.path.abspath(__file__)), "test_meshio_pvtu.py")
    done = subprocess.run([sys.executable, checks, pvtu, kept_json, surface])
    if done.returncode != 0:
        failures.append("the kept run's mesh failed test_meshio_pvtu.py")
    print("flat crossings: %d taken out by default, %d with --keep-flat-crossings; tetrahedra %d and %d" % (
        default.get("flat_crossings_removed", -1), kept.get("flat_crossings_removed", -1),
        default["tetrahedra"], kept["tetrahedra"]))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
