#ifndef PTM_CONTOUR_SUBDIVISION_H
#define PTM_CONTOUR_SUBDIVISION_H
// Stage 2a of the method: the long edges of the interfaces' boundaries split
// at the mesh size, before the interfaces are triangulated (issue #18).
//
// Why. A contour edge is where a plane crosses one input triangle, so it is
// as long as that triangle is wide: on a coarse CAD or organic surface many
// times the mesh size (3torus from the corpus: 1.25 against a size of
// 0.075). Nothing after the cut may split it (the interface mesher and the
// boundary refinement keep every boundary segment, since the neighbour has
// the same one), so the triangles on both sides of it stayed long and thin,
// and 29 % of the tetrahedra touching a contour were under 10 degrees
// (3torus, K = 2). Here every edge of every interface region (contours and
// the lines where two planes meet) is split into equal parts at most the
// local size, by a rule that reads nothing but the edge: both subdomains,
// every rank holding the edge and every rank count get the same points.
//
// Contract.
//  Input: a complex straight from the cut (interfaces still loops of
//  directed edges; triangles are surface pieces), its points' global ids.
//  Splits: an edge {a, b} of length L gets n - 1 points, n = round(L / s) >= 2,
//  at a + (i / n) (b - a), i = 1 .. n - 1, a being the end with the smaller
//  global id. So they lie on the edge up to one rounding: on the input
//  triangle the edge crosses, and in the plane. s is the size h at the
//  edge's midpoint (the size field where set and below `size`, never under
//  size / 1000), or less next to a thin piece of a cut triangle: where a
//  surface triangle on the edge has an angle under minimumAngleDegrees, s is
//  its width (the smallest distance of a corner from the edge across it),
//  never under kThinPieceSpacingFraction h (SizeFunction.h), the floor of the
//  boundary refinement's segments too.
//  Why: the boundary refinement splits the input edge across such a thin
//  piece at that spacing but may not split the contour, and the facet mesh
//  between the two was a fan of caps (angles of 175-178 degrees). Those caps
//  were the outer face of most tetrahedra under 2 degrees at K = 16 on the
//  corpus (elephant, fandisk, gmsh fillet, rotor, part, screw; every one of
//  the 63 on elephant with parallel planes; 10 of 11 are left there, at
//  contours the cut made risky to split). A rank sees only the triangles
//  of its own subdomains, one side of the edge, so the caller agrees on the
//  largest n any rank wants (splitIntoParts).
//  Not split: an edge where a face on it nearly continues the plane
//  (EdgeSplit::risky). Applied: the points are appended in the order of the
//  splits; every region
//  edge becomes its chain; every triangle with a split edge becomes a fan
//  from the corner across that edge (one edge at a time, so a triangle with
//  two split edges is fanned twice, never into a flat triangle). The volume
//  of every subdomain is unchanged up to round-off.
#include "SizeFunction.h"
#include "SurfaceComplex.h"

#include <vector>

namespace ptm
{
struct ContourSubdivisionOptions
{
  double size = 0.0;   // the largest part, > 0
  SizeFunction sizeAt; // optional: smaller parts where it is positive and below `size`
  // a surface triangle on an edge with an angle under this is a thin piece,
  // whose third corner bounds the parts (0: no such bound); the
  // triangulator passes its MinimumAngle
  double minimumAngleDegrees = 0.0;
};

struct EdgeSplit
{
  std::array<Index, 2> ends; // complex points; ends[0] has the smaller global id
  int parts = 1;             // the edge in this many equal parts
  std::vector<Vec3> points;  // the parts - 1 points from ends[0] to ends[1], strictly between them
  // Splitting it could make a subdomain surface cross itself, which the
  // cutter checked for with the loops as they were: a surface triangle on
  // the edge, or a second plane through it, lies within about 1e-6 radians
  // of the edge's plane, and the new points lie on the edge only up to one
  // rounding, enough for a face to overlap one that nearly continues it.
  // (Regions bent at a snapped vertex are split; the interface stage checks
  // them after triangulating, see markRisky in ContourSubdivision.cpp.)
  // Each rank judges only the faces it holds, so a caller with several ranks
  // splits an edge only if no rank finds it risky.
  bool risky = false;
};

// The split of every region edge, each edge once (parts 1 where it needs
// none), sorted by the global ids of its ends, each judged risky or not by
// the faces held.
std::vector<EdgeSplit> interfaceEdgeSplits(const SurfaceComplex& complex, const std::vector<Index>& globalIds,
  const ContourSubdivisionOptions& options);

// Sets split.parts to `parts` and puts its points where they belong: every
// holder of an edge computes the same points from the same count.
void splitIntoParts(const SurfaceComplex& complex, EdgeSplit& split, int parts);

// Applies the splits into 2 or more parts that are not risky (a caller with several ranks marks
// an edge risky where any rank found it so): appends their points to
// complex.points (split k's points after those of the splits before it) and
// rewires the regions' edges and the triangles (their pairs, source faces and
// planes copied to the fan's triangles).
void applyEdgeSplits(SurfaceComplex& complex, const std::vector<EdgeSplit>& splits);
} // namespace ptm
#endif
