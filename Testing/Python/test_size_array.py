"""A size field given as a point array on the input surface (the cutter's
SizeArray without a SizeSource), checked on the boundary, where the samples
are: the ball meshed on 2 ranks from make_size_sources.py's SURFACE.vtp with
`--size-array h --size 0.3`.

    /usr/bin/python3 test_size_array.py OUT.pvtu Data/ball.off

Checks (meshio and numpy only, the field recomputed here):
* the mesh is valid and its volume is the input surface's to 1e-9;
* the boundary follows the samples: over the boundary edges in z < 0 the
  median ratio of edge to field lies in [0.5, 1.2] (measured 0.646, as with
  the same field given as an expression: the boundary refinement halves
  input edges longer than the field), and the median boundary edge in
  z < -0.5 is at most half the median boundary edge in 0 < z < 0.5.
Inside, a surface array is interpolated from the nearest surface samples,
so the interior is not checked against the expression; the background-grid
run (size_array_grid_np2) checks the interior with test_size_field.py.
"""
import sys

import numpy as np

from test_size_field import check_valid, field, read_pieces


def boundary_edges(points, tets, ids):
    """The edges of the faces that belong to one tetrahedron (by global ids)."""
    order = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
    faces = np.vstack([tets[:, o] for o in order])
    _, inverse, counts = np.unique(np.sort(ids[faces], axis=1), axis=0,
                                   return_inverse=True, return_counts=True)
    boundary = faces[counts[inverse.ravel()] == 1]
    edges = np.vstack([boundary[:, [0, 1]], boundary[:, [1, 2]], boundary[:, [0, 2]]])
    _, first = np.unique(np.sort(ids[edges], axis=1), axis=0, return_index=True)
    return points[edges[first, 0]], points[edges[first, 1]]


def main(argv):
    if len(argv) != 2:
        raise SystemExit(__doc__)
    points, tets, ids = read_pieces(argv[0])
    check_valid(points, tets, argv[1])
    a, b = boundary_edges(points, tets, ids)
    middle = 0.5 * (a + b)
    length = np.linalg.norm(a - b, axis=1)
    ratio = length / field(middle)
    south = middle[:, 2] < 0
    median = np.median(ratio[south])
    polar = np.median(length[middle[:, 2] < -0.5])
    band = np.median(length[(middle[:, 2] > 0) & (middle[:, 2] < 0.5)])
    print("size array on the surface: %d boundary edges in z < 0, median edge / field %.3f, "
          "%.1f%% within 1.5 x; median boundary edge %.4f in z < -0.5, %.4f in 0 < z < 0.5"
          % (south.sum(), median, 100 * np.mean((ratio[south] > 1 / 1.5) & (ratio[south] < 1.5)),
             polar, band))
    assert 0.5 <= median <= 1.2, "median boundary edge / field %.3f" % median
    assert polar <= 0.5 * band, "boundary edges near the fine pole %.4f, middle %.4f" % (polar, band)
    print("ok")


if __name__ == "__main__":
    main(sys.argv[1:])
