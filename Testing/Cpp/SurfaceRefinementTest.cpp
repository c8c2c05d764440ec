#include "SurfaceRefinement.h"
#include "TestSurfaces.h"
#include "TetGenSubdomainMesher.h"
#include "TetrahedronQuality.h"
#include "VolumeBalancedDecomposition.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace ptm;
using namespace ptm::test;

namespace
{
// A long thin bar as a CAD exporter writes it: every face two triangles, so
// the long faces are slivers (about 2.3 degrees at their sharp corners).
// With a raised centre (lift != 0), the top face is four triangles around a
// point lifted off it, as a file with 7 digits leaves a flat face nearly flat.
TriangleSurface thinBar(double lift = 0.0)
{
  TriangleSurface s;
  const double L = 1.0, W = 0.06, H = 0.04;
  for (int k = 0; k < 8; ++k)
  {
    s.points.push_back({ (k & 1) ? L : 0.0, (k & 2) ? W : 0.0, (k & 4) ? H : 0.0 });
  }
  const std::array<std::array<Index, 4>, 6> quads{ { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
    { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } } };
  for (std::size_t q = 0; q < quads.size(); ++q)
  {
    const auto& c = quads[q];
    if (q == 1 && lift != 0.0)
    {
      s.points.push_back({ L / 2, W / 2, H + lift });
      const Index m = 8;
      for (int k = 0; k < 4; ++k)
      {
        s.triangles.push_back({ c[k], c[(k + 1) % 4], m });
      }
      continue;
    }
    s.triangles.push_back({ c[0], c[1], c[2] });
    s.triangles.push_back({ c[0], c[2], c[3] });
  }
  return s;
}

// A cylinder of radius 1 and length `length` along z as an extrusion
// exporter writes it: `sides` long strips, each two triangles, and fans
// around the centres of its ends (outward).
TriangleSurface extrudedCircle(int sides, double length)
{
  TriangleSurface s;
  for (double z : { 0.0, length })
  {
    for (int i = 0; i < sides; ++i)
    {
      const double a = 2 * kPi * i / sides;
      s.points.push_back({ std::cos(a), std::sin(a), z });
    }
  }
  const Index bottom = static_cast<Index>(s.points.size()), top = bottom + 1;
  s.points.push_back({ 0, 0, 0 });
  s.points.push_back({ 0, 0, length });
  for (Index i = 0; i < sides; ++i)
  {
    const Index j = (i + 1) % sides;
    s.triangles.push_back({ i, j, sides + j });
    s.triangles.push_back({ i, sides + j, sides + i });
    s.triangles.push_back({ bottom, j, i });
    s.triangles.push_back({ top, sides + i, sides + j });
  }
  return s;
}

SubdomainSurface wholeSurface(const TriangleSurface& s)
{
  SubdomainSurface out;
  out.surface = s;
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    out.globalIds.push_back(static_cast<Index>(i));
  }
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    out.sourceFaces.push_back(static_cast<Index>(t));
    out.otherSide.push_back(-1);
  }
  return out;
}

bool closedAndConsistent(const TriangleSurface& s)
{
  std::map<std::pair<Index, Index>, int> edges;
  for (const Triangle& t : s.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++edges[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (const auto& [e, n] : edges)
  {
    auto back = edges.find({ e.second, e.first });
    if (n != 1 || back == edges.end() || back->second != 1)
    {
      return false;
    }
  }
  return true;
}

double smallestAngleDegrees(const TriangleSurface& s)
{
  double smallest = 180;
  for (const Triangle& t : s.triangles)
  {
    smallest = std::min(smallest,
      triangleMinimumAngle(s.points[t[0]], s.points[t[1]], s.points[t[2]]) * 180.0 / kPi);
  }
  return smallest;
}
} // namespace

TEST(SurfaceRefinement, SliverFacesBecomeQualityTrianglesOnTheSameSurface)
{
  const TriangleSurface box = thinBar();
  SubdomainSurface s = wholeSurface(box);
  ASSERT_LT(smallestAngleDegrees(s.surface), 3.0);
  SurfaceRefinementOptions options;
  options.size = 0.05;
  const SurfaceRefinementResult r = refineSubdomainSurface(s, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.facets, 6u);
  EXPECT_EQ(r.facetsMeshed, 6u);
  EXPECT_TRUE(closedAndConsistent(s.surface));
  // every input point kept, in its place; new points on the box's faces
  for (std::size_t i = 0; i < box.points.size(); ++i)
  {
    EXPECT_EQ(s.surface.points[i], box.points[i]);
  }
  for (const Vec3& p : s.surface.points)
  {
    const double d = std::min({ std::fabs(p[0]), std::fabs(p[0] - 1.0), std::fabs(p[1]), std::fabs(p[1] - 0.06),
      std::fabs(p[2]), std::fabs(p[2] - 0.04) });
    EXPECT_LT(d, 1e-15);
  }
  EXPECT_NEAR(signedVolume(s.surface), 0.0024, 1e-15);
  EXPECT_NEAR(r.volumeChange, 0.0, 1e-15);
  // the slivers are gone: the long edges are split at about the faces'
  // width (a corner across a long edge is that near) and the faces meshed
  // with the bound
  EXPECT_GT(smallestAngleDegrees(s.surface), 20.0);
  EXPECT_GT(r.minimumAngleAfter, r.minimumAngleBefore);
  std::set<Index> sources(s.sourceFaces.begin(), s.sourceFaces.end());
  EXPECT_EQ(sources.size(), 12u); // new triangles name the input triangle under them
  EXPECT_EQ(sources.count(-1), 0u);
}

TEST(SurfaceRefinement, TetrahedraNextToTheBoundaryImprove)
{
  const TriangleSurface box = thinBar();
  TetMeshingOptions tet;
  tet.maximumVolume = 0.05 * 0.05 * 0.05 / (6.0 * std::sqrt(2.0));
  const TetMeshingResult before = meshClosedSurface(box, tet);
  ASSERT_TRUE(before.ok) << before.error;
  SubdomainSurface s = wholeSurface(box);
  SurfaceRefinementOptions options;
  options.size = 0.05;
  ASSERT_TRUE(refineSubdomainSurface(s, options).ok);
  const TetMeshingResult after = meshClosedSurface(s.surface, tet);
  ASSERT_TRUE(after.ok) << after.error;
  const DihedralQuality q0 = dihedralQuality(before.mesh), q1 = dihedralQuality(after.mesh);
  const double share0 = static_cast<double>(q0.below10Degrees) / q0.tetrahedra;
  const double share1 = static_cast<double>(q1.below10Degrees) / q1.tetrahedra;
  EXPECT_GT(share0, 0.0);
  EXPECT_LT(share1, 0.1 * share0) << "under 10 degrees: " << q0.below10Degrees << " of " << q0.tetrahedra
                                  << " before, " << q1.below10Degrees << " of " << q1.tetrahedra << " after";
  EXPECT_GT(q1.minimumDihedralDegrees, q0.minimumDihedralDegrees);
}

// On every decomposition case, the refined subdomain surfaces keep their
// interface triangles and volumes, stay closed, and neighbours still match:
// the contour edges are never split.
TEST(SurfaceRefinement, SubdomainsStayCompatible)
{
  for (const NamedSurface& named : namedTestSurfaces())
  {
    for (CutStrategy strategy : { CutStrategy::RecursiveBisection, CutStrategy::ParallelPlanes })
    {
      DecompositionResult d = decomposeVolumeBalanced(named.surface, stageCaseOptions(4, strategy));
      ASSERT_TRUE(d.ok) << named.name << ": " << d.error;
      ASSERT_TRUE(triangulateAllInterfaces(d.complex).ok);
      for (int sub = 0; sub < d.complex.subdomainCount; ++sub)
      {
        SubdomainSurface s;
        std::string error;
        ASSERT_TRUE(extractSubdomainSurface(d.complex, {}, sub, s, error)) << error;
        const double volume = signedVolume(s.surface);
        std::multiset<std::array<Index, 3>> interfaceBefore, interfaceAfter;
        for (std::size_t t = 0; t < s.surface.triangles.size(); ++t)
        {
          if (s.otherSide[t] >= 0)
          {
            interfaceBefore.insert(s.surface.triangles[t]);
          }
        }
        SurfaceRefinementOptions options;
        options.size = 0.1;
        SubdomainSurface again = s;
        const SurfaceRefinementResult r = refineSubdomainSurface(s, options);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_TRUE(r.warnings.empty()) << named.name << ": " << r.warnings.front();
        ASSERT_TRUE(closedAndConsistent(s.surface)) << named.name << " subdomain " << sub;
        EXPECT_NEAR(signedVolume(s.surface), volume, 1e-12 * std::fabs(volume)) << named.name;
        for (std::size_t t = 0; t < s.surface.triangles.size(); ++t)
        {
          if (s.otherSide[t] >= 0)
          {
            interfaceAfter.insert(s.surface.triangles[t]);
          }
        }
        EXPECT_EQ(interfaceBefore, interfaceAfter) << named.name << " subdomain " << sub;
        // deterministic: the same input gives the same output
        ASSERT_TRUE(refineSubdomainSurface(again, options).ok);
        EXPECT_EQ(again.surface.points, s.surface.points);
        EXPECT_EQ(again.surface.triangles, s.surface.triangles);
      }
    }
  }
}

TEST(SurfaceRefinement, CoplanarToleranceMergesNearlyFlatFacesAndReportsTheChange)
{
  const TriangleSurface bar = thinBar(1e-7);
  SurfaceRefinementOptions options;
  options.size = 0.05;
  SubdomainSurface exact = wholeSurface(bar);
  const SurfaceRefinementResult r0 = refineSubdomainSurface(exact, options);
  ASSERT_TRUE(r0.ok);
  EXPECT_EQ(r0.facets, 9u); // the raised top face is four facets
  EXPECT_EQ(r0.largestDeviation, 0.0);
  EXPECT_NEAR(signedVolume(exact.surface), signedVolume(bar), 1e-15);
  options.coplanarToleranceDegrees = 0.01;
  SubdomainSurface merged = wholeSurface(bar);
  const SurfaceRefinementResult r1 = refineSubdomainSurface(merged, options);
  ASSERT_TRUE(r1.ok);
  EXPECT_EQ(r1.facets, 6u);
  EXPECT_GT(r1.largestDeviation, 0.0);
  EXPECT_LE(r1.largestDeviation, 1e-7);
  EXPECT_NEAR(r1.volumeChange, signedVolume(merged.surface) - signedVolume(bar), 1e-15);
  EXPECT_TRUE(closedAndConsistent(merged.surface));
}

// A bar 0.06 x 0.04 thin at the size 1: beside its long thin faces the
// long edges are split no finer than the floor, an eighth of the size by
// default, so the strips keep thin triangles; a floor of 1/64 lets them be
// split at the bar's own width (BoundarySpacingFloor).
TEST(SurfaceRefinement, ALowerSpacingFloorFollowsAThinStrip)
{
  SurfaceRefinementOptions options;
  options.size = 1.0;
  SubdomainSurface coarse = wholeSurface(thinBar());
  const SurfaceRefinementResult byDefault = refineSubdomainSurface(coarse, options);
  ASSERT_TRUE(byDefault.ok) << byDefault.error;
  options.segmentSpacingFloor = 1.0 / 64;
  SubdomainSurface fine = wholeSurface(thinBar());
  const SurfaceRefinementResult lower = refineSubdomainSurface(fine, options);
  ASSERT_TRUE(lower.ok) << lower.error;
  EXPECT_TRUE(closedAndConsistent(fine.surface));
  EXPECT_NEAR(signedVolume(fine.surface), 0.0024, 1e-15);
  EXPECT_GT(lower.pointsAdded, 2 * byDefault.pointsAdded);
  EXPECT_LT(smallestAngleDegrees(coarse.surface), 20.0);
  EXPECT_GT(smallestAngleDegrees(fine.surface), 20.0);
}

TEST(SurfaceRefinement, ASurfaceOfStripsFarFinerThanTheSizeIsLeftAsItIs)
{
  // 1,000 strips 0.0063 wide and 20 long: split at an eighth of the size
  // they would get 159 points each, about 50 x the tetrahedra the size
  // predicts (the pattern of OpenFOAM's NACA0012 wing, where TetGen then
  // stalled); 100 strips 0.063 wide stay under the bound and are refined
  SurfaceRefinementOptions options;
  options.size = 1.0;
  SubdomainSurface many = wholeSurface(extrudedCircle(1000, 20.0));
  const TriangleSurface before = many.surface;
  const SurfaceRefinementResult skipped = refineSubdomainSurface(many, options);
  ASSERT_TRUE(skipped.ok) << skipped.error;
  EXPECT_EQ(skipped.pointsAdded, 0u);
  ASSERT_EQ(skipped.warnings.size(), 1u);
  EXPECT_NE(skipped.warnings[0].find("boundary refinement skipped: it would put"), std::string::npos)
    << skipped.warnings[0];
  EXPECT_EQ(many.surface.points, before.points);
  EXPECT_EQ(many.surface.triangles, before.triangles);

  SubdomainSurface few = wholeSurface(extrudedCircle(100, 20.0));
  const SurfaceRefinementResult refined = refineSubdomainSurface(few, options);
  ASSERT_TRUE(refined.ok) << refined.error;
  EXPECT_TRUE(refined.warnings.empty());
  EXPECT_GT(refined.pointsAdded, 10000u);
  EXPECT_TRUE(closedAndConsistent(few.surface));
}

TEST(SurfaceRefinement, RefusesNonsenseOptions)
{
  SubdomainSurface s = wholeSurface(thinBar());
  SurfaceRefinementOptions options;
  options.size = 0.0;
  EXPECT_FALSE(refineSubdomainSurface(s, options).ok);
  options.size = 0.1;
  options.minimumAngleDegrees = 40;
  const SurfaceRefinementResult r = refineSubdomainSurface(s, options);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("minimum angle"), std::string::npos);
  options.minimumAngleDegrees = 20;
  options.segmentSpacingFloor = 0.0;
  const SurfaceRefinementResult noFloor = refineSubdomainSurface(s, options);
  EXPECT_FALSE(noFloor.ok);
  EXPECT_NE(noFloor.error.find("segment spacing floor"), std::string::npos);
}
