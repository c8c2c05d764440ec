#ifndef PTM_SURFACE_INPUT_CHECK_H
#define PTM_SURFACE_INPUT_CHECK_H
// Checking and preparing an input surface before it is cut.
//
// Real surfaces are dirty. This stage says exactly what is wrong, repairs what
// is safe to repair (announced as warnings) and refuses the rest with one
// message that names every problem found, with counts and a location:
//
//   repaired (warnings):  duplicate points (merged within 1e-10 of the
//                         bounding-box diagonal), triangles that repeat a
//                         corner, exactly duplicated triangles, zero-area
//                         (collinear, exact predicate) triangles -- the last
//                         three only where removing them leaves a closed
//                         surface -- and inconsistently oriented or inside-out
//                         shells (orientation propagation, nesting);
//   refused (the error):  empty input, fewer than 4 points, NaN or infinite
//                         coordinates, coordinates beyond 1e100 (volumes
//                         would overflow), a bounding-box diagonal under
//                         1e-50 (the predicates' products would underflow),
//                         indices out of range, boundary edges
//                         (open surface), non-manifold edges and vertices,
//                         self-intersections (CGAL, exact predicates; checked
//                         when the surface has at most `selfIntersectionLimit`
//                         triangles), shells that cannot be oriented, no
//                         enclosed volume.
//
// Deterministic: the same input gives the same output on every rank.
#include "SurfaceOrientation.h"
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
struct InputCheckOptions
{
  bool checkSelfIntersections = true;
  // above this many triangles the self-intersection check is skipped (with a
  // warning): it costs about as much as cutting
  std::size_t selfIntersectionLimit = 2000000;
  double mergeTolerance = 1e-10; // relative to the bounding-box diagonal
};

struct InputCheckCounts
{
  std::size_t inputPoints = 0;
  std::size_t inputTriangles = 0;
  std::size_t nonFinitePoints = 0;
  std::size_t badIndexTriangles = 0;
  std::size_t mergedPoints = 0;
  std::size_t collapsedTriangles = 0;  // repeat a corner after merging (removed)
  std::size_t duplicateTriangles = 0;  // same three corners as an earlier one (removed)
  std::size_t zeroAreaTriangles = 0;   // three distinct collinear corners (removed)
  std::size_t boundaryEdges = 0;
  std::size_t nonManifoldEdges = 0;
  std::size_t nonManifoldVertices = 0;
  std::size_t selfIntersectingPairs = 0; // up to the search limit of the check
  bool selfIntersectionChecked = false;
};

struct PreparedSurface
{
  bool ok = false;
  std::string error;                 // every problem found, "; "-separated
  std::vector<std::string> warnings; // every repair made, and skipped checks
  InputCheckCounts counts;
  TriangleSurface surface;            // merged, cleaned, oriented
  std::vector<Index> sourceOfTriangle; // input triangle of every kept triangle
  OrientationReport orientation;
  double enclosedVolume = 0;
};

PreparedSurface prepareInputSurface(const TriangleSurface& input, const InputCheckOptions& options);
} // namespace ptm
#endif
