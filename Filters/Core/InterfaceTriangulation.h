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
// (exact predicates); refined Ruppert-style by inserting circumcentres of
// triangles with a small angle or a size above the sizing field, except where
// a circumcentre would encroach a boundary segment: then a point in front of
// the segment is tried, and if no safe point exists the triangle is left and
// counted. The same input always gives bit-identical output.
#include "TriangleSurface.h"

#include <string>

namespace ptm
{
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
};

struct InterfaceTriangulation
{
  std::vector<Vec3> newPoints;     // on the plane
  std::vector<Triangle> triangles; // < points.size(): boundary point; else newPoints[i - points.size()]
  std::size_t trianglesBelowMinimumAngle = 0;
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
} // namespace ptm
#endif
