#include "SurfaceOrientation.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

using namespace ptm;
using namespace ptm::test;

TEST(SurfaceOrientation, MergesDuplicatePointsOfAnStlLikeSoup)
{
  const TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  TriangleSurface soup;
  for (const auto& t : box.triangles)
  {
    const Index base = static_cast<Index>(soup.points.size());
    for (Index v : t)
    {
      soup.points.push_back(box.points[v]);
    }
    soup.triangles.push_back({ base, base + 1, base + 2 });
  }
  std::size_t dropped = 0;
  std::vector<Index> source;
  const std::size_t merged = mergeDuplicatePoints(soup, dropped, source);
  EXPECT_EQ(soup.points.size(), box.points.size());
  EXPECT_EQ(merged, 3 * box.triangles.size() - box.points.size());
  EXPECT_EQ(dropped, 0u);
  ASSERT_EQ(source.size(), box.triangles.size());
  EXPECT_EQ(source.back(), static_cast<Index>(box.triangles.size() - 1));
}

TEST(SurfaceOrientation, RepairsFlippedTrianglesAndInsideOutShell)
{
  TriangleSurface ball = flipped(icosphere({ 0, 0, 0 }, 1.0, 2));
  std::swap(ball.triangles[5][1], ball.triangles[5][2]);   // one triangle now disagrees
  std::swap(ball.triangles[77][0], ball.triangles[77][1]); // another one
  const double expected = -signedVolume(flipped(icosphere({ 0, 0, 0 }, 1.0, 2)));
  OrientationResult r = orientShells(ball);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.report.shellCount, 1u);
  EXPECT_EQ(r.report.invertedShells, 1u);
  EXPECT_GT(r.report.reorientedTriangles, 0u);
  EXPECT_NEAR(signedVolume(ball), expected, 1e-12);
  EXPECT_GT(signedVolume(ball), 0);
}

// An inside-out file turned back must be the outward file exactly, corner
// order included: the cutter's thickness rays start from the corners in
// order, and on Cura's BIQU bed a rotated corner order moved a cut by
// rounding and made TetGen split a shared triangle (session 24).
TEST(SurfaceOrientation, TurnsAnInsideOutShellBackToTheSameTriangles)
{
  const TriangleSurface outward = icosphere({ 0, 0, 0 }, 1.0, 2);
  TriangleSurface insideOut = outward;
  for (auto& t : insideOut.triangles)
  {
    std::swap(t[0], t[2]);
  }
  OrientationResult r = orientShells(insideOut);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.report.invertedShells, 1u);
  EXPECT_EQ(insideOut.triangles, outward.triangles);
}

TEST(SurfaceOrientation, CavityPointsIntoTheHole)
{
  // both shells given outward: the inner one must be turned into a cavity
  TriangleSurface s =
    merged(subdividedBox({ -2, -2, -2 }, { 2, 2, 2 }, 3), icosphere({ 0, 0, 0 }, 1.0, 2));
  const double box = 64.0;
  const double ball = signedVolume(icosphere({ 0, 0, 0 }, 1.0, 2));
  OrientationResult r = orientShells(s);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.report.shellCount, 2u);
  EXPECT_EQ(r.report.cavityCount, 1u);
  EXPECT_EQ(r.report.invertedShells, 1u);
  EXPECT_NEAR(signedVolume(s), box - ball, 1e-9);
}

TEST(SurfaceOrientation, RejectsOpenAndNonManifoldSurfaces)
{
  TriangleSurface open = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  open.triangles.pop_back();
  OrientationResult r = orientShells(open);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("3 boundary edges"), std::string::npos) << r.error;

  // two boxes sharing an edge through merged points -> 4 triangles on that edge
  TriangleSurface a = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 1);
  TriangleSurface b = subdividedBox({ 1, 1, 0 }, { 2, 2, 1 }, 1);
  TriangleSurface both = merged(a, b);
  std::size_t dropped = 0;
  std::vector<Index> source;
  mergeDuplicatePoints(both, dropped, source);
  r = orientShells(both);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("non-manifold"), std::string::npos) << r.error;
}

TEST(SurfaceOrientation, WindingNumberInsideAndOutside)
{
  const TriangleSurface ball = icosphere({ 0, 0, 0 }, 1.0, 2);
  std::vector<Index> all(ball.triangles.size());
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    all[i] = static_cast<Index>(i);
  }
  EXPECT_NEAR(windingNumber(ball, all, { 0.1, 0.2, 0.3 }), 1.0, 1e-9);
  EXPECT_NEAR(windingNumber(ball, all, { 3, 0, 0 }), 0.0, 1e-9);
}
