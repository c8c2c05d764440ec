#include "InterfaceTriangulation.h"
#include "InterfaceTriangulationCache.h"
#include "TestSurfaces.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

using namespace ptm;
using namespace ptm::test;

namespace
{
// Adds a closed loop of 2D points (in the basis of `plane`) to the region.
void addLoop(PlanarRegion& r, const std::vector<std::array<double, 2>>& loop)
{
  Vec3 e1, e2;
  planeBasis(r.normal, e1, e2);
  const Index first = static_cast<Index>(r.points.size());
  for (const auto& p : loop)
  {
    r.points.push_back(r.origin + p[0] * e1 + p[1] * e2);
  }
  const Index m = static_cast<Index>(loop.size());
  for (Index i = 0; i < m; ++i)
  {
    r.edges.push_back({ first + i, first + (i + 1) % m });
  }
}

std::vector<std::array<double, 2>> square(double x0, double y0, double side, int perSide, bool ccw)
{
  std::vector<std::array<double, 2>> loop;
  const double corners[4][2] = { { x0, y0 }, { x0 + side, y0 }, { x0 + side, y0 + side }, { x0, y0 + side } };
  for (int c = 0; c < 4; ++c)
  {
    for (int k = 0; k < perSide; ++k)
    {
      const double t = static_cast<double>(k) / perSide;
      const auto& a = corners[c];
      const auto& b = corners[(c + 1) % 4];
      loop.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) });
    }
  }
  if (!ccw)
  {
    std::reverse(loop.begin(), loop.end());
  }
  return loop;
}

std::vector<std::array<double, 2>> circle(double cx, double cy, double radius, int count, bool ccw)
{
  std::vector<std::array<double, 2>> loop;
  for (int k = 0; k < count; ++k)
  {
    const double a = (ccw ? 1 : -1) * 2 * kPi * k / count;
    loop.push_back({ cx + radius * std::cos(a), cy + radius * std::sin(a) });
  }
  return loop;
}

PlanarRegion plane(const Vec3& normal = { 0, 0, 1 }, const Vec3& origin = { 0, 0, 0 })
{
  PlanarRegion r;
  r.origin = origin;
  r.normal = normalized(normal);
  return r;
}

// Checks the contract; returns the triangulated area.
double check(const PlanarRegion& r, const InterfaceTriangulationResult& result, double minimumAngle)
{
  EXPECT_TRUE(result.ok) << result.error;
  const auto& t = result.triangulation;
  const std::size_t n = r.points.size();
  auto point = [&](Index i) { return i < static_cast<Index>(n) ? r.points[i] : t.newPoints[i - n]; };
  // new points on the plane and strictly not on the boundary
  for (const Vec3& p : t.newPoints)
  {
    EXPECT_NEAR(dot(p - r.origin, r.normal), 0.0, 1e-12);
  }
  std::map<std::pair<Index, Index>, int> directed;
  double area = 0;
  std::size_t below = 0;
  for (const auto& tri : t.triangles)
  {
    const Vec3 a = point(tri[0]), b = point(tri[1]), c = point(tri[2]);
    const double twice = dot(cross(b - a, c - a), r.normal);
    EXPECT_GT(twice, 0) << "triangle not counter-clockwise about the normal";
    area += 0.5 * twice;
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ tri[k], tri[(k + 1) % 3] }];
    }
    auto angle = [](const Vec3& p, const Vec3& q, const Vec3& s) {
      return std::atan2(norm(cross(q - p, s - p)), dot(q - p, s - p)) * 180 / kPi;
    };
    if (std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) }) < minimumAngle)
    {
      ++below;
    }
  }
  EXPECT_EQ(below, t.trianglesBelowMinimumAngle);
  // every boundary segment is an edge of exactly one triangle, in its direction
  for (const auto& e : r.edges)
  {
    const std::pair<Index, Index> forward{ e[0], e[1] }, backward{ e[1], e[0] };
    EXPECT_EQ(directed[forward], 1);
    EXPECT_EQ(directed.count(backward), 0u);
  }
  // every other edge is shared by two triangles in opposite directions
  std::set<std::pair<Index, Index>> boundary;
  for (const auto& e : r.edges)
  {
    boundary.insert({ e[0], e[1] });
  }
  for (const auto& [e, count] : directed)
  {
    if (!boundary.count(e))
    {
      EXPECT_EQ(count, 1);
      const std::pair<Index, Index> reverse{ e.second, e.first };
      EXPECT_EQ(directed.count(reverse), 1u) << "open interior edge";
    }
  }
  return area;
}
} // namespace

TEST(InterfaceTriangulation, CoarseAndFineSquares)
{
  for (int perSide : { 1, 10, 40 })
  {
    PlanarRegion r = plane();
    addLoop(r, square(0, 0, 1, perSide, true));
    const auto result = triangulateInterface(r, {});
    EXPECT_NEAR(check(r, result, 20.7), 1.0, 1e-12);
    EXPECT_EQ(result.triangulation.trianglesBelowMinimumAngle, 0u) << perSide;
    // sizes follow the boundary spacing
    const auto& t = result.triangulation;
    double longest = 0;
    for (const auto& tri : t.triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        auto p = [&](Index i) { return i < static_cast<Index>(r.points.size()) ? r.points[i] : t.newPoints[i - r.points.size()]; };
        longest = std::max(longest, norm(p(tri[k]) - p(tri[(k + 1) % 3])));
      }
    }
    if (perSide == 40)
    {
      // automatic size: at most 1.5 x the boundary spacing, edges within about 2.2 x of it
      EXPECT_LT(longest, 2.2 / perSide) << "interior triangles much coarser than the boundary";
      EXPECT_GT(t.newPoints.size(), 500u);
    }
  }
}

// A size field replaces the automatic sizing: edges grow with it from left
// to right (0.02 at x = 0 to 0.2 at x = 1), boundary spacing 0.02 all round.
// The cache gives what triangulateInterface gives, computes a region asked
// again only once, and takes a region differing by one unit in the last
// place of one coordinate, or other options, as a new one.
TEST(InterfaceTriangulationCache, SameInputOnceDifferentInputAgain)
{
  PlanarRegion r = plane();
  addLoop(r, circle(0, 0, 1, 40, true));
  addLoop(r, circle(0.2, 0, 0.3, 12, false));
  InterfaceTriangulationCache cache;
  const auto first = cache.triangulate(r, {});
  const auto direct = triangulateInterface(r, {});
  ASSERT_TRUE(first->ok && direct.ok);
  EXPECT_EQ(first->triangulation.triangles, direct.triangulation.triangles);
  EXPECT_EQ(first->triangulation.newPoints, direct.triangulation.newPoints);
  const auto again = cache.triangulate(PlanarRegion(r), {});
  EXPECT_EQ(again.get(), first.get());
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(cache.misses(), 1u);

  PlanarRegion moved = r;
  moved.points[5][0] = std::nextafter(moved.points[5][0], 2.0);
  const auto other = cache.triangulate(moved, {});
  EXPECT_NE(other.get(), first.get());
  InterfaceTriangulationOptions coarse;
  coarse.minimumAngleDegrees = 10;
  EXPECT_NE(cache.triangulate(r, coarse).get(), first.get());
  EXPECT_EQ(cache.misses(), 3u);
  const auto moreDirect = triangulateInterface(moved, {});
  EXPECT_EQ(other->triangulation.newPoints, moreDirect.triangulation.newPoints);
}

// Past its byte limit the cache starts again: results stay right, and the
// region asked before the drop is computed again.
TEST(InterfaceTriangulationCache, DropsEverythingPastTheLimit)
{
  PlanarRegion r = plane();
  addLoop(r, square(0, 0, 1, 10, true));
  PlanarRegion s = plane();
  addLoop(s, square(0, 0, 2, 10, true));
  InterfaceTriangulationCache cache(1); // below one entry: nothing is kept
  const auto a = cache.triangulate(r, {});
  const auto b = cache.triangulate(r, {});
  EXPECT_EQ(a->triangulation.triangles, b->triangulation.triangles);
  EXPECT_EQ(cache.hits(), 0u);
  InterfaceTriangulationCache roomy;
  roomy.triangulate(r, {});
  roomy.triangulate(s, {});
  roomy.triangulate(r, {});
  EXPECT_EQ(roomy.hits(), 1u);
}

TEST(InterfaceTriangulation, SizeFieldSetsTheEdgeLengths)
{
  PlanarRegion r = plane();
  addLoop(r, square(0, 0, 1, 50, true));
  Vec3 e1, e2; // the square's own axes, as addLoop placed it
  planeBasis(r.normal, e1, e2);
  InterfaceTriangulationOptions options;
  options.sizeAt = [&](const Vec3& p) { return 0.02 + 0.18 * dot(p, e1); };
  const auto result = triangulateInterface(r, options);
  EXPECT_NEAR(check(r, result, 20.7), 1.0, 1e-12);
  const auto& t = result.triangulation;
  auto p = [&](Index i) { return i < static_cast<Index>(r.points.size()) ? r.points[i] : t.newPoints[i - r.points.size()]; };
  std::size_t edges = 0, tooLong = 0;
  double left = 0, right = 0, ratio = 0; // ratio: summed over the edges of the two bands
  std::size_t nLeft = 0, nRight = 0;
  for (const auto& tri : t.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 a = p(tri[k]), b = p(tri[(k + 1) % 3]);
      const Vec3 middle = 0.5 * (a + b);
      const double length = norm(a - b);
      ++edges;
      // the field is the length wanted: edges up to 1.4 x it are allowed
      // (InterfaceTriangulation.cpp: kFieldAllowance), none longer
      tooLong += length > 1.4 * 1.01 * options.sizeAt(middle) + 0.02 ? 1 : 0;
      const double u = dot(middle, e1), v = dot(middle, e2);
      if (u > 0.2 && u < 0.4 && v > 0.2 && v < 0.8)
      {
        left += length;
        ++nLeft;
        ratio += length / options.sizeAt(middle);
      }
      if (u > 0.6 && u < 0.8 && v > 0.2 && v < 0.8)
      {
        right += length;
        ++nRight;
        ratio += length / options.sizeAt(middle);
      }
    }
  }
  ASSERT_GT(nLeft, 0u);
  ASSERT_GT(nRight, 0u);
  EXPECT_EQ(tooLong, 0u) << "of " << edges << " edges";
  // and they come out near it, not well under it (0.63-0.66 x the field
  // when it was a hard bound)
  EXPECT_GT(ratio / (nLeft + nRight), 0.8);
  EXPECT_LT(ratio / (nLeft + nRight), 1.2);
  // the field is 0.074 and 0.146 in the middle of the two bands
  EXPECT_GT(right / nRight, 1.5 * left / nLeft);
}

// Inside a region the filters do not check the field: where it crosses 0
// it is floored (1e-3 of the region's diagonal), not refined without end.
TEST(InterfaceTriangulation, SizeFieldCrossingZeroInsideStaysBounded)
{
  PlanarRegion r = plane();
  addLoop(r, square(0, 0, 1, 50, true));
  Vec3 e1, e2;
  planeBasis(r.normal, e1, e2);
  InterfaceTriangulationOptions options;
  options.sizeAt = [&](const Vec3& p) { return 0.02 - 0.18 * dot(p, e1); };
  const auto result = triangulateInterface(r, options);
  EXPECT_NEAR(check(r, result, 20.7), 1.0, 1e-12);
  EXPECT_LT(result.triangulation.newPoints.size(), 200000u); // 26,046 measured
}

// Where a size field has no value (+inf: the thickness cap away from every
// thin wall) a vertex is sized as with no field at all: by the maximum
// edge length when there is one, else automatically with its 1.3 x slack.
// Falling back to the automatic size under a maximum edge length made the
// whole square as fine as its boundary spacing (0.02, not 0.1).
TEST(InterfaceTriangulation, SizeFieldWithoutValueSizesAsNoField)
{
  PlanarRegion r = plane();
  addLoop(r, square(0, 0, 1, 50, true));
  const SizeFunction none = [](const Vec3&) { return std::numeric_limits<double>::infinity(); };
  InterfaceTriangulationOptions bounded; // a maximum edge length, as tetmesh.py gives
  bounded.maximumEdgeLength = 0.1;
  std::vector<std::size_t> newPoints;
  for (const InterfaceTriangulationOptions& plain : { bounded, InterfaceTriangulationOptions{} })
  {
    InterfaceTriangulationOptions capped = plain;
    capped.sizeAt = none;
    const auto a = triangulateInterface(r, plain);
    const auto b = triangulateInterface(r, capped);
    ASSERT_TRUE(a.ok && b.ok);
    EXPECT_EQ(a.triangulation.newPoints, b.triangulation.newPoints);
    EXPECT_EQ(a.triangulation.triangles, b.triangulation.triangles);
    newPoints.push_back(a.triangulation.newPoints.size());
  }
  // the maximum edge length coarsens the inside: fewer points than automatic
  EXPECT_LT(2 * newPoints[0], newPoints[1]);
}

TEST(InterfaceTriangulation, HolesComponentsAndLShape)
{
  PlanarRegion r = plane({ 0, 0, 1 }, { 0, 0, 2 });
  addLoop(r, square(0, 0, 4, 16, true));
  addLoop(r, square(1, 1, 1, 4, false));      // square hole
  addLoop(r, circle(3, 3, 0.5, 24, false));   // round hole
  addLoop(r, square(10, 0, 1, 4, true));       // second component
  const auto result = triangulateInterface(r, {});
  const double holeArea = 0.5 * 24 * 0.25 * std::sin(2 * kPi / 24);
  EXPECT_NEAR(check(r, result, 20.7), 16.0 - 1.0 - holeArea + 1.0, 1e-10);

  PlanarRegion l = plane();
  addLoop(l, { { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } });
  EXPECT_NEAR(check(l, triangulateInterface(l, {}), 20.7), 3.0, 1e-12);
}

TEST(InterfaceTriangulation, SharpCornerIsCountedNotFatal)
{
  PlanarRegion r = plane();
  addLoop(r, { { 0, 0 }, { 1, 0.05 }, { 1, 0.1 } }); // a sliver of about 2.9 degrees
  const auto result = triangulateInterface(r, {});
  check(r, result, 20.7);
  EXPECT_GE(result.triangulation.trianglesBelowMinimumAngle, 1u);
}

TEST(InterfaceTriangulation, LoopsTouchingAtAVertex)
{
  PlanarRegion r = plane();
  addLoop(r, { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } });
  addLoop(r, { { 1, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 } });
  // the second loop's first point is the first loop's corner (1, 1): share it
  const Index duplicate = 4, shared = 2;
  for (auto& e : r.edges)
  {
    for (Index& v : e)
    {
      v = v == duplicate ? shared : v;
    }
  }
  r.points[duplicate] = { 7, 7, 7 }; // unused now; must be ignored
  EXPECT_NEAR(check(r, triangulateInterface(r, {}), 20.7), 2.0, 1e-12);
}

TEST(InterfaceTriangulation, TiltedPlaneWithPointsSlightlyOff)
{
  PlanarRegion r = plane({ 1, 2, 3 }, { 0.3, -1, 2 });
  addLoop(r, circle(0, 0, 1, 64, true));
  for (std::size_t i = 0; i < r.points.size(); i += 3)
  {
    r.points[i] = r.points[i] + 1e-12 * r.normal;
  }
  const auto result = triangulateInterface(r, {});
  EXPECT_NEAR(check(r, result, 20.7), 0.5 * 64 * std::sin(2 * kPi / 64), 1e-9);
  EXPECT_EQ(result.triangulation.trianglesBelowMinimumAngle, 0u);
}

TEST(InterfaceTriangulation, DeterministicAndBoundsRespected)
{
  PlanarRegion r = plane();
  addLoop(r, circle(0, 0, 1, 100, true));
  addLoop(r, circle(0.3, 0.1, 0.2, 20, false));
  InterfaceTriangulationOptions options;
  options.minimumAngleDegrees = 28;
  const auto a = triangulateInterface(r, options);
  const auto b = triangulateInterface(r, options);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.triangulation.triangles, b.triangulation.triangles);
  EXPECT_EQ(a.triangulation.newPoints, b.triangulation.newPoints);
  check(r, a, 28);
  EXPECT_GE(a.triangulation.minimumAngleDegrees, 20.0);
  options.maximumEdgeLength = 0.05;
  const auto fine = triangulateInterface(r, options);
  check(r, fine, 28);
  EXPECT_GT(fine.triangulation.triangles.size(), 3 * a.triangulation.triangles.size());
  // the maximum edge length holds away from the boundary (spacing 0.063,
  // never split): in every triangle without a boundary point whose
  // circumcircle reaches no boundary segment
  const auto& t = fine.triangulation;
  const Index boundaryCount = static_cast<Index>(r.points.size());
  auto at = [&](Index i) { return t.newPoints[i - boundaryCount]; };
  double longest = 0;
  std::size_t away = 0;
  for (const Triangle& tri : t.triangles)
  {
    if (*std::min_element(tri.begin(), tri.end()) < boundaryCount)
    {
      continue;
    }
    const Vec3 a = at(tri[0]), u = at(tri[1]) - a, v = at(tri[2]) - a, w = cross(u, v);
    const Vec3 centre = a + (1.0 / (2.0 * dot(w, w))) * (dot(u, u) * cross(v, w) + dot(v, v) * cross(w, u));
    bool reaches = false;
    for (const auto& e : r.edges)
    {
      const Vec3 p = r.points[e[0]], q = r.points[e[1]];
      const double s = std::clamp(dot(centre - p, q - p) / dot(q - p, q - p), 0.0, 1.0);
      reaches = reaches || norm(centre - (p + s * (q - p))) < norm(centre - a);
    }
    if (!reaches)
    {
      ++away;
      longest = std::max({ longest, norm(u), norm(v), norm(v - u) });
    }
  }
  EXPECT_GT(away, t.triangles.size() / 2);
  EXPECT_LE(longest, 0.05 * (1 + 1e-12));
}

TEST(InterfaceTriangulation, ClearErrors)
{
  PlanarRegion empty = plane();
  EXPECT_FALSE(triangulateInterface(empty, {}).ok);

  PlanarRegion open = plane();
  addLoop(open, square(0, 0, 1, 2, true));
  open.edges.pop_back();
  auto r = triangulateInterface(open, {});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("closed loops"), std::string::npos) << r.error;

  PlanarRegion crossing = plane();
  addLoop(crossing, { { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } }); // a bow tie
  r = triangulateInterface(crossing, {});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("cross"), std::string::npos) << r.error;

  PlanarRegion inverted = plane();
  addLoop(inverted, square(0, 0, 1, 2, false)); // clockwise outer loop
  r = triangulateInterface(inverted, {});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("oriented"), std::string::npos) << r.error;

  PlanarRegion nan = plane();
  addLoop(nan, square(0, 0, 1, 2, true));
  nan.points[1][0] = std::nan("");
  EXPECT_FALSE(triangulateInterface(nan, {}).ok);

  PlanarRegion good = plane();
  addLoop(good, square(0, 0, 1, 2, true));
  InterfaceTriangulationOptions bad;
  bad.minimumAngleDegrees = 45;
  EXPECT_FALSE(triangulateInterface(good, bad).ok);
}

TEST(InterfaceTriangulation, LargeRegionFigure)
{
  PlanarRegion r = plane();
  addLoop(r, circle(0, 0, 1, 1000, true));
  const auto start = std::chrono::steady_clock::now();
  const auto result = triangulateInterface(r, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(result.ok) << result.error;
  std::cout << "[ figure ] 1000 boundary points: " << result.triangulation.triangles.size()
            << " triangles, " << result.triangulation.newPoints.size() << " new points, minimum angle "
            << result.triangulation.minimumAngleDegrees << " degrees, " << seconds << " s\n";
  EXPECT_EQ(result.triangulation.trianglesBelowMinimumAngle, 0u);
}

// A boundary that runs almost straight through its points, with uneven
// spacing and points a hair off the line (as the cutter leaves them where a
// contour passes through snapped vertices): refinement and smoothing must
// not leave a flat triangle over such a point, nor trade a few poor
// triangles for one sliver.
TEST(InterfaceTriangulation, StraightRunsGetNoFlatTriangles)
{
  std::size_t cases = 0;
  double smallest = 180;
  for (int seed = 0; seed < 40; ++seed)
  {
    PlanarRegion r = plane();
    std::vector<std::array<double, 2>> loop;
    // the bottom side: uneven steps, each point off the line by up to 1e-6
    double x = 0;
    unsigned state = 12345u + 977u * static_cast<unsigned>(seed);
    auto next = [&]() {
      state = state * 1664525u + 1013904223u;
      return (state >> 8) / 16777216.0;
    };
    while (x < 1)
    {
      loop.push_back({ x, x > 0 ? (next() - 0.5) * 2e-6 : 0.0 });
      x += 0.01 + 0.06 * next();
    }
    // the other sides evenly at the mean spacing of the bottom
    for (int k = 0; k < 10; ++k)
    {
      loop.push_back({ 1, 0.3 * k / 10 });
    }
    for (int k = 0; k < 25; ++k)
    {
      loop.push_back({ 1 - k / 25.0, 0.3 });
    }
    for (int k = 0; k < 10; ++k)
    {
      loop.push_back({ 0, 0.3 - 0.3 * k / 10 });
    }
    addLoop(r, loop);
    const auto result = triangulateInterface(r, {});
    check(r, result, 20.7);
    smallest = std::min(smallest, result.triangulation.minimumAngleDegrees);
    ++cases;
  }
  std::cout << "[ figure ] " << cases << " regions with a nearly straight uneven side: smallest angle " << smallest
            << " degrees\n";
  EXPECT_GT(smallest, 4.0); // 3.1 degrees when smoothing could trade triangles for a sliver
}

TEST(InterfaceTriangulation, HairlineSegmentDoesNotDrawRefinementBelowRoundOff)
{
  // A region of the cutter's self-intersection check on a fuzzed surface
  // (Testing/Fuzz/corpus/decomposition/regression-interface-refinement-
  // below-round-off): points snapped up to 0.02 off the plane x = 0.4797,
  // and three nearly collinear boundary points 9e-15 apart. Without the
  // clearance floor the refinement put 53,208 points, most of them 1e-9 to
  // 1e-11 from that spot, in 40 s; with it, 587 in milliseconds.
  PlanarRegion r;
  r.origin = { 0.47965494791666669, 0.48, 0.5 };
  r.normal = { 1, 0, 0 };
  r.points = { { 0.5, 1, 0 }, { 0.5, 1, 1 }, { 0.5, 0.5, 0 }, { 0.5, 0.5, 1 },
    { 0.47965494791666669, 1, 0.23982747395833334 }, { 0.47965494791666669, 1, 0.47965494791666669 },
    { 0.47965494791666669, 0.44958623350782084, 0.5 }, { 0.5, 0.45377842087358572, 1 },
    { 0.5, 0.45377842087358572, 0 }, { 0.47965494791666707, 0.44958623350782079, 0.49999999999999106 },
    { 0.47965494791666707, 0.44958623350782079, 0.50000000000000888 },
    { 0.47965494791666669, 0.44958623350782073, 0.2499999999999955 },
    { 0.47965494791666669, 0.44958623350782073, 0.75000000000000433 } };
  r.edges = { { 3, 7 }, { 2, 0 }, { 5, 1 }, { 8, 2 }, { 1, 3 }, { 0, 4 }, { 4, 5 }, { 6, 9 }, { 10, 6 },
    { 11, 8 }, { 9, 11 }, { 12, 10 }, { 7, 12 } };
  for (bool smooth : { false, true })
  {
    InterfaceTriangulationOptions options;
    options.smooth = smooth;
    const auto result = triangulateInterface(r, options);
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_LT(result.triangulation.newPoints.size(), 2000u) << "smooth " << smooth;
  }
}
