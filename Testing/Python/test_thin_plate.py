"""A part thinner than the mesh size, through the batch command.

    /usr/bin/python3 test_thin_plate.py SUMMARY.json SURFACE.off [INSIDE_OUT_SUMMARY.json]

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

INSIDE_OUT_SUMMARY.json is the same run on the bed inside out (surface_tool.py
invert), as STL exports often are: its mesh must be the same, tetrahedron for
tetrahedron. Until session 24 the cutter cast the thickness rays on the
surface as read, so inside out they went outward, measured the gaps between
the ribs instead of the walls, and the mesh had 2.6 x the tetrahedra (792,363
against 305,446 at the size 14.47).
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


def inside_out_failures(summary, inside_out_json):
    """The inside-out run's mesh differs from the outward run's (counts)."""
    with open(inside_out_json) as f:
        inside_out = json.load(f)
    return ["inside out, the bed has %d %s, outward %d" % (inside_out[key], key, summary[key])
            for key in ("tetrahedra", "points") if inside_out[key] != summary[key]]


def main(summary_json, surface, inside_out_json=None):
    with open(summary_json) as f:
        summary = json.load(f)
    failures = inside_out_failures(summary, inside_out_json) if inside_out_json else []
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
    sys.exit(main(*sys.argv[1:4]))
