#include "SurfaceDistance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ptm
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalTriangle = Kernel::Triangle_3;
using Face = std::array<std::size_t, 3>;
using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
namespace PMP = CGAL::Polygon_mesh_processing;

// A surface as CGAL samples and measures it: area and total edge length
// (every triangle's three edges), since the grid sampling puts about
// area / h^2 samples in the faces and length / h on the edges (CAD
// tessellations' long thin triangles make the second term the larger: 1.5
// million samples on the coarse OCCT bottle when only the area was counted).
struct Soup
{
  std::vector<Point> points;
  std::vector<Face> faces;
  std::vector<CgalTriangle> triangles;
  double area = 0;
  double edges = 0;
};

Soup soupOf(const TriangleSurface& s)
{
  Soup soup;
  soup.points.reserve(s.points.size());
  for (const Vec3& p : s.points)
  {
    soup.points.emplace_back(p[0], p[1], p[2]);
  }
  const Index n = static_cast<Index>(s.points.size());
  for (const Triangle& t : s.triangles)
  {
    const bool inRange = t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[0] < n && t[1] < n && t[2] < n;
    if (!inRange || t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
      continue;
    }
    soup.faces.push_back(
      { static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]) });
    const CgalTriangle& c = soup.triangles.emplace_back(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
    soup.area += std::sqrt(std::max(0.0, c.squared_area()));
    for (int k = 0; k < 3; ++k)
    {
      soup.edges += std::sqrt(CGAL::squared_distance(c.vertex(k), c.vertex(k + 1)));
    }
  }
  return soup;
}

// The spacing h at which area / h^2 + edges / h = samples.
double spacingFor(const Soup& s, double samples)
{
  if (!(s.area > 0))
  {
    return 0.0;
  }
  const double x = (-s.edges + std::sqrt(s.edges * s.edges + 4 * s.area * samples)) / (2 * s.area);
  return x > 0 ? 1.0 / x : 0.0;
}

// Largest distance from the samples of `from` to the triangles of `to`.
double largestDistance(const Soup& from, const Soup& to, double spacing, double stopAbove)
{
  if (from.faces.empty() || to.triangles.empty())
  {
    return 0.0;
  }
  std::vector<Point> samples;
  PMP::sample_triangle_soup(from.points, from.faces, std::back_inserter(samples),
    CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing));
  // Also every corner, edge midpoint and centroid: where the grid is wider
  // than the triangles (a CAD input's total edge length takes the samples),
  // it hit little but corners. OCCT's hammer.iges remeshed at 103: the grid
  // 85 apart, the remeshed surface "1e-11" from the input.
  for (const CgalTriangle& t : from.triangles)
  {
    samples.push_back(t.vertex(0));
    samples.push_back(CGAL::midpoint(t.vertex(0), t.vertex(1)));
    samples.push_back(CGAL::centroid(t));
  }
  Tree tree(to.triangles.begin(), to.triangles.end());
  tree.accelerate_distance_queries();
  double worst = 0;
  const double stop = stopAbove * stopAbove;
  for (const Point& p : samples)
  {
    worst = std::max(worst, tree.squared_distance(p));
    if (worst > stop)
    {
      break;
    }
  }
  return std::sqrt(worst);
}
} // namespace

TwoSidedDistance sampledTwoSidedDistance(const TriangleSurface& first, const TriangleSurface& second,
  double minimumSpacing, double maximumSamples, double stopAbove)
{
  const Soup a = soupOf(first), b = soupOf(second);
  TwoSidedDistance d;
  d.sampleSpacing = std::max({ minimumSpacing, spacingFor(a, maximumSamples), spacingFor(b, maximumSamples) });
  if (!(d.sampleSpacing > 0))
  {
    return d;
  }
  d.firstToSecond = largestDistance(a, b, d.sampleSpacing, stopAbove);
  d.secondToFirst = largestDistance(b, a, d.sampleSpacing, stopAbove);
  return d;
}
} // namespace ptm
