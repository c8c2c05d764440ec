#ifndef PTM_TRIANGLE_SURFACE_H
#define PTM_TRIANGLE_SURFACE_H
// An indexed triangle surface: the plain-C++ exchange type between the VTK
// filters and the geometry core.
#include "Vec3.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace ptm
{
using Index = std::int64_t;
using Triangle = std::array<Index, 3>;
// An edge with its smaller index first: the key of an edge whatever way
// its triangles run along it.
using UndirectedEdge = std::array<Index, 2>;
inline UndirectedEdge undirected(Index a, Index b)
{
  return a < b ? UndirectedEdge{ a, b } : UndirectedEdge{ b, a };
}

// A triangle with its corners sorted: the key of a face whichever way it runs.
inline Triangle sortedCorners(Triangle t)
{
  std::sort(t.begin(), t.end());
  return t;
}

struct TriangleSurface
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};
} // namespace ptm
#endif
