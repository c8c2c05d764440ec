// Every class of bad input: refused with a message that names it (count and
// location), or repaired with a warning when the repair is safe.
#include "SelfIntersectionCheck.h"
#include "SurfaceInputCheck.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ptm;
using namespace ptm::test;

namespace
{
::testing::AssertionResult mentions(const std::string& text, const std::string& part)
{
  if (text.find(part) != std::string::npos)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "'" << text << "' does not mention '" << part << "'";
}

std::string allWarnings(const PreparedSurface& p)
{
  std::string all;
  for (const auto& w : p.warnings)
  {
    all += w + "\n";
  }
  return all;
}

// the soup an STL file gives: three separate corners per triangle
TriangleSurface soup(const TriangleSurface& s)
{
  TriangleSurface out;
  for (const auto& t : s.triangles)
  {
    const Index base = static_cast<Index>(out.points.size());
    for (Index v : t)
    {
      out.points.push_back(s.points[v]);
    }
    out.triangles.push_back({ base, base + 1, base + 2 });
  }
  return out;
}
} // namespace

TEST(SurfaceInputCheck, CleanSurfacePassesUnchanged)
{
  const TriangleSurface ball = icosphere({ 0, 0, 0 }, 1.0, 2);
  const PreparedSurface p = prepareInputSurface(ball, {});
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_TRUE(p.warnings.empty()) << allWarnings(p);
  EXPECT_TRUE(p.counts.selfIntersectionChecked);
  EXPECT_EQ(p.surface.triangles, ball.triangles);
  EXPECT_NEAR(p.enclosedVolume, signedVolume(ball), 1e-12);
}

TEST(SurfaceInputCheck, EmptyAndTooFewPoints)
{
  PreparedSurface p = prepareInputSurface(TriangleSurface{}, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "empty"));
  TriangleSurface three;
  three.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  three.triangles = { { 0, 1, 2 }, { 0, 2, 1 } };
  p = prepareInputSurface(three, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "3 points; a closed surface needs at least 4"));
}

TEST(SurfaceInputCheck, NanInfiniteAndBadIndicesAreNamedTogether)
{
  TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  box.points[3][1] = std::numeric_limits<double>::quiet_NaN();
  box.points[7][2] = std::numeric_limits<double>::infinity();
  box.triangles[4][2] = 1000;
  const PreparedSurface p = prepareInputSurface(box, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "2 points have a NaN or infinite coordinate (the first is point 3)"));
  EXPECT_TRUE(mentions(p.error, "1 triangle refers to a point that does not exist (the first is triangle 4)"));
}

// The decomposition fuzzer's case: 22 triangles 3e-106 across took 36 s to
// cut, every predicate falling back to exact arithmetic. Far smaller than
// any model, yet 1e-40 across still passes.
TEST(SurfaceInputCheck, SurfaceTooSmallForThePredicatesIsRefused)
{
  const TriangleSurface ball = icosphere({ 0, 0, 0 }, 1.0, 1);
  auto scaled = [&](double s) {
    TriangleSurface t = ball;
    for (Vec3& p : t.points)
    {
      p = s * p;
    }
    return t;
  };
  const PreparedSurface tiny = prepareInputSurface(scaled(1e-106), {});
  EXPECT_FALSE(tiny.ok);
  EXPECT_TRUE(mentions(tiny.error, "below the 1e-50 at which")) << tiny.error;
  EXPECT_TRUE(mentions(tiny.error, "scale the surface up")) << tiny.error;
  const PreparedSurface small = prepareInputSurface(scaled(1e-40), {});
  EXPECT_TRUE(small.ok) << small.error;
}

TEST(SurfaceInputCheck, OpenBoxNamesItsBoundaryEdges)
{
  TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  box.triangles.pop_back();
  box.triangles.pop_back(); // one whole square of the grid: 4 boundary edges
  const PreparedSurface p = prepareInputSurface(box, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "the surface is open: 4 boundary edges"));
  EXPECT_TRUE(mentions(p.error, "e.g. from ("));
  EXPECT_EQ(p.counts.boundaryEdges, 4u);
}

TEST(SurfaceInputCheck, TwoCubesSharingAnEdgeAreNonManifold)
{
  TriangleSurface both =
    soup(merged(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 1), subdividedBox({ 1, 1, 0 }, { 2, 2, 1 }, 1)));
  const PreparedSurface p = prepareInputSurface(both, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "1 non-manifold edge (used by more than two triangles, up to 4)"));
  EXPECT_TRUE(mentions(p.error, "(1, 1, 0) to (1, 1, 1)"));
}

TEST(SurfaceInputCheck, TwoCubesSharingAVertexAreNonManifold)
{
  TriangleSurface both =
    soup(merged(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 1), subdividedBox({ 1, 1, 1 }, { 2, 2, 2 }, 1)));
  const PreparedSurface p = prepareInputSurface(both, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "1 non-manifold vertex"));
  EXPECT_TRUE(mentions(p.error, "at (1, 1, 1)"));
  EXPECT_EQ(p.counts.nonManifoldEdges, 0u);
}

TEST(SurfaceInputCheck, OverlappingBoxesIntersectThemselves)
{
  TriangleSurface both =
    merged(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2), subdividedBox({ 0.5, 0.3, 0.2 }, { 1.5, 0.8, 0.7 }, 2));
  PreparedSurface p = prepareInputSurface(both, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "the surface intersects itself"));
  EXPECT_TRUE(mentions(p.error, "pairs of triangles cross, e.g. input triangles"));
  EXPECT_GT(p.counts.selfIntersectingPairs, 1u);

  InputCheckOptions skip;
  skip.checkSelfIntersections = false;
  p = prepareInputSurface(both, skip);
  EXPECT_TRUE(p.ok) << "with the check off the overlap is not seen: " << p.error;
  EXPECT_FALSE(p.counts.selfIntersectionChecked);

  InputCheckOptions small;
  small.selfIntersectionLimit = 10;
  p = prepareInputSurface(both, small);
  EXPECT_TRUE(p.ok);
  EXPECT_TRUE(mentions(allWarnings(p), "self-intersections were not checked"));
}

// The cutter checks patches of a part (VolumeBalancedDecomposition.cpp:
// partCrossesItself). A patch may have two fans at one point (a bow tie);
// orienting the soup splits that point, after which the two triangles
// merely touching there count as crossing. So a patch is checked only where
// no triangle checked has a split corner.
TEST(SelfIntersectionCheck, PatchIsCheckedOnlyAwayFromItsSplitCorners)
{
  TriangleSurface patch;
  patch.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 }, // bow tie at 0
    { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 },                                          // C
    { 5.2, 0.2, -1 }, { 5.4, 0.2, 1 }, { 5.2, 0.5, 1 },                             // D, through C
    { 10, 0, 0 }, { 11, 0, 0 }, { 10, 1, 0 } };                                     // E, apart
  patch.triangles = { { 0, 1, 2 }, { 0, 3, 4 }, { 5, 6, 7 }, { 8, 9, 10 }, { 11, 12, 13 } };

  SelfIntersectionReport bowTie = checkPatchSelfIntersection(patch, { 0, 1 });
  EXPECT_FALSE(bowTie.checked) << "a corner of a triangle checked was split";
  const SelfIntersectionReport repaired = checkSelfIntersection(patch, { 0, 1 });
  EXPECT_TRUE(repaired.checked) << repaired.note;
  EXPECT_TRUE(repaired.intersects) << "after the split the bow tie's touch counts as a crossing";

  const SelfIntersectionReport crossing = checkPatchSelfIntersection(patch, { 2, 3 });
  ASSERT_TRUE(crossing.checked) << crossing.note;
  EXPECT_TRUE(crossing.intersects);
  EXPECT_EQ(crossing.firstTriangle + crossing.secondTriangle, 5);

  const SelfIntersectionReport apart = checkPatchSelfIntersection(patch, { 2, 4 });
  ASSERT_TRUE(apart.checked) << apart.note;
  EXPECT_FALSE(apart.intersects);
}

// The check's own manifold test (isOrientedManifold) lets a closed oriented
// surface go straight to CGAL's mesh; anything else must take CGAL's soup
// repair as before: one triangle turned the wrong way, and a fin (an edge
// of three triangles) on an otherwise closed sphere. Were the fin taken for
// a mesh, CGAL's mesh would not hold it and the check would not be made.
TEST(SelfIntersectionCheck, SoupsThatAreNotOrientedMeshesAreStillChecked)
{
  const TriangleSurface ball = icosphere({ 0, 0, 0 }, 1.0, 2);
  const SelfIntersectionReport plain = checkSelfIntersection(ball);
  ASSERT_TRUE(plain.checked) << plain.note;
  EXPECT_FALSE(plain.intersects);

  TriangleSurface turned = ball;
  std::swap(turned.triangles[7][1], turned.triangles[7][2]);
  const SelfIntersectionReport oriented = checkSelfIntersection(turned);
  ASSERT_TRUE(oriented.checked) << oriented.note;
  EXPECT_FALSE(oriented.intersects);

  TriangleSurface fin = ball;
  const Triangle& t = fin.triangles[0];
  fin.points.push_back(3.0 * (fin.points[t[0]] + fin.points[t[1]]));
  fin.triangles.push_back({ t[0], t[1], static_cast<Index>(fin.points.size() - 1) });
  const SelfIntersectionReport finned = checkSelfIntersection(fin);
  ASSERT_TRUE(finned.checked) << finned.note;
  EXPECT_TRUE(finned.intersects) << "CGAL splits the fin's edge, after which the fin touches the sphere there";
}

// A closed surface folded onto itself at an edge, in one plane to
// round-off, crosses itself although CGAL's exact predicates see four
// points off one plane (the aneurysm's subdomain 26 at K = 64, 2e-15): a
// tetrahedron 1e-13 high. One 1e-6 high is a thin wedge, not a fold.
TEST(SelfIntersectionCheck, FoldsInOnePlaneToRoundOffCount)
{
  auto tetrahedron = [](double height) {
    TriangleSurface t;
    t.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, 0.5, height } };
    t.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } };
    return t;
  };
  const SelfIntersectionReport flat = checkSelfIntersection(tetrahedron(1e-13));
  ASSERT_TRUE(flat.checked) << flat.note;
  EXPECT_TRUE(flat.intersects);
  EXPECT_EQ(flat.folds, 1u);
  const SelfIntersectionReport patch = checkSelfIntersection(tetrahedron(1e-13), { 2 });
  EXPECT_TRUE(patch.intersects) << "the fold at each edge of triangle 2";
  const SelfIntersectionReport thin = checkSelfIntersection(tetrahedron(1e-6));
  ASSERT_TRUE(thin.checked) << thin.note;
  EXPECT_FALSE(thin.intersects);
  EXPECT_EQ(thin.folds, 0u);
}

TEST(SurfaceInputCheck, FlippedTrianglesAndInsideOutSphereAreRepaired)
{
  TriangleSurface ball = flipped(icosphere({ 0, 0, 0 }, 1.0, 2));
  std::swap(ball.triangles[9][1], ball.triangles[9][2]);
  const PreparedSurface p = prepareInputSurface(ball, {});
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_TRUE(mentions(allWarnings(p), "orientation repaired"));
  EXPECT_TRUE(mentions(allWarnings(p), "1 inside-out shell inverted"));
  EXPECT_NEAR(p.enclosedVolume, signedVolume(icosphere({ 0, 0, 0 }, 1.0, 2)), 1e-12);
}

TEST(SurfaceInputCheck, StlSoupIsMergedAndCollapsedTrianglesRemoved)
{
  const TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  TriangleSurface s = soup(box);
  // a triangle whose corners all sit on one point of the box
  const Vec3 corner = box.points[0];
  for (int k = 0; k < 3; ++k)
  {
    s.points.push_back(corner);
  }
  const Index base = static_cast<Index>(s.points.size()) - 3;
  s.triangles.push_back({ base, base + 1, base + 2 });
  const PreparedSurface p = prepareInputSurface(s, {});
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.surface.points.size(), box.points.size());
  EXPECT_EQ(p.counts.collapsedTriangles, 1u);
  EXPECT_TRUE(mentions(allWarnings(p), "merged "));
  EXPECT_TRUE(mentions(allWarnings(p), "removed 1 triangle that repeats a corner"));
  EXPECT_NEAR(p.enclosedVolume, 1.0, 1e-12);
}

TEST(SurfaceInputCheck, RemovableDuplicateAndZeroAreaTrianglesAreRemoved)
{
  TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 2);
  const std::size_t original = box.triangles.size();
  box.triangles.push_back(box.triangles[5]); // an exact duplicate
  // a zero-area triangle on an edge of triangle 0, and its mirror
  const Triangle t0 = box.triangles[0];
  const Index m = static_cast<Index>(box.points.size());
  box.points.push_back(0.5 * (box.points[t0[0]] + box.points[t0[1]]));
  box.triangles.push_back({ t0[0], t0[1], m });
  box.triangles.push_back({ t0[1], t0[0], m });
  const PreparedSurface p = prepareInputSurface(box, {});
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_EQ(p.surface.triangles.size(), original);
  EXPECT_EQ(p.counts.duplicateTriangles, 2u);
  EXPECT_EQ(p.counts.zeroAreaTriangles, 1u);
  EXPECT_EQ(p.surface.points.size(), box.points.size() - 1) << "the sliver's own point goes too";
  EXPECT_TRUE(mentions(allWarnings(p), "removed 2 duplicated triangles (the first is input triangle"));
  EXPECT_TRUE(mentions(allWarnings(p), "removed 1 zero-area triangle"));
}

TEST(SurfaceInputCheck, ZeroAreaTriangleThatClosesTheSurfaceIsAnError)
{
  // a tetrahedron whose edge (0,1) is split by point 4 on one side only: the
  // zero-area triangle (0,4,1) closes the T-junction, removing it opens it
  TriangleSurface t;
  t.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.5, 0, 0 } };
  t.triangles = { { 0, 2, 1 }, { 0, 4, 3 }, { 4, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 4 } };
  const PreparedSurface p = prepareInputSurface(t, {});
  EXPECT_FALSE(p.ok);
  EXPECT_TRUE(mentions(p.error, "the surface is open: 3 boundary edges"));
  EXPECT_TRUE(mentions(p.error, "cannot be removed without opening the surface"));
}

TEST(SurfaceInputCheck, EveryProblemOfTheBundledSurfacesIsAbsent)
{
  for (const auto& named : namedTestSurfaces())
  {
    const PreparedSurface p = prepareInputSurface(named.surface, {});
    EXPECT_TRUE(p.ok) << named.name << ": " << p.error;
  }
}
