// Stages 1 and 2 together (issue: InterfaceTriangulator): for every test
// surface, K and strategy, triangulating every interface region of the
// decomposition gives each subdomain a closed, edge-manifold, outward surface
// that does not cross itself and whose volumes add up to the input volume;
// interface triangles under the minimum angle are counted.
#include "InterfaceTriangulation.h"
#include "SelfIntersectionCheck.h"
#include "TestSurfaces.h"
#include "VolumeBalancedDecomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

using namespace ptm;
using namespace ptm::test;

namespace
{
// Replaces every interface region by its triangles, like the filter does.
void triangulateAll(SurfaceComplex& c, std::size_t& exceptions, std::size_t& interiorExceptions,
  double& smallestAngle)
{
  exceptions = 0;
  interiorExceptions = 0;
  smallestAngle = 180;
  for (const InterfaceRegion& region : c.interfaces)
  {
    std::vector<Index> points;
    for (const auto& e : region.edges)
    {
      points.push_back(e[0]);
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    std::map<Index, Index> local;
    PlanarRegion planar;
    planar.origin = c.planes[region.planeId].origin;
    planar.normal = c.planes[region.planeId].normal;
    for (Index p : points)
    {
      local[p] = static_cast<Index>(planar.points.size());
      planar.points.push_back(c.points[p]);
    }
    for (const auto& e : region.edges)
    {
      planar.edges.push_back({ local[e[0]], local[e[1]] });
    }
    const InterfaceTriangulationResult r = triangulateInterface(planar, {});
    ASSERT_TRUE(r.ok) << r.error;
    exceptions += r.triangulation.trianglesBelowMinimumAngle;
    smallestAngle = std::min(smallestAngle, r.triangulation.minimumAngleDegrees);
    // exceptions are counted; record how many do not touch the boundary
    const Index boundaryCount = static_cast<Index>(planar.points.size());
    for (const Triangle& t : r.triangulation.triangles)
    {
      auto at = [&](Index i) { return i < boundaryCount ? planar.points[i] : r.triangulation.newPoints[i - boundaryCount]; };
      const Vec3 a = at(t[0]), b = at(t[1]), d = at(t[2]);
      auto angle = [](const Vec3& p, const Vec3& q, const Vec3& w) {
        return std::atan2(norm(cross(q - p, w - p)), dot(q - p, w - p)) * 180 / kPi;
      };
      if (std::min({ angle(a, b, d), angle(b, d, a), angle(d, a, b) }) < 20.7 &&
        t[0] >= boundaryCount && t[1] >= boundaryCount && t[2] >= boundaryCount)
      {
        ++interiorExceptions;
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
    }
  }
  c.interfaces.clear();
}
} // namespace

class CompatibleSubdomainSurfaces : public ::testing::TestWithParam<std::tuple<int, CutStrategy>>
{
};

TEST_P(CompatibleSubdomainSurfaces, ClosedManifoldOutwardAndVolumesAddUp)
{
  const auto [K, strategy] = GetParam();
  for (const NamedSurface& k : namedTestSurfaces())
  {
    std::ostringstream label;
    label << k.name << " K=" << K << " " << toString(strategy);
    DecompositionOptions options;
    options.numberOfSubdomains = K;
    options.strategy = strategy;
    options.direction = strategy == CutStrategy::ParallelPlanes ? CutDirection::LongestExtent : CutDirection::Inertia;
    DecompositionResult d = decomposeVolumeBalanced(k.surface, options);
    ASSERT_TRUE(d.ok) << label.str() << ": " << d.error;
    SurfaceComplex c = d.complex;
    std::size_t exceptions = 0, interior = 0;
    double smallest = 0;
    triangulateAll(c, exceptions, interior, smallest);
    double total = 0;
    for (int s = 0; s < K; ++s)
    {
      const std::vector<Triangle> surface = subdomainTriangles(c, s);
      std::map<DirectedEdge, int> directed;
      for (const Triangle& t : surface)
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
      EXPECT_EQ(bad, 0u) << label.str() << ": subdomain " << s << " not closed or not edge-manifold";
      TriangleSurface closed{ c.points, surface };
      // TetGen can only mesh it if it does not cross itself (exact predicates)
      const SelfIntersectionReport crossing = checkSelfIntersection(closed);
      EXPECT_TRUE(crossing.checked) << label.str() << ": " << crossing.note;
      EXPECT_FALSE(crossing.intersects) << label.str() << ": subdomain " << s << " crosses itself";
      const double v = signedVolume(closed);
      EXPECT_GT(v, 0) << label.str() << ": subdomain " << s;
      total += v;
    }
    EXPECT_NEAR(total / d.totalVolume, 1.0, 1e-9) << label.str();
    EXPECT_GT(smallest, 0.0) << label.str();
    if (exceptions > 0)
    {
      std::cout << "[ figure ] " << label.str() << ": " << exceptions
                << " interface triangles under 20.7 degrees (" << interior
                << " of them not touching the boundary), smallest " << smallest << " degrees\n";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(KAndStrategy, CompatibleSubdomainSurfaces,
  ::testing::Combine(::testing::Values(2, 3, 4, 7, 8),
    ::testing::Values(CutStrategy::ParallelPlanes, CutStrategy::RecursiveBisection)),
  [](const auto& info) {
    return std::string(toString(std::get<1>(info.param))) + "_K" + std::to_string(std::get<0>(info.param));
  });
