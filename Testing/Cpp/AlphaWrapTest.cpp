// CGAL alpha wrapping of surfaces the input check refuses: the wrap must pass
// the same check, and the reported distances must match the geometry.
#include "AlphaWrap.h"
#include "SurfaceInputCheck.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
using namespace ptm;

TEST(AlphaWrap, OverlappingSpheresBecomeOneClosedSurface)
{
  // two unit spheres whose centres are about 1 apart (off axis, so that no
  // vertex of one lands on the other): their caps inside each other cross
  const TriangleSurface input =
    test::merged(test::icosphere({ 0, 0, 0 }, 1.0, 3), test::icosphere({ 1, 0.013, 0.007 }, 1.0, 3));
  const PreparedSurface refused = prepareInputSurface(input, InputCheckOptions());
  ASSERT_FALSE(refused.ok);
  EXPECT_NE(refused.error.find("intersects itself"), std::string::npos) << refused.error;
  EXPECT_NE(refused.error.find("--wrap"), std::string::npos) << refused.error;

  const AlphaWrapResult wrap = alphaWrapSurface(input, AlphaWrapOptions());
  ASSERT_TRUE(wrap.ok) << wrap.error;
  std::printf("spheres: %zu triangles, wrap %.2f s, distances %.2f s\n", wrap.surface.triangles.size(),
    wrap.wrapSeconds, wrap.distanceSeconds);
  const PreparedSurface accepted = prepareInputSurface(wrap.surface, InputCheckOptions());
  ASSERT_TRUE(accepted.ok) << accepted.error;
  EXPECT_EQ(accepted.orientation.invertedShells, 0u) << "the wrap comes out oriented outward";
  EXPECT_EQ(accepted.orientation.shellVolume.size(), 1u) << "one shell around both spheres";

  const double diagonal = boundingBoxDiagonal(input.points);
  EXPECT_NEAR(wrap.alpha, diagonal / 100, 1e-12 * diagonal);
  EXPECT_NEAR(wrap.offset, diagonal / 3000, 1e-12 * diagonal);
  // the wrap hugs the outer surface at the offset, and bridges the concave
  // crease where the spheres meet, which is narrower than alpha
  EXPECT_GT(wrap.wrapToInput, 0.5 * wrap.offset);
  EXPECT_LT(wrap.wrapToInput, wrap.alpha);
  // the inner caps are swallowed: the deepest point of each, near the other
  // sphere's centre, lies about 1 inside the union
  EXPECT_GT(wrap.inputToWrap, 0.9);
  EXPECT_LT(wrap.inputToWrap, 1.02);
  // the union's volume: two unit balls minus their lens (5 pi / 12)
  const double union_ = 2 * 4.0 / 3.0 * kPi - 5.0 * kPi / 12.0;
  EXPECT_NEAR(accepted.enclosedVolume, union_, 0.03 * union_);
}

TEST(AlphaWrap, OpenBoxWithAWideHoleIsAHollowSkin)
{
  TriangleSurface box = test::subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4);
  box.triangles.erase(box.triangles.begin(), box.triangles.begin() + 3);
  const PreparedSurface refused = prepareInputSurface(box, InputCheckOptions());
  ASSERT_FALSE(refused.ok);
  EXPECT_NE(refused.error.find("open"), std::string::npos) << refused.error;
  EXPECT_NE(refused.error.find("--wrap"), std::string::npos) << refused.error;

  // alpha 0.087 (not the default 0.017: wrapping both sides of every wall
  // at that resolution makes 300,000 triangles in 20 s)
  AlphaWrapOptions options;
  options.relativeAlpha = 0.05;
  options.relativeOffset = 0.005;
  // the missing triangles leave a hole of 0.25 x 0.25, wider than alpha: the
  // wrap goes in through it and wraps the box's walls from both sides, a
  // skin, which is refused by default, naming its thickness and the way out
  const AlphaWrapResult refusedSkin = alphaWrapSurface(box, options);
  ASSERT_FALSE(refusedSkin.ok);
  EXPECT_NE(refusedSkin.error.find("hollow skin"), std::string::npos) << refusedSkin.error;
  EXPECT_NE(refusedSkin.error.find("--wrap-alpha"), std::string::npos) << refusedSkin.error;
  EXPECT_NE(refusedSkin.error.find("--wrap-allow-skin"), std::string::npos) << refusedSkin.error;
  std::printf("open box skin: mean thickness %g = %.3f x the offset\n", refusedSkin.meanThickness,
    refusedSkin.meanThickness / refusedSkin.offset);
  EXPECT_GT(refusedSkin.meanThickness, 1.8 * refusedSkin.offset);
  EXPECT_LT(refusedSkin.meanThickness, kSkinThicknessInOffsets * refusedSkin.offset);

  options.allowSkin = true;
  const AlphaWrapResult wrap = alphaWrapSurface(box, options);
  ASSERT_TRUE(wrap.ok) << wrap.error;
  ASSERT_EQ(wrap.warnings.size(), 1u);
  EXPECT_NE(wrap.warnings[0].find("hollow skin"), std::string::npos) << wrap.warnings[0];
  EXPECT_EQ(wrap.meanThickness, refusedSkin.meanThickness);
  std::printf("open box: %zu triangles, wrap %.2f s, distances %.2f s (%g, %g, spacing %g)\n",
    wrap.surface.triangles.size(), wrap.wrapSeconds, wrap.distanceSeconds, wrap.wrapToInput,
    wrap.inputToWrap, wrap.sampleSpacing);
  const PreparedSurface accepted = prepareInputSurface(wrap.surface, InputCheckOptions());
  ASSERT_TRUE(accepted.ok) << accepted.error;
  // it encloses only the thin walls (2 x offset thick), far less than the box
  EXPECT_LT(accepted.enclosedVolume, 0.2);
}

TEST(AlphaWrap, LargeAlphaClosesTheSameHole)
{
  TriangleSurface box = test::subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4);
  box.triangles.erase(box.triangles.begin(), box.triangles.begin() + 3);
  AlphaWrapOptions options;
  options.relativeAlpha = 0.3; // alpha 0.52, wider than the hole
  const AlphaWrapResult wrap = alphaWrapSurface(box, options);
  ASSERT_TRUE(wrap.ok) << wrap.error;
  const PreparedSurface accepted = prepareInputSurface(wrap.surface, InputCheckOptions());
  ASSERT_TRUE(accepted.ok) << accepted.error;
  EXPECT_NEAR(accepted.enclosedVolume, 1.0, 0.05);
  EXPECT_TRUE(wrap.warnings.empty());
  std::printf("closed box: mean thickness %g = %.1f x the offset\n", wrap.meanThickness,
    wrap.meanThickness / wrap.offset);
  EXPECT_GT(wrap.meanThickness, 10 * kSkinThicknessInOffsets * wrap.offset);
}

TEST(AlphaWrap, RefusesWhatCannotBeWrapped)
{
  TriangleSurface nothing;
  nothing.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  nothing.triangles = { { 0, 0, 1 } };
  AlphaWrapResult r = alphaWrapSurface(nothing, AlphaWrapOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("nothing to wrap"), std::string::npos) << r.error;

  TriangleSurface nan = test::icosphere({ 0, 0, 0 }, 1.0, 1);
  nan.points[0][1] = std::nan("");
  r = alphaWrapSurface(nan, AlphaWrapOptions());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("NaN"), std::string::npos) << r.error;

  AlphaWrapOptions zero;
  zero.relativeAlpha = 0;
  r = alphaWrapSurface(test::icosphere({ 0, 0, 0 }, 1.0, 1), zero);
  EXPECT_FALSE(r.ok);
}
} // namespace
