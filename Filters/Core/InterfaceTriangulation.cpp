#include "InterfaceTriangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <set>
#include <sstream>

namespace ptm
{
namespace
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo
{
  Index index = -1;
  double size = 0; // sizing field at the vertex
};
struct FaceInfo
{
  int inside = 0; // 1 inside the region
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
using Point = K::Point_2;
using Face = CDT::Face_handle;
using Vertex = CDT::Vertex_handle;

constexpr double kPi = 3.14159265358979323846;

double minimumAngle(const Point& a, const Point& b, const Point& c)
{
  auto angle = [](const Point& p, const Point& q, const Point& r) {
    const double ux = q.x() - p.x(), uy = q.y() - p.y(), vx = r.x() - p.x(), vy = r.y() - p.y();
    return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  return std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) });
}

// p strictly inside the diametral circle of segment ab
bool encroaches(const Point& p, const Point& a, const Point& b)
{
  return (a.x() - p.x()) * (b.x() - p.x()) + (a.y() - p.y()) * (b.y() - p.y()) < 0;
}

using FaceKey = std::array<Index, 3>;
FaceKey keyOf(Face f)
{
  FaceKey k{ f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index };
  std::sort(k.begin(), k.end());
  return k;
}
} // namespace

InterfaceTriangulationResult triangulateInterface(
  const PlanarRegion& region, const InterfaceTriangulationOptions& options)
{
  InterfaceTriangulationResult result;
  const std::size_t n = region.points.size();
  if (!(options.minimumAngleDegrees > 0 && options.minimumAngleDegrees <= 34) ||
    !(options.maximumEdgeLength >= 0))
  {
    result.error = "invalid options: the minimum angle must lie in (0, 34] degrees and the "
                   "maximum edge length must not be negative";
    return result;
  }
  if (region.edges.size() < 3 || n < 3)
  {
    result.error = "the region has fewer than three boundary segments";
    return result;
  }
  if (!(std::fabs(norm(region.normal) - 1.0) < 1e-9))
  {
    result.error = "the plane normal is not a unit vector";
    return result;
  }
  std::vector<int> degree(n, 0);
  for (const auto& e : region.edges)
  {
    if (e[0] < 0 || e[1] < 0 || e[0] >= static_cast<Index>(n) || e[1] >= static_cast<Index>(n) ||
      e[0] == e[1])
    {
      result.error = "a boundary segment refers to a missing point or is degenerate";
      return result;
    }
    ++degree[e[0]];
    --degree[e[1]];
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (degree[i] != 0)
    {
      std::ostringstream msg;
      msg << "the boundary is not made of closed loops (point " << i
          << " has unequal numbers of incoming and outgoing segments)";
      result.error = msg.str();
      return result;
    }
  }
  Vec3 e1, e2;
  planeBasis(region.normal, e1, e2);
  auto to2D = [&](const Vec3& p) {
    const Vec3 d = p - region.origin;
    return Point(dot(d, e1), dot(d, e2));
  };
  for (const auto& p : region.points)
  {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      result.error = "a boundary point has a NaN or infinite coordinate";
      return result;
    }
  }

  // Local boundary spacing at every boundary point.
  std::vector<double> spacing(n, 0.0);
  std::vector<int> segmentCount(n, 0);
  for (const auto& e : region.edges)
  {
    const double l = norm(region.points[e[1]] - region.points[e[0]]);
    for (Index v : e)
    {
      spacing[v] += l;
      ++segmentCount[v];
    }
  }

  CDT cdt;
  std::vector<Vertex> vertices(n);
  try
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      if (segmentCount[i] == 0)
      {
        continue; // a point no segment uses does not belong to the region
      }
      Vertex v = cdt.insert(to2D(region.points[i]));
      if (v->info().index >= 0)
      {
        std::ostringstream msg;
        msg << "boundary points " << v->info().index << " and " << i
            << " coincide in the plane of the interface";
        result.error = msg.str();
        return result;
      }
      v->info().index = static_cast<Index>(i);
      v->info().size = options.maximumEdgeLength > 0 ? options.maximumEdgeLength
                                                     : spacing[i] / segmentCount[i];
      vertices[i] = v;
    }
    for (const auto& e : region.edges)
    {
      cdt.insert_constraint(vertices[e[0]], vertices[e[1]]);
    }
  }
  catch (const std::exception&)
  {
    result.error = "boundary segments of the interface cross each other";
    return result;
  }
  std::size_t constrained = 0;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
  {
    constrained += cdt.is_constrained(*e) ? 1 : 0;
  }
  std::set<std::pair<Index, Index>> undirected;
  for (const auto& e : region.edges)
  {
    undirected.insert({ std::min(e[0], e[1]), std::max(e[0], e[1]) });
  }
  if (constrained != undirected.size() || undirected.size() != region.edges.size())
  {
    result.error = "a boundary point lies on another boundary segment, or a segment is repeated";
    return result;
  }

  // Inside: the face left of every directed segment, flooded without crossing segments.
  std::vector<Face> stack;
  for (const auto& e : region.edges)
  {
    Face f;
    int i = 0;
    if (!cdt.is_edge(vertices[e[0]], vertices[e[1]], f, i))
    {
      result.error = "internal: a boundary segment is missing from the triangulation";
      return result;
    }
    // in face f, the edge opposite vertex i runs ccw(i) -> cw(i)
    if (f->vertex(CDT::ccw(i)) != vertices[e[0]])
    {
      const Face g = f->neighbor(i);
      f = g;
    }
    stack.push_back(f);
  }
  while (!stack.empty())
  {
    Face f = stack.back();
    stack.pop_back();
    if (f->info().inside)
    {
      continue;
    }
    if (cdt.is_infinite(f))
    {
      result.error = "the loops are not consistently oriented (the region to their left is unbounded)";
      return result;
    }
    f->info().inside = 1;
    for (int i = 0; i < 3; ++i)
    {
      if (!f->is_constrained(i) && !f->neighbor(i)->info().inside)
      {
        stack.push_back(f->neighbor(i));
      }
    }
  }
  for (const auto& e : region.edges)
  {
    // the face right of each segment must be outside: else loops disagree in orientation
    Face f;
    int i = 0;
    cdt.is_edge(vertices[e[0]], vertices[e[1]], f, i);
    const Face right = f->vertex(CDT::ccw(i)) == vertices[e[0]] ? f->neighbor(i) : f;
    if (right->info().inside)
    {
      result.error = "the loops are not consistently oriented (a segment has the region on both sides)";
      return result;
    }
  }

  // Refinement.
  const double bound = options.minimumAngleDegrees * kPi / 180.0;
  double area = 0;
  double smallestSize = std::numeric_limits<double>::infinity();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info().inside)
    {
      area += std::fabs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (segmentCount[i])
    {
      smallestSize = std::min(smallestSize, vertices[i]->info().size);
    }
  }
  // Automatic sizing grows inward from the boundary spacing by a quarter of
  // the distance, up to 1.5 x the region's mean boundary spacing, so the
  // interface keeps the resolution of the surface around it.
  const double gradation = 0.25;
  double meanSpacing = 0;
  for (const auto& e : region.edges)
  {
    meanSpacing += norm(region.points[e[1]] - region.points[e[0]]);
  }
  meanSpacing /= static_cast<double>(region.edges.size());
  const double largestSize = 1.5 * meanSpacing;
  const std::size_t cap = static_cast<std::size_t>(
    std::min(2e7, 50.0 * area / (smallestSize * smallestSize) + 20.0 * n + 100));
  auto faceSize = [&](Face f) {
    return (f->vertex(0)->info().size + f->vertex(1)->info().size + f->vertex(2)->info().size) / 3.0;
  };
  // badness: < 0 good; larger is worse. Angle deficit first, then size excess.
  auto badness = [&](Face f) {
    const Point& a = f->vertex(0)->point();
    const Point& b = f->vertex(1)->point();
    const Point& c = f->vertex(2)->point();
    const double angle = minimumAngle(a, b, c);
    if (angle < bound)
    {
      return 1.0 + (bound - angle);
    }
    const double radius = std::sqrt(CGAL::squared_radius(a, b, c));
    const double allowed = 0.7 * faceSize(f);
    return radius > allowed ? (radius / allowed - 1.0) * 1e-3 : -1.0;
  };
  using Entry = std::pair<double, FaceKey>;
  auto worse = [](const Entry& x, const Entry& y) {
    return x.first < y.first || (x.first == y.first && x.second > y.second);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(worse)> queue(worse);
  std::map<FaceKey, Face> live;
  auto consider = [&](Face f) {
    if (cdt.is_infinite(f) || !f->info().inside)
    {
      return;
    }
    const double b = badness(f);
    if (b > 0)
    {
      const FaceKey key = keyOf(f);
      live[key] = f;
      queue.push({ b, key });
    }
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    consider(f);
  }
  std::set<FaceKey> unfixable;
  std::vector<Point> added;
  // Whether p can be inserted: strictly inside the region and encroaching no segment.
  auto safe = [&](const Point& p, Face hint, Face& located) {
    CDT::Locate_type lt;
    int li = 0;
    located = cdt.locate(p, lt, li, hint);
    if (lt != CDT::FACE || cdt.is_infinite(located) || !located->info().inside)
    {
      return false;
    }
    std::vector<Face> conflicts;
    cdt.get_conflicts(p, std::back_inserter(conflicts), located);
    for (Face f : conflicts)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (f->is_constrained(i) &&
          encroaches(p, f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point()))
        {
          return false;
        }
      }
    }
    return true;
  };
  auto insertAt = [&](const Point& p, Face located, const std::array<Vertex, 3>& around) {
    Vertex v = cdt.insert(p, located);
    v->info().index = static_cast<Index>(n + added.size());
    double size = std::numeric_limits<double>::infinity();
    for (const Vertex& w : around)
    {
      size = std::min(size, w->info().size + gradation * std::sqrt(CGAL::squared_distance(p, w->point())));
    }
    v->info().size = options.maximumEdgeLength > 0 ? options.maximumEdgeLength : std::min(size, largestSize);
    added.push_back(p);
    auto f = cdt.incident_faces(v), done = f;
    do
    {
      f->info().inside = 1;
    } while (++f != done);
    do
    {
      consider(f);
    } while (++f != done);
  };
  while (!queue.empty() && added.size() < cap)
  {
    const Entry top = queue.top();
    queue.pop();
    auto it = live.find(top.second);
    if (it == live.end())
    {
      continue;
    }
    Face f = it->second;
    if (keyOf(f) != top.second || badness(f) != top.first)
    {
      live.erase(it); // stale: the face was destroyed or changed
      continue;
    }
    live.erase(it);
    const std::array<Vertex, 3> around{ f->vertex(0), f->vertex(1), f->vertex(2) };
    const Point centre = CGAL::circumcenter(around[0]->point(), around[1]->point(), around[2]->point());
    Face located;
    if (safe(centre, f, located))
    {
      insertAt(centre, located, around);
      continue;
    }
    // A point in front of the segment that the circumcentre encroaches or lies
    // behind: the apex of a near-equilateral triangle on it, inside the region.
    bool inserted = false;
    std::vector<Face> conflicts;
    CDT::Locate_type lt;
    int li = 0;
    Face where = cdt.locate(centre, lt, li, f);
    std::vector<std::pair<Vertex, Vertex>> segments;
    for (int i = 0; i < 3; ++i)
    {
      if (f->is_constrained(i))
      {
        segments.push_back({ f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i)) });
      }
    }
    if (lt == CDT::FACE && !cdt.is_infinite(where))
    {
      cdt.get_conflicts(centre, std::back_inserter(conflicts), where);
      for (Face g : conflicts)
      {
        for (int i = 0; i < 3; ++i)
        {
          if (g->is_constrained(i) &&
            encroaches(centre, g->vertex(CDT::ccw(i))->point(), g->vertex(CDT::cw(i))->point()))
          {
            const bool gInside = g->info().inside;
            segments.push_back(gInside ? std::make_pair(g->vertex(CDT::ccw(i)), g->vertex(CDT::cw(i)))
                                       : std::make_pair(g->vertex(CDT::cw(i)), g->vertex(CDT::ccw(i))));
          }
        }
      }
    }
    for (const auto& [a, b] : segments)
    {
      // the inside is to the left of a -> b
      const double dx = b->point().x() - a->point().x(), dy = b->point().y() - a->point().y();
      const double length = std::sqrt(dx * dx + dy * dy);
      const double height = 0.75 * length;
      const Point apex((a->point().x() + b->point().x()) / 2 - dy / length * height,
        (a->point().y() + b->point().y()) / 2 + dx / length * height);
      if (safe(apex, f, located))
      {
        insertAt(apex, located, around);
        inserted = true;
        break;
      }
    }
    if (!inserted)
    {
      unfixable.insert(top.second);
    }
  }

  // Output.
  InterfaceTriangulation& t = result.triangulation;
  for (const Point& p : added)
  {
    t.newPoints.push_back(region.origin + p.x() * e1 + p.y() * e2);
  }
  t.minimumAngleDegrees = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!f->info().inside)
    {
      continue;
    }
    t.triangles.push_back({ f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index });
    const double angle = minimumAngle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) * 180.0 / kPi;
    t.minimumAngleDegrees = std::min(t.minimumAngleDegrees, angle);
    t.trianglesBelowMinimumAngle += angle < options.minimumAngleDegrees ? 1 : 0;
    for (int i = 0; i < 3; ++i)
    {
      if (f->is_constrained(i) &&
        encroaches(f->vertex(i)->point(), f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point()))
      {
        ++t.encroachedSegmentsLeft;
      }
    }
  }
  // deterministic order: rotate each triangle to its smallest index, then sort
  for (auto& tri : t.triangles)
  {
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
  }
  std::sort(t.triangles.begin(), t.triangles.end());
  result.ok = true;
  return result;
}
} // namespace ptm
