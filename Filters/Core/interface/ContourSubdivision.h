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
//  Splits: an edge {a, b} of length L gets n - 1 points, n = round(L / h) >= 2,
//  h the size at its midpoint (the size field where set and below `size`,
//  never under size / 1000), at a + (i / n) (b - a), i = 1 .. n - 1, a being
//  the end with the smaller global id. So they lie on the edge up to one
//  rounding: on the input triangle the edge crosses, and in the plane.
//  Not split: an edge of a region bent at a snapped vertex next to a shallow
//  surface triangle, or where a face on it nearly continues the plane
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
};

struct EdgeSplit
{
  std::array<Index, 2> ends; // complex points; ends[0] has the smaller global id
  std::vector<Vec3> points;  // from ends[0] to ends[1], strictly between them
  // Splitting it could make a subdomain surface cross itself, which the
  // cutter checked for with the loops as they were:
  //  * a region on the edge has a vertex that the cut snapped onto its plane
  //    without moving it, so the interface is bent there, and a surface
  //    triangle within 30 degrees of the plane at that vertex: a new
  //    triangulation of the region may cross it (CGAL's rotor from the
  //    corpus, 16 parallel planes);
  //  * a surface triangle on the edge, or a second plane through it, lies
  //    within about 1e-6 radians of the edge's plane: the new points lie on
  //    the edge only up to one rounding, enough for a face to overlap one that
  //    nearly continues it.
  // Each rank judges only the faces it holds, so a caller with several ranks
  // splits an edge only if no rank finds it risky.
  bool risky = false;
};

// The split of every region edge that needs one, each edge once, sorted by
// the global ids of its ends, each judged risky or not by the faces held.
std::vector<EdgeSplit> interfaceEdgeSplits(const SurfaceComplex& complex, const std::vector<Index>& globalIds,
  const ContourSubdivisionOptions& options);

// Applies the splits that are not risky (a caller with several ranks marks
// an edge risky where any rank found it so): appends their points to
// complex.points (split k's points after those of the splits before it) and
// rewires the regions' edges and the triangles (their pairs, source faces and
// planes copied to the fan's triangles).
void applyEdgeSplits(SurfaceComplex& complex, const std::vector<EdgeSplit>& splits);
} // namespace ptm
#endif
