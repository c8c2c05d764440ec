#include "TestSurfaces.h"

#include "InterfaceTriangulation.h"
#include "OffFormat.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace ptm::test
{
TriangleSurface subdividedBox(const Vec3& lo, const Vec3& hi, int n)
{
  TriangleSurface s;
  std::map<std::array<int, 3>, Index> ids;
  auto point = [&](int i, int j, int k) {
    const std::array<int, 3> key{ i, j, k };
    auto it = ids.find(key);
    if (it != ids.end())
    {
      return it->second;
    }
    const Vec3 p{ lo[0] + (hi[0] - lo[0]) * i / n, lo[1] + (hi[1] - lo[1]) * j / n,
      lo[2] + (hi[2] - lo[2]) * k / n };
    // exact end values, so that box faces are exactly planar
    Vec3 q = p;
    if (i == n) q[0] = hi[0];
    if (j == n) q[1] = hi[1];
    if (k == n) q[2] = hi[2];
    s.points.push_back(q);
    ids[key] = static_cast<Index>(s.points.size() - 1);
    return ids[key];
  };
  // For each axis a and side (0 = low, 1 = high): the face grid spans the two other axes.
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (int u = 0; u < n; ++u)
      {
        for (int v = 0; v < n; ++v)
        {
          auto at = [&](int du, int dv) {
            std::array<int, 3> g{};
            g[a] = side * n;
            g[b] = u + du;
            g[c] = v + dv;
            return point(g[0], g[1], g[2]);
          };
          // (b, c, a) is right-handed, so (u, v) counter-clockwise faces +a.
          const Index p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (side == 1)
          {
            s.triangles.push_back({ p00, p10, p11 });
            s.triangles.push_back({ p00, p11, p01 });
          }
          else
          {
            s.triangles.push_back({ p00, p11, p10 });
            s.triangles.push_back({ p00, p01, p11 });
          }
        }
      }
    }
  }
  return s;
}

TriangleSurface icosphere(const Vec3& center, double radius, int level)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t },
    { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 },
    { -t, 0, 1 } };
  std::vector<Triangle> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  for (auto& q : p)
  {
    q = normalized(q);
  }
  for (int l = 0; l < level; ++l)
  {
    std::map<std::pair<Index, Index>, Index> mid;
    auto midpoint = [&](Index a, Index b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      p.push_back(normalized(0.5 * (p[a] + p[b])));
      const Index id = static_cast<Index>(p.size() - 1);
      mid[key] = id;
      return id;
    };
    std::vector<Triangle> g;
    for (const auto& tri : f)
    {
      const Index ab = midpoint(tri[0], tri[1]);
      const Index bc = midpoint(tri[1], tri[2]);
      const Index ca = midpoint(tri[2], tri[0]);
      g.push_back({ tri[0], ab, ca });
      g.push_back({ tri[1], bc, ab });
      g.push_back({ tri[2], ca, bc });
      g.push_back({ ab, bc, ca });
    }
    f.swap(g);
  }
  TriangleSurface s;
  for (const auto& q : p)
  {
    s.points.push_back(center + radius * q);
  }
  s.triangles = f;
  return s;
}

TriangleSurface torus(const Vec3& center, double R, double r, int nu, int nv)
{
  TriangleSurface s;
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2 * kPi * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2 * kPi * j / nv;
      s.points.push_back(center +
        Vec3{ (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
          r * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      // d/du x d/dv points outward for this parametrisation
      s.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      s.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return s;
}

TriangleSurface flipped(const TriangleSurface& s)
{
  TriangleSurface f = s;
  for (auto& t : f.triangles)
  {
    std::swap(t[1], t[2]);
  }
  return f;
}

TriangleSurface merged(const TriangleSurface& a, const TriangleSurface& b)
{
  TriangleSurface m = a;
  const Index offset = static_cast<Index>(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  for (const auto& t : b.triangles)
  {
    m.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return m;
}

double signedVolume(const TriangleSurface& s)
{
  // about a corner, not (0, 0, 0), so surfaces far from the origin measure right
  const Vec3 o = s.triangles.empty() ? Vec3{ 0, 0, 0 } : s.points[s.triangles[0][0]];
  double v = 0;
  for (const auto& t : s.triangles)
  {
    v += dot(s.points[t[0]] - o, cross(s.points[t[1]] - o, s.points[t[2]] - o));
  }
  return v / 6.0;
}
std::vector<NamedSurface> namedTestSurfaces()
{
  return {
    { "ball", icosphere({ 0.1, -0.2, 0.3 }, 1.0, 3) },
    { "box", subdividedBox({ 0, 0, 0 }, { 2, 1, 1 }, 6) },
    { "torus", torus({ 0, 0, 0 }, 2.0, 0.7, 40, 16) },
    { "boxWithCavity",
      merged(subdividedBox({ -2, -2, -2 }, { 2, 2, 2 }, 8), flipped(icosphere({ 0, 0, 0 }, 1.0, 3))) },
    { "twoBodies",
      merged(icosphere({ -2, 0, 0 }, 1.0, 3), subdividedBox({ 1, -1, -1 }, { 3, 1, 1 }, 6)) },
    // a CAD-like part from gmsh (OpenCASCADE booleans): planar faces on round
    // coordinates, a through hole, a slot, a boss
    { "bracket", readOffFile(PTM_DATA_DIR "/bracket.off").data.surface },
  };
}

std::size_t badDirectedEdges(const std::vector<Triangle>& triangles)
{
  std::map<DirectedEdge, int> directed;
  for (const Triangle& t : triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      ++directed[{ t[e], t[(e + 1) % 3] }];
    }
  }
  std::size_t bad = 0;
  for (const auto& [e, n] : directed)
  {
    auto reverse = directed.find({ e[1], e[0] });
    bad += (n != 1 || reverse == directed.end() || reverse->second != 1) ? 1 : 0;
  }
  return bad;
}

DecompositionOptions stageCaseOptions(int K, CutStrategy strategy)
{
  DecompositionOptions options;
  options.numberOfSubdomains = K;
  options.strategy = strategy;
  options.direction = strategy == CutStrategy::ParallelPlanes ? CutDirection::LongestExtent : CutDirection::Inertia;
  // the stages are tested, not the size policy: the coarse test surfaces'
  // slabs are under a quarter of their mean edge
  options.minimumSlabThickness = 0;
  return options;
}

DecompositionResult decomposeDataFile(const std::string& relativePath, int K)
{
  const OffReadResult file = readOffFile(std::string(PTM_DATA_DIR) + "/" + relativePath);
  if (!file.ok)
  {
    DecompositionResult failed;
    failed.error = file.error;
    return failed;
  }
  DecompositionOptions options;
  options.numberOfSubdomains = K;
  options.direction = CutDirection::Inertia; // as the cutter's default
  return decomposeVolumeBalanced(file.data.surface, options);
}

InterfaceFigures triangulateAllInterfaces(SurfaceComplex& c)
{
  InterfaceFigures figures;
  if (c.trianglePlanes.size() != c.triangles.size())
  {
    c.trianglePlanes.assign(c.triangles.size(), -1);
  }
  for (const InterfaceRegion& region : c.interfaces)
  {
    const std::vector<Index> points = regionPoints(region);
    const PlanarRegion planar = planarRegionOf(c, region, points);
    const InterfaceTriangulationResult r = triangulateInterface(planar, {});
    if (!r.ok)
    {
      figures.ok = false;
      figures.error = r.error;
      return figures;
    }
    figures.exceptions += r.triangulation.trianglesBelowMinimumAngle;
    figures.smallestAngle = std::min(figures.smallestAngle, r.triangulation.minimumAngleDegrees);
    figures.reportedAwayFromBoundary += r.triangulation.trianglesBelowMinimumAngleAwayFromBoundary;
    const Index boundaryCount = static_cast<Index>(planar.points.size());
    for (const Triangle& t : r.triangulation.triangles)
    {
      auto at = [&](Index i) {
        return i < boundaryCount ? planar.points[i] : r.triangulation.newPoints[i - boundaryCount];
      };
      const Vec3 a = at(t[0]), b = at(t[1]), d = at(t[2]);
      auto angle = [](const Vec3& p, const Vec3& q, const Vec3& w) {
        return std::atan2(norm(cross(q - p, w - p)), dot(q - p, w - p)) * 180 / kPi;
      };
      if (std::min({ angle(a, b, d), angle(b, d, a), angle(d, a, b) }) >= 20.7)
      {
        continue;
      }
      if (t[0] < boundaryCount || t[1] < boundaryCount || t[2] < boundaryCount)
      {
        continue; // touches the boundary
      }
      // circumcentre in 3D: a + (|u|^2 (v x w) + |v|^2 (w x u)) / (2 |w|^2), w = u x v
      const Vec3 u = b - a, v = d - a, w = cross(u, v);
      const Vec3 centre = a + (1.0 / (2.0 * dot(w, w))) * (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u));
      const double radius = norm(centre - a);
      bool reaches = false;
      for (const auto& e : planar.edges)
      {
        const Vec3 p = planar.points[e[0]], q = planar.points[e[1]];
        const double s = std::clamp(dot(centre - p, q - p) / dot(q - p, q - p), 0.0, 1.0);
        reaches = reaches || norm(centre - (p + s * (q - p))) < radius;
      }
      if (!reaches)
      {
        ++figures.awayFromBoundary;
      }
    }
    std::vector<Index> global = points;
    for (const Vec3& p : r.triangulation.newPoints)
    {
      global.push_back(static_cast<Index>(c.points.size()));
      c.points.push_back(p);
    }
    for (const Triangle& t : r.triangulation.triangles)
    {
      c.triangles.push_back({ global[t[0]], global[t[1]], global[t[2]] });
      c.trianglePairs.push_back(region.pair);
      c.sourceFaces.push_back(-1);
      c.trianglePlanes.push_back(region.planeId);
    }
  }
  c.interfaces.clear();
  return figures;
}
} // namespace ptm::test
