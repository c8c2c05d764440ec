#!/usr/bin/env bash
# Regenerates the bundled surfaces from Data/geo/*.geo (gmsh 4.8, Debian
# bookworm's; OpenCASCADE geometry), byte for byte:
#   NAME.stl  binary STL straight from gmsh (every .geo)
#   NAME.off  the same triangles with coincident points merged (meshio),
#             for ball, bracket (the default demo part) and two_bodies
#   cube.stl  the 12 triangles of the hand-written cube.off (6 quads)
# and checks that every surface is closed, edge-manifold and consistently
# oriented. Usage: bash Data/generate.sh
set -euo pipefail
cd "$(dirname "$0")"

for geo in geo/*.geo; do
  name=$(basename "$geo" .geo)
  gmsh -2 "$geo" -format stl -bin -o "$name.stl" > /dev/null
done

/usr/bin/python3 - <<'PY'
import collections
import meshio
import numpy as np

for name in ("ball", "bracket", "two_bodies"):
    m = meshio.read(name + ".stl")
    points, inverse = np.unique(m.points, axis=0, return_inverse=True)
    meshio.write(name + ".off", meshio.Mesh(points, [("triangle", inverse[m.cells_dict["triangle"]])]))

# cube.stl from cube.off: its quads are convex, so a fan splits them
lines = [l.split("#")[0].split() for l in open("cube.off")]
words = [w for w in lines if w]
nv, nf = int(words[1][0]), int(words[1][1])
corners = np.array([[float(x) for x in w[:3]] for w in words[2:2 + nv]])
with open("cube.stl", "w") as out:
    out.write("solid cube\n")
    for w in words[2 + nv:2 + nv + nf]:
        face = [int(i) for i in w[1:1 + int(w[0])]]
        for k in range(1, len(face) - 1):
            a, b, c = corners[[face[0], face[k], face[k + 1]]]
            n = np.cross(b - a, c - a)
            n /= np.linalg.norm(n)
            out.write("  facet normal %g %g %g\n    outer loop\n" % tuple(n))
            for p in (a, b, c):
                out.write("      vertex %g %g %g\n" % tuple(p))
            out.write("    endloop\n  endfacet\n")
    out.write("endsolid cube\n")

# every bundled surface: each directed edge once, its reverse once
import glob
for path in sorted(glob.glob("*.stl")):
    m = meshio.read(path)
    points, inverse = np.unique(m.points, axis=0, return_inverse=True)
    triangles = inverse[m.cells_dict["triangle"]]
    directed = collections.Counter()
    for t in triangles:
        for k in range(3):
            directed[(t[k], t[(k + 1) % 3])] += 1
    closed = all(c == 1 and directed.get((b, a)) == 1 for (a, b), c in directed.items())
    volume = sum(np.dot(points[a], np.cross(points[b], points[c])) for a, b, c in triangles) / 6
    print("%-20s %6d points %6d triangles  volume %8.4f  %s" % (
        path, len(points), len(triangles), volume,
        "closed, manifold, outward" if closed and volume > 0 else "NOT CLOSED/ORIENTED"))
    if not (closed and volume > 0):
        raise SystemExit(1)
PY
