"""Corpus helpers in numpy only (run with /usr/bin/python3).

    surface_tool.py normalize IN OUT.off   # STL (ASCII or binary) or OFF -> OFF of triangles
    surface_tool.py stats FILE.off         # one JSON line: size, volume, triangle shape
    surface_tool.py invert IN.off OUT.off  # the same surface inside out (every triangle reversed)

normalize merges points with bit-identical coordinates (an STL repeats every
corner), drops triangles that use one point twice (an exactly collapsed
triangle; counted in the output), fan-triangulates OFF polygons, puts points
and triangles in a canonical order (sorted) and writes coordinates with 17
significant digits, so the same surface always gives the same bytes, whatever
order the tessellator wrote it in.
"""
import json
import os
import struct
import sys

import numpy as np


def read_stl(path):
    data = open(path, "rb").read()
    if len(data) >= 84:
        n = struct.unpack("<I", data[80:84])[0]
        if 84 + 50 * n == len(data):
            rec = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                                count=n, offset=84)
            return rec["v"].astype(np.float64).reshape(-1, 3)
    corners = []
    for line in data.decode("ascii", "replace").splitlines():
        words = line.split()
        if len(words) == 4 and words[0] == "vertex":
            corners.append([float(w) for w in words[1:]])
    return np.array(corners, dtype=np.float64).reshape(-1, 3)


def read_off(path):
    """OFF, COFF, NOFF...: the first three numbers of a vertex line are its
    coordinates, a face line is n and n ids (colours after them are ignored)."""
    lines = []
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            lines.append(line)
    header = lines[0]
    if not header[0].endswith("OFF"):
        raise SystemExit("%s: not an OFF file" % path)
    counts, rest = (header[1:], lines[1:]) if len(header) > 1 else (lines[1], lines[2:])
    nv, nf = int(counts[0]), int(counts[1])
    points = np.array([[float(w) for w in l[:3]] for l in rest[:nv]], dtype=np.float64).reshape(-1, 3)
    tris = []
    for l in rest[nv:nv + nf]:
        n = int(l[0])
        ids = [int(w) for w in l[1:1 + n]]
        for k in range(1, n - 1):
            tris.append((ids[0], ids[k], ids[k + 1]))
    return points, np.array(tris, dtype=np.int64).reshape(-1, 3)


def merge(corners_points, tris):
    """Merge bit-identical points, keeping the order of first appearance."""
    keys = np.ascontiguousarray(corners_points).view(np.dtype((np.void, 24))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    order = np.argsort(first, kind="stable")       # unique ids sorted by first appearance
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    points = corners_points[first[order]]
    return points, rank[inverse.ravel()][tris]


def normalize(src, dst):
    lower = src.lower()
    if lower.endswith(".stl"):
        corners = read_stl(src)
        tris = np.arange(len(corners)).reshape(-1, 3)
        points, tris = merge(corners, tris)
    elif lower.endswith(".off"):
        points, tris = read_off(src)
        points, tris = merge(points, tris)
    else:
        raise SystemExit("%s: only STL and OFF are read" % src)
    collapsed = (tris[:, 0] == tris[:, 1]) | (tris[:, 1] == tris[:, 2]) | (tris[:, 0] == tris[:, 2])
    tris = tris[~collapsed]
    used = np.unique(tris)
    remap = -np.ones(len(points), dtype=np.int64)
    remap[used] = np.arange(len(used))
    points, tris = points[used], remap[tris]
    # canonical order: points sorted by coordinates, each triangle rotated to
    # start at its smallest id (orientation kept), triangles sorted; OpenSCAD
    # writes the same triangles in a different order from run to run
    order = np.lexsort((points[:, 2], points[:, 1], points[:, 0]))
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    points, tris = points[order], rank[tris]
    k = np.argmin(tris, axis=1)
    tris = tris[np.arange(len(tris))[:, None], (k[:, None] + np.arange(3)) % 3]
    tris = tris[np.lexsort((tris[:, 2], tris[:, 1], tris[:, 0]))]
    if len(tris) < 4:
        raise SystemExit("%s: no closed surface (%d triangles)" % (src, len(tris)))
    write_off(dst, points, tris)
    print(json.dumps({"points": len(points), "triangles": len(tris), "collapsed_removed": int(collapsed.sum())}))


def write_off(dst, points, tris):
    """Triangles as OFF, coordinates with 17 significant digits (exact)."""
    with open(dst, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(tris)))
        f.write("".join("%.17g %.17g %.17g\n" % tuple(p) for p in points))
        f.write("".join("3 %d %d %d\n" % tuple(t) for t in tris))


def invert(src, dst):
    """The surface inside out, as STL exports often are: the same points,
    every triangle reversed (the mesher must orient it back itself)."""
    points, tris = read_off(src)
    os.makedirs(os.path.dirname(os.path.abspath(dst)), exist_ok=True)
    write_off(dst, points, tris[:, ::-1])


def triangle_angles(p):
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    out = []
    for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
        e1, e2 = v - u, w - u
        n1, n2 = np.linalg.norm(e1, axis=1), np.linalg.norm(e2, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = np.einsum("ij,ij->i", e1, e2) / (n1 * n2)
        out.append(np.degrees(np.arccos(np.clip(np.nan_to_num(cos, nan=1.0), -1, 1))))
    return np.array(out).T


def stats(path):
    points, tris = read_off(path)
    p = points[tris]
    o = p - p[0, 0]  # about a corner: far from (0, 0, 0) the terms would swamp the volume
    volume = np.einsum("ij,ij->i", o[:, 0], np.cross(o[:, 1], o[:, 2])).sum() / 6.0
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    angles = triangle_angles(p).min(axis=1)
    edges = np.linalg.norm(p - p[:, [1, 2, 0]], axis=2)
    lo, hi = points.min(axis=0), points.max(axis=0)
    return {"points": len(points), "triangles": len(tris), "volume": float(volume), "area": float(area.sum()),
            "bbox_diagonal": float(np.linalg.norm(hi - lo)), "mean_edge": float(edges.mean()),
            "min_triangle_angle": float(angles.min()), "share_triangles_below_10": float((angles < 10).mean()),
            "max_edge_ratio": float((edges.max(axis=1) / np.maximum(edges.min(axis=1), 1e-300)).max())}


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "normalize":
        normalize(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "invert":
        invert(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == "stats":
        print(json.dumps(stats(sys.argv[2])))
    else:
        raise SystemExit(__doc__)
