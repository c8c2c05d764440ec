#ifndef PTM_CUT_DIRECTION_H
#define PTM_CUT_DIRECTION_H
// Choosing the normal of a cutting plane for one part.
#include "SurfaceComplex.h"

namespace ptm
{
enum class CutDirection
{
  X,
  Y,
  Z,
  LongestExtent, // the axis along which the part's bounding box is longest
  Inertia // the principal axis of the node inertia matrix with the smallest moment (the long axis)
};

// Unit normal for cutting the given points; sign fixed so that the largest
// component is positive (deterministic).
Vec3 cutNormal(const std::vector<Vec3>& allPoints, const std::vector<Index>& points,
  CutDirection direction);
} // namespace ptm
#endif
