#!/usr/bin/env python3
"""Compare two corpus sweeps (results.json of sweep.py, or .json.gz) per
surface and strategy: the worst ratio over K of the share of tetrahedra under
10 degrees to serial TetGen -pq's (goal <= 1.5), and the worst ratio of the
minimum dihedral angle (goal >= 0.5), before -> now, and failed runs. The
sweep's own table takes the worst over both strategies; this one shows what a
change did to each.

    /usr/bin/python3 Testing/Corpus/compare_sweeps.py OLD/results.json NEW/results.json
"""
import gzip
import json
import math
import sys


def load(path):
    with (gzip.open(path, "rt") if path.endswith(".gz") else open(path)) as f:
        return json.load(f)


def ratios(sweep):
    """(surface, strategy) -> list of (share ratio, dihedral ratio), None for a failed run."""
    serial = sweep["serial"]
    out = {}
    for run in sweep["runs"]:
        key = (run["surface"], run["strategy"])
        quality = run.get("quality") or {}
        ref = serial.get(run["surface"], {})
        if not run.get("ok") or not quality or not ref.get("ok"):
            out.setdefault(key, []).append(None)
            continue
        share = quality["share_below_10_degrees"] / max(ref["share_below_10_degrees"], 1e-12)
        dihedral = quality["minimum_dihedral_angle_degrees"] / max(ref["minimum_dihedral_angle_degrees"], 1e-12)
        out.setdefault(key, []).append((share, dihedral))
    return out


def worst(runs):
    ok = [r for r in runs if r]
    return (max((r[0] for r in ok), default=math.nan), min((r[1] for r in ok), default=math.nan),
            len(runs) - len(ok))


def main():
    before, now = ratios(load(sys.argv[1])), ratios(load(sys.argv[2]))
    print("| surface | strategy | worst share ratio before -> now | worst min-dihedral ratio before -> now | failed runs |")
    print("| --- | --- | --- | --- | --- |")
    totals = {}
    for key in sorted(set(before) | set(now)):
        s0, d0, f0 = worst(before.get(key, []))
        s1, d1, f1 = worst(now.get(key, []))
        strategy = "RB" if key[1] == "RecursiveBisection" else "PP"
        print("| %s | %s | %.2f -> %.2f | %.2f -> %.2f | %d -> %d |" % (key[0], strategy, s0, s1, d0, d1, f0, f1))
        t = totals.setdefault(strategy, {"surfaces": 0, "share lower": 0, "dihedral higher": 0,
                                         "share goal before": 0, "share goal now": 0,
                                         "dihedral goal before": 0, "dihedral goal now": 0})
        t["surfaces"] += 1
        t["share lower"] += s1 < s0
        t["dihedral higher"] += d1 > d0
        t["share goal before"] += s0 <= 1.5
        t["share goal now"] += s1 <= 1.5
        t["dihedral goal before"] += d0 >= 0.5
        t["dihedral goal now"] += d1 >= 0.5
    print()
    for strategy, t in sorted(totals.items()):
        print("%s: %s" % (strategy, ", ".join("%s %d" % kv for kv in t.items())))


if __name__ == "__main__":
    main()
