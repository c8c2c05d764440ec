"""The batch command cutting again where a stage after the cut failed.

    /usr/bin/python3 test_recut.py SUMMARY.json SURFACE.off

SUMMARY.json is the summary of `tetmesh.py Data/regression/freecad_tcmt1107_4.off
--subdomains 16 --strategy RecursiveBisection --size 0.1747` (the CTest fixture
tetmesh_recut_np2), whose .pvtu lies beside it. That cut leaves subdomain 4
folded onto itself (two interfaces overlap), so the first attempt fails in the
volume meshing. Checks: the run was made again (its `recuts` name the
failure and the change), it ended with a mesh, and the mesh passes the
corpus sweep's independent conformity check (Testing/Corpus/conformity.py:
pieces merged by global id, every interior face used once from each side, the
boundary closed, volume and area of the input). Without the recut
(`--recut-attempts 0`) the run fails.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Corpus"))

import conformity  # noqa: E402
import surface_tool  # noqa: E402


def main(summary_json, surface):
    with open(summary_json) as f:
        summary = json.load(f)
    failures = []
    recuts = summary.get("recuts") or []
    if not recuts:
        failures.append("the first cut meshed: this case no longer exercises the recut")
    for r in recuts:
        if "intersects itself" not in r["failure"] and "TetGen" not in r["failure"]:
            failures.append("an attempt failed for an unexpected reason: %s" % r["failure"])
    pvtu = os.path.splitext(summary_json)[0] + ".pvtu"
    check = conformity.check(pvtu, surface_tool.stats(surface))
    if not check["conforming"]:
        failures.append("the mesh does not conform: %s" % check["problems"])
    if check.get("volume_error", 1) > 1e-9:
        failures.append("volume error %.3g" % check.get("volume_error", 1))
    print("recut: %d failed attempt(s) (%s), then %d tetrahedra, conforming %s, volume error %.2g" % (
        len(recuts), "; ".join(r["change"] for r in recuts), summary["tetrahedra"], check["conforming"],
        check.get("volume_error", -1)))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
