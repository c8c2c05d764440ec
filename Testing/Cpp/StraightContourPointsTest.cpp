// Stage 3, last step (StraightContourPoints.h): points in the middle of a
// straight contour kept inside the input surface, so that TetGen makes no
// needle of two flat tetrahedra there.
//
//  * The surface of CGAL's itemb subdomain 40 of 64 as it reached TetGen
//    (Data/regression/tetgen_needle_at_a_contour.off, with the subdomain
//    across every triangle in .sides): TetGen (-pYz, no quality refinement)
//    meshes it with a tetrahedron of 0.0146 degrees at a contour point
//    1.1e-16 outside the input plane; with the stage's moves, by at most
//    1e-13 of the coordinates, none under 1 degree. A box of two subdomains
//    with its contour point put outside both planes by rounding was tried
//    first: TetGen made no needle there, so the test is on the real surface.
//  * The unit-test surfaces (TestSurfaces.h) at K = 8, both strategies,
//    interfaces triangulated and relaxed (the relaxer ends with this stage):
//    no subdomain's TetGen mesh (-pYz) has a tetrahedron with three corners
//    on a line, and the enclosed volume changes by at most 1e-12 (points
//    pulled inside printed: 33 by planes, 1 by bisection).
#include "OffFormat.h"
#include "StraightContourPoints.h"
#include "SurfaceRelaxation.h"
#include "SubdomainSurface.h"
#include "TestSurfaces.h"
#include "TetGenSubdomainMesher.h"
#include "TetrahedronQuality.h"
#include "VolumeBalancedDecomposition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace ptm;
using namespace ptm::test;

namespace
{
// The one-subdomain complex of a subdomain surface and the subdomain across
// each of its triangles (-1: the outer surface); each interface gets a
// plane through its first triangle with the mean normal of its triangles.
SurfaceComplex oneSubdomain(const TriangleSurface& surface, const std::vector<int>& across)
{
  SurfaceComplex c;
  c.points = surface.points;
  c.triangles = surface.triangles;
  std::map<int, int> planeOf;
  for (std::size_t i = 0; i < across.size(); ++i)
  {
    const int other = across[i];
    const Triangle& t = surface.triangles[i];
    const Vec3 n = normalized(cross(c.points[t[1]] - c.points[t[0]], c.points[t[2]] - c.points[t[0]]));
    int plane = -1;
    if (other >= 0)
    {
      const auto [it, added] = planeOf.emplace(other, static_cast<int>(c.planes.size()));
      if (added)
      {
        c.planes.push_back({ c.points[t[0]], { 0, 0, 0 }, 1 });
      }
      plane = it->second;
      c.planes[plane].normal = c.planes[plane].normal + n;
    }
    c.trianglePairs.push_back({ 0, other });
    c.sourceFaces.push_back(other < 0 ? 0 : -1);
    c.trianglePlanes.push_back(plane);
  }
  for (CuttingPlane& plane : c.planes)
  {
    plane.normal = normalized(plane.normal);
  }
  c.subdomainCount = 1;
  return c;
}

// TetGen's mesh of subdomain s with its surface kept, as the boundary
// recovery leaves it: no quality refinement, no volume bound to speak of, no
// repair (-pYz).
TetMesh keptSurfaceMesh(const SurfaceComplex& c, int s)
{
  std::vector<Index> ids(c.points.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    ids[i] = static_cast<Index>(i);
  }
  SubdomainSurface surface;
  std::string error;
  EXPECT_TRUE(extractSubdomainSurface(c, ids, s, surface, error)) << error;
  TetMeshingOptions options;
  options.qualityRefinement = false;
  options.sliverRepairAngle = 0;
  options.maximumVolume = 1e30;
  TetMeshingResult r = meshClosedSurface(surface.surface, options);
  EXPECT_TRUE(r.ok) << r.error;
  return std::move(r.mesh);
}

double smallestDihedral(const SurfaceComplex& c, int s)
{
  return dihedralQuality(keptSurfaceMesh(c, s)).minimumDihedralDegrees;
}
} // namespace

TEST(StraightContourPoints, ANeedleOfTheCorpusIsGone)
{
  const OffReadResult file = readOffFile(PTM_DATA_DIR "/regression/tetgen_needle_at_a_contour.off");
  ASSERT_TRUE(file.ok) << file.error;
  std::ifstream sides(PTM_DATA_DIR "/regression/tetgen_needle_at_a_contour.sides");
  std::vector<int> across;
  for (int other; sides >> other;)
  {
    across.push_back(other);
  }
  ASSERT_EQ(across.size(), file.data.surface.triangles.size());
  const SurfaceComplex before = oneSubdomain(file.data.surface, across);
  const double needle = smallestDihedral(before, 0);
  EXPECT_LT(needle, 0.1) << "the needle this stage is for";

  SurfaceComplex after = before;
  const std::size_t moved = keepStraightContourPointsInside(after);
  double largest = 0;
  for (std::size_t v = 0; v < before.points.size(); ++v)
  {
    largest = std::max(largest, norm(after.points[v] - before.points[v]) / largestCoordinate(before.points[v]));
  }
  const double mended = smallestDihedral(after, 0);
  std::cout << "[ figure ] itemb subdomain 40: " << moved << " contour points moved, by at most " << largest
            << " of their coordinates; smallest dihedral " << needle << " -> " << mended << " degrees\n";
  EXPECT_GE(moved, 1u);
  EXPECT_LE(largest, 1e-13);
  EXPECT_GE(mended, 1.0);
  const std::size_t again = keepStraightContourPointsInside(after);
  EXPECT_EQ(again, 0u) << "nothing left to move";
}

namespace
{
// How many tetrahedra of keptSurfaceMesh of subdomain s have three
// corners on one line: a face whose height is under 1e-9 of its longest edge.
std::size_t needles(const SurfaceComplex& c, int s)
{
  const TetMesh mesh = keptSurfaceMesh(c, s);
  std::size_t count = 0;
  for (const auto& t : mesh.tets)
  {
    bool flat = false;
    for (const Triangle& f : outwardTetrahedronFaces(t))
    {
      const Vec3 &a = mesh.points[f[0]], &b = mesh.points[f[1]], &d = mesh.points[f[2]];
      const double longest = std::max({ norm(b - a), norm(d - b), norm(a - d) });
      flat = flat || norm(cross(b - a, d - a)) <= 1e-9 * longest * longest;
    }
    count += flat ? 1 : 0;
  }
  return count;
}
} // namespace

class StraightContourPointsOnTestSurfaces : public ::testing::TestWithParam<std::tuple<int, CutStrategy>>
{
};

// After the relaxer (which ends with this stage) no subdomain's TetGen mesh
// has a needle, and the stage moved points by rounding only.
TEST_P(StraightContourPointsOnTestSurfaces, NoNeedleAfterRelaxation)
{
  const auto [K, strategy] = GetParam();
  std::size_t pulled = 0;
  for (const NamedSurface& k : namedTestSurfaces())
  {
    std::ostringstream label;
    label << k.name << " K=" << K << " " << toString(strategy);
    const DecompositionResult d = decomposeVolumeBalanced(k.surface, stageCaseOptions(K, strategy));
    ASSERT_TRUE(d.ok) << label.str() << ": " << d.error;
    SurfaceComplex c = d.complex;
    ASSERT_TRUE(triangulateAllInterfaces(c).ok) << label.str();
    const RelaxationResult r = relaxSurfaceComplex(c, RelaxationOptions{});
    ASSERT_TRUE(r.ok) << label.str() << ": " << r.error;
    pulled += r.contourPointsPulledInside;
    EXPECT_LE(std::fabs(r.change.volumeChange), 1e-12) << label.str();
    for (int s = 0; s < K; ++s)
    {
      EXPECT_EQ(needles(c, s), 0u) << label.str() << " subdomain " << s;
    }
  }
  std::cout << "[ figure ] K=" << K << " " << toString(strategy) << ": " << pulled
            << " straight-contour points pulled inside over the test surfaces\n";
}

INSTANTIATE_TEST_SUITE_P(KAndStrategy, StraightContourPointsOnTestSurfaces,
  ::testing::Combine(::testing::Values(8),
    ::testing::Values(CutStrategy::ParallelPlanes, CutStrategy::RecursiveBisection)),
  [](const auto& info) {
    return std::string(toString(std::get<1>(info.param))) + "_K" + std::to_string(std::get<0>(info.param));
  });
