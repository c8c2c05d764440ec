#ifndef PTM_INTERFACE_TRIANGULATION_H
#define PTM_INTERFACE_TRIANGULATION_H
// Stage 2 of the method: a quality triangulation of one interface region,
// refined inside only.
//
// The region lies in a plane and is bounded by closed loops of directed
// segments (region on the LEFT seen from the normal: outer loops
// counter-clockwise, holes clockwise; several components and loops touching
// at a vertex are allowed). The boundary points are shared with the surface
// and other interfaces, so no point is ever put on a segment: the result
// contains every segment as an edge of exactly one triangle, and new points
// only strictly inside. Built on CGAL's constrained Delaunay triangulation
// (exact predicates). Refinement, Ruppert-style but without ever splitting a
// segment: the worst triangle (angle under the bound, or an edge longer than
// the size field) gets its circumcentre, or, where that would make the
// triangle on some boundary segment worse than the bound and than it is, a
// point nearer to it on the bisector of its shortest edge (off-centres); a
// point closer than half that edge to a vertex is never inserted. Then the
// new points of triangles still under the bound move within their stars to
// where the angle shortfall of their triangles is least (a triangle without
// a boundary point never becomes poor), and edges flip where that lowers it.
// Triangles under the bound are left only next to the boundary: with a
// boundary point, or with a circumcircle that reaches a boundary segment.
// The same input always gives bit-identical output.
#include "SizeFunction.h"
#include "SurfaceComplex.h"

#include <functional>
#include <string>

namespace ptm
{
// The most new points one region gets (InterfaceMesher's cap): beyond it
// refinement stops short of the size asked. A region of area A at a
// maximum edge length h gets about 2.5 A / h^2 of them (the unit ball's
// disc at h = 0.01 and 0.02), so the filter refuses a length whose
// estimate 2 A / h^2 is over this before triangulating.
constexpr double kMostNewPointsPerRegion = 2e7;

struct PlanarRegion
{
  Vec3 origin;                            // a point of the plane
  Vec3 normal;                            // unit
  std::vector<Vec3> points;               // boundary points (may lie off the plane by round-off or snapping)
  std::vector<std::array<Index, 2>> edges; // directed boundary segments, indices into points
};

struct InterfaceTriangulationOptions
{
  double minimumAngleDegrees = 20.7; // (0, 34]
  double maximumEdgeLength = 0.0;    // 0: sizing from the boundary spacing, graded inward
  bool refine = true;                // false: only check the boundary (every error below), no triangles
  // false: no smoothing after the refinement (nor the refinement that
  // follows it): for the cutter's self-intersection check, which needs a
  // triangulation covering the region, not its best shape
  bool smooth = true;
  // Points no segment uses: false drops them (an interface has none); true
  // keeps them as fixed vertices, which must lie strictly inside the region
  // (the input vertices inside a planar facet of the boundary refinement).
  bool keepIsolatedPoints = false;
  // A size field: the edge length wanted at a point in space (> 0). When
  // set, it replaces the automatic sizing at every vertex: edges up to 1.4 x
  // the field are allowed, which puts them near it (InterfaceTriangulation.cpp,
  // kFieldAllowance); maximumEdgeLength, when set too, stays a hard bound. It
  // must be deterministic, so that both sides of an interface get the same mesh.
  SizeFunction sizeAt;
};

struct InterfaceTriangulation
{
  std::vector<Vec3> newPoints;     // on the plane
  std::vector<Triangle> triangles; // < points.size(): boundary point; else newPoints[i - points.size()]
  std::size_t trianglesBelowMinimumAngle = 0;
  // ... of them neither touching the boundary nor with a circumcircle that
  // reaches a boundary segment (none are expected)
  std::size_t trianglesBelowMinimumAngleAwayFromBoundary = 0;
  std::size_t encroachedSegmentsLeft = 0;
  double minimumAngleDegrees = 0;
};

struct InterfaceTriangulationResult
{
  bool ok = false;
  std::string error;
  InterfaceTriangulation triangulation;
};

InterfaceTriangulationResult triangulateInterface(
  const PlanarRegion& region, const InterfaceTriangulationOptions& options);

// One interface of a complex as a planar region: its plane, the complex
// points `points` (every point of the region's edges once, in the order the
// caller wants them numbered) and the region's edges in those local numbers.
PlanarRegion planarRegionOf(
  const SurfaceComplex& complex, const InterfaceRegion& region, const std::vector<Index>& points);
} // namespace ptm
#endif
