#ifndef PTM_SIZE_FUNCTION_H
#define PTM_SIZE_FUNCTION_H
// The type every stage takes a size field as.
#include "Vec3.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace ptm
{
// A size field: the edge length wanted at a point in space. Empty: none.
using SizeFunction = std::function<double(const Vec3&)>;

// The volume of the regular tetrahedron of edge h: TetGen's volume bound
// (-a) for the mesh size h, as tetmesh.py --size H sets MaximumVolume.
inline double regularTetrahedronVolume(double h)
{
  return h * h * h / (6.0 * std::sqrt(2.0));
}

// The edge of the regular tetrahedron of volume v (the inverse).
inline double regularTetrahedronEdge(double v)
{
  return std::cbrt(6.0 * std::sqrt(2.0) * v);
}

// The size wanted at p under the largest size `size`: the field where it is
// set, positive and below `size`, never under size / 1000 (a field near 0,
// or crossing 0 between two positive points, must not split an edge into
// millions of parts); `size` elsewhere. The contour subdivision and the
// boundary refinement's segments both size by it.
inline double cappedSizeAt(const SizeFunction& sizeAt, double size, const Vec3& p)
{
  if (!sizeAt)
  {
    return size;
  }
  const double field = sizeAt(p);
  return field > 0 && field < size ? std::max(field, 1e-3 * size) : size;
}

// The shortest spacing a thin piece of a cut triangle may ask for, as a
// fraction of the local size: of the contour beside it (ContourSubdivision.h)
// and of the boundary refinement's segment across it (SurfaceRefinement.cpp).
// Both must use the same value, or the two sides of the piece get points at
// different spacings and its mesh is a fan of caps. A quarter against an
// eighth (corpus, K = 16, 2 ranks, 8 surfaces x both strategies, measured
// with the quarter for every segment): the share of tetrahedra under 10
// degrees fell on 12 of 16 runs (elephant with parallel planes 1.88 -> 1.31 %,
// fandisk 0.96 -> 0.61 %) and rose on 4 (OCCT screw with parallel planes
// 0.50 -> 0.75 %), with 10-45 % fewer tetrahedra; on the ball with a size
// field it kept 88.4 % of the edges within 1.5 x the field, where an eighth
// kept 86.6 %. Segments away from contours keep an eighth.
constexpr double kThinPieceSpacingFraction = 0.25;
} // namespace ptm
#endif
