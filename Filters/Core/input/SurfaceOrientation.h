#ifndef PTM_SURFACE_ORIENTATION_H
#define PTM_SURFACE_ORIENTATION_H
// Preparing a closed input surface for cutting: exact merge of duplicate
// points (STL stores every triangle's corners), a closedness check, and
// consistent orientation of every shell so that normals point out of the
// material: outer shells enclose positive volume, cavities (a shell inside an
// odd number of others) point into the hole and enclose negative volume.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
struct OrientationReport
{
  std::size_t mergedPoints = 0;    // points removed because identical to an earlier one
  std::size_t droppedTriangles = 0; // triangles that collapsed by the merge
  std::size_t shellCount = 0;
  std::size_t cavityCount = 0;      // shells nested inside an odd number of others
  std::size_t reorientedTriangles = 0; // flipped to agree with their neighbours
  std::size_t invertedShells = 0;   // shells flipped as a whole (inside-out)
  std::vector<int> triangleShell;   // shell of every triangle
  std::vector<double> shellVolume;  // signed, after orientation
};

struct OrientationResult
{
  bool ok = false;
  std::string error;
  OrientationReport report;
};

// Merges points that coincide within relativeTolerance x the bounding-box
// diagonal (per coordinate) into the first of them, removes unused points and
// triangles that repeat a corner. Keeps triangle and point order. STL stores
// every corner of every triangle; pieces of a distributed source repeat
// their seam points with round-off differences.
// Returns the number of merged points; `droppedTriangles` gets the count of
// collapsed triangles and `sourceOfTriangle` the input index of each kept one.
std::size_t mergeDuplicatePoints(TriangleSurface& surface, std::size_t& droppedTriangles,
  std::vector<Index>& sourceOfTriangle, double relativeTolerance = 1e-10);

// Orients every shell (edge-connected component) consistently and by nesting.
// Fails with a message if an edge is used by other than exactly two triangles
// (open or non-manifold surface) or if a shell cannot be oriented (Moebius).
OrientationResult orientShells(TriangleSurface& surface);

// Generalized winding number of a closed triangle set around point p
// (about +1 inside a positively oriented shell, 0 outside).
double windingNumber(const TriangleSurface& surface, const std::vector<Index>& triangles,
  const Vec3& p);
} // namespace ptm
#endif
