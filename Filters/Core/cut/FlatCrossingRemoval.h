#ifndef PTM_FLAT_CROSSING_REMOVAL_H
#define PTM_FLAT_CROSSING_REMOVAL_H
// Stage 1b: contour points that only mark where a plane crossed an edge
// inside a planar face, taken out again after the cuts (with parallel
// planes after every cut, so that they do not pile up on the next planes,
// each time only the points that cut made: VolumeBalancedDecomposition.cpp,
// Cutting::cut).
//
// Why. CAD exports triangulate a planar face with long thin triangles (a
// cylinder's wall as rectangles cut by one diagonal each). A plane crosses
// such a face in one straight segment, but also every diagonal it meets,
// and splitting a crossed triangle leaves a quad piece whose new diagonal
// runs across the next planes: each parallel plane crosses those diagonals
// nearer an end than the last. On CGAL's oblong (walls 26 long, 0.52 wide)
// at K = 16 with parallel planes the contours got points 0.001 apart in
// geometric progression (0.025, 0.015, 0.008, 0.004, 0.001 from a wall's
// edge), the interfaces were refined down to them, and four subdomains held
// 72 k of the 185 k tetrahedra, 7-9 % of them under 10 degrees.
//
// Contract of removeFlatCrossings: `c` is a complex straight from the cuts
// (surface triangles, interfaces still loops). A point p made by the cuts
// (index >= firstCutPoint) goes if
//  * it is on exactly one interface loop edge in and one out (q -> p -> r,
//    not on a line where two planes meet),
//  * every surface triangle around it lies in one plane, and p on the
//    segment q r, each within `tolerance` (a length), and comes from an input
//    triangle of one face (`faceGroups` by source face; empty: all one face),
//  * p and q (or r, the nearer first) share exactly the two triangles of
//    their edge (the link condition: the surface stays a manifold), and no
//    triangle of p turns over or degenerates when p becomes q.
// Then every triangle of p takes q instead, the two on the edge p q vanish
// and the loop runs q -> r; Lawson flips between coplanar triangles of one
// side and one face then make the changed fans Delaunay in their plane. The surface stays the same point set up to
// `tolerance` (the faces are planar and p lay on the segment q r), so the
// subdomains' volumes change by round-off only. Points left unused are
// removed and the others renumbered in their order; points below
// firstCutPoint keep their index. Candidates are taken in index order, so
// the same complex gives the same result on every rank. Returns the number
// of points removed. Optional: `keep` (per point of `c`, nonzero: never
// taken out), for a caller that checks the result and takes out less where
// it must (VolumeBalancedDecomposition.cpp, removeCheckedFlatCrossings).
#include "SurfaceComplex.h"

#include <cstddef>
#include <vector>

namespace ptm
{
std::size_t removeFlatCrossings(SurfaceComplex& c, Index firstCutPoint, double tolerance,
  const std::vector<Index>& faceGroups = {}, const std::vector<char>* keep = nullptr);
} // namespace ptm
#endif
