#ifndef PTM_SURFACE_DISTANCE_H
#define PTM_SURFACE_DISTANCE_H
// How far apart two triangle surfaces are, in both directions: what the
// stages that replace the input surface (AlphaWrap.h, IsotropicRemeshing.h)
// report, since the surface they hand on is not the input.
//
// Both surfaces are sampled on CGAL's grids (faces and edges, the same
// spacing on both) and at every triangle's corners, edge midpoints and
// centroid, and every sample's distance to the other surface is
// measured against an AABB tree of its triangles, so each figure is the true
// largest distance to within the spacing. Triangles with a repeated corner
// or a corner that does not exist are not sampled.
#include "TriangleSurface.h"

#include <cmath>

namespace ptm
{
struct TwoSidedDistance
{
  double firstToSecond = 0; // largest distance from a point of the first surface to the second
  double secondToFirst = 0;
  double sampleSpacing = 0; // the grid spacing used
};

// The spacing is at least `minimumSpacing`, widened so that neither surface
// gets more than about `maximumSamples` samples (CGAL's grid sampling gives up
// to twice that). Measuring a direction stops at its first sample farther
// than `stopAbove` (that distance is then returned: enough to refuse a bound,
// a lower bound of the largest).
TwoSidedDistance sampledTwoSidedDistance(const TriangleSurface& first, const TriangleSurface& second,
  double minimumSpacing, double maximumSamples, double stopAbove = HUGE_VAL);
} // namespace ptm
#endif
