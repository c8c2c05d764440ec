#include "SelfIntersectionCheck.h"

#include "UnionFind.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
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

// Whether the triangles already form an oriented manifold mesh (boundary
// allowed), as CGAL's is_polygon_soup_a_polygon_mesh decides, from one sort
// of the half-edges instead of its ordered edge set and per-vertex walks:
// that test took 56 % of every check, 1.1 s per rank on the 10 M ball at
// K = 2 (perf). No corner repeated in a triangle, no half-edge twice, and
// the corners at every point joined across shared edges into one fan. True
// means CGAL would say so too; false sends the soup to CGAL's own test.
bool isOrientedManifold(const TriangleSurface& s)
{
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
  std::vector<HalfEdge> halves;
  halves.reserve(3 * s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Index a = s.triangles[t][c], b = s.triangles[t][(c + 1) % 3];
      if (a == b)
      {
        return false;
      }
      halves.push_back({ std::min(a, b), std::max(a, b), a < b, 3 * t + c });
    }
  }
  std::sort(halves.begin(), halves.end());
  UnionFind corners(halves.size());
  auto next = [](std::size_t corner) { return corner - corner % 3 + (corner % 3 + 1) % 3; };
  for (std::size_t i = 0; i < halves.size();)
  {
    std::size_t j = i + 1;
    while (j < halves.size() && halves[j].lo == halves[i].lo && halves[j].hi == halves[i].hi)
    {
      ++j;
    }
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
  if (!isOrientedManifold(s) && !PMP::is_polygon_soup_a_polygon_mesh(polygons))
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
