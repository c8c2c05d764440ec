#ifndef PTM_LOCAL_THICKNESS_H
#define PTM_LOCAL_THICKNESS_H
// The input surface's local thickness, and the size cap it gives every stage
// that puts points on the boundary (contour split, interface triangulation,
// boundary refinement).
//
// Why: TetGen keeps every subdomain surface (-Y), so the surface spacing
// must already suit the part. A size larger than a wall is thick leaves
// flat tetrahedra across the wall: Cura's BIQU_SSS printer bed (a base
// 1.395 thick under ribs 7.4 high, size 21.8) had 16.5 % of its tetrahedra
// under 10 degrees at K = 1, where serial TetGen -pq, which splits the
// surface wherever a tetrahedron is poor, has 0.87 %.
//
// Contract.
//  thicknessSamples: rays along every input triangle's inward normal, from
//  points strictly inside it about limit / 2 apart (in rows along its
//  longest edge, so a long thin triangle gets rays along its length only),
//  and, where one finds the wall thinner, again about that thickness apart
//  (never under kThicknessFloor of `limit`). Each ray's sample is the
//  distance to the first other triangle it meets (CGAL's AABB tree, exact
//  predicates), if that triangle faces back within 30 degrees (the far side
//  of a wall, not the other side of a sharp edge). Samples thicker than
//  `limit` or thinner than kThicknessFloor of it (a place where the surface
//  nearly touches itself), and rays that meet nothing within it or an
//  oblique triangle first, are left out.
//  x, y, z, thickness per sample, in triangle order: the same surface gives
//  the same samples on every rank. Only triangles first .. end - 1 cast
//  rays (all of them by default), against the whole surface, so blocks of
//  triangles measured by different ranks and concatenated in order give
//  the samples of one call over all of them. The surface must be closed and
//  outward (the cutter's input after its checks).
//  thicknessCappedSize: the size at p is the smaller of `base` (none: no cap
//  from it) and min over samples s of (t_s + kThicknessGradation |p - s|),
//  never under kThicknessFloor of `limit`; +inf (no cap) where no sample
//  gives less than `limit`. With no sample it returns `base` itself.
#include "SizeFunction.h"
#include "TriangleSurface.h"

#include <cstddef>
#include <vector>

namespace ptm
{
// How fast the cap grows away from a thin place: size t at the wall, t +
// 0.5 d at distance d.
constexpr double kThicknessGradation = 0.5;
// Walls thinner than this fraction of the largest size give no sample, so
// the cap never asks for less and a sliver gap in a CAD export does not
// split edges into thousands of parts.
constexpr double kThicknessFloor = 1.0 / 64.0;

std::vector<double> thicknessSamples(const TriangleSurface& surface, double limit, std::size_t first = 0,
  std::size_t end = static_cast<std::size_t>(-1));

SizeFunction thicknessCappedSize(const SizeFunction& base, const std::vector<double>& xyzt, double limit);
} // namespace ptm
#endif
