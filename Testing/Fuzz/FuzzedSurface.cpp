#include "FuzzedSurface.h"

#include "ClosedShapes.h"

#include <algorithm>
#include <cmath>

namespace ptm::fuzz
{
namespace
{
enum class Edit
{
  NudgePoint,        // one coordinate moved by a small multiple of the unit
  SnapToLattice,     // one coordinate set to k/8 of the unit: coplanar points, points on cuts
  MoveOntoPoint,     // exact duplicate point
  MoveOntoLine,      // on the line through two points: collinear corners
  CollapseEdge,      // one end of a triangle's edge onto the other
  NearlyCollapseEdge,// ... within a tiny distance (around the merge tolerance)
  FlipTriangle,
  DropTriangle,      // opens the surface
  DuplicateTriangle, // as it is or flipped
  RewireCorner,      // a corner to any point, or to one that does not exist
  SplitTriangle,     // at an interior point: stays closed
  SplitEdge,         // in every triangle that has it: stays closed
  AddShiftedCopy,    // a second body, apart or overlapping
  Scale,             // by a power of two
  ScaleExtremely,    // by up to 2^+-1000: overflow and underflow in products
  Stretch,           // one axis only: flat or needle-like shapes
  Rotate,            // about a coordinate axis by k * pi / 32
  MoveFarAway,       // by up to 1e15: lost digits
};
constexpr int kEditCount = 18;

struct Editor
{
  FuzzedDataProvider& in;
  TriangleSurface& s;
  double unit = 1; // follows the scalings, so nudges stay relative to the shape

  Index anyPoint() { return in.ConsumeIntegralInRange<Index>(0, static_cast<Index>(s.points.size()) - 1); }
  std::size_t anyTriangle() { return in.ConsumeIntegralInRange<std::size_t>(0, s.triangles.size() - 1); }
  int anyAxis() { return in.ConsumeIntegralInRange<int>(0, 2); }
  // RewireCorner may leave a corner pointing nowhere; edits that read the
  // corners' coordinates skip such triangles (the input check must refuse them).
  bool hasValidCorners(const Triangle& t) const
  {
    return std::all_of(t.begin(), t.end(),
      [&](Index v) { return v >= 0 && v < static_cast<Index>(s.points.size()); });
  }

  void splitEdge()
  {
    const Triangle t = s.triangles[anyTriangle()];
    const int k = in.ConsumeIntegralInRange<int>(0, 2);
    if (!hasValidCorners(t))
    {
      return;
    }
    const Index a = t[k], b = t[(k + 1) % 3];
    const double w = in.ConsumeIntegralInRange<int>(1, 15) / 16.0;
    const Index m = static_cast<Index>(s.points.size());
    s.points.push_back(s.points[a] + w * (s.points[b] - s.points[a]));
    const std::size_t count = s.triangles.size();
    for (std::size_t i = 0; i < count && s.triangles.size() < kMaxFuzzedTriangles; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        Triangle& u = s.triangles[i];
        const Index p = u[c], q = u[(c + 1) % 3], r = u[(c + 2) % 3];
        if ((p == a && q == b) || (p == b && q == a))
        {
          u = { p, m, r };
          s.triangles.push_back({ m, q, r });
          break;
        }
      }
    }
  }

  void apply(Edit edit)
  {
    switch (edit)
    {
      case Edit::NudgePoint:
        s.points[anyPoint()][anyAxis()] += in.ConsumeIntegralInRange<int>(-128, 127) / 256.0 * unit;
        break;
      case Edit::SnapToLattice:
        s.points[anyPoint()][anyAxis()] = in.ConsumeIntegralInRange<int>(-16, 16) / 8.0 * unit;
        break;
      case Edit::MoveOntoPoint:
        s.points[anyPoint()] = s.points[anyPoint()];
        break;
      case Edit::MoveOntoLine:
      {
        const Index p = anyPoint(), a = anyPoint(), b = anyPoint();
        const double w = in.ConsumeIntegralInRange<int>(-8, 16) / 8.0;
        s.points[p] = s.points[a] + w * (s.points[b] - s.points[a]);
        break;
      }
      case Edit::CollapseEdge:
      case Edit::NearlyCollapseEdge:
      {
        const Triangle t = s.triangles[anyTriangle()];
        const int k = in.ConsumeIntegralInRange<int>(0, 2);
        if (!hasValidCorners(t))
        {
          break;
        }
        Vec3 p = s.points[t[k]];
        if (edit == Edit::NearlyCollapseEdge)
        {
          p[anyAxis()] += std::ldexp(unit, -in.ConsumeIntegralInRange<int>(20, 52));
        }
        s.points[t[(k + 1) % 3]] = p;
        break;
      }
      case Edit::FlipTriangle:
      {
        Triangle& t = s.triangles[anyTriangle()];
        std::swap(t[1], t[2]);
        break;
      }
      case Edit::DropTriangle:
        if (s.triangles.size() > 1)
        {
          s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(anyTriangle()));
        }
        break;
      case Edit::DuplicateTriangle:
      {
        Triangle t = s.triangles[anyTriangle()];
        if (in.ConsumeBool())
        {
          std::swap(t[1], t[2]);
        }
        s.triangles.push_back(t);
        break;
      }
      case Edit::RewireCorner:
      {
        Triangle& t = s.triangles[anyTriangle()];
        const Index n = static_cast<Index>(s.points.size());
        t[in.ConsumeIntegralInRange<int>(0, 2)] = in.ConsumeIntegralInRange<Index>(-1, n);
        break;
      }
      case Edit::SplitTriangle:
      {
        const std::size_t i = anyTriangle();
        const Triangle t = s.triangles[i];
        if (!hasValidCorners(t))
        {
          break;
        }
        const double wa = in.ConsumeIntegralInRange<int>(1, 255), wb = in.ConsumeIntegralInRange<int>(1, 255),
                     wc = in.ConsumeIntegralInRange<int>(1, 255);
        const Index m = static_cast<Index>(s.points.size());
        s.points.push_back((1.0 / (wa + wb + wc)) *
          (wa * s.points[t[0]] + wb * s.points[t[1]] + wc * s.points[t[2]]));
        s.triangles[i] = { t[0], t[1], m };
        s.triangles.push_back({ t[1], t[2], m });
        s.triangles.push_back({ t[2], t[0], m });
        break;
      }
      case Edit::SplitEdge:
        splitEdge();
        break;
      case Edit::AddShiftedCopy:
      {
        if (2 * s.points.size() > kMaxFuzzedPoints || 2 * s.triangles.size() > kMaxFuzzedTriangles)
        {
          break;
        }
        Vec3 shift;
        for (double& x : shift)
        {
          x = in.ConsumeIntegralInRange<int>(-12, 12) / 4.0 * unit;
        }
        const Index offset = static_cast<Index>(s.points.size());
        const std::size_t points = s.points.size(), triangles = s.triangles.size();
        for (std::size_t p = 0; p < points; ++p)
        {
          s.points.push_back(s.points[p] + shift);
        }
        for (std::size_t t = 0; t < triangles; ++t)
        {
          const Triangle u = s.triangles[t];
          s.triangles.push_back({ u[0] + offset, u[1] + offset, u[2] + offset });
        }
        break;
      }
      case Edit::Scale:
      case Edit::ScaleExtremely:
      {
        const int e = edit == Edit::Scale ? in.ConsumeIntegralInRange<int>(-20, 20)
                                          : in.ConsumeIntegralInRange<int>(-1000, 1000);
        for (Vec3& p : s.points)
        {
          p = std::ldexp(1.0, e) * p;
        }
        unit = std::ldexp(unit, e);
        break;
      }
      case Edit::Stretch:
      {
        const int axis = anyAxis();
        const double factor = std::ldexp(1.0, in.ConsumeIntegralInRange<int>(-30, 30));
        for (Vec3& p : s.points)
        {
          p[axis] *= factor;
        }
        break;
      }
      case Edit::Rotate:
      {
        const int axis = anyAxis(), u = (axis + 1) % 3, v = (axis + 2) % 3;
        const double angle = in.ConsumeIntegralInRange<int>(1, 63) * 3.14159265358979323846 / 32;
        const double c = std::cos(angle), sn = std::sin(angle);
        for (Vec3& p : s.points)
        {
          const double pu = p[u], pv = p[v];
          p[u] = c * pu - sn * pv;
          p[v] = sn * pu + c * pv;
        }
        break;
      }
      case Edit::MoveFarAway:
      {
        const int axis = anyAxis();
        const double distance = std::pow(10.0, in.ConsumeIntegralInRange<int>(3, 15)) * unit;
        for (Vec3& p : s.points)
        {
          p[axis] += distance;
        }
        break;
      }
    }
  }
};

TriangleSurface freeForm(FuzzedDataProvider& in)
{
  TriangleSurface s;
  const int points = in.ConsumeIntegralInRange<int>(4, 16);
  for (int p = 0; p < points; ++p)
  {
    Vec3 x;
    for (double& c : x)
    {
      c = in.ConsumeIntegralInRange<int>(-4, 4);
    }
    s.points.push_back(x);
  }
  const int triangles = in.ConsumeIntegralInRange<int>(4, 32);
  for (int t = 0; t < triangles; ++t)
  {
    Triangle tri;
    for (Index& v : tri)
    {
      v = in.ConsumeIntegralInRange<Index>(0, points - 1);
    }
    s.triangles.push_back(tri);
  }
  return s;
}
} // namespace

TriangleSurface fuzzedSurface(FuzzedDataProvider& in)
{
  const int shape = in.ConsumeIntegralInRange<int>(0, kClosedShapeCount);
  TriangleSurface s =
    shape == kClosedShapeCount ? freeForm(in) : closedShape(static_cast<ClosedShape>(shape));
  Editor editor{ in, s };
  for (int e = 0; e < kMaxFuzzedEdits && in.remaining_bytes() > 0; ++e)
  {
    if (s.points.size() >= kMaxFuzzedPoints || s.triangles.size() >= kMaxFuzzedTriangles)
    {
      break;
    }
    editor.apply(static_cast<Edit>(in.ConsumeIntegralInRange<int>(0, kEditCount - 1)));
  }
  return s;
}
} // namespace ptm::fuzz
