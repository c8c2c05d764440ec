#ifndef PTM_TRIANGLE_SURFACE_H
#define PTM_TRIANGLE_SURFACE_H
// An indexed triangle surface: the plain-C++ exchange type between the VTK
// filters and the geometry core.
#include "Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace ptm
{
using Index = std::int64_t;
using Triangle = std::array<Index, 3>;

struct TriangleSurface
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};
} // namespace ptm
#endif
