#ifndef PTM_TEST_SURFACES_H
#define PTM_TEST_SURFACES_H
// Closed, outward-oriented test surfaces built exactly in code, so the unit
// tests know their true volume and need no files.
#include "SurfaceComplex.h"
#include "TriangleSurface.h"
#include "VolumeBalancedDecomposition.h"

#include <string>
#include <vector>

namespace ptm::test
{
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
// How many directed edges of a closed, edge-manifold, consistently oriented
// surface would be wrong: used more than once, or without exactly one
// reverse (0 for such a surface).
std::size_t badDirectedEdges(const std::vector<Triangle>& triangles);
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

// The decomposition of a stage test case: K subdomains, cut directions
// along the longest extent for parallel planes and the inertia axes for
// recursive bisection; thin slabs are cut, not refused.
DecompositionOptions stageCaseOptions(int K, CutStrategy strategy);

// A file of Data/ (path relative to it) cut into K subdomains by recursive
// bisection along the inertia axes, the cutter's defaults: the regression
// cases of real surfaces. An unreadable file gives a result with ok false
// and the reader's error.
DecompositionResult decomposeDataFile(const std::string& relativePath, int K);

// Replaces every interface region of a decomposition by its quality
// triangulation (default bounds), like the InterfaceTriangulator filter does on
// one rank: new points appended, interface triangles with their pair and
// plane. Counts the triangles left under the minimum angle.
struct InterfaceFigures
{
  bool ok = true;
  std::string error;
  std::size_t exceptions = 0;         // interface triangles under the minimum angle
  // ... of them with no boundary point and a circumcircle that reaches no
  // boundary segment, counted here and by the triangulator
  std::size_t awayFromBoundary = 0;
  std::size_t reportedAwayFromBoundary = 0;
  double smallestAngle = 180;
};
InterfaceFigures triangulateAllInterfaces(SurfaceComplex& complex);
} // namespace ptm::test
#endif
