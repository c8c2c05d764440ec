#ifndef PTM_VEC3_H
#define PTM_VEC3_H
// Small fixed-size 3D vector arithmetic shared by the geometry core.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace ptm
{
using Vec3 = std::array<double, 3>;

constexpr double kPi = 3.14159265358979323846;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return { a[0] + b[0], a[1] + b[1], a[2] + b[2] }; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
inline Vec3 operator*(double s, const Vec3& a) { return { s * a[0], s * a[1], s * a[2] }; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
// The largest |coordinate|: one rounding of p is about eps times this.
inline double largestCoordinate(const Vec3& p) { return std::max({ std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) }); }
inline Vec3 normalized(const Vec3& a)
{
  const double n = norm(a);
  return n > 0 ? (1.0 / n) * a : a;
}

// A right-handed orthonormal basis (e1, e2, n) of the plane with unit normal
// n, computed from n alone (the same n always gives the same basis).
inline void planeBasis(const Vec3& n, Vec3& e1, Vec3& e2)
{
  const int axis = std::fabs(n[0]) <= std::fabs(n[1])
    ? (std::fabs(n[0]) <= std::fabs(n[2]) ? 0 : 2)
    : (std::fabs(n[1]) <= std::fabs(n[2]) ? 1 : 2);
  Vec3 a{ 0, 0, 0 };
  a[axis] = 1;
  e1 = normalized(cross(n, a));
  e2 = cross(n, e1);
}

// The angle at corner p of the triangle pqr, in radians.
inline double cornerAngle(const Vec3& p, const Vec3& q, const Vec3& r)
{
  const Vec3 u = q - p, v = r - p;
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

// The smallest interior angle of the triangle abc, in radians.
inline double triangleMinimumAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return std::min({ cornerAngle(a, b, c), cornerAngle(b, c, a), cornerAngle(c, a, b) });
}

// The distance from p to the segment ab (a != b).
inline double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return norm(p - (a + t * d));
}

// The point nearest the origin of the line where the planes n1 . x = d1 and
// n2 . x = d2 meet (the line runs along cross(n1, n2), which must not be 0).
inline Vec3 pointOnBothPlanes(const Vec3& n1, double d1, const Vec3& n2, double d2)
{
  const Vec3 line = cross(n1, n2);
  return (1.0 / dot(line, line)) * (d1 * cross(n2, line) + d2 * cross(line, n1));
}

// Axis-aligned box of some points, for a cheap overlap test (empty: lo > hi).
struct Box
{
  Vec3 lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec3 hi{ -lo[0], -lo[1], -lo[2] };
  void add(const Vec3& p)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  bool overlaps(const Box& o) const
  {
    for (int k = 0; k < 3; ++k)
    {
      if (hi[k] < o.lo[k] || o.hi[k] < lo[k])
      {
        return false;
      }
    }
    return true;
  }
};

// The box of all the points (empty, lo > hi, for none).
inline Box boxOf(const std::vector<Vec3>& points)
{
  Box box;
  for (const Vec3& p : points)
  {
    box.add(p);
  }
  return box;
}

// The length of the diagonal of the points' bounding box (0 for none): the
// scale that relative tolerances refer to.
inline double boundingBoxDiagonal(const std::vector<Vec3>& points)
{
  if (points.empty())
  {
    return 0;
  }
  const Box box = boxOf(points);
  return norm(box.hi - box.lo);
}

// How far a point computed on a plane, a line or a triangle (a crossing, a
// split) may lie off it and still count as on it: `relative` of the points'
// bounding-box diagonal, but never under 100 roundings (2.2e-14) of their
// largest coordinate. A computed point is rounded to its coordinates'
// precision, not the part's size: 1000 diagonals from the origin one
// rounding is already 1e-13 of the diagonal. With the diagonal alone the
// relaxer found no cut point on its plane there and moved none, and KiCad's
// HC49U at K = 8 fell from 4.41 degrees near the origin to 0.24 at 1000
// diagonals and 0.09 at 10^4 (serial TetGen -pq: 4.77, 4.55, 4.77).
// Near the origin (largest coordinate under 4.5 diagonals at 1e-13) the
// diagonal decides, as before.
inline double roundOffTolerance(const std::vector<Vec3>& points, double relative)
{
  if (points.empty())
  {
    return 0;
  }
  const Box box = boxOf(points);
  const double largest = std::max(largestCoordinate(box.lo), largestCoordinate(box.hi));
  constexpr double kRoundings = 100 * std::numeric_limits<double>::epsilon();
  return std::max(relative * norm(box.hi - box.lo), kRoundings * largest);
}
} // namespace ptm
#endif
