#include "SelfIntersectionCheck.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
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
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
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
