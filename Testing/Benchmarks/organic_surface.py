"""A scanned-like organic surface: a sphere with a smooth radial displacement
of several frequencies (like a rock, a bone head or a scanned casting), closed
and free of self-intersections by construction.

Each point u of a triangulated unit sphere moves to r(u) u with

    r(u) = 1 + sum_k a_k sin(pi f_k (u . d_k) + phase_k)

plane waves of frequency f_k along fixed random directions d_k, amplitudes
falling with frequency (a rough, natural-looking spectrum). r stays positive,
so the surface is a radial graph over the sphere; as long as every triangle
still faces away from the origin (checked), the triangulation stays embedded:
no two triangles can cross because their central projections onto the sphere
do not overlap.

    /usr/bin/python3 organic_surface.py SPHERE.stl OUT.stl
"""
import sys

import numpy as np

# Fixed, so every run meshes the same surface.
SEED = 20260101
FREQUENCIES = (1, 2, 3, 5, 8, 13)
WAVES_PER_FREQUENCY = 3
LARGEST_AMPLITUDE = 0.12


def _waves():
    rng = np.random.default_rng(SEED)
    waves = []
    for f in FREQUENCIES:
        for _ in range(WAVES_PER_FREQUENCY):
            direction = rng.normal(size=3)
            direction /= np.linalg.norm(direction)
            amplitude = LARGEST_AMPLITUDE * rng.uniform(0.5, 1.0) / f ** 1.3
            waves.append((f, direction, rng.uniform(0, 2 * np.pi), amplitude))
    return waves


def radius(unit):
    r = np.ones(len(unit))
    for f, direction, phase, amplitude in _waves():
        r += amplitude * np.sin(np.pi * f * unit @ direction + phase)
    return r


def displace(points, triangles):
    """Points of the unit sphere triangulation moved to the organic surface;
    raises if a triangle would fold (face the origin)."""
    unit = points / np.linalg.norm(points, axis=1)[:, None]
    moved = unit * radius(unit)[:, None]
    a, b, c = (moved[triangles[:, k]] for k in range(3))
    orientation = np.einsum("ij,ij->i", a, np.cross(b, c))
    if not (np.all(orientation > 0) or np.all(orientation < 0)):
        raise SystemExit("organic_surface: the displacement folds %d triangles; use a finer sphere"
                         % min(np.count_nonzero(orientation > 0), np.count_nonzero(orientation < 0)))
    if np.all(orientation < 0):
        triangles = triangles[:, ::-1]  # outward, as for every bundled surface
    return moved, triangles


def main(sphere_path, out_path):
    import meshio

    sphere = meshio.read(sphere_path)
    points, inverse = np.unique(sphere.points.astype(np.float64), axis=0, return_inverse=True)
    triangles = inverse.reshape(-1)[sphere.cells_dict["triangle"]]
    moved, triangles = displace(points, triangles)
    meshio.write(out_path, meshio.Mesh(moved, [("triangle", triangles)]), binary=True)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
