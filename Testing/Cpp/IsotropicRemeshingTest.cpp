// CGAL isotropic remeshing of CAD-like input (the explicit mode that moves
// the surface): the needles go, the sharp edges and corners stay, and the
// change is measured, reported and bounded.
#include "IsotropicRemeshing.h"
#include "SurfaceInputCheck.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
using namespace ptm;

// A cylinder tessellated as CAD exports do: the wall split into one long
// rectangle per facet with one diagonal each, and each cap a fan from one
// rim point (needles as thin as 1/n of the rim).
TriangleSurface cadCylinder(double radius, double height, int n)
{
  TriangleSurface s;
  for (int z = 0; z < 2; ++z)
  {
    for (int i = 0; i < n; ++i)
    {
      const double a = 2 * kPi * i / n;
      s.points.push_back({ radius * std::cos(a), radius * std::sin(a), z * height });
    }
  }
  for (int i = 0; i < n; ++i)
  {
    const Index j = (i + 1) % n;
    s.triangles.push_back({ i, j, n + j });
    s.triangles.push_back({ i, n + j, n + i });
  }
  for (Index i = 1; i + 1 < n; ++i)
  {
    s.triangles.push_back({ 0, i + 1, i });         // bottom, facing -z
    s.triangles.push_back({ n, n + i, n + i + 1 }); // top, facing +z
  }
  return s;
}

// 3e4 grid samples per surface instead of 4e5: enough for these small
// surfaces, and the cylinder's needles make every sample slow
RemeshOptions testOptions()
{
  RemeshOptions options;
  options.distanceSamples = 3e4;
  return options;
}

double smallestAngleDegrees(const TriangleSurface& s)
{
  double smallest = 180;
  for (const Triangle& t : s.triangles)
  {
    smallest = std::min(smallest, triangleMinimumAngle(s.points[t[0]], s.points[t[1]], s.points[t[2]]) * 180.0 / kPi);
  }
  return smallest;
}

TEST(IsotropicRemeshing, CADCylinderLosesItsNeedlesAndKeepsItsRims)
{
  const TriangleSurface input = cadCylinder(1.0, 3.0, 48);
  ASSERT_LT(smallestAngleDegrees(input), 4.0) << "the input has needles";
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.25;
  options.maximumDeviation = 0.01;
  const RemeshResult r = remeshSurface(input, options);
  ASSERT_TRUE(r.ok) << r.error;
  std::printf("cylinder: %zu -> %zu triangles, smallest angle %.1f -> %.1f degrees, %zu feature edges, %zu "
              "corners, distances %.2e / %.2e (spacing %.2e), volume change %.2e, %.2f + %.2f s\n",
    input.triangles.size(), r.surface.triangles.size(), smallestAngleDegrees(input),
    smallestAngleDegrees(r.surface), r.featureEdges, r.corners, r.remeshToInput, r.inputToRemesh, r.sampleSpacing,
    r.volumeChange, r.remeshSeconds, r.distanceSeconds);
  EXPECT_EQ(r.featureEdges, 96u) << "the two rims";
  EXPECT_EQ(r.corners, 0u) << "the rims turn by 7.5 degrees at each point: no corner";
  EXPECT_GT(smallestAngleDegrees(r.surface), 20.0);
  const PreparedSurface checked = prepareInputSurface(r.surface, InputCheckOptions());
  ASSERT_TRUE(checked.ok) << checked.error;
  EXPECT_EQ(checked.orientation.invertedShells, 0u) << "oriented like the input";
  // new points lie on the input (projected), so only chords across the
  // facets and the rims move it: far less than an edge
  EXPECT_LT(std::max(r.remeshToInput, r.inputToRemesh), 0.01 * r.boundingBoxDiagonal);
  EXPECT_LT(std::fabs(r.volumeChange), 1e-2);
  EXPECT_NEAR(checked.enclosedVolume, test::signedVolume(input) * (1 + r.volumeChange), 1e-9);
  // the rims survive: every remeshed point at z = 0 or 3 lies within the
  // rim polygon's distance of the circle
  std::size_t onRims = 0;
  for (const Vec3& p : r.surface.points)
  {
    if (p[2] == 0.0 || p[2] == 3.0)
    {
      const double rho = std::hypot(p[0], p[1]);
      onRims += rho > std::cos(kPi / 48) - 1e-9 ? 1 : 0;
    }
  }
  EXPECT_GE(onRims, 2u * static_cast<std::size_t>(2 * kPi / 0.25 * 0.7));
}

TEST(IsotropicRemeshing, BoxKeepsCornersAndVolumeExactly)
{
  const TriangleSurface box = test::subdividedBox({ 0, 0, 0 }, { 2, 1, 1 }, 3);
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.1;
  const RemeshResult r = remeshSurface(box, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.corners, 8u);
  EXPECT_NEAR(r.volumeChange, 0.0, 1e-12) << "planar faces and straight edges: nothing moves off them";
  EXPECT_LT(r.remeshToInput, 1e-12);
  for (const Vec3& corner : { Vec3{ 0, 0, 0 }, Vec3{ 2, 1, 1 }, Vec3{ 2, 0, 1 } })
  {
    EXPECT_NE(std::find(r.surface.points.begin(), r.surface.points.end(), corner), r.surface.points.end());
  }
  EXPECT_GT(smallestAngleDegrees(r.surface), 25.0);
}

TEST(IsotropicRemeshing, FaceLabelsSurviveWithTheirBorders)
{
  // two labels meeting along x = 0.5, across flat faces: the border stays a
  // line of edges and every new triangle keeps the label of its side
  const TriangleSurface box = test::subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4);
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.07;
  for (const Triangle& t : box.triangles)
  {
    const Vec3 c = (1.0 / 3.0) * (box.points[t[0]] + box.points[t[1]] + box.points[t[2]]);
    options.faceLabels.push_back(c[0] < 0.5 ? 0 : 1);
  }
  const RemeshResult r = remeshSurface(box, options);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.faceLabels.size(), r.surface.triangles.size());
  std::size_t wrong = 0, ones = 0;
  for (std::size_t i = 0; i < r.surface.triangles.size(); ++i)
  {
    const Triangle& t = r.surface.triangles[i];
    const Vec3 c = (1.0 / 3.0) * (r.surface.points[t[0]] + r.surface.points[t[1]] + r.surface.points[t[2]]);
    wrong += r.faceLabels[i] != (c[0] < 0.5 ? 0 : 1) ? 1 : 0;
    ones += r.faceLabels[i] == 1 ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(ones, r.surface.triangles.size() / 3);
  EXPECT_GT(r.surface.triangles.size(), 10 * box.triangles.size());

  options.faceLabels.pop_back();
  const RemeshResult refused = remeshSurface(box, options);
  ASSERT_FALSE(refused.ok);
  EXPECT_NE(refused.error.find("face labels"), std::string::npos) << refused.error;
}

TEST(IsotropicRemeshing, DeviationBeyondTheBoundFailsWithTheFigures)
{
  // a coarse sphere remeshed at a third of its radius moves by about the
  // sagitta of those edges
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.3;
  options.maximumDeviation = 1e-4;
  options.halvings = 0;
  const RemeshResult r = remeshSurface(test::icosphere({ 0, 0, 0 }, 1.0, 2), options);
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.attempts, 1);
  EXPECT_NE(r.error.find("MaximumDeviation 0.0001"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("smaller target edge length"), std::string::npos) << r.error;
  EXPECT_GT(r.inputToRemesh, 0.0) << "the figures are still reported";
}

TEST(IsotropicRemeshing, TooFarMeansAgainAtHalfTheEdgeLength)
{
  // the cylinder at edge 0.25 strays about 0.012 (the first test); a bound
  // of 0.006 / diagonal is met only at a quarter of that
  const TriangleSurface input = cadCylinder(1.0, 3.0, 48);
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.25;
  options.maximumDeviation = 0.006 / boundingBoxDiagonal(input.points);
  const RemeshResult r = remeshSurface(input, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.attempts, 1);
  EXPECT_EQ(r.targetEdgeLength, 0.25 / (1 << (r.attempts - 1)));
  EXPECT_LE(std::max(r.remeshToInput, r.inputToRemesh), 0.006);

  options.halvings = 0;
  const RemeshResult once = remeshSurface(input, options);
  ASSERT_FALSE(once.ok);
  EXPECT_EQ(once.attempts, 1);
}

TEST(IsotropicRemeshing, VolumeChangeIsBoundedToo)
{
  // the cylinder at edge 0.25 loses 0.7 % of its volume (the first test)
  const TriangleSurface input = cadCylinder(1.0, 3.0, 48);
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.25;
  options.maximumVolumeChange = 2e-3;
  options.halvings = 0;
  const RemeshResult once = remeshSurface(input, options);
  ASSERT_FALSE(once.ok);
  EXPECT_NE(once.error.find("MaximumVolumeChange 0.002"), std::string::npos) << once.error;
  EXPECT_LT(once.volumeChange, -2e-3);

  options.halvings = 3;
  const RemeshResult r = remeshSurface(input, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.attempts, 1);
  EXPECT_LE(std::fabs(r.volumeChange), 2e-3);
}

TEST(IsotropicRemeshing, OpenOrInvalidInputIsRefusedByName)
{
  TriangleSurface open = test::subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  open.triangles.pop_back();
  RemeshOptions options = testOptions();
  options.targetEdgeLength = 0.2;
  RemeshResult r = remeshSurface(open, options);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("open"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("AlphaWrap"), std::string::npos) << r.error;

  options.targetEdgeLength = -1;
  r = remeshSurface(test::icosphere({ 0, 0, 0 }, 1.0, 1), options);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("target edge length must be 0 (automatic) or positive"), std::string::npos) << r.error;
}
} // namespace
