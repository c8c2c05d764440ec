#include "GlobalMeshNumbering.h"
#include "SubdomainSurface.h"
#include "TestSurfaces.h"
#include "VolumeBalancedDecomposition.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace ptm;
using namespace ptm::test;

namespace
{
// Cube cut at x = 0.5; the square interface is filled with a fan around a
// new centre point, so that both halves are closed triangle surfaces.
SurfaceComplex halvedCube()
{
  DecompositionOptions options;
  options.numberOfSubdomains = 2;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::X;
  DecompositionResult r = decomposeVolumeBalanced(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4), options);
  EXPECT_TRUE(r.ok) << r.error;
  SurfaceComplex c = r.complex;
  const InterfaceRegion region = c.interfaces.at(0);
  c.points.push_back({ 0.5, 0.5, 0.5 });
  const Index centre = static_cast<Index>(c.points.size() - 1);
  for (const auto& e : region.edges)
  {
    c.triangles.push_back({ e[0], e[1], centre });
    c.trianglePairs.push_back(region.pair);
    c.sourceFaces.push_back(-1);
  }
  c.interfaces.clear();
  return c;
}
} // namespace

TEST(SubdomainSurface, ClosedOutwardAndCanonical)
{
  const SurfaceComplex c = halvedCube();
  double total = 0;
  for (int s = 0; s < 2; ++s)
  {
    SubdomainSurface out;
    std::string error;
    ASSERT_TRUE(extractSubdomainSurface(c, {}, s, out, error)) << error;
    EXPECT_NEAR(signedVolume(out.surface), 0.5, 1e-12);
    total += signedVolume(out.surface);
    EXPECT_TRUE(std::is_sorted(out.globalIds.begin(), out.globalIds.end()));
    std::size_t interfaceTriangles = 0;
    for (std::size_t i = 0; i < out.sourceFaces.size(); ++i)
    {
      interfaceTriangles += out.sourceFaces[i] < 0 ? 1 : 0;
      EXPECT_EQ(out.otherSide[i] >= 0, out.sourceFaces[i] < 0);
    }
    EXPECT_EQ(interfaceTriangles, 16u);
  }
  EXPECT_NEAR(total, 1.0, 1e-12);

  // the same subdomain from a permuted piece with other local indices
  SurfaceComplex shuffled = c;
  std::reverse(shuffled.triangles.begin(), shuffled.triangles.end());
  std::reverse(shuffled.trianglePairs.begin(), shuffled.trianglePairs.end());
  std::reverse(shuffled.sourceFaces.begin(), shuffled.sourceFaces.end());
  SubdomainSurface a, b;
  std::string error;
  ASSERT_TRUE(extractSubdomainSurface(c, {}, 1, a, error));
  ASSERT_TRUE(extractSubdomainSurface(shuffled, {}, 1, b, error));
  EXPECT_EQ(a.surface.points, b.surface.points);
  EXPECT_EQ(a.surface.triangles, b.surface.triangles);
  EXPECT_EQ(a.globalIds, b.globalIds);
}

TEST(SubdomainSurface, RefusesLoopsAndOpenSurfaces)
{
  DecompositionOptions options;
  options.numberOfSubdomains = 2;
  DecompositionResult r = decomposeVolumeBalanced(icosphere({ 0, 0, 0 }, 1, 2), options);
  ASSERT_TRUE(r.ok);
  SubdomainSurface out;
  std::string error;
  EXPECT_FALSE(extractSubdomainSurface(r.complex, {}, 0, out, error));
  EXPECT_NE(error.find("InterfaceTriangulator"), std::string::npos) << error;

  SurfaceComplex c = halvedCube();
  c.triangles.pop_back();
  c.trianglePairs.pop_back();
  c.sourceFaces.pop_back();
  EXPECT_FALSE(extractSubdomainSurface(c, {}, 0, out, error));
  EXPECT_NE(error.find("not closed"), std::string::npos) << error;
  EXPECT_FALSE(extractSubdomainSurface(c, {}, 5, out, error));
}

TEST(GlobalMeshNumbering, OffsetsFollowSubdomainOrder)
{
  const GlobalMeshOffsets o = globalMeshOffsets(100, { 5, 0, 7 }, { 10, 3, 20 });
  EXPECT_EQ(o.firstInteriorPoint, (std::vector<long long>{ 100, 105, 105 }));
  EXPECT_EQ(o.firstTetrahedron, (std::vector<long long>{ 0, 10, 13 }));
  EXPECT_EQ(o.pointCount, 112);
  EXPECT_EQ(o.tetrahedronCount, 33);
  EXPECT_EQ(owningRank(2, { 0, 0, 1 }), 1);
  EXPECT_EQ(owningRank(-1, { 0 }), -1);
}
