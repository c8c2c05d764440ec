#include "ClosedShapes.h"

#include <array>
#include <cmath>
#include <map>

namespace ptm::fuzz
{
namespace
{
TriangleSurface fromQuads(std::vector<Vec3> points, const std::vector<std::array<Index, 4>>& quads)
{
  TriangleSurface s;
  s.points = std::move(points);
  for (const auto& q : quads)
  {
    s.triangles.push_back({ q[0], q[1], q[2] });
    s.triangles.push_back({ q[0], q[2], q[3] });
  }
  return s;
}

TriangleSurface cube(const Vec3& lo, const Vec3& hi)
{
  return fromQuads(
    { { lo[0], lo[1], lo[2] }, { hi[0], lo[1], lo[2] }, { hi[0], hi[1], lo[2] },
      { lo[0], hi[1], lo[2] }, { lo[0], lo[1], hi[2] }, { hi[0], lo[1], hi[2] },
      { hi[0], hi[1], hi[2] }, { lo[0], hi[1], hi[2] } },
    { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 },
      { 3, 0, 4, 7 } });
}

// The unit cube with every face split into n x n squares; points are shared
// through their lattice coordinates.
TriangleSurface latticeCube(int n)
{
  TriangleSurface s;
  std::map<std::array<int, 3>, Index> id;
  auto point = [&](std::array<int, 3> ijk) {
    auto [it, added] = id.emplace(ijk, static_cast<Index>(s.points.size()));
    if (added)
    {
      s.points.push_back({ double(ijk[0]) / n, double(ijk[1]) / n, double(ijk[2]) / n });
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side : { 0, n })
    {
      // (u, v, axis) right handed on the upper face, so u x v points out;
      // on the lower face swap them.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (side == 0)
      {
        std::swap(u, v);
      }
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          auto at = [&](int di, int dj) {
            std::array<int, 3> ijk{};
            ijk[axis] = side;
            ijk[u] = i + di;
            ijk[v] = j + dj;
            return point(ijk);
          };
          const Index a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
          s.triangles.push_back({ a, b, c });
          s.triangles.push_back({ a, c, d });
        }
      }
    }
  }
  return s;
}

TriangleSurface tetrahedron()
{
  return { { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } } };
}

// Convex and around `center`: every face is turned to point away from it.
void orientConvexOutward(TriangleSurface& s, const Vec3& center)
{
  for (Triangle& t : s.triangles)
  {
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    if (dot(cross(b - a, c - a), a - center) < 0)
    {
      std::swap(t[1], t[2]);
    }
  }
}

TriangleSurface octahedron(const Vec3& center, double radius)
{
  TriangleSurface s;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double sign : { 1.0, -1.0 })
    {
      Vec3 p = center;
      p[axis] += sign * radius;
      s.points.push_back(p);
    }
  }
  // +x, -x, +y, -y, +z, -z
  for (Index x : { 0, 1 })
  {
    for (Index y : { 2, 3 })
    {
      for (Index z : { 4, 5 })
      {
        s.triangles.push_back({ x, y, z });
      }
    }
  }
  orientConvexOutward(s, center);
  return s;
}

TriangleSurface icosahedron()
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSurface s;
  s.points = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  s.triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  orientConvexOutward(s, { 0, 0, 0 });
  return s;
}

// Orientation follows the (u, v) parametrisation; the input check orients
// shells anyway, and the torus is not convex.
TriangleSurface torus(int nu, int nv, double R, double r)
{
  const double pi = 3.14159265358979323846;
  std::vector<Vec3> points;
  std::vector<std::array<Index, 4>> quads;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      points.push_back(
        { (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v) });
      auto id = [&](int a, int b) { return static_cast<Index>((a % nu) * nv + (b % nv)); };
      quads.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return fromQuads(std::move(points), quads);
}

TriangleSurface merged(TriangleSurface a, const TriangleSurface& b, bool flipB)
{
  const Index shift = static_cast<Index>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles)
  {
    if (flipB)
    {
      std::swap(t[1], t[2]);
    }
    a.triangles.push_back({ t[0] + shift, t[1] + shift, t[2] + shift });
  }
  return a;
}
} // namespace

TriangleSurface closedShape(ClosedShape shape)
{
  switch (shape)
  {
    case ClosedShape::Tetrahedron: return tetrahedron();
    case ClosedShape::Octahedron: return octahedron({ 0, 0, 0 }, 1);
    case ClosedShape::Cube: return cube({ 0, 0, 0 }, { 1, 1, 1 });
    case ClosedShape::LatticeCube: return latticeCube(2);
    case ClosedShape::Icosahedron: return icosahedron();
    case ClosedShape::Torus: return torus(6, 3, 2.0, 0.75);
    case ClosedShape::TwoBodies:
      return merged(cube({ 0, 0, 0 }, { 1, 1, 1 }), octahedron({ 3, 0.5, 0.5 }, 0.5), false);
    case ClosedShape::CubeWithCavity:
      return merged(cube({ -1, -1, -1 }, { 1, 1, 1 }), octahedron({ 0, 0, 0 }, 0.5), true);
    case ClosedShape::NearlyTouchingCubes:
      return merged(cube({ 0, 0, 0 }, { 1, 1, 1 }), cube({ 0, 0, 1 + 1e-9 }, { 1, 1, 2 }), false);
  }
  return tetrahedron();
}
} // namespace ptm::fuzz
