"""The batch command's other cuts after a failed stage (tetmesh.recut_changes).

    /usr/bin/python3 test_recut_changes.py

The order and content matter: each attempt costs a whole run (Cura's
BIQU_SSS bed at K = 64 with parallel planes needed the fourth, 7 min in
all), and a change missing from an attempt makes it repeat a cut that
already failed. Checks: no attempt repeats the cut as asked or another
attempt; the thickness size is switched off only where the cutter measured
thin walls, after the cut's own settings, and with the flat crossings kept
where the cut took some out; tilt is only undone for recursive bisection;
parallel planes give way to recursive bisection only last.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Scripts"))

import tetmesh  # noqa: E402


def settings(attempts):
    return [change for change, _ in attempts]


def main():
    failures = []

    def expect(what, got, wanted):
        if got != wanted:
            failures.append("%s: got %s, wanted %s" % (what, got, wanted))

    expect("planes, crossings removed, thin walls",
           settings(tetmesh.recut_changes("ParallelPlanes", 5.0, 10.0, 12.0, True)),
           [{"RemoveFlatCrossings": 0}, {"PlaneTiltAngle": 0, "PlaneAlignmentAngle": 0},
            {"SizeByThickness": 0, "RemoveFlatCrossings": 0}, {"Strategy": "RecursiveBisection"}])
    expect("planes, nothing else to change",
           settings(tetmesh.recut_changes("ParallelPlanes", 0.0, 0.0, 0.0, False)), [{"Strategy": "RecursiveBisection"}])
    expect("bisection, nothing removed, thin walls",
           settings(tetmesh.recut_changes("RecursiveBisection", 5.0, 10.0, 0.0, True)),
           [{"PlaneTiltAngle": 0}, {"PlaneTiltAngle": 0, "PlaneAlignmentAngle": 0}, {"SizeByThickness": 0}])
    expect("bisection, no thin walls",
           settings(tetmesh.recut_changes("RecursiveBisection", 5.0, 10.0, None, False)),
           [{"PlaneTiltAngle": 0}, {"PlaneTiltAngle": 0, "PlaneAlignmentAngle": 0}])
    expect("nothing left to change", tetmesh.recut_changes("RecursiveBisection", 0.0, 0.0, 0.0, False), [])
    for attempts in (tetmesh.recut_changes("RecursiveBisection", 5.0, 10.0, 3.0, True),
                     tetmesh.recut_changes("ParallelPlanes", 0.0, 10.0, 3.0, True)):
        changes = settings(attempts)
        if any(not change for change in changes) or len(set(map(repr, changes))) != len(changes):
            failures.append("an attempt repeats a cut: %s" % changes)
        if any(not description for _, description in attempts):
            failures.append("an attempt has no description: %s" % attempts)
    print("recut changes: %d failures" % len(failures))
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
