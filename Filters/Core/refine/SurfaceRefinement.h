#ifndef PTM_SURFACE_REFINEMENT_H
#define PTM_SURFACE_REFINEMENT_H
// Stage 4a of the method: conforming refinement of one subdomain surface
// before TetGen, so that the tetrahedra next to the boundary are as good as
// serial TetGen's with boundary refinement (-pq), while TetGen itself runs
// with the surface preserved (-Y) and neighbours still match node for node.
//
// Contract.
//  Input: a closed, outward subdomain surface (SubdomainSurface). Its
//  triangles are outer (otherSide < 0: pieces of input triangles, which no
//  other subdomain has) or interface triangles (shared with the neighbour
//  across, triangulated by stage 2).
//  Output: the same surface as a point set, re-triangulated on its outer part:
//   * facets: maximal edge-connected sets of outer triangles that are exactly
//     coplanar (CGAL's exact orientation predicate) and face the same way
//     (or, only when asked, nearly coplanar: coplanarToleranceDegrees);
//   * segments: edges between two facets (every edge of the input that is not
//     flat), split into round(length / size) equal parts;
//   * every facet with more than one triangle or a split segment is meshed
//     anew inside its boundary by the interface mesher (CGAL constrained
//     Delaunay, refinement inside only, every input vertex kept).
//  Unchanged: the interface triangles, every edge next to one (the contours:
//  the neighbour has the same ones) and every point of the input, in the same
//  order. New points are appended after them, in a deterministic order, and
//  lie on the input surface: on a segment, or in a facet's plane inside it.
//  So the enclosed volume does not change beyond round-off.
//  On a facet the mesher refuses (degenerate input), or where the segments
//  alone would get more points than kMostPointsAddedPerExpected allows (a
//  surface of strips far thinner than the size), the surface is returned
//  unrefined with a warning: still conforming, only not improved.
#include "InterfaceTriangulation.h"
#include "SubdomainSurface.h"

#include <string>
#include <vector>

namespace ptm
{
// The default of SurfaceRefinementOptions::segmentSpacingFloor; the
// measurements behind it are at SegmentSpacing in SurfaceRefinement.cpp.
constexpr double kDefaultSegmentSpacingFloor = 1.0 / 8.0;
// The smallest floor accepted (the largest is 1, the whole local size).
constexpr double kSmallestSegmentSpacingFloor = 1.0 / 1024;
// The most points the refinement puts on the segments of one subdomain, as
// a multiple of the tetrahedra its volume bound predicts plus its surface
// points, at the default floor (times default floor / floor for another);
// beyond it the surface is meshed as it is, with a warning. On 10 real CAD
// and scanned parts at K = 16 and 64 (2 ranks, the sweep's sizes) the
// largest multiple was 12.5 (KiCad's heat sink HS-125 at the automatic
// size, thin strips; DSUB-9 8.9, the rest at most 4.1). OpenFOAM's
// NACA0012 wing, all long span-wise strips, at K = 7: one subdomain's
// segments would get 984,281 points, 34 x (22,740 predicted tetrahedra +
// 6,119 surface points), the others 4-10 x with all their points; TetGen
// meshed none of the refined ones in minutes. So this bound only stops the
// extreme case; see TetMeshingOptions::processorBudgetSeconds for the rest.
constexpr double kMostPointsAddedPerExpected = 32.0;

struct SurfaceRefinementOptions
{
  double size = 0.0;                 // target edge length, > 0 (with sizeAt: its upper bound)
  // optional size field (edge length wanted at a point); where it is
  // positive and below `size` it sets the local target instead
  SizeFunction sizeAt;
  double minimumAngleDegrees = 20.7; // quality bound of the facet meshes, (0, 34]
  // The shortest spacing a segment is split at beside a poor facet, as a
  // fraction of the local size, in [kSmallestSegmentSpacingFloor, 1]: lower follows thin input
  // strips (chamfers, fillets of CAD exports) down to their width, as
  // TetGen -q does, at the price of many more tetrahedra there.
  double segmentSpacingFloor = kDefaultSegmentSpacingFloor;
  // 0 (default): a facet is exactly planar, and the surface keeps its
  // geometry. > 0: outer triangles whose normals lie within this angle of a
  // facet's first triangle join it, as TetGen -p merges nearly coplanar
  // facets (files keep 6-7 digits, so a flat CAD face is rarely flat to the
  // last bit): new points are put on the input triangles under them, but the
  // new triangles may leave the input surface by up to largestDeviation.
  double coplanarToleranceDegrees = 0.0;
};

struct SurfaceRefinementResult
{
  bool ok = false;
  std::string error;
  std::vector<std::string> warnings;
  std::size_t facets = 0;          // planar facets of the outer part
  std::size_t facetsMeshed = 0;    // of them meshed anew
  std::size_t segmentsSplit = 0;
  std::size_t pointsAdded = 0;
  double minimumAngleBefore = 0.0; // degrees, outer triangles
  double minimumAngleAfter = 0.0;
  double volumeChange = 0.0;     // of the enclosed volume (round-off only without a tolerance)
  double largestDeviation = 0.0; // of a new triangle's centroid from the input surface (0 without a tolerance)
};

// Refines `surface` in place: points appended, triangles (with sourceFaces
// and otherSide) replaced; globalIds keeps the input points' ids only, so
// points at index >= globalIds.size() are new.
SurfaceRefinementResult refineSubdomainSurface(
  SubdomainSurface& surface, const SurfaceRefinementOptions& options);
} // namespace ptm
#endif
