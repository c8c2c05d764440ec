"""A part thinner than the mesh size, through the batch command.

    /usr/bin/python3 test_thin_plate.py SUMMARY.json SURFACE.off

SUMMARY.json is the summary of `tetmesh.py Data/regression/cura_biqu_sss.off
--subdomains 2 --size 21.81` (the CTest fixture tetmesh_thin_plate_np2), whose
.pvtu lies beside it. Cura's printer bed has a base 1.395 thick, and at the
size 21.81 every stage spaced the boundary by the size alone: TetGen, which
keeps the surface, could only fill the base with flat tetrahedra (17.6 % under
10 degrees at K = 2, where serial TetGen -pq2.0 at the same bound has 0.87 %).
The cutter now measures the thickness (LocalThickness.h) and every stage caps
the boundary spacing by it. Checks: the mesh passes the corpus sweep's
independent conformity check, keeps the input's volume to 1e-9, and has under
4 % of its tetrahedra under 10 degrees (2.5 % measured in session 21).
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Corpus"))
sys.path.insert(0, os.path.join(HERE, "..", "Benchmarks"))

import conformity  # noqa: E402
import mesh_quality  # noqa: E402
import surface_tool  # noqa: E402

LARGEST_SHARE_UNDER_10_DEGREES = 0.04


def main(summary_json, surface):
    with open(summary_json) as f:
        summary = json.load(f)
    failures = []
    check, mesh_failures = conformity.check_summary_mesh(summary_json, surface_tool.stats(surface))
    failures += mesh_failures
    quality = mesh_quality.mesh_quality(os.path.splitext(summary_json)[0] + ".pvtu")
    share = quality["share_below_10_degrees"]
    if share > LARGEST_SHARE_UNDER_10_DEGREES:
        failures.append("%.2f %% of the tetrahedra are under 10 degrees (at most %.0f %% expected)" % (
            100 * share, 100 * LARGEST_SHARE_UNDER_10_DEGREES))
    print("thin plate: %d tetrahedra, conforming %s, volume error %.2g, %.2f %% under 10 degrees, "
          "minimum dihedral %.3f degrees" % (summary["tetrahedra"], check["conforming"],
                                             check.get("volume_error", -1), 100 * share,
                                             quality["minimum_dihedral_angle_degrees"]))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
