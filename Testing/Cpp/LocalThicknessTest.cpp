#include "LocalThickness.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ptm;
using namespace ptm::test;

namespace
{
// A plate 10 x 8 x 0.5, each face two triangles (as a CAD export writes it).
TriangleSurface plate()
{
  return subdividedBox({ 0, 0, 0 }, { 10, 8, 0.5 }, 1);
}
} // namespace

TEST(LocalThickness, RaysAcrossAPlateMeasureItsThickness)
{
  const std::vector<double> xyzt = thicknessSamples(plate(), 2.0);
  ASSERT_FALSE(xyzt.empty());
  int across = 0;
  for (std::size_t i = 0; i < xyzt.size(); i += 4)
  {
    // only the two large faces are thinner than the limit across; a ray from
    // a side face crosses 8 or 10, beyond the limit, and is left out
    EXPECT_NEAR(xyzt[i + 3], 0.5, 1e-12);
    EXPECT_TRUE(std::fabs(xyzt[i + 2]) < 1e-12 || std::fabs(xyzt[i + 2] - 0.5) < 1e-12);
    ++across;
  }
  // the big faces are longer than the limit, so each triangle sends many rays
  EXPECT_GT(across, 4 * 20);
}

TEST(LocalThickness, ACubeThickerThanTheLimitGivesNoSample)
{
  EXPECT_TRUE(thicknessSamples(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2), 0.5).empty());
}

TEST(LocalThickness, TheCapIsTheThicknessAtTheWallAndGrowsAway)
{
  const double limit = 2.0;
  const SizeFunction size = thicknessCappedSize({}, thicknessSamples(plate(), limit), limit);
  ASSERT_TRUE(size);
  // on a face: a sample lies at most a ray spacing (limit / 2) away
  const double onFace = size({ 5, 4, 0.5 });
  EXPECT_GE(onFace, 0.5);
  EXPECT_LE(onFace, 0.5 + kThicknessGradation * 0.5 * limit);
  // far from every sample: no cap
  EXPECT_TRUE(std::isinf(size({ 100, 100, 100 })));
  // a base field below the cap wins, and a base that is not set gives way
  const SizeFunction finer = thicknessCappedSize([](const Vec3&) { return 0.1; }, thicknessSamples(plate(), limit), limit);
  EXPECT_DOUBLE_EQ(finer({ 5, 4, 0.5 }), 0.1);
  const SizeFunction unset = thicknessCappedSize([](const Vec3&) { return 0.0; }, thicknessSamples(plate(), limit), limit);
  EXPECT_DOUBLE_EQ(unset({ 5, 4, 0.5 }), onFace);
}

TEST(LocalThickness, AWallThinnerThanTheFloorGivesNoSample)
{
  const double limit = 100.0; // the plate is 0.5 thick, under the floor 100 / 64
  const std::vector<double> xyzt = thicknessSamples(plate(), limit);
  ASSERT_FALSE(xyzt.empty()); // rays from the sides cross 8 or 10
  for (std::size_t i = 3; i < xyzt.size(); i += 4)
  {
    EXPECT_GE(xyzt[i], kThicknessFloor * limit);
  }
  const SizeFunction size = thicknessCappedSize({}, xyzt, limit);
  EXPECT_GE(size({ 5, 4, 0.5 }), kThicknessFloor * limit);
}

TEST(LocalThickness, TheSameSurfaceGivesTheSameSamples)
{
  EXPECT_EQ(thicknessSamples(plate(), 2.0), thicknessSamples(plate(), 2.0));
}

// The cutter's ranks each measure a block of triangles and concatenate the
// blocks in rank order: that must be the samples of one call over all.
TEST(LocalThickness, BlocksOfTrianglesConcatenateToTheWhole)
{
  const TriangleSurface s = subdividedBox({ 0, 0, 0 }, { 10, 8, 0.5 }, 3);
  const std::vector<double> whole = thicknessSamples(s, 2.0);
  ASSERT_FALSE(whole.empty());
  for (std::size_t blocks : { 2u, 3u, 7u })
  {
    std::vector<double> joined;
    for (std::size_t b = 0; b < blocks; ++b)
    {
      const std::vector<double> part =
        thicknessSamples(s, 2.0, s.triangles.size() * b / blocks, s.triangles.size() * (b + 1) / blocks);
      joined.insert(joined.end(), part.begin(), part.end());
    }
    EXPECT_EQ(joined, whole) << blocks << " blocks";
  }
  EXPECT_TRUE(thicknessSamples(s, 2.0, 5, 5).empty());
}
