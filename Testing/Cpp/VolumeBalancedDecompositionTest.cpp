#include "OffFormat.h"
#include "SelfIntersectionCheck.h"
#include "SubdomainAssignment.h"
#include "TestSurfaces.h"
#include "TwoThreadExchange.h"
#include "VolumeBalancedDecomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <thread>
#include <stdexcept>
#include <functional>
#include <set>
#include <sstream>

using namespace ptm;
using namespace ptm::test;

namespace
{
using Case = NamedSurface;
std::vector<Case> cases()
{
  return namedTestSurfaces();
}

double triangleArea(const SurfaceComplex& c, const Triangle& t)
{
  return 0.5 * norm(cross(c.points[t[1]] - c.points[t[0]], c.points[t[2]] - c.points[t[0]]));
}

// Every subdomain's faces (surface triangles and interface regions, oriented
// outward) must close up: each directed edge is matched by its reverse.
void expectClosedSubdomains(const SurfaceComplex& c, const std::string& label)
{
  for (int s = 0; s < c.subdomainCount; ++s)
  {
    std::map<DirectedEdge, int> count;
    auto add = [&](Index a, Index b) { ++count[{ a, b }]; };
    for (const Triangle& t : subdomainTriangles(c, s))
    {
      add(t[0], t[1]);
      add(t[1], t[2]);
      add(t[2], t[0]);
    }
    for (const auto& region : c.interfaces)
    {
      for (const auto& e : region.edges)
      {
        if (region.pair[0] == s)
        {
          add(e[0], e[1]);
        }
        else if (region.pair[1] == s)
        {
          add(e[1], e[0]);
        }
      }
    }
    std::size_t unmatched = 0;
    for (const auto& [e, n] : count)
    {
      auto it = count.find({ e[1], e[0] });
      if (it == count.end() || it->second != n)
      {
        ++unmatched;
      }
    }
    EXPECT_EQ(unmatched, 0u) << label << ": subdomain " << s << " is not closed";
  }
}

void checkDecomposition(const Case& k, int K, CutStrategy strategy, CutDirection direction)
{
  std::ostringstream label;
  label << k.name << " K=" << K << " " << toString(strategy) << " " << toString(direction);
  DecompositionOptions options;
  options.numberOfSubdomains = K;
  options.strategy = strategy;
  options.direction = direction;
  const DecompositionResult r = decomposeVolumeBalanced(k.surface, options);
  ASSERT_TRUE(r.ok) << label.str() << ": " << r.error;
  const SurfaceComplex& c = r.complex;
  ASSERT_EQ(c.subdomainCount, K);

  // volumes: within tolerance of the target and adding up to the input volume
  double sum = 0;
  for (int s = 0; s < K; ++s)
  {
    sum += r.subdomainVolume[s];
    EXPECT_NEAR(r.subdomainVolume[s] / (r.totalVolume / K), 1.0, options.balanceTolerance)
      << label.str() << " subdomain " << s;
  }
  EXPECT_NEAR(sum / r.totalVolume, 1.0, 1e-9) << label.str();
  EXPECT_NEAR(r.totalVolume, std::fabs(signedVolume(k.surface)), 1e-9 * r.totalVolume);

  // every interface: closed loops, a real pair, a known plane
  for (const auto& region : c.interfaces)
  {
    std::vector<std::vector<Index>> loops;
    EXPECT_TRUE(chainLoops(region.edges, loops)) << label.str();
    EXPECT_FALSE(loops.empty());
    EXPECT_GE(region.pair[0], 0);
    EXPECT_GE(region.pair[1], 0);
    EXPECT_NE(region.pair[0], region.pair[1]);
    EXPECT_LT(region.planeId, static_cast<int>(c.planes.size()));
  }
  // no zero-area triangle, every source face valid
  const double scale = 1.0;
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    EXPECT_GT(triangleArea(c, c.triangles[i]), 1e-12 * scale) << label.str() << " triangle " << i;
    EXPECT_GE(c.sourceFaces[i], 0);
    EXPECT_LT(c.sourceFaces[i], static_cast<Index>(k.surface.triangles.size()));
    EXPECT_EQ(c.trianglePairs[i][1], -1);
  }
  expectClosedSubdomains(c, label.str());
}

// A regular n-gon prism of radius r from z = 0 to z = h, the way CAD
// exports walls: each side one rectangle split by one diagonal (bottom of
// corner i to top of corner i + 1), the caps fans from their centres.
TriangleSurface wallPrism(int n, double r, double h)
{
  TriangleSurface s;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * pi * i / n;
    s.points.push_back({ r * std::cos(a), r * std::sin(a), 0.0 });
    s.points.push_back({ r * std::cos(a), r * std::sin(a), h });
  }
  const Index bottomCentre = 2 * n, topCentre = 2 * n + 1;
  s.points.push_back({ 0, 0, 0 });
  s.points.push_back({ 0, 0, h });
  for (Index i = 0; i < n; ++i)
  {
    const Index b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * ((i + 1) % n), t1 = b1 + 1;
    s.triangles.push_back({ b0, b1, t1 });
    s.triangles.push_back({ b0, t1, t0 });
    s.triangles.push_back({ bottomCentre, b1, b0 });
    s.triangles.push_back({ topCentre, t0, t1 });
  }
  return s;
}

// The subdomains of a decomposition of `whole` add up to its volume (1e-9).
void expectSubdomainsAddUp(const DecompositionResult& r, const TriangleSurface& whole)
{
  double parts = 0;
  for (double v : r.subdomainVolume)
  {
    EXPECT_GT(v, 0.0);
    parts += v;
  }
  const double volume = enclosedVolume(whole);
  EXPECT_LE(std::fabs(parts - volume), 1e-9 * volume) << parts << " against " << volume;
}

// A file of Data/regression cut as tetmesh.py cuts it (inertia axes, by the
// cost predicted for `size`), expected to give K subdomains that add up to it.
DecompositionResult cutRegressionFileByCost(const std::string& name, int K, CutStrategy strategy, double size)
{
  const OffReadResult file = readOffFile(std::string(PTM_DATA_DIR "/regression/") + name);
  EXPECT_TRUE(file.ok) << file.error;
  DecompositionOptions options;
  options.numberOfSubdomains = K;
  options.strategy = strategy;
  options.direction = CutDirection::Inertia;
  options.criterion = BalanceCriterion::PredictedCost;
  options.costMaximumSize = size;
  DecompositionResult r = decomposeVolumeBalanced(file.data.surface, options);
  EXPECT_TRUE(r.ok) << name << ": " << r.error;
  if (r.ok)
  {
    EXPECT_EQ(r.complex.subdomainCount, K);
    expectSubdomainsAddUp(r, file.data.surface);
  }
  return r;
}
} // namespace

class DecompositionCases : public ::testing::TestWithParam<std::tuple<int, CutStrategy>>
{
};

TEST_P(DecompositionCases, EveryTestSurface)
{
  const auto [K, strategy] = GetParam();
  for (const Case& k : cases())
  {
    checkDecomposition(k, K, strategy,
      strategy == CutStrategy::ParallelPlanes ? CutDirection::LongestExtent : CutDirection::Inertia);
  }
}

INSTANTIATE_TEST_SUITE_P(KAndStrategy, DecompositionCases,
  ::testing::Combine(::testing::Values(2, 3, 4, 7, 8),
    ::testing::Values(CutStrategy::ParallelPlanes, CutStrategy::RecursiveBisection)),
  [](const auto& info) {
    return std::string(toString(std::get<1>(info.param))) + "_K" +
      std::to_string(std::get<0>(info.param));
  });

TEST(VolumeBalancedDecomposition, AxisDirectionsAndLongestExtent)
{
  for (CutDirection d : { CutDirection::X, CutDirection::Y, CutDirection::Z, CutDirection::LongestExtent })
  {
    checkDecomposition(cases()[0], 4, CutStrategy::RecursiveBisection, d);
    checkDecomposition(cases()[3], 3, CutStrategy::ParallelPlanes, d);
  }
}

// KiCad's SOD-70 (kicad-packages3d, tessellated by the plugin's CAD reader)
// by parallel planes at K = 37, cut by predicted cost as tetmesh.py does:
// with the flat crossings removed no sound plane was found for one part
// and the cut failed half-way ("no balanced cut of a part kept both halves
// free of self-intersections"); the decomposition now cuts again keeping
// them, says so, and the subdomains still add up to the input (session 32).
TEST(VolumeBalancedDecomposition, ACutThatFailsRemovingFlatCrossingsIsMadeKeepingThem)
{
  const DecompositionResult r =
    cutRegressionFileByCost("kicad_sod70.off", 37, CutStrategy::ParallelPlanes, 0.26176408961727343);
  ASSERT_TRUE(r.ok);
  const bool keptThem = std::any_of(r.warnings.begin(), r.warnings.end(),
    [](const std::string& w) { return w.find("cut again keeping them") != std::string::npos; });
  std::cout << "[ figure ] SOD-70 K=37 ParallelPlanes: " << (keptThem ? "cut again keeping the flat crossings" : "cut at once")
            << ", " << r.flatCrossingsRemoved << " flat crossings removed\n";
}

// Two balls 10^6 of their radii from the coordinate origin: volumes taken
// about (0, 0, 0) lost every digit there, and the cutter refused the part
// ("subdomain 0 encloses no volume"; at 10^4 TetGen's volume check refused
// the subdomains). Each part's volume is now taken about one of its corners.
TEST(VolumeBalancedDecomposition, APartFarFromTheOriginKeepsItsVolume)
{
  const TriangleSurface two =
    merged(icosphere({ 1e6, -7e5, 3e5 }, 1.0, 3), icosphere({ 1e6 + 3, -7e5, 3e5 }, 0.5, 3));
  for (CutStrategy strategy : { CutStrategy::RecursiveBisection, CutStrategy::ParallelPlanes })
  {
    DecompositionOptions options;
    options.numberOfSubdomains = 5;
    options.strategy = strategy;
    const DecompositionResult r = decomposeVolumeBalanced(two, options);
    ASSERT_TRUE(r.ok) << r.error;
    double total = 0;
    for (double v : r.subdomainVolume)
    {
      EXPECT_GT(v, 0.0);
      total += v;
    }
    EXPECT_NEAR(total / signedVolume(two), 1.0, 1e-9);
  }
}

TEST(VolumeBalancedDecomposition, UnitCubeCutExactlyThroughVerticesAndEdges)
{
  // planes at x = 0.25, 0.5, 0.75 pass through grid vertices and along edges
  const TriangleSurface cube = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4);
  DecompositionOptions options;
  options.numberOfSubdomains = 4;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::X;
  const DecompositionResult r = decomposeVolumeBalanced(cube, options);
  ASSERT_TRUE(r.ok) << r.error;
  for (int s = 0; s < 4; ++s)
  {
    EXPECT_NEAR(r.subdomainVolume[s], 0.25, 1e-12);
  }
  // the planes fall on grid lines: no triangle is split, no point is added
  EXPECT_EQ(r.complex.points.size(), cube.points.size());
  EXPECT_EQ(r.complex.triangles.size(), cube.triangles.size());
  EXPECT_EQ(r.complex.interfaces.size(), 3u);
  for (const auto& region : r.complex.interfaces)
  {
    EXPECT_EQ(region.edges.size(), 16u); // 4 x 4 grid edges around each square
  }
  expectClosedSubdomains(r.complex, "cube");

  // and a recursive bisection with 8 parts: three orthogonal planes through the centre
  options.numberOfSubdomains = 8;
  options.strategy = CutStrategy::RecursiveBisection;
  options.direction = CutDirection::LongestExtent;
  const DecompositionResult rb = decomposeVolumeBalanced(cube, options);
  ASSERT_TRUE(rb.ok) << rb.error;
  for (int s = 0; s < 8; ++s)
  {
    EXPECT_NEAR(rb.subdomainVolume[s], 0.125, 1e-12);
  }
  expectClosedSubdomains(rb.complex, "cube8");
}

namespace
{
// The 4 x 1 x 1 bar of the slab tests, and K parallel slabs along x at size 0.5.
TriangleSurface slabBar()
{
  return subdividedBox({ 0, 0, 0 }, { 4, 1, 1 }, 4);
}

DecompositionOptions barSlabs(int K)
{
  DecompositionOptions options;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::X;
  options.numberOfSubdomains = K;
  options.costMaximumSize = 0.5;
  return options;
}
} // namespace

TEST(VolumeBalancedDecomposition, ParallelSlabsThinnerThanTheSizeWarnWithTheLargestThickEnoughK)
{
  // K = 10 makes slabs 0.4 thick
  const TriangleSurface bar = slabBar();
  DecompositionOptions options = barSlabs(10);
  auto thinSlabWarnings = [](const DecompositionResult& r) {
    std::vector<std::string> found;
    for (const std::string& w : r.warnings)
    {
      if (w.find("slabs as thin as") != std::string::npos)
      {
        found.push_back(w);
      }
    }
    return found;
  };
  const DecompositionResult thin = decomposeVolumeBalanced(bar, options);
  ASSERT_TRUE(thin.ok) << thin.error; // a warning, never a refusal
  const auto warned = thinSlabWarnings(thin);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("as thin as 0.4, 0.8 x the mesh size 0.5"), std::string::npos) << warned[0];
  EXPECT_NE(warned[0].find("at most 8 parallel slabs"), std::string::npos) << warned[0];
  options.numberOfSubdomains = 8; // slabs 0.5 thick: as thick as the size
  EXPECT_TRUE(thinSlabWarnings(decomposeVolumeBalanced(bar, options)).empty());
  options.numberOfSubdomains = 10;
  options.strategy = CutStrategy::RecursiveBisection; // parts are not slabs
  EXPECT_TRUE(thinSlabWarnings(decomposeVolumeBalanced(bar, options)).empty());
}

TEST(VolumeBalancedDecomposition, ParallelSlabsUnderTheMinimumThicknessAreRefusedWithTheLargestKThatIsNot)
{
  // K = 40 makes slabs 0.1 thick, 0.2 x the size, under the default
  // quarter; 32 slabs are 0.125 = a quarter thick
  const TriangleSurface bar = slabBar();
  DecompositionOptions options = barSlabs(40);
  ASSERT_EQ(options.minimumSlabThickness, kMinimumSlabThickness);
  const DecompositionResult refused = decomposeVolumeBalanced(bar, options);
  ASSERT_FALSE(refused.ok);
  EXPECT_TRUE(refused.refusedBeforeCutting);
  EXPECT_NE(refused.error.find("slabs as thin as 0.1, 0.2 x the mesh size 0.5"), std::string::npos) << refused.error;
  EXPECT_NE(refused.error.find("refused before cutting"), std::string::npos) << refused.error;
  EXPECT_NE(refused.error.find("At most 32 parallel slabs are 0.25 x the size thick (8 as thick as the size)"),
    std::string::npos)
    << refused.error;
  options.numberOfSubdomains = 32; // as thin as allowed: cut, with the warning
  const DecompositionResult quarter = decomposeVolumeBalanced(bar, options);
  ASSERT_TRUE(quarter.ok) << quarter.error;
  EXPECT_EQ(quarter.subdomainVolume.size(), 32u);
  options.numberOfSubdomains = 40;
  options.minimumSlabThickness = 0; // never refuses
  const DecompositionResult anyway = decomposeVolumeBalanced(bar, options);
  ASSERT_TRUE(anyway.ok) << anyway.error;
  EXPECT_EQ(anyway.subdomainVolume.size(), 40u);
  ASSERT_FALSE(anyway.warnings.empty());
  options.minimumSlabThickness = kMinimumSlabThickness;
  options.costSize = [](const Vec3&) { return 0.05; }; // a size field: warned, not refused
  const DecompositionResult field = decomposeVolumeBalanced(bar, options);
  ASSERT_TRUE(field.ok) << field.error;
  EXPECT_FALSE(field.warnings.empty());
  options.costSize = nullptr;
  options.strategy = CutStrategy::RecursiveBisection; // parts are not slabs
  EXPECT_TRUE(decomposeVolumeBalanced(bar, options).ok);
}

// Parallel planes across long thin wall triangles (FlatCrossingRemoval.h):
// each plane crossed the diagonals the earlier cuts left in the walls nearer
// a wall's edge than the last, down to points 0.001 of the wall's width
// apart on CGAL's oblong. With the crossings inside the planar walls taken
// out, the contours keep only points on the walls' edges (and where that
// would make a triangle worse, a crossing), and the subdomains stay closed
// with the same volumes.
TEST(VolumeBalancedDecomposition, PlanesThroughLongWallTrianglesLeaveNoNeedlePoints)
{
  const int n = 24;
  const TriangleSurface prism = wallPrism(n, 3.0, 26.0);
  const double side = 2 * 3.0 * std::sin(3.14159265358979323846 / n);
  for (int K : { 8, 16 })
  {
    DecompositionOptions options;
    options.numberOfSubdomains = K;
    options.strategy = CutStrategy::ParallelPlanes;
    options.direction = CutDirection::Z;
    options.minimumSlabThickness = 0; // the cut is tested, not the size policy
    const DecompositionResult r = decomposeVolumeBalanced(prism, options);
    ASSERT_TRUE(r.ok) << r.error;
    const SurfaceComplex& c = r.complex;
    EXPECT_GT(r.flatCrossingsRemoved, 0u);
    double shortest = std::numeric_limits<double>::infinity();
    for (const InterfaceRegion& region : c.interfaces)
    {
      for (const DirectedEdge& e : region.edges)
      {
        shortest = std::min(shortest, norm(c.points[e[1]] - c.points[e[0]]));
      }
    }
    std::cout << "[ figure ] prism of 24 walls " << side << " wide, K = " << K << " parallel planes: "
              << r.flatCrossingsRemoved << " crossings taken out, shortest contour edge " << shortest / side
              << " x the wall's width\n";
    EXPECT_GT(shortest, 0.1 * side) << "K = " << K;
    double sum = 0;
    for (double v : r.subdomainVolume)
    {
      sum += v;
    }
    EXPECT_NEAR(sum / r.totalVolume, 1.0, 1e-12);
    expectClosedSubdomains(c, "prism K = " + std::to_string(K));
    for (int s = 0; s < K; ++s)
    {
      const SelfIntersectionReport crossing = checkSelfIntersection({ c.points, subdomainTriangles(c, s) });
      EXPECT_FALSE(crossing.intersects) << "K = " << K << ": subdomain " << s;
    }
    // no point left unused
    std::vector<char> used(c.points.size(), 0);
    for (const Triangle& t : c.triangles)
    {
      for (Index v : t)
      {
        used[v] = 1;
      }
    }
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "K = " << K;
  }
  // every input triangle a CAD face of its own: no crossing lies inside one
  DecompositionOptions options;
  options.numberOfSubdomains = 8;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::Z;
  options.faceGroups.resize(prism.triangles.size());
  std::iota(options.faceGroups.begin(), options.faceGroups.end(), Index{ 0 });
  const DecompositionResult separate = decomposeVolumeBalanced(prism, options);
  ASSERT_TRUE(separate.ok) << separate.error;
  // (crossings of the diagonals that cut pieces of one input triangle got still go)
  std::set<Index> onDiagonals; // contour points on the walls' input diagonals, between their ends
  for (const InterfaceRegion& region : separate.complex.interfaces)
  {
    for (const DirectedEdge& e : region.edges)
    {
      for (std::size_t t = 0; t < prism.triangles.size(); t += 4)
      {
        const Vec3 &a = prism.points[prism.triangles[t][0]], &b = prism.points[prism.triangles[t][2]];
        const Vec3& x = separate.complex.points[e[0]];
        if (distanceToSegment(x, a, b) < 1e-9 && norm(x - a) > 1e-9 && norm(x - b) > 1e-9)
        {
          onDiagonals.insert(e[0]);
        }
      }
    }
  }
  EXPECT_EQ(onDiagonals.size(), static_cast<std::size_t>(n * 7)) << "one per wall and plane";
  // and none taken out when the option is off
  options.faceGroups.clear();
  options.removeFlatCrossings = false;
  const DecompositionResult kept = decomposeVolumeBalanced(prism, options);
  ASSERT_TRUE(kept.ok) << kept.error;
  EXPECT_EQ(kept.flatCrossingsRemoved, 0u);
  EXPECT_GT(kept.complex.points.size(), separate.complex.points.size());
}

// With parallel planes the crossings go after every cut, so the next plane
// does not cross the diagonals the last one left: the triangles the planes
// split grow with K, not with K^2 as when they went only after the last cut
// (which split exactly what keeping them splits). CGAL's pinion_small at
// K = 64 had piled 15,085 points on its 62nd interface that way.
TEST(VolumeBalancedDecomposition, ParallelPlanesTakeTheFlatCrossingsOutAfterEveryCut)
{
  const TriangleSurface prism = wallPrism(24, 3.0, 26.0);
  DecompositionOptions options;
  options.numberOfSubdomains = 32;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::Z;
  options.minimumSlabThickness = 0; // the cut is tested, not the size policy
  const DecompositionResult removed = decomposeVolumeBalanced(prism, options);
  options.removeFlatCrossings = false;
  const DecompositionResult kept = decomposeVolumeBalanced(prism, options);
  ASSERT_TRUE(removed.ok) << removed.error;
  ASSERT_TRUE(kept.ok) << kept.error;
  std::cout << "[ figure ] prism of 24 walls, 32 parallel planes: " << removed.splitStats.splitTriangles
            << " triangles split with the crossings taken out after every cut, "
            << kept.splitStats.splitTriangles << " with them kept\n";
  // each plane splits the two triangles of each wall (31 x 24 x 2 = 1,488
  // measured); kept, 12,648
  EXPECT_LE(removed.splitStats.splitTriangles, 31u * 24u * 3u);
  EXPECT_GT(kept.splitStats.splitTriangles, 3 * removed.splitStats.splitTriangles);
  expectClosedSubdomains(removed.complex, "prism, 32 planes");
}

TEST(VolumeBalancedDecomposition, TorusThroughItsHoleGivesTwoLoopsOnOnePlane)
{
  DecompositionOptions options;
  options.numberOfSubdomains = 2;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::X;
  const DecompositionResult r = decomposeVolumeBalanced(torus({ 0, 0, 0 }, 2.0, 0.7, 40, 16), options);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.complex.interfaces.size(), 1u);
  std::vector<std::vector<Index>> loops;
  ASSERT_TRUE(chainLoops(r.complex.interfaces[0].edges, loops));
  EXPECT_EQ(loops.size(), 2u);
}

TEST(VolumeBalancedDecomposition, CavityCutThroughGivesAnInterfaceWithAHole)
{
  DecompositionOptions options;
  options.numberOfSubdomains = 2;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::Z;
  const DecompositionResult r = decomposeVolumeBalanced(cases()[3].surface, options);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.complex.interfaces.size(), 1u);
  const auto& region = r.complex.interfaces[0];
  std::vector<std::vector<Index>> loops;
  ASSERT_TRUE(chainLoops(region.edges, loops));
  ASSERT_EQ(loops.size(), 2u);
  // one loop counter-clockwise (outer), one clockwise (hole) about the normal
  const Vec3 n = r.complex.planes[0].normal;
  int positive = 0, negative = 0;
  for (const auto& loop : loops)
  {
    std::vector<DirectedEdge> edges;
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      edges.push_back({ loop[i], loop[(i + 1) % loop.size()] });
    }
    (dot(vectorArea(r.complex.points, edges), n) > 0 ? positive : negative)++;
  }
  EXPECT_EQ(positive, 1);
  EXPECT_EQ(negative, 1);
}

TEST(VolumeBalancedDecomposition, DeterministicAndCriteria)
{
  DecompositionOptions options;
  options.numberOfSubdomains = 7;
  const auto a = decomposeVolumeBalanced(cases()[2].surface, options);
  const auto b = decomposeVolumeBalanced(cases()[2].surface, options);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.complex.points, b.complex.points);
  EXPECT_EQ(a.complex.triangles, b.complex.triangles);
  EXPECT_EQ(a.complex.trianglePairs, b.complex.trianglePairs);

  for (BalanceCriterion criterion : { BalanceCriterion::Nodes, BalanceCriterion::BoundaryFacets })
  {
    options.criterion = criterion;
    options.numberOfSubdomains = 4;
    const auto r = decomposeVolumeBalanced(cases()[1].surface, options);
    ASSERT_TRUE(r.ok) << r.error;
    double total = 0;
    for (double m : r.subdomainMeasure)
    {
      total += m;
    }
    EXPECT_GT(total, 0);
    EXPECT_LT(r.maximumImbalance, 0.25) << toString(criterion);
  }
}

TEST(VolumeBalancedDecomposition, ClearErrors)
{
  DecompositionOptions options;
  options.numberOfSubdomains = 0;
  EXPECT_FALSE(decomposeVolumeBalanced(cases()[0].surface, options).ok);
  options.numberOfSubdomains = 2;
  TriangleSurface open = cases()[1].surface;
  open.triangles.pop_back();
  const auto r = decomposeVolumeBalanced(open, options);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("the surface is open"), std::string::npos) << r.error;
  TriangleSurface nan = cases()[0].surface;
  nan.points[3][1] = std::nan("");
  EXPECT_NE(decomposeVolumeBalanced(nan, options).error.find("NaN"), std::string::npos);
  // far more subdomains than a tetrahedron can be split into
  TriangleSurface tet;
  tet.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  tet.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  options.numberOfSubdomains = 64;
  const auto many = decomposeVolumeBalanced(tet, options);
  if (!many.ok)
  {
    EXPECT_FALSE(many.error.empty());
  }
}

TEST(SubdomainAssignment, OneEachOrBalancedByMeasure)
{
  EXPECT_EQ(assignSubdomainsToRanks({ 1, 1, 1 }, 3), (std::vector<int>{ 0, 1, 2 }));
  const std::vector<int> owner = assignSubdomainsToRanks({ 5, 4, 3, 3, 2, 1 }, 2);
  double load[2] = { 0, 0 };
  const double m[6] = { 5, 4, 3, 3, 2, 1 };
  for (int s = 0; s < 6; ++s)
  {
    load[owner[s]] += m[s];
  }
  EXPECT_DOUBLE_EQ(load[0], 9);
  EXPECT_DOUBLE_EQ(load[1], 9);
  // longest first: the two largest go to different ranks, wherever they
  // stand in the numbering (contiguous blocks put both on rank 1)
  const std::vector<int> large = assignSubdomainsToRanks({ 1, 1, 1, 1, 1, 1, 8, 8 }, 2);
  EXPECT_NE(large[6], large[7]);
  // equal measures: deterministic, by subdomain number, alternating
  EXPECT_EQ(assignSubdomainsToRanks({ 1, 1, 1, 1, 1, 1, 1, 1 }, 2),
    (std::vector<int>{ 0, 1, 0, 1, 0, 1, 0, 1 }));
  // every rank within one subdomain of the mean
  const std::vector<double> seven{ 1.0, 1.01, 0.99, 1.0, 1.0, 1.005, 0.995 };
  const std::vector<int> three = assignSubdomainsToRanks(seven, 3);
  std::vector<double> loads(3, 0.0);
  for (int s = 0; s < 7; ++s)
  {
    loads[three[s]] += seven[s];
  }
  for (double l : loads)
  {
    EXPECT_LE(std::fabs(l - 7.0 / 3), 1.01);
    EXPECT_GT(l, 0);
  }
}

TEST(VolumeBalancedDecomposition, PlaneThroughTheGapBetweenBodiesIsAValidCut)
{
  // two equal boxes apart along x: the balanced plane falls in the gap
  const TriangleSurface two =
    merged(subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 3), subdividedBox({ 2, 0, 0 }, { 3, 1, 1 }, 3));
  DecompositionOptions options;
  options.numberOfSubdomains = 2;
  options.strategy = CutStrategy::ParallelPlanes;
  options.direction = CutDirection::X;
  const DecompositionResult r = decomposeVolumeBalanced(two, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.complex.interfaces.empty());
  EXPECT_NEAR(r.subdomainVolume[0], 1.0, 1e-12);
  EXPECT_NEAR(r.subdomainVolume[1], 1.0, 1e-12);
  EXPECT_EQ(r.complex.triangles.size(), two.triangles.size());
}

TEST(VolumeBalancedDecomposition, TwoBodiesFromGmshStayBalanced)
{
  // K = 7 by recursive bisection once placed a plane in the gap between the
  // bodies (the measure function's start), missing the balance by 39 %
  const TriangleSurface two = readOffFile(PTM_DATA_DIR "/two_bodies.off").data.surface;
  for (int K : { 3, 5, 7 })
  {
    DecompositionOptions options;
    options.numberOfSubdomains = K;
    const DecompositionResult r = decomposeVolumeBalanced(two, options);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_LE(r.maximumImbalance, options.balanceTolerance) << "K=" << K;
  }
}

// Interfaces are flat where nothing forces otherwise: the boundary points of
// interfaces that are not points of the input surface (chord points, where
// planes meet inside the object) lie on their interfaces' planes, but for
// a few: a point stays put when the later plane crosses none of its chord
// edges, or where three or more planes meet. Points of the input surface may
// lie a snapping distance off (moving them would change the surface). A fold
// that small in a subdomain surface forces TetGen into flat tetrahedra.
TEST(VolumeBalancedDecomposition, InterfacePointsInsideTheObjectLieOnTheirPlanes)
{
  std::size_t checked = 0, off = 0;
  for (const Case& k : cases())
  {
    for (int K : { 8, 16 })
    {
      const auto r = decomposeVolumeBalanced(k.surface, stageCaseOptions(K, CutStrategy::RecursiveBisection));
      ASSERT_TRUE(r.ok) << k.name << ": " << r.error;
      const SurfaceComplex& c = r.complex;
      std::set<Index> onSurface;
      double scale = 0;
      for (const Triangle& t : c.triangles)
      {
        onSurface.insert(t.begin(), t.end());
      }
      for (const Vec3& p : c.points)
      {
        scale = std::max({ scale, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) });
      }
      for (const InterfaceRegion& region : c.interfaces)
      {
        const CuttingPlane& plane = c.planes[region.planeId];
        for (const DirectedEdge& e : region.edges)
        {
          if (!onSurface.count(e[0]))
          {
            ++checked;
            off += std::fabs(dot(plane.normal, c.points[e[0]] - plane.origin)) > 1e-12 * scale ? 1 : 0;
          }
        }
      }
    }
  }
  std::cout << "[ figure ] interface boundary points inside the object: " << off << " of " << checked
            << " off their plane\n";
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(off, checked / 50); // measured 40 of 3,244; 763 before chord points were put on their line
}

namespace
{
// Triangulates every interface (as the InterfaceTriangulator does) and
// counts the subdomains whose closed surface crosses itself (CGAL, exact
// predicates) or cannot be checked.
int crossingSubdomains(const DecompositionResult& r)
{
  SurfaceComplex c = r.complex;
  const InterfaceFigures figures = triangulateAllInterfaces(c);
  EXPECT_TRUE(figures.ok) << figures.error;
  int crossing = 0;
  for (int s = 0; s < c.subdomainCount; ++s)
  {
    const SelfIntersectionReport report = checkSelfIntersection({ c.points, subdomainTriangles(c, s) });
    crossing += (!report.checked || report.intersects) ? 1 : 0;
  }
  return crossing;
}
} // namespace

// Issue #18: CGAL's 19-vertex triple torus (Data/regression/triple_torus.off)
// came out of recursive bisection with 1 or 2 self-intersecting subdomains
// at K = 4, 6, 8, 16 (and 9 more K up to 64): planes passing near saddle
// vertices snapped them, the contour crossed itself there and pinched the
// part. Every subdomain must be closed and free of self-intersections, with
// both strategies.
TEST(VolumeBalancedDecomposition, CoarseTripleTorusNeverCrossesItself)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/triple_torus.off");
  ASSERT_TRUE(file.ok) << file.error;
  for (CutStrategy strategy : { CutStrategy::RecursiveBisection, CutStrategy::ParallelPlanes })
  {
    for (int K : { 4, 6, 8, 14, 16 })
    {
      std::ostringstream label;
      label << "triple torus K=" << K << " " << toString(strategy);
      DecompositionOptions options;
      options.numberOfSubdomains = K;
      options.strategy = strategy;
      options.minimumSlabThickness = 0; // the cut is tested, not the size policy
      const DecompositionResult r = decomposeVolumeBalanced(file.data.surface, options);
      ASSERT_TRUE(r.ok) << label.str() << ": " << r.error;
      EXPECT_LE(r.maximumImbalance, options.balanceTolerance) << label.str();
      expectClosedSubdomains(r.complex, label.str());
      EXPECT_EQ(crossingSubdomains(r), 0) << label.str();
    }
  }
}

// The OpenSCAD example002 at $fn = 12 (Data/regression/openscad_example002.off):
// edges of about 10 units snap vertices up to 0.5 off a plane; at K = 12 the
// interface bent through them crossed a surface triangle. Such a cut is
// replaced (rejectedCuts counts it), never shipped.
TEST(VolumeBalancedDecomposition, CoarseCadNeverCrossesItself)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/openscad_example002.off");
  ASSERT_TRUE(file.ok) << file.error;
  for (int K : { 8, 12, 16 })
  {
    DecompositionOptions options;
    options.numberOfSubdomains = K;
    const DecompositionResult r = decomposeVolumeBalanced(file.data.surface, options);
    ASSERT_TRUE(r.ok) << "K=" << K << ": " << r.error;
    expectClosedSubdomains(r.complex, "example002");
    EXPECT_EQ(crossingSubdomains(r), 0) << "example002 K=" << K;
  }
}

// PrusaSlicer's cylinder (Data/regression/prusa_cylinder.off), every
// triangle under 10 degrees, by 64 bisections: balancing trials cut without
// snapping, and a vertex 5e-15 off such a plane kept its side, so the plane
// crossed its edges 7.9e-15 from it. TetGen merged the two points and the
// subdomain failed. No two points of the complex may lie within round-off.
TEST(VolumeBalancedDecomposition, NoPointDuplicatedWithinRoundOff)
{
  const DecompositionResult r = decomposeDataFile("regression/prusa_cylinder.off", 64);
  ASSERT_TRUE(r.ok) << r.error;
  expectClosedSubdomains(r.complex, "prusa cylinder");
  const std::vector<Vec3>& p = r.complex.points;
  const double tolerance = 1e-12 * boundingBoxDiagonal(p);
  std::vector<Index> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return p[a][0] < p[b][0]; });
  int near = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    for (std::size_t j = i + 1; j < order.size() && p[order[j]][0] - p[order[i]][0] <= tolerance; ++j)
    {
      if (norm(p[order[i]] - p[order[j]]) <= tolerance)
      {
        ++near;
        ADD_FAILURE() << "points " << order[i] << " and " << order[j] << " are "
                      << norm(p[order[i]] - p[order[j]]) << " apart";
      }
    }
  }
  EXPECT_EQ(near, 0);
}

namespace
{
struct SharedRun
{
  DecompositionResult result;
  std::string thrown;
  int checks = 0;
};

// Decomposes `surface` as processes 0 and 1 sharing the cut checks, and
// then, as the filter does, keeps answering until both have left.
void decomposeAsTwoProcesses(const TriangleSurface& surface, const DecompositionOptions& options, SharedRun runs[2],
  const std::function<bool(int process, int part)>& checks)
{
  // as vtkVolumeBalancedCutter's all-reduce: the largest of each entry
  TwoThreadExchange<std::vector<long long>> exchange(
    [](const std::vector<long long>& x, const std::vector<long long>& y) {
      std::vector<long long> largest = x;
      for (std::size_t i = 0; i < largest.size(); ++i)
      {
        largest[i] = std::max(largest[i], y[i]);
      }
      return largest;
    });
  std::vector<std::thread> processes;
  for (int p = 0; p < 2; ++p)
  {
    processes.emplace_back([&, p] {
      DecompositionOptions o = options;
      o.checksPart = [&, p](int part) {
        const bool mine = checks(p, part);
        runs[p].checks += mine ? 1 : 0;
        return mine;
      };
      o.maxOverProcesses = [&, p](int verdict) { return static_cast<int>(exchange.exchange(p, { verdict, 1 })[0]); };
      try
      {
        runs[p].result = decomposeVolumeBalanced(surface, o);
      }
      catch (const std::exception& e)
      {
        runs[p].thrown = e.what();
      }
      while (exchange.exchange(p, { runs[p].thrown.empty() ? 0 : kCheckFailed, 0 })[1] != 0)
      {
      }
    });
  }
  for (std::thread& t : processes)
  {
    t.join();
  }
}
} // namespace

// The cut checks shared out between two processes (each the parts of its
// parity) give both the one-process decomposition, bit for bit, on
// surfaces where cuts are refused for crossing; a check throwing on one
// process makes both throw, neither waiting for ever.
TEST(VolumeBalancedDecompositionShared, TwoProcessesGiveTheOneProcessResult)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/openscad_example002.off");
  ASSERT_TRUE(file.ok) << file.error;
  for (CutStrategy strategy : { CutStrategy::RecursiveBisection, CutStrategy::ParallelPlanes })
  {
    DecompositionOptions options;
    options.numberOfSubdomains = 12;
    options.strategy = strategy;
    options.minimumSlabThickness = 0; // the cut is tested, not the size policy
    const DecompositionResult one = decomposeVolumeBalanced(file.data.surface, options);
    ASSERT_TRUE(one.ok) << one.error;
    SharedRun two[2];
    decomposeAsTwoProcesses(file.data.surface, options, two, [](int p, int part) { return part % 2 == p; });
    for (const SharedRun& r : two)
    {
      ASSERT_TRUE(r.thrown.empty()) << r.thrown;
      ASSERT_TRUE(r.result.ok) << r.result.error;
      EXPECT_EQ(r.result.complex.points, one.complex.points) << toString(strategy);
      EXPECT_EQ(r.result.complex.triangles, one.complex.triangles) << toString(strategy);
      EXPECT_EQ(r.result.complex.trianglePairs, one.complex.trianglePairs) << toString(strategy);
      EXPECT_EQ(r.result.rejectedCuts, one.rejectedCuts) << toString(strategy);
    }
    EXPECT_GT(two[0].checks, 0);
    EXPECT_GT(two[1].checks, 0);

    // process 0 checks nothing: every verdict it acts on comes from process 1
    SharedRun lopsided[2];
    decomposeAsTwoProcesses(file.data.surface, options, lopsided, [](int p, int) { return p == 1; });
    ASSERT_TRUE(lopsided[0].result.ok) << lopsided[0].result.error << lopsided[0].thrown;
    EXPECT_EQ(lopsided[0].checks, 0);
    EXPECT_EQ(lopsided[0].result.complex.points, one.complex.points) << toString(strategy);
    EXPECT_EQ(lopsided[0].result.complex.trianglePairs, one.complex.trianglePairs) << toString(strategy);

    SharedRun failing[2];
    decomposeAsTwoProcesses(file.data.surface, options, failing, [](int p, int part) -> bool {
      if (p == 1 && part % 2 == 1)
      {
        throw std::runtime_error("injected");
      }
      return part % 2 == p;
    });
    EXPECT_NE(failing[0].thrown.find("on another process"), std::string::npos) << failing[0].thrown;
    EXPECT_NE(failing[1].thrown.find("injected"), std::string::npos) << failing[1].thrown;
  }
}

// The OpenSCAD example005 at $fn = 12 (Data/regression/openscad_example005.off):
// at K = 10 a later cut split a piece of the first interface that snapped
// vertices had left bent, and the piece, triangulated anew, crossed a
// surface triangle of the part on its other side. The parts across the
// split interfaces are checked too.
TEST(VolumeBalancedDecomposition, CadPartAcrossASplitInterfaceNeverCrossesItself)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/openscad_example005.off");
  ASSERT_TRUE(file.ok) << file.error;
  DecompositionOptions options;
  options.numberOfSubdomains = 10;
  const DecompositionResult r = decomposeVolumeBalanced(file.data.surface, options);
  ASSERT_TRUE(r.ok) << r.error;
  expectClosedSubdomains(r.complex, "example005");
  EXPECT_EQ(crossingSubdomains(r), 0) << "example005 K=10";
}

// PlaneClearance: points on the plane (up to round-off) do not count, a
// plane a hair off a row of points scores about 0, and within a window the
// clearest offset is the one through the grid plane, not a hair off it.
TEST(PlaneClearance, AwayFromPointsOrThroughThem)
{
  SurfaceComplex c;
  const TriangleSurface box = subdividedBox({ 0, 0, 0 }, { 1, 1, 1 }, 4); // edges 0.25 (diagonals longer)
  c.points = box.points;
  c.triangles = box.triangles;
  c.trianglePairs.assign(c.triangles.size(), SubdomainPair{ 0, -1 });
  const PlaneClearance clearance(c, 0, { 1, 0, 0 });
  EXPECT_NEAR(clearance.at(0.25), 1.0, 1e-9);          // next points 0.25 away, edges 0.25
  EXPECT_NEAR(clearance.at(0.25 + 1e-4), 4e-4, 1e-9);  // a hair off the grid plane
  EXPECT_NEAR(clearance.at(0.375), 0.5, 1e-9);         // half way between grid planes
  EXPECT_EQ(clearance.clearestOffset(0.24, 0.26, 0.2501, 0.5), 0.25);
  EXPECT_NEAR(clearance.clearestOffset(0.3, 0.45, 0.31, 0.5), 0.375, 1e-12);
  // enough is enough: of offsets clear by half an edge, the nearest to the preferred one
  EXPECT_NEAR(clearance.clearestOffset(0.3, 0.45, 0.31, 0.2), 0.31, 1e-12);
}

namespace
{
// A complex of one part (label 0) bounded by `surface`, with one plane of
// normal n on record, ready for splitCell.
SurfaceComplex onePart(const TriangleSurface& surface, const Vec3& n)
{
  SurfaceComplex c;
  c.points = surface.points;
  c.triangles = surface.triangles;
  c.trianglePairs.assign(c.triangles.size(), SubdomainPair{ 0, -1 });
  c.sourceFaces.assign(c.triangles.size(), -1);
  CuttingPlane plane;
  plane.normal = n;
  c.planes.push_back(plane);
  return c;
}
} // namespace

// A vertex within the snap distance of the plane whose neighbours all lie
// across it (here the lower apex of a diamond, 0.01 under z = 0, its four
// neighbours at z = 0.5): snapped, it would take its four triangles above
// and poke through the plane by 0.01 (femur at K = 64 crossed itself so).
// It keeps its side, and the plane cuts the small cap around it off.
TEST(PlaneSplit, VertexWhoseNeighboursAllLieAcrossKeepsItsSide)
{
  TriangleSurface diamond;
  diamond.points = { { 0, 0, -0.01 }, { 1, 0, 0.5 }, { 0, 1, 0.5 }, { -1, 0, 0.5 }, { 0, -1, 0.5 }, { 0, 0, 1 } };
  for (Index k = 0; k < 4; ++k)
  {
    const Index a = 1 + k, b = 1 + (k + 1) % 4;
    diamond.triangles.push_back({ 0, b, a }); // outward: the lower apex's fan faces down
    diamond.triangles.push_back({ 5, a, b });
  }
  SurfaceComplex c = onePart(diamond, { 0, 0, 1 });
  PlaneSplitStats stats;
  std::string error;
  ASSERT_TRUE(splitCell(c, 0, { 0, 0, 1 }, 0.0, 0, 1, 2, {}, stats, error)) << error;
  EXPECT_EQ(stats.unsnappedPoints, 1u);
  EXPECT_EQ(stats.snappedPoints, 0u);
  std::size_t below = 0;
  for (const SubdomainPair& pair : c.trianglePairs)
  {
    below += pair[0] == 1 ? 1 : 0;
  }
  EXPECT_EQ(below, 4u); // the cap: the lower apex's four triangles, cut near it
  ASSERT_EQ(c.interfaces.size(), 1u);
  EXPECT_EQ(c.interfaces[0].edges.size(), 4u);
}

namespace
{
// The box [-5, 5]^2 x [0, 10] whose bottom face rises to a pyramid with its
// apex (point 8) at (0, 0, apexZ): a dent into the box for apexZ > 0, a
// bump out of it for apexZ < 0. Outward.
TriangleSurface boxWithApex(double apexZ)
{
  TriangleSurface box;
  for (double z : { 0.0, 10.0 })
  {
    for (const auto& [x, y] : std::vector<std::array<double, 2>>{ { -5, -5 }, { 5, -5 }, { 5, 5 }, { -5, 5 } })
    {
      box.points.push_back({ x, y, z });
    }
  }
  box.points.push_back({ 0, 0, apexZ });
  for (Index i = 0; i < 4; ++i)
  {
    const Index j = (i + 1) % 4;
    box.triangles.push_back({ i, j, 4 + j });
    box.triangles.push_back({ i, 4 + j, 4 + i });
    box.triangles.push_back({ 8, j, i }); // the bottom's fan
  }
  box.triangles.push_back({ 4, 5, 6 });
  box.triangles.push_back({ 4, 6, 7 });
  if (signedVolume(box) < 0)
  {
    box = flipped(box);
  }
  return box;
}
} // namespace

// A vertex within the snap distance of the plane (0.03 off, 0.0035 of its
// shortest edge) whose neighbours all lie across it, so far off that the
// plane would cross its edges at 0.6 % of their length: it stays snapped
// and its faces go across. At the tip of a dent the new interface then
// covers it and the dent pokes through the interface (Prusa's bunny at K =
// 48, parallel planes: TetGen refused the subdomain after three cuts). The
// split reports the vertex, and made again with it kept off the plane it
// cuts the tip off, leaving a small hole in the interface. At the tip of a
// bump nothing crosses: the plane beside the tip lies outside the part.
TEST(PlaneSplit, SnappedTipOfADentUnderTheInterfaceIsCutOff)
{
  SurfaceComplex dent = onePart(boxWithApex(5.0), { 0, 0, 1 });
  PlaneSplitStats stats;
  std::string error;
  SurfaceComplex copy = dent;
  EXPECT_FALSE(splitCell(copy, 0, { 0, 0, 1 }, 4.97, 0, 1, 2, {}, stats, error));
  EXPECT_EQ(stats.coveredPokes, (std::vector<Index>{ 8 })) << error;
  EXPECT_NE(error.find("under the new interface"), std::string::npos) << error;

  PlaneSplitOptions keepOff;
  keepOff.keepOffPlane = { 8 };
  PlaneSplitStats cut;
  ASSERT_TRUE(splitCell(dent, 0, { 0, 0, 1 }, 4.97, 0, 1, 2, keepOff, cut, error)) << error;
  EXPECT_TRUE(cut.coveredPokes.empty());
  ASSERT_EQ(dent.interfaces.size(), 1u);
  EXPECT_EQ(dent.interfaces[0].edges.size(), 12u); // the section of the walls (2 triangles each), the hole around the tip
  std::size_t tipPieces = 0;
  for (std::size_t i = 0; i < dent.triangles.size(); ++i)
  {
    const Triangle& t = dent.triangles[i];
    tipPieces += (dent.trianglePairs[i][0] == 2 && (t[0] == 8 || t[1] == 8 || t[2] == 8)) ? 1 : 0;
  }
  EXPECT_EQ(tipPieces, 4u);

  SurfaceComplex bump = onePart(boxWithApex(-5.0), { 0, 0, 1 });
  PlaneSplitStats harmless;
  EXPECT_TRUE(splitCell(bump, 0, { 0, 0, 1 }, -4.97, 0, 1, 2, {}, harmless, error)) << error;
  EXPECT_TRUE(harmless.coveredPokes.empty());
  EXPECT_EQ(harmless.snappedPoints, 1u);
}

// The same dent with the plane exactly through its tip: the surface touches
// the new interface at that one point (femur at K = 48 with parallel
// planes: the clearance search, for which points on the plane cost
// nothing, put a plane through such a tip, and TetGen refused the
// subdomain). The split reports the tip and the side of its faces, and a
// hair off it, on that side, the cut is clean. Through the tip of a bump
// there is no interface, and nothing to report.
TEST(PlaneSplit, PlaneThroughTheTipOfADentIsMovedOffIt)
{
  SurfaceComplex dent = onePart(boxWithApex(5.0), { 0, 0, 1 });
  PlaneSplitStats stats;
  std::string error;
  SurfaceComplex copy = dent;
  EXPECT_FALSE(splitCell(copy, 0, { 0, 0, 1 }, 5.0, 0, 1, 2, {}, stats, error));
  EXPECT_EQ(stats.touchingPoint, 8) << error;
  EXPECT_EQ(stats.touchingSide, -1);
  EXPECT_NE(error.find("touch"), std::string::npos) << error;

  PlaneSplitStats clean;
  ASSERT_TRUE(splitCell(dent, 0, { 0, 0, 1 }, 5.0 + 1e-3, 0, 1, 2, {}, clean, error)) << error;
  EXPECT_EQ(clean.touchingSide, 0);
  ASSERT_EQ(dent.interfaces.size(), 1u);
  EXPECT_EQ(dent.interfaces[0].edges.size(), 8u); // the walls' section, no hole

  SurfaceComplex bump = onePart(boxWithApex(-5.0), { 0, 0, 1 });
  PlaneSplitStats harmless;
  EXPECT_TRUE(splitCell(bump, 0, { 0, 0, 1 }, -5.0, 0, 1, 2, {}, harmless, error)) << error;
  EXPECT_EQ(harmless.touchingSide, 0);
}

// A prism along x whose cross-section (z, y) is a square with a notch from
// below: its walls rise from y = 0 to a reflex edge at y = 0.5. The plane
// y = 0.5 runs exactly along that edge, with both walls under it: the new
// interface would pass over the edge and the part below would touch itself
// along it (OpenSCAD's example024 at K = 16, parallel planes, left a
// subdomain that TetGen refused so). The split reports the edge's ends as
// pinched, exactly on the plane, so the caller moves the plane off them.
TEST(PlaneSplit, PlaneAlongTheBottomOfANotchIsAPinch)
{
  const std::vector<std::array<double, 2>> section = { { -1, 0 }, { -0.3, 0 }, { 0, 0.5 }, { 0.3, 0 }, { 1, 0 },
    { 1, 1 }, { -1, 1 } }; // (z, y), counter-clockwise
  const Index m = static_cast<Index>(section.size());
  TriangleSurface prism;
  for (double x : { 0.0, 1.0 })
  {
    for (const auto& [z, y] : section)
    {
      prism.points.push_back({ x, y, z });
    }
  }
  for (Index i = 0; i < m; ++i)
  {
    const Index j = (i + 1) % m;
    prism.triangles.push_back({ i, j, m + j });
    prism.triangles.push_back({ i, m + j, m + i });
  }
  for (const Triangle& t : std::vector<Triangle>{ { 0, 1, 6 }, { 1, 2, 6 }, { 2, 5, 6 }, { 2, 3, 5 }, { 3, 4, 5 } })
  {
    prism.triangles.push_back({ t[0], t[2], t[1] });
    prism.triangles.push_back({ m + t[0], m + t[1], m + t[2] });
  }
  if (signedVolume(prism) < 0)
  {
    prism = flipped(prism);
  }
  ASSERT_EQ(badDirectedEdges(prism.triangles), 0u);
  SurfaceComplex c = onePart(prism, { 0, 1, 0 });
  PlaneSplitStats stats;
  std::string error;
  EXPECT_FALSE(splitCell(c, 0, { 0, 1, 0 }, 0.5, 0, 1, 2, {}, stats, error));
  EXPECT_EQ(stats.pinchedPoints, (std::vector<Index>{ 2, m + 2 })) << error;
  EXPECT_TRUE(stats.pinchedOnPlane);
  EXPECT_NE(error.find("notch"), std::string::npos) << error;

  // Just off the edge the cut is made, and a plane through the top face
  // (its edges are not reflex) is no pinch either.
  for (double offset : { 0.55, 1.0 })
  {
    SurfaceComplex copy = c;
    PlaneSplitStats fine;
    EXPECT_TRUE(splitCell(copy, 0, { 0, 1, 0 }, offset, 0, 1, 2, {}, fine, error)) << offset << ": " << error;
  }
}

// Points a cut pinched at count for the clearance even exactly on the plane;
// other points there do not lower it.
TEST(PlaneClearance, PointsThatMustClearCountOnThePlane)
{
  SurfaceComplex c;
  c.points = { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 0, 2 } };
  const std::vector<PointSpacing> spacing = { { 0, 1.0 }, { 1, 1.0 }, { 2, 1.0 } };
  const PlaneClearance free(c, spacing, { 0, 0, 1 });
  const PlaneClearance keepOff(c, spacing, { 0, 0, 1 }, { 1 });
  EXPECT_DOUBLE_EQ(free.at(1.0), 1.0);
  EXPECT_DOUBLE_EQ(keepOff.at(1.0), 0.0);
  EXPECT_DOUBLE_EQ(keepOff.at(0.5), 0.5);
  EXPECT_NE(keepOff.clearestOffset(0.6, 1.4, 1.0, 0.5), 1.0);
}

// A part whose volume measure puts the balanced plane at the part's end (a
// fraction strictly between 0 and 1 never can): OpenFOAM's flange at K = 64
// by bisection, cut by predicted cost along the inertia axes, failed
// saying the subdomains were too many. The trials now start from the
// part's middle and bisect on the real split, as for a measure with no
// guide at all.
TEST(VolumeBalancedDecomposition, AMeasureSolvedToThePartsEndIsNoGuide)
{
  EXPECT_TRUE(
    cutRegressionFileByCost("openfoam_flange.off", 64, CutStrategy::RecursiveBisection, 0.0016450716943988051).ok);
}

// A snapped vertex a hair across the plane from all its faces (over
// round-off, under a thousandth of its shortest edge), under the new
// interface: TetGen's example (a block with a closed cavity) at K = 64 with
// parallel planes, cut by predicted cost. Plane 6 runs 1.06 degrees off the
// cavity's floor and passed 4.8e-4 over its corners at y = 1.5; snapped,
// they took the whole floor above, under the interface, and subdomain 7
// crossed itself (12 pairs of triangles; tetmesh.py meshed it only by
// recursive bisection after 12-31 s of failed attempts). The plane now moves
// past such a vertex.
TEST(VolumeBalancedDecomposition, AHairlinePokeUnderTheInterfaceMovesThePlane)
{
  const DecompositionResult r =
    cutRegressionFileByCost("tetgen_example_cavity.off", 64, CutStrategy::ParallelPlanes, 0.1646);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(crossingSubdomains(r), 0);
}

namespace
{
// `surface` cut into K subdomains with the cutter's defaults (inertia
// direction, flat crossings taken out) by `strategy`, balancing `criterion`
// (the cutter's default: volume).
DecompositionResult cutWithTheCuttersDefaults(const TriangleSurface& surface, CutStrategy strategy, int K,
  BalanceCriterion criterion = BalanceCriterion::Volume)
{
  DecompositionOptions options;
  options.numberOfSubdomains = K;
  options.strategy = strategy;
  options.direction = CutDirection::Inertia;
  options.criterion = criterion;
  return decomposeVolumeBalanced(surface, options);
}
} // namespace

// OCCT's Top at K = 64 by parallel planes (inertia direction, by volume, as
// the cutter's defaults): each cut's removal of flat crossings took out the
// earlier planes' too; after plane 44 the rest then crossed itself near a
// vertex the bent interface runs through, no try of plane 45 was sound, and
// the whole decomposition was cut again keeping every flat crossing (59,496
// points instead of 27,461; 31.2 s instead of 11.3 s). Taking out only the
// points of the plane just cut, it is cut at once, and no subdomain crosses
// itself by this file's check (with every cut point a candidate and the
// failing removal put back instead, subdomains 45 and 51 did).
TEST(VolumeBalancedDecomposition, EachPlaneTakesOutOnlyItsOwnFlatCrossings)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/occt_top.off");
  ASSERT_TRUE(file.ok) << file.error;
  const DecompositionResult r = cutWithTheCuttersDefaults(file.data.surface, CutStrategy::ParallelPlanes, 64);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.flatCrossingsRemoved, 0u);
  for (const std::string& w : r.warnings)
  {
    EXPECT_EQ(w.find("cut again keeping them"), std::string::npos) << w;
  }
  expectSubdomainsAddUp(r, file.data.surface);
  EXPECT_EQ(crossingSubdomains(r), 0);
}

// The same part at K = 64 by recursive bisection (the cutter's defaults),
// which takes the flat crossings out once, after the last cut: that removal
// left subdomain 19 crossing itself by this file's check, and the four
// filters with their defaults failed in the mesher ("the surface of
// subdomain 19 is not closed"), with no recut in the GUI or pvbatch. The
// removal is now checked and made again keeping subdomain 19's points.
TEST(VolumeBalancedDecomposition, TakingOutFlatCrossingsAfterBisectionKeepsSubdomainsWhole)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/occt_top.off");
  ASSERT_TRUE(file.ok) << file.error;
  const DecompositionResult r = cutWithTheCuttersDefaults(file.data.surface, CutStrategy::RecursiveBisection, 64);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(r.flatCrossingsRemoved, 2000u); // 2,407 of the 2,477 an unchecked removal takes out
  expectSubdomainsAddUp(r, file.data.surface);
  EXPECT_EQ(crossingSubdomains(r), 0);
}

// OCCT's Bottom at K = 16 by parallel planes (inertia direction): by volume
// the last removal of flat crossings, then unchecked for parallel planes,
// left subdomain 7 crossing itself, and tetmesh.py failed on it in the
// mesher after 67 s of attempts, then recut keeping every flat crossing
// (2.57 M tetrahedra); by predicted cost the removals after the planes'
// cuts left subdomain 10 crossing itself. The last removal is now checked
// as bisection's is, and the planes whose removals broke a subdomain are
// cut again keeping their flat crossings, not every plane's.
TEST(VolumeBalancedDecomposition, TakingOutFlatCrossingsAfterParallelPlanesKeepsSubdomainsWhole)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/occt_bottom.off");
  ASSERT_TRUE(file.ok) << file.error;
  for (BalanceCriterion criterion : { BalanceCriterion::Volume, BalanceCriterion::PredictedCost })
  {
    const DecompositionResult r = cutWithTheCuttersDefaults(file.data.surface, CutStrategy::ParallelPlanes, 16, criterion);
    const std::string label = criterion == BalanceCriterion::Volume ? "by volume" : "by cost";
    ASSERT_TRUE(r.ok) << label << ": " << r.error;
    EXPECT_GT(r.flatCrossingsRemoved, 1000u) << label; // 1,293 and 1,234 of 1,297 and 1,236 unchecked
    for (const std::string& w : r.warnings)
    {
      EXPECT_EQ(w.find("cut again keeping them"), std::string::npos) << label << ": " << w;
    }
    expectSubdomainsAddUp(r, file.data.surface);
    EXPECT_EQ(crossingSubdomains(r), 0) << label;
  }
}

// CGAL's oblong blob at K = 16 by parallel planes and predicted cost: plane
// 1's cut of the rest crossed itself at the planes' normal beside plane 0,
// whose flat crossings were taken out, with no part crossing itself to
// name; plane 1 was cut along another normal, unsaid. Now the next round
// keeps plane 0's flat crossings and every plane is parallel.
TEST(VolumeBalancedDecomposition, APlaneTurnedBesideARemovalKeepsThePreviousPlanesFlatCrossings)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/cgal_oblong.off");
  ASSERT_TRUE(file.ok) << file.error;
  const DecompositionResult r =
    cutWithTheCuttersDefaults(file.data.surface, CutStrategy::ParallelPlanes, 16, BalanceCriterion::PredictedCost);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.complex.planes.size(), 15u);
  for (const CuttingPlane& plane : r.complex.planes)
  {
    EXPECT_GT(std::fabs(dot(plane.normal, r.complex.planes[0].normal)), 1.0 - 1e-12);
  }
  for (const std::string& w : r.warnings)
  {
    EXPECT_EQ(w.find("not parallel"), std::string::npos) << w;
  }
  EXPECT_GT(r.flatCrossingsRemoved, 700u); // 819
  expectSubdomainsAddUp(r, file.data.surface);
  EXPECT_EQ(crossingSubdomains(r), 0);
}
