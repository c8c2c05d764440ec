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

// An edge of a triangle (edgesOfTriangles).
struct EdgeOfTriangle
{
  UndirectedEdge edge;
  Index triangle;
  bool operator<(const EdgeOfTriangle& o) const
  {
    return edge != o.edge ? edge < o.edge : triangle < o.triangle;
  }
};

// Every edge of every triangle with its triangle, sorted by edge, then
// triangle: the triangles at an edge are one run.
inline std::vector<EdgeOfTriangle> edgesOfTriangles(const std::vector<Triangle>& triangles)
{
  std::vector<EdgeOfTriangle> edges;
  edges.reserve(3 * triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const Triangle& t = triangles[i];
    for (int k = 0; k < 3; ++k)
    {
      edges.push_back({ undirected(t[k], t[(k + 1) % 3]), static_cast<Index>(i) });
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// The triangles at each of `pointCount` points, in increasing order.
inline std::vector<std::vector<std::size_t>> trianglesAtPoints(
  const std::vector<Triangle>& triangles, std::size_t pointCount)
{
  std::vector<std::vector<std::size_t>> at(pointCount);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (Index p : triangles[t])
    {
      at[p].push_back(t);
    }
  }
  return at;
}

struct TriangleSurface
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};

// Six times the signed volume of the tetrahedron (o, a, b, c). Summed over
// the triangles of a closed surface it is six times the enclosed volume
// whatever o is, but each term grows as the cube of the distance to o while
// the volume does not, so o should be a point of the surface, not a far
// (0, 0, 0): two spheres of radius 1 and 0.5 centred 10^4 from the origin came out
// 3e-5 off that way (TetGen's volume check then refused every mesh), and
// at 10^6 the cutter found no volume at all (session 31).
inline double sixTimesVolumeAbout(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c)
{
  return dot(a - o, cross(b - o, c - o));
}

// The signed volume the triangles `which` of `points` (a closed surface)
// enclose, taken about the point `o` (see sixTimesVolumeAbout).
template <typename Triangles>
double volumeAbout(const Vec3& o, const std::vector<Vec3>& points, const Triangles& which)
{
  double sixTimes = 0;
  for (const Triangle& t : which)
  {
    sixTimes += sixTimesVolumeAbout(o, points[t[0]], points[t[1]], points[t[2]]);
  }
  return sixTimes / 6.0;
}

// The same for the triangles of `triangles` whose indices are in `which`, in
// that order (a shell, or the outer part of a subdomain surface).
template <typename Indices>
double volumeAbout(
  const Vec3& o, const std::vector<Vec3>& points, const std::vector<Triangle>& triangles, const Indices& which)
{
  double sixTimes = 0;
  for (Index t : which)
  {
    const Triangle& f = triangles[t];
    sixTimes += sixTimesVolumeAbout(o, points[f[0]], points[f[1]], points[f[2]]);
  }
  return sixTimes / 6.0;
}

// The signed volume a closed surface encloses, about its first corner.
inline double enclosedVolume(const TriangleSurface& s)
{
  return s.triangles.empty() ? 0.0 : volumeAbout(s.points[s.triangles[0][0]], s.points, s.triangles);
}

// Mean length of the triangles' edges (an edge of two triangles counted
// twice); 0 without triangles. The input's resolution, which the cutter
// reports and the remesher and the mesher's volume bound default to.
inline double meanEdgeLength(const TriangleSurface& surface)
{
  double edgeSum = 0;
  for (const Triangle& t : surface.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edgeSum += norm(surface.points[t[(k + 1) % 3]] - surface.points[t[k]]);
    }
  }
  return surface.triangles.empty() ? 0.0 : edgeSum / (3.0 * static_cast<double>(surface.triangles.size()));
}

// How many triangles have an angle under `radians`: the long thin
// triangles that make TetGen slow and the boundary refinement's strips dense.
inline std::size_t trianglesWithAngleUnder(const TriangleSurface& surface, double radians)
{
  return static_cast<std::size_t>(std::count_if(surface.triangles.begin(), surface.triangles.end(),
    [&](const Triangle& t)
    { return triangleMinimumAngle(surface.points[t[0]], surface.points[t[1]], surface.points[t[2]]) < radians; }));
}
} // namespace ptm
#endif
