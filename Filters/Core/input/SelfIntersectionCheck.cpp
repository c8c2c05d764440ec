#include "SelfIntersectionCheck.h"

#include "UnionFind.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <unordered_set>
#include <vector>

namespace ptm
{
namespace
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Stops the search once enough pairs are found.
struct Enough
{
};

// Whether orienting the soup split a point of one of the triangles `among`
// (it renumbers the split copies).
bool splitAtAny(const std::vector<std::vector<std::size_t>>& before,
  const std::vector<std::vector<std::size_t>>& after, const std::vector<Index>& among)
{
  for (Index f : among)
  {
    std::vector<std::size_t> a = before[f], b = after[f];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b)
    {
      return true;
    }
  }
  return false;
}

// A side of a triangle, as the edge it runs along.
struct HalfEdge
{
  Index lo, hi;
  bool forward;       // runs from lo to hi
  std::size_t corner; // 3 t + c: corner c of triangle t, where the half-edge starts
  bool operator<(const HalfEdge& o) const
  {
    return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : forward < o.forward;
  }
};

// Every triangle's half-edges, sorted by edge (the sides of one edge
// adjacent) and direction.
std::vector<HalfEdge> sortedHalfEdges(const TriangleSurface& s)
{
  std::vector<HalfEdge> halves;
  halves.reserve(3 * s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Index a = s.triangles[t][c], b = s.triangles[t][(c + 1) % 3];
      halves.push_back({ std::min(a, b), std::max(a, b), a < b, 3 * t + c });
    }
  }
  std::sort(halves.begin(), halves.end());
  return halves;
}

// The end of the run of half-edges of the edge halves[i] is on.
std::size_t endOfEdge(const std::vector<HalfEdge>& halves, std::size_t i)
{
  std::size_t j = i + 1;
  while (j < halves.size() && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi)
  {
    ++j;
  }
  return j;
}

// Whether the triangles already form an oriented manifold mesh (boundary
// allowed), as CGAL's is_polygon_soup_a_polygon_mesh decides, from one sort
// of the half-edges instead of its ordered edge set and per-vertex walks:
// that test took 56 % of every check, 1.1 s per rank on the 10 M ball at
// K = 2 (perf). No corner repeated in a triangle, no half-edge twice, and
// the corners at every point joined across shared edges into one fan. True
// means CGAL would say so too; false sends the soup to CGAL's own test.
bool isOrientedManifold(const TriangleSurface& s, const std::vector<HalfEdge>& halves)
{
  if (std::any_of(halves.begin(), halves.end(), [](const HalfEdge& h) { return h.lo == h.hi; }))
  {
    return false;
  }
  UnionFind corners(halves.size());
  auto next = [](std::size_t corner) { return corner - corner % 3 + (corner % 3 + 1) % 3; };
  for (std::size_t i = 0; i < halves.size();)
  {
    const std::size_t j = endOfEdge(halves, i);
    if (j - i > 2 || (j - i == 2 && halves[i].forward == halves[i + 1].forward))
    {
      return false; // an edge of three triangles, or two running the same way
    }
    if (j - i == 2)
    {
      // a to b in one triangle, b to a in the other: join the corners at a, and at b
      const std::size_t one = halves[i].corner, other = halves[i + 1].corner;
      corners.unite(one, next(other));
      corners.unite(next(one), other);
    }
    i = j;
  }
  std::vector<std::size_t> fanOf(s.points.size(), SIZE_MAX);
  for (std::size_t corner = 0; corner < halves.size(); ++corner)
  {
    const Index v = s.triangles[corner / 3][corner % 3];
    const std::size_t root = corners.find(corner);
    if (v < 0 || static_cast<std::size_t>(v) >= fanOf.size())
    {
      return false;
    }
    if (fanOf[v] == SIZE_MAX)
    {
      fanOf[v] = root;
    }
    else if (fanOf[v] != root)
    {
      return false; // two fans meet at v
    }
  }
  return true;
}

// Below this sine of the angle between two triangles at their shared edge
// they lie in one plane to round-off: a 1e-9 radian wedge is no feature of
// any real part, while the folds below come out at 1e-14.
constexpr double kFoldSine = 1e-9;

// Whether the triangles (a, b, c) and (b, a, d) or (a, b, d) on edge ab
// fold onto each other: c and d on the same side of the edge, the angle
// between the triangles (0 to 180 degrees, whatever their orientation)
// below kFoldSine. A triangle with no width across ab is left to the
// checks of degenerate triangles.
bool folded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3 e = b - a;
  const double ee = dot(e, e);
  if (!(ee > 0))
  {
    return false;
  }
  const Vec3 uc = (c - a) - (dot(c - a, e) / ee) * e; // c's offset across the edge
  const Vec3 ud = (d - a) - (dot(d - a, e) / ee) * e;
  const double lengths = norm(uc) * norm(ud);
  return lengths > 0 && dot(uc, ud) > 0 && norm(cross(uc, ud)) < kFoldSine * lengths;
}

// Pairs of triangles that share an edge and fold onto each other (folded),
// with one of them in `among` (all if empty), up to `limit`. CGAL counts
// such a pair as crossing only when the four points are exactly coplanar;
// where a cut makes them coplanar to round-off, the surface is a wedge of
// no thickness that TetGen fills with a flat tetrahedron (DOLFIN's aneurysm
// at K = 64, bisection: two interfaces of subdomain 26 in one plane to
// 2e-15, a tetrahedron of volume 1.4e-17 and dihedral 0.00 degrees).
std::vector<std::pair<Index, Index>> foldedPairs(const TriangleSurface& s, const std::vector<HalfEdge>& halves,
  const std::vector<Index>& among, std::size_t limit)
{
  const std::unordered_set<Index> listed(among.begin(), among.end());
  auto third = [&](const HalfEdge& h) { return s.points[s.triangles[h.corner / 3][(h.corner % 3 + 2) % 3]]; };
  std::vector<std::pair<Index, Index>> found;
  for (std::size_t i = 0; i < halves.size() && found.size() < limit;)
  {
    const std::size_t j = endOfEdge(halves, i);
    // an edge of more triangles is not a manifold surface's, which CGAL's orientation handles
    if (j - i == 2)
    {
      const Index f = static_cast<Index>(halves[i].corner / 3), g = static_cast<Index>(halves[i + 1].corner / 3);
      if ((listed.empty() || listed.count(f) || listed.count(g)) &&
        folded(s.points[halves[i].lo], s.points[halves[i].hi], third(halves[i]), third(halves[i + 1])))
      {
        found.emplace_back(f, g);
      }
    }
    i = j;
  }
  return found;
}

// Pairs among the triangles `among` (all if empty). A soup that is not a
// polygon mesh is oriented first, which splits its non-manifold points;
// with `patch`, the check is off if that split a point of `among`.
SelfIntersectionReport checkSoup(
  const TriangleSurface& s, const std::vector<Index>& among, std::size_t limit, bool patch)
{
  SelfIntersectionReport report;
  std::vector<K::Point_3> points;
  points.reserve(s.points.size());
  for (const auto& p : s.points)
  {
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(s.triangles.size());
  for (const auto& t : s.triangles)
  {
    polygons.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
      static_cast<std::size_t>(t[2]) });
  }
  // the soup's faces keep their order in the mesh, so face i is triangle i
  const std::vector<HalfEdge> halves = sortedHalfEdges(s); // for both tests of the soup's edges
  if (!isOrientedManifold(s, halves) && !PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    const std::vector<std::vector<std::size_t>> before = patch ? polygons : std::vector<std::vector<std::size_t>>();
    PMP::orient_polygon_soup(points, polygons); // duplicates non-manifold points
    if (patch && splitAtAny(before, polygons, among))
    {
      report.note = "the patch splits at a corner of a triangle checked";
      return report;
    }
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    {
      report.note = "the surface is not a manifold polygon mesh";
      return report;
    }
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (mesh.number_of_faces() != s.triangles.size())
  {
    report.note = "the surface could not be converted to a mesh";
    return report;
  }
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  struct Collector
  {
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>>* out;
    std::size_t limit;
    Collector& operator*() { return *this; }
    Collector& operator++() { return *this; }
    Collector operator++(int) { return *this; }
    Collector& operator=(const std::pair<Mesh::Face_index, Mesh::Face_index>& p)
    {
      out->push_back(p);
      if (out->size() >= limit)
      {
        throw Enough();
      }
      return *this;
    }
  };
  try
  {
    if (among.empty())
    {
      PMP::self_intersections(mesh, Collector{ &pairs, std::max<std::size_t>(limit, 1) });
    }
    else
    {
      std::vector<Mesh::Face_index> range;
      range.reserve(among.size());
      for (Index f : among)
      {
        range.push_back(Mesh::Face_index(static_cast<Mesh::size_type>(f)));
      }
      PMP::self_intersections(range, mesh, Collector{ &pairs, std::max<std::size_t>(limit, 1) });
    }
  }
  catch (const Enough&)
  {
  }
  if (pairs.empty())
  {
    for (const auto& [f, g] : foldedPairs(s, halves, among, std::max<std::size_t>(limit, 1)))
    {
      pairs.emplace_back(Mesh::Face_index(static_cast<Mesh::size_type>(f)),
        Mesh::Face_index(static_cast<Mesh::size_type>(g)));
      report.folds += 1;
    }
  }
  report.checked = true;
  report.intersects = !pairs.empty();
  report.pairs = pairs.size();
  if (!pairs.empty())
  {
    report.firstTriangle = static_cast<Index>(pairs.front().first);
    report.secondTriangle = static_cast<Index>(pairs.front().second);
  }
  for (const auto& [f, g] : pairs)
  {
    report.crossings.emplace_back(static_cast<Index>(f), static_cast<Index>(g));
  }
  return report;
}
} // namespace

SelfIntersectionReport checkSelfIntersection(const TriangleSurface& s, std::size_t limit)
{
  return checkSoup(s, std::vector<Index>(), limit, false);
}

SelfIntersectionReport checkSelfIntersection(
  const TriangleSurface& s, const std::vector<Index>& among, std::size_t limit)
{
  return checkSoup(s, among, limit, false);
}

SelfIntersectionReport checkPatchSelfIntersection(
  const TriangleSurface& patch, const std::vector<Index>& among, std::size_t limit)
{
  return checkSoup(patch, among, limit, true);
}
} // namespace ptm
