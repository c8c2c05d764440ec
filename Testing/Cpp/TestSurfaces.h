#ifndef PTM_TEST_SURFACES_H
#define PTM_TEST_SURFACES_H
// Closed, outward-oriented test surfaces built exactly in code, so the unit
// tests know their true volume and need no files.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm::test
{
constexpr double kPi = 3.14159265358979323846;

// Axis-aligned box [lo, hi] with every face split into n x n squares of two triangles.
TriangleSurface subdividedBox(const Vec3& lo, const Vec3& hi, int n);
// Sphere from a subdivided icosahedron (20 * 4^level triangles), vertices on the sphere.
TriangleSurface icosphere(const Vec3& center, double radius, int level);
// Torus around the z axis: major radius R, minor radius r, nu x nv quads.
TriangleSurface torus(const Vec3& center, double R, double r, int nu, int nv);
// The same triangles with reversed orientation (normals pointing in).
TriangleSurface flipped(const TriangleSurface& s);
// Both surfaces in one (indices of b shifted).
TriangleSurface merged(const TriangleSurface& a, const TriangleSurface& b);
// Volume of a polyhedron inscribed in the sphere / torus is below the exact one;
// the tests compare against the divergence-theorem volume of the triangles.
double signedVolume(const TriangleSurface& s);

struct NamedSurface
{
  std::string name;
  TriangleSurface surface;
};
// The surfaces every stage is tested on: ball, box, torus, box with a
// spherical cavity, two disjoint bodies, and the CAD-like bracket from Data/.
std::vector<NamedSurface> namedTestSurfaces();
} // namespace ptm::test
#endif
