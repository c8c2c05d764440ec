#!/usr/bin/env python3
"""Writes the seed corpus of DecompositionFuzzer into corpus/decomposition/.

The fuzzer reads its bytes with LLVM's FuzzedDataProvider, which takes the
integers from the END of the input, one byte for each small range
(value = min + byte % (max - min + 1)). So a seed is the list of choices in
the order the fuzzer makes them, written back to front. The choices, in
order (DecompositionFuzzer.cpp, FuzzedSurface.cpp):
  K-2, ParallelPlanes?, direction, criterion, tolerance, snap, check off?,
  shape (ClosedShapes.h order; 9 = free form), then edits: kind + arguments.
Each seed is one unmutated shape with one set of options, or a shape with a
few edits that keep it valid; the fuzzer grows the rest.
Usage: python3 make_decomposition_seeds.py   (rewrites the seed-* files)
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "decomposition")

SHAPES = ["tetrahedron", "octahedron", "cube", "lattice-cube", "icosahedron", "torus",
          "two-bodies", "cube-with-cavity", "nearly-touching-cubes"]
DIRECTIONS = ["longest", "inertia", "x", "y", "z"]
# edit kinds, as in FuzzedSurface.cpp
SPLIT_EDGE, SCALE, ROTATE, MOVE_FAR = 11, 13, 16, 17

def write(name, choices):
    data = bytes(reversed(choices))
    with open(os.path.join(OUT, "seed-" + name), "wb") as f:
        f.write(data)

def main():
    os.makedirs(OUT, exist_ok=True)
    for old in os.listdir(OUT):
        if old.startswith("seed-"):
            os.remove(os.path.join(OUT, old))
    for shape, shape_name in enumerate(SHAPES):
        for k, parallel, direction in ((2, False, 0), (3, True, 1), (4, False, 2 + shape % 3)):
            options = [k - 2, int(parallel), direction, 0, 0, 0, 0]
            strategy = "parallel" if parallel else "bisection"
            write("%s-k%d-%s-%s" % (shape_name, k, strategy, DIRECTIONS[direction]),
                  options + [shape])
    # the other balance criteria, tolerances and snap fractions on the lattice cube
    write("lattice-cube-k3-facets", [1, 0, 0, 3, 1, 1, 0, 3])
    write("lattice-cube-k4-nodes", [2, 1, 0, 4, 2, 3, 0, 3])
    write("icosahedron-k4-tight-no-snap", [2, 0, 1, 0, 3, 1, 0, 4])
    # edits that keep the shape valid: split edges, rotate, scale, move away
    write("cube-split-edges-k3", [1, 0, 0, 0, 0, 0, 0, 2, SPLIT_EDGE, 0, 0, 8, SPLIT_EDGE, 5, 1, 4])
    write("octahedron-rotated-k4-inertia", [2, 0, 1, 0, 0, 0, 0, 1, ROTATE, 2, 5, ROTATE, 0, 9])
    write("torus-scaled-down-k2", [0, 0, 0, 0, 0, 0, 0, 5, SCALE, 0])   # 2^-20
    write("cube-far-away-k2", [0, 0, 0, 0, 0, 0, 0, 2, MOVE_FAR, 0, 6])  # 1e9 along x
    # free form: the 4 corners of a tetrahedron and its 4 triangles
    points = [4, 4, 4, 5, 4, 4, 4, 5, 4, 4, 4, 5]  # (0,0,0) (1,0,0) (0,1,0) (0,0,1)
    write("free-form-tetrahedron-k2", [0, 0, 0, 0, 0, 0, 0, 9, 0] + points +
          [0, 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3])

if __name__ == "__main__":
    main()
