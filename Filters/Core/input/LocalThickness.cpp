#include "LocalThickness.h"

#include "PointSamples.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_incremental_neighbor_search.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>

namespace ptm
{
namespace
{
/// @name Rays inward
/// @{
// A wall's far side faces back: its outward normal within this angle of
// the ray. Hits on a surface that meets the ray more obliquely are the
// other side of a wedge (a sharp edge), not of a wall, and give no sample.
// Measured at K = 16 (2 ranks, the sweep's sizes): counting every hit (90
// degrees) took CGAL's coarse triple torus, whose arms are prisms thinner
// than the size, from 84,064 to 515,643 tetrahedra (0.17 -> 0.36 % under
// 10 degrees; serial TetGen -pq: 79,053, 0.44 %) and OpenSCAD's
// example001 from 136,482 to 316,087; 45 degrees still gave the torus
// 518,137. With 30 both stay as they were and the printer bed keeps its
// gain (Cura's BIQU_SSS: 2.19 % under 10 degrees, 275,307 tetrahedra).
constexpr double kFacingAngle = 30.0;
const double kFacingCosine = std::cos(kFacingAngle * kPi / 180.0);
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalTriangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Rays start about `spacing` apart: in rows parallel to a triangle's
// longest edge, so a long thin triangle (a CAD export's cylinder wall) gets
// rays along its length only, not n^2 / 2 of them over a sliver (that cost
// 2.4 s on OCCT's Bottom, 31,000 triangles). At most kMaxRays rows, and
// rays per row, so a huge triangle cannot cost millions.
constexpr int kMaxRays = 64;

int raysAcross(double length, double spacing)
{
  return std::clamp(static_cast<int>(std::ceil(length / spacing)), 1, kMaxRays);
}

// Where the rays of triangle abc start: rows between its longest edge and
// the opposite corner, each split evenly; every point lies strictly inside,
// so no ray starts on a neighbour.
void rayOrigins(Vec3 a, Vec3 b, Vec3 c, double spacing, std::vector<Vec3>& origins)
{
  origins.clear();
  if (norm(c - b) > norm(b - a) && norm(c - b) >= norm(a - c))
  {
    std::swap(a, c); // bc longest: a becomes the far corner
  }
  else if (norm(a - c) > norm(b - a))
  {
    std::swap(b, c); // ca longest
  }
  const Vec3 ab = b - a;
  const double length = norm(ab);
  const double height = norm(cross(ab, c - a)) / length;
  const int rows = raysAcross(height, spacing);
  for (int j = 0; j < rows; ++j)
  {
    const double up = (j + 0.5) / rows;
    const Vec3 left = a + up * (c - a), right = b + up * (c - b);
    const int count = raysAcross((1.0 - up) * length, spacing);
    for (int i = 0; i < count; ++i)
    {
      origins.push_back(left + ((i + 0.5) / count) * (right - left));
    }
  }
}

// The distance from `origin` along `direction` (unit, the inward normal of
// triangle `self`) to the first other triangle within `limit`, if that
// triangle faces back (its outward normal within kFacingAngle of the ray's
// direction: the far side of a wall); +inf otherwise. A segment of that
// length, not a ray: the tree then opens only the boxes near it (an
// unbounded ray cost 330 us each on OCCT's Bottom, 31,000 long thin
// triangles).
double firstHit(const Tree& tree, const std::vector<CgalTriangle>& triangles, std::size_t self,
  const Vec3& origin, const Vec3& direction, double limit)
{
  const Vec3 end = origin + limit * direction;
  const Point o(origin[0], origin[1], origin[2]);
  const Kernel::Segment_3 query(o, Point(end[0], end[1], end[2]));
  const TriangleIterator mine = triangles.begin() + static_cast<std::ptrdiff_t>(self);
  double nearest = std::numeric_limits<double>::infinity();
  TriangleIterator nearestId = mine;
  std::vector<Tree::Intersection_and_primitive_id<Kernel::Segment_3>::Type> hits;
  tree.all_intersections(query, std::back_inserter(hits));
  for (const auto& [where, id] : hits)
  {
    double d = std::numeric_limits<double>::infinity();
    if (const Point* p = boost::get<Point>(&where))
    {
      d = std::sqrt(CGAL::squared_distance(o, *p));
    }
    else if (const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&where))
    {
      d = std::sqrt(std::min(CGAL::squared_distance(o, s->source()), CGAL::squared_distance(o, s->target())));
    }
    if (id != mine && (d < nearest || (d == nearest && id < nearestId)))
    {
      nearest = d;
      nearestId = id;
    }
  }
  if (nearestId == mine)
  {
    return std::numeric_limits<double>::infinity();
  }
  const Kernel::Vector_3 n = CGAL::normal(nearestId->vertex(0), nearestId->vertex(1), nearestId->vertex(2));
  const double length = std::sqrt(n.squared_length());
  const double facing = (n.x() * direction[0] + n.y() * direction[1] + n.z() * direction[2]) / length;
  return length > 0 && facing >= kFacingCosine ? nearest : std::numeric_limits<double>::infinity();
}
/// @}

/// @name The capped field
/// @{
using Search = CGAL::Orthogonal_incremental_neighbor_search<PointSamples::Traits>;

// The samples in a k-d tree, visited nearest first until no farther one can
// give less: a sample at distance d gives at least thinnest + g d. A grid
// of cubes was tried first: on a sheet thinner than its cubes by 100 x
// (Prusa's aq_bed) each query visited some 400,000 samples.
class ThicknessField
{
public:
  ThicknessField(const std::vector<double>& xyzt, double limit)
    : Limit(limit)
    , Samples(xyzt)
  {
    for (std::size_t i = 0; i < this->Samples.size(); ++i)
    {
      this->Thinnest = std::min(this->Thinnest, this->Samples.value(i));
    }
  }

  // +inf where no sample counts
  double At(const Vec3& p) const
  {
    double best = std::numeric_limits<double>::infinity();
    const Search search(this->Samples.tree(), PointSamples::Point(p[0], p[1], p[2]), 0.0, true,
      Search::Distance(this->Samples.map()));
    for (auto it = search.begin(); it != search.end(); ++it)
    {
      const double d = std::sqrt(it->second);
      if (this->Thinnest + kThicknessGradation * d >= std::min(best, this->Limit))
      {
        break;
      }
      best = std::min(best, this->Samples.value(it->first) + kThicknessGradation * d);
    }
    return best; // never under the floor: no sample is thinner
  }

private:
  double Limit;
  double Thinnest = std::numeric_limits<double>::infinity();
  PointSamples Samples;
};
/// @}
} // namespace

std::vector<double> thicknessSamples(const TriangleSurface& s, double limit, std::size_t first, std::size_t end)
{
  std::vector<double> xyzt;
  if (!(limit > 0) || s.triangles.empty())
  {
    return xyzt;
  }
  std::vector<CgalTriangle> triangles;
  triangles.reserve(s.triangles.size());
  for (const Triangle& t : s.triangles)
  {
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    triangles.emplace_back(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]), Point(c[0], c[1], c[2]));
  }
  Tree tree(triangles.begin(), triangles.end());
  // A wall thinner than the cap's floor cannot be followed anyway, and
  // capping at the floor around it only packs tiny triangles beside coarse
  // ones: CGAL's double torus, whose surface nearly touches itself at one
  // place (207 samples under 1e-3 of the size), went from 0.70 to 3.72 % of
  // its tetrahedra under 10 degrees at K = 16 with those samples, 0.70 %
  // without; Cura's bed, 2.18 and 2.21 %.
  const double thinnestCounted = std::max(1e-9 * boundingBoxDiagonal(s.points), kThicknessFloor * limit);
  std::vector<Vec3> origins;
  for (std::size_t t = first; t < std::min(end, s.triangles.size()); ++t)
  {
    const Vec3 &a = s.points[s.triangles[t][0]], &b = s.points[s.triangles[t][1]], &c = s.points[s.triangles[t][2]];
    const Vec3 inward = -1.0 * normalized(cross(b - a, c - a));
    if (!(norm(inward) > 0))
    {
      continue; // a degenerate triangle has no inward direction
    }
    // first limit / 2 apart; where a wall turns out thinner, again at its
    // thickness, so the cap between two samples is not much above it
    double spacing = 0.5 * limit;
    for (int pass = 0; pass < 2; ++pass)
    {
      double thinnest = std::numeric_limits<double>::infinity();
      rayOrigins(a, b, c, spacing, origins);
      for (const Vec3& o : origins)
      {
        const double d = firstHit(tree, triangles, t, o, inward, limit);
        if (d >= thinnestCounted && d < limit)
        {
          xyzt.insert(xyzt.end(), { o[0], o[1], o[2], d });
          thinnest = std::min(thinnest, d);
        }
      }
      if (!(thinnest < 0.5 * spacing)) // thinnest is at least the floor
      {
        break;
      }
      spacing = thinnest;
    }
  }
  return xyzt;
}

SizeFunction thicknessCappedSize(const SizeFunction& base, const std::vector<double>& xyzt, double limit)
{
  if (xyzt.size() < 4 || !(limit > 0))
  {
    return base;
  }
  auto field = std::make_shared<const ThicknessField>(xyzt, limit);
  return [field, base](const Vec3& p) {
    const double thin = field->At(p);
    if (!base)
    {
      return thin;
    }
    const double b = base(p);
    return b > 0 && b < thin ? b : thin;
  };
}
} // namespace ptm
