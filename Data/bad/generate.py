"""Writes the malformed surfaces of Data/bad/ (one per class of bad input the
mesher must name or repair). Run with Debian's python3 (numpy):

    /usr/bin/python3 Data/bad/generate.py

The files are committed; this script documents how each was made.
"""
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

# unit cube, outward, 12 triangles
CUBE_POINTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                        [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
CUBE_TRIANGLES = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                           [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])


def box(lo, hi):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return lo + CUBE_POINTS * (hi - lo), CUBE_TRIANGLES.copy()


def icosphere(level):
    t = (1 + 5 ** 0.5) / 2
    p = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
         [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    points = [np.array(q, float) / np.linalg.norm(q) for q in p]
    for _ in range(level):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = points[a] + points[b]
                points.append(m / np.linalg.norm(m))
                middle[key] = len(points) - 1
            return middle[key]

        f = [g for a, b, c in f for g in ([a, mid(a, b), mid(c, a)], [b, mid(b, c), mid(a, b)],
                                          [c, mid(c, a), mid(b, c)], [mid(a, b), mid(b, c), mid(c, a)])]
    return np.array(points), np.array(f)


def join(*parts):
    points, triangles, offset = [], [], 0
    for p, t in parts:
        points.append(p)
        triangles.append(t + offset)
        offset += len(p)
    return np.vstack(points), np.vstack(triangles)


def write_stl(name, points, triangles, coordinate_text=None):
    with open(os.path.join(HERE, name), "w") as out:
        out.write("solid %s\n" % name)
        for k, tri in enumerate(triangles):
            out.write(" facet normal 0 0 0\n  outer loop\n")
            for v in tri:
                if coordinate_text and (k, v) in coordinate_text:
                    out.write("   vertex %s\n" % coordinate_text[(k, v)])
                else:
                    out.write("   vertex %.17g %.17g %.17g\n" % tuple(points[v]))
            out.write("  endloop\n endfacet\n")
        out.write("endsolid %s\n" % name)


def write_off(name, points, triangles):
    with open(os.path.join(HERE, name), "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            out.write("%.17g %.17g %.17g\n" % tuple(p))
        for t in triangles:
            out.write("3 %d %d %d\n" % tuple(t))


def main():
    # refused
    p, t = box([0, 0, 0], [1, 1, 1])
    write_stl("open_box.stl", p, t[:-1])
    write_stl("cubes_sharing_edge.stl", *join(box([0, 0, 0], [1, 1, 1]), box([1, 1, 0], [2, 2, 1])))
    write_stl("cubes_sharing_vertex.stl", *join(box([0, 0, 0], [1, 1, 1]), box([1, 1, 1], [2, 2, 2])))
    write_stl("overlapping_boxes.stl", *join(box([0, 0, 0], [1, 1, 1]), box([0.5, 0.3, 0.2], [1.5, 0.8, 0.7])))
    # a NaN where a coordinate should be
    p, t = box([0, 0, 0], [1, 1, 1])
    write_stl("nan_coordinate.stl", p, t, {(3, t[3][1]): "nan 1 0"})
    open(os.path.join(HERE, "empty.stl"), "w").close()
    # no reader takes an empty PLY (assimp's test models ship one,
    # models/invalid/empty.ply): tetmesh.py must say so, not show a traceback
    open(os.path.join(HERE, "empty.ply"), "w").close()
    # a tetrahedron whose edge (0,1) carries a point on one side only, closed
    # by a zero-area triangle: removing that triangle would open the surface
    write_off("zero_area_sliver.off",
              np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.5, 0, 0]], float),
              np.array([[0, 2, 1], [0, 4, 3], [4, 1, 3], [1, 2, 3], [0, 3, 2], [0, 1, 4]]))

    # repaired with a warning
    sphere_points, sphere_triangles = icosphere(2)
    write_stl("inside_out_sphere.stl", sphere_points, sphere_triangles[:, ::-1])
    flipped = sphere_triangles.copy()
    flipped[::7] = flipped[::7, ::-1]
    write_off("flipped_triangles.off", sphere_points, flipped)
    # a cube with a duplicated triangle and a zero-area triangle (with its
    # mirror) lying on one of its edges: all three can go, the cube stays closed
    p, t = box([0, 0, 0], [1, 1, 1])
    p = np.vstack([p, 0.5 * (p[0] + p[2])])
    extra = np.array([t[5], [0, 2, 8], [2, 0, 8]])
    write_off("duplicate_and_zero_area.off", p, np.vstack([t, extra]))

    # for the fault test: a bar with a small box crossing its far end. With the
    # self-intersection check off, cutting succeeds and only the subdomain at
    # that end fails, on one rank.
    write_stl("bar_with_crossing_box.stl", *join(box([0, 0, 0], [10, 1, 1]), box([8.5, 0.5, 0.5], [9.5, 1.5, 1.5])))


if __name__ == "__main__":
    main()
