"""A cut that used to fold a subdomain onto itself, through the batch command.

    /usr/bin/python3 test_folded_subdomain.py SUMMARY.json SURFACE.off [MINIMUM_DIHEDRAL]

SUMMARY.json is the summary of `tetmesh.py Data/regression/freecad_tcmt1107_4.off
--subdomains 16 --strategy RecursiveBisection --size 0.1747 --recut-attempts 0`
(the CTest fixture tetmesh_folded_subdomain_np2), whose .pvtu lies beside it.
Until session 20 plane 10 of that cut split an edge where planes 0 and 5
meet, bent off plane 5, and subdomain 4's plane-5 interface then crossed its
plane-6 one, which the cutter's check did not look at: TetGen refused
subdomain 4 (and the run needed a recut). Checks: the run meshed without a
recut, and the mesh passes the corpus sweep's independent conformity check
(Testing/Corpus/conformity.py: pieces merged by global id, every interior
face used once from each side, the boundary closed, volume and area of the
input). With MINIMUM_DIHEDRAL (degrees), also that the mesh's smallest
dihedral angle is at least that (the bent-region test: KiCad's DPDT switch
at K = 2 by planes had 0.07 degrees while its bent interface kept its long
contour edges whole, 1.07 split).
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Corpus"))

import conformity  # noqa: E402
import surface_tool  # noqa: E402


def main(summary_json, surface, minimum_dihedral=None):
    with open(summary_json) as f:
        summary = json.load(f)
    failures = []
    recuts = summary.get("recuts") or []
    if recuts:
        failures.append("the run was cut again: %s" % recuts)
    check, mesh_failures = conformity.check_summary_mesh(summary_json, surface_tool.stats(surface))
    failures += mesh_failures
    smallest = summary["quality"]["minimum_dihedral_angle_degrees"]
    if minimum_dihedral is not None and smallest < float(minimum_dihedral):
        failures.append("minimum dihedral angle %.3g degrees, under %s" % (smallest, minimum_dihedral))
    print("%s: %d recuts, %d tetrahedra, conforming %s, volume error %.2g, minimum dihedral %.3g degrees" % (
        os.path.basename(surface), len(recuts), summary["tetrahedra"], check["conforming"],
        check.get("volume_error", -1), smallest))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
