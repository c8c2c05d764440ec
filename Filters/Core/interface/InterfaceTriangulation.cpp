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
  double size = 0;    // sizing field at the vertex
  double allowed = 0; // longest edge its triangles may have: the size, or 1.3 x an automatic size
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

double faceAngle(Face f)
{
  return minimumAngle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
}

double longestEdge(const Point& a, const Point& b, const Point& c)
{
  return std::sqrt(std::max(
    { CGAL::squared_distance(a, b), CGAL::squared_distance(b, c), CGAL::squared_distance(c, a) }));
}

// How far the triangles around v (a new point, never a boundary point) would
// fall short of the angle bound if v stood at p: the sum of the deficits, then (negated, as a tie-break) the
// smallest angle; infinite if one of them would be inverted or degenerate,
// or would get an edge longer than both the size allows (the mean of its
// corners' allowed lengths) and it has now.
std::pair<double, double> starShortfallAt(
  const CDT& cdt, Vertex v, const Point& p, Index boundaryCount, double bound)
{
  double deficit = 0, worst = kPi;
  auto f = cdt.incident_faces(v), done = f;
  do
  {
    const int i = f->index(v);
    const Vertex va = f->vertex(CDT::ccw(i)), vb = f->vertex(CDT::cw(i));
    const Point& a = va->point();
    const Point& b = vb->point();
    const double allowed = (v->info().allowed + va->info().allowed + vb->info().allowed) / 3.0;
    const double longest = longestEdge(p, a, b);
    if (CGAL::orientation(p, a, b) != CGAL::LEFT_TURN ||
      (longest > allowed && longest > longestEdge(v->point(), a, b)))
    {
      return { std::numeric_limits<double>::infinity(), 0 };
    }
    const double angle = minimumAngle(p, a, b);
    // a triangle with a boundary point may be forced to be poor by the
    // boundary; one without may not, so a move must not make it poor
    if (angle < bound && va->info().index >= boundaryCount && vb->info().index >= boundaryCount &&
      minimumAngle(v->point(), a, b) >= bound)
    {
      return { std::numeric_limits<double>::infinity(), 0 };
    }
    deficit += std::max(0.0, bound - angle);
    worst = std::min(worst, angle);
  } while (++f != done);
  return { deficit, -worst };
}

// At most kMovesPerStep moves per step length: the step scales with the
// nearest neighbour, and where that is a hair away in a wide star the
// search crept across it in ever tinier gains (a fuzzed 7-point surface
// spent 11.6 s here, Release, in 14 triangles; capped, 36 ms). Real
// input never comes near the cap: at 32 it changed the interfaces of
// CGAL's oblong at K = 16 parallel planes, and TetGen then crashed on
// one subdomain; at 2048 every corpus mesh is as without a cap.
constexpr int kMovesPerStep = 2048;

// No new point nearer than this fraction of the region's diagonal to a
// vertex of its conflict zone, whatever the bad face's own edges. A
// boundary with a segment of 1e-14 of the diagonal (a fuzzed 26-point
// surface, cut with snapping, in the cutter's self-intersection check)
// otherwise drew the refinement into points 1e-9 to 1e-11 apart, where
// the inexact circumcentres stop improving anything: 53,208 points in
// 40 s, Release. With a floor of 1e-12 it gives 708 points in 10 ms, and
// 1e-10 gives 587. Faces on so short a segment stay poor, as they would
// anyway: boundary segments are never split. Real boundaries have no
// feature near 1e-10 of the diagonal (float STL keeps about 1e-7).
constexpr double kClearanceFloor = 1e-10;

// How far over a size field an edge may be (InterfaceMesher::setSize).
constexpr double kFieldAllowance = 1.4;

// The new vertices of the region's triangles under the angle bound, in index order.
std::map<Index, Vertex> movableVertices(const CDT& cdt, Index boundaryCount, double bound)
{
  std::map<Index, Vertex> movable;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info().inside && faceAngle(f) < bound)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (f->vertex(i)->info().index >= boundaryCount)
        {
          movable[f->vertex(i)->info().index] = f->vertex(i);
        }
      }
    }
  }
  return movable;
}

// Moves v where its star falls least short of the angle bound, among the
// centroid of its neighbours and the points a pattern search reaches;
// whether it moved.
bool moveToBetterPoint(CDT& cdt, Vertex v, Index boundaryCount, double bound)
{
  const Point start = v->point();
  auto best = starShortfallAt(cdt, v, start, boundaryCount, bound);
  Point bestPoint = start;
  // A move may lower the sum of the deficits only if it does not make the
  // star's worst triangle worse (below the bound): otherwise it would
  // trade several poor triangles for one sliver, such as a point pushed
  // almost onto a boundary segment.
  const double worstFloor = std::min(-best.second, bound);
  auto better = [&](const std::pair<double, double>& candidate) {
    return -candidate.second >= worstFloor && candidate < best;
  };
  // candidates: the centroid of the neighbours, then a pattern search
  double cx = 0, cy = 0, shortest = std::numeric_limits<double>::infinity();
  int count = 0;
  auto w = cdt.incident_vertices(v), done = w;
  do
  {
    cx += w->point().x();
    cy += w->point().y();
    shortest = std::min(shortest, std::sqrt(CGAL::squared_distance(start, w->point())));
    ++count;
  } while (++w != done);
  const Point centroid(cx / count, cy / count);
  const auto atCentroid = starShortfallAt(cdt, v, centroid, boundaryCount, bound);
  if (better(atCentroid))
  {
    best = atCentroid;
    bestPoint = centroid;
  }
  for (double step = 0.25 * shortest; step > 0.01 * shortest; step *= 0.5)
  {
    bool improved = true;
    for (int moves = 0; improved && moves < kMovesPerStep; ++moves)
    {
      improved = false;
      for (int d = 0; d < 8; ++d)
      {
        const double a = d * kPi / 4;
        const Point q(bestPoint.x() + step * std::cos(a), bestPoint.y() + step * std::sin(a));
        const auto shortfall = starShortfallAt(cdt, v, q, boundaryCount, bound);
        if (better(shortfall))
        {
          best = shortfall;
          bestPoint = q;
          improved = true;
        }
      }
    }
  }
  if (bestPoint != start)
  {
    v->set_point(bestPoint);
    return true;
  }
  return false;
}

// The unconstrained edges between two faces of the region, by their sorted
// end indices, each with a face and the index of the vertex opposite it.
std::map<std::pair<Index, Index>, std::pair<Face, int>> innerEdges(const CDT& cdt)
{
  std::map<std::pair<Index, Index>, std::pair<Face, int>> edges;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!f->info().inside)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      const Face g = f->neighbor(i);
      if (f->is_constrained(i) || cdt.is_infinite(g) || !g->info().inside)
      {
        continue;
      }
      const Index a = f->vertex(CDT::ccw(i))->info().index, b = f->vertex(CDT::cw(i))->info().index;
      edges.insert({ { std::min(a, b), std::max(a, b) }, { f, i } });
    }
  }
  return edges;
}

// One round of flips that raise the smaller angle of the two triangles of
// an edge; whether any edge flipped.
bool flipRound(CDT& cdt, Index boundaryCount, double bound)
{
  bool flipped = false;
  for (const auto& [key, edge] : innerEdges(cdt))
  {
    Face f = edge.first;
    const int i = edge.second;
    // the edge may have been flipped away already
    const Index a = f->vertex(CDT::ccw(i))->info().index, b = f->vertex(CDT::cw(i))->info().index;
    if (std::make_pair(std::min(a, b), std::max(a, b)) != key || f->is_constrained(i))
    {
      continue;
    }
    const Face g = f->neighbor(i);
    const Point& p = f->vertex(i)->point();
    const Point& q = g->vertex(g->index(f))->point();
    const Point& u = f->vertex(CDT::ccw(i))->point();
    const Point& t = f->vertex(CDT::cw(i))->point();
    if (CGAL::orientation(p, u, q) != CGAL::LEFT_TURN || CGAL::orientation(p, q, t) != CGAL::LEFT_TURN)
    {
      continue; // not a convex quadrilateral
    }
    // nor a new diagonal longer than the old one and than the size allows
    const double diagonal = std::sqrt(CGAL::squared_distance(p, q));
    const double allowed = (f->vertex(i)->info().allowed + g->vertex(g->index(f))->info().allowed) / 2;
    if (diagonal > allowed && diagonal * diagonal > CGAL::squared_distance(u, t))
    {
      continue;
    }
    // the same measure as for moves: the deficits, then the smaller angle
    auto shortfall = [&](double x, double y) {
      return std::make_pair(std::max(0.0, bound - x) + std::max(0.0, bound - y), -std::min(x, y));
    };
    const auto now = shortfall(minimumAngle(p, u, t), minimumAngle(q, t, u));
    const auto then = shortfall(minimumAngle(p, u, q), minimumAngle(p, q, t));
    // and, like a move, never at the price of a worse smallest angle, nor
    // making a triangle without a boundary point poor
    const bool noWorse = -then.second >= std::min(-now.second, bound);
    const Index ip = f->vertex(i)->info().index, iq = g->vertex(g->index(f))->info().index;
    auto poorInside = [&](Index x, Index y, Index z, double angle) {
      return angle < bound && x >= boundaryCount && y >= boundaryCount && z >= boundaryCount;
    };
    const bool keepsInsideGood = !poorInside(ip, a, iq, minimumAngle(p, u, q)) &&
      !poorInside(ip, iq, b, minimumAngle(p, q, t));
    if (noWorse && keepsInsideGood &&
      (then.first < now.first - 1e-12 || (then.first <= now.first && then.second < now.second - 1e-12)))
    {
      cdt.flip(f, i);
      flipped = true;
    }
  }
  return flipped;
}

void smoothBadTriangles(CDT& cdt, std::size_t boundaryCount, double bound)
{
  const Index boundary = static_cast<Index>(boundaryCount);
  const int sweeps = 20;
  for (int sweep = 0; sweep < sweeps; ++sweep)
  {
    bool moved = false;
    for (const auto& [index, v] : movableVertices(cdt, boundary, bound))
    {
      if (moveToBetterPoint(cdt, v, boundary, bound))
      {
        moved = true;
      }
    }
    bool flipped = true;
    for (int round = 0; flipped && round < 4; ++round)
    {
      flipped = flipRound(cdt, boundary, bound);
    }
    if (!moved && !flipped)
    {
      break;
    }
  }
}

using FaceKey = std::array<Index, 3>;
FaceKey keyOf(Face f)
{
  FaceKey k{ f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index };
  std::sort(k.begin(), k.end());
  return k;
}

// Why the region cannot be triangulated with these options, before any
// triangulation is built; empty if it can.
std::string regionError(const PlanarRegion& region, const InterfaceTriangulationOptions& options)
{
  const std::size_t n = region.points.size();
  if (!(options.minimumAngleDegrees > 0 && options.minimumAngleDegrees <= 34) ||
    !(options.maximumEdgeLength >= 0))
  {
    return "invalid options: the minimum angle must lie in (0, 34] degrees and the "
           "maximum edge length must not be negative";
  }
  if (region.edges.size() < 3 || n < 3)
  {
    return "the region has fewer than three boundary segments";
  }
  if (!(std::fabs(norm(region.normal) - 1.0) < 1e-9))
  {
    return "the plane normal is not a unit vector";
  }
  std::vector<int> degree(n, 0);
  for (const auto& e : region.edges)
  {
    if (e[0] < 0 || e[1] < 0 || e[0] >= static_cast<Index>(n) || e[1] >= static_cast<Index>(n) ||
      e[0] == e[1])
    {
      return "a boundary segment refers to a missing point or is degenerate";
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
      return msg.str();
    }
  }
  for (const auto& p : region.points)
  {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "a boundary point has a NaN or infinite coordinate";
    }
  }
  return {};
}

// The worst bad face first; among equally bad ones, the smallest key.
using Entry = std::pair<double, FaceKey>;
struct Worse
{
  bool operator()(const Entry& x, const Entry& y) const
  {
    return x.first < y.first || (x.first == y.first && x.second > y.second);
  }
};

// The triangulation of one region and what its steps share: the boundary
// (points 0..n-1, the region's own), the sizing of every vertex and the
// queue of bad faces. Each step that can fail returns why, empty if not.
struct InterfaceMesher
{
  InterfaceMesher(const PlanarRegion& r, const InterfaceTriangulationOptions& o);
  const PlanarRegion& region;
  const InterfaceTriangulationOptions& options;
  const std::size_t n;
  Vec3 e1, e2;
  const bool fixedSize;
  const double smallestField;
  const double clearanceFloor; // kClearanceFloor x the diagonal
  std::vector<double> spacing;   // summed length of the segments at each boundary point
  std::vector<int> segmentCount; // segments at each boundary point
  CDT cdt;
  std::vector<Vertex> vertices; // of the boundary points
  // Automatic sizing grows inward from the boundary spacing by a quarter of
  // the distance, up to 1.5 x the region's mean boundary spacing, so the
  // interface keeps the resolution of the surface around it.
  static constexpr double gradation = 0.25;
  double bound = 0, largestSize = 0;
  std::size_t cap = 0; // most new points
  std::priority_queue<Entry, std::vector<Entry>, Worse> queue;
  std::map<FaceKey, Face> live;
  std::vector<Point> added; // new points, in index order from n

  Point to2D(const Vec3& p) const;
  void setSize(Vertex v, double automatic) const;
  void measureSpacing();
  std::string insertBoundary();
  std::string checkSegments() const;
  std::string markInside();
  void prepareRefinement();
  double faceAllowed(Face f) const;
  double badness(Face f) const;
  void consider(Face f);
  bool acceptable(const Point& p, Face hint, double clearance, Face& located);
  void insertAt(const Point& p, Face located, const std::array<Vertex, 3>& around);
  static std::vector<std::pair<Point, double>> splitCandidates(const std::array<Vertex, 3>& around);
  void refine();
  bool nextToBoundary(Face f) const;
  void refinePoorAwayFromBoundary();
  void writeOutput(InterfaceTriangulation& t) const;
};

InterfaceMesher::InterfaceMesher(const PlanarRegion& r, const InterfaceTriangulationOptions& o)
  : region(r)
  , options(o)
  , n(r.points.size())
  , fixedSize(o.maximumEdgeLength > 0 || o.sizeAt)
  , smallestField(1e-3 * boundingBoxDiagonal(r.points))
  , clearanceFloor(kClearanceFloor * boundingBoxDiagonal(r.points))
  , vertices(r.points.size())
{
  planeBasis(region.normal, e1, e2);
}

Point InterfaceMesher::to2D(const Vec3& p) const
{
  const Vec3 d = p - region.origin;
  return Point(dot(d, e1), dot(d, e2));
}

// The size of vertex v and the longest edge its triangles may have. Where
// the size field has a value, that is the edge length wanted there, so
// edges up to kFieldAllowance x it are allowed: keeping every edge under
// the field made edges of 0.63-0.66 x it (median, graded ball of issue
// #22), while edges split under 1.4 x come out near it. None goes below
// 1e-3 of the region's diagonal: a field crossing 0 inside a unit square
// refined towards the zero line until the point cap (over 4 minutes).
// Where it has none (a value that is not positive and finite: away from
// every thin wall for the thickness cap, or a user field inside, where the
// filters do not check it) the vertex is sized as with no field at all.
// A maximum edge length is a hard bound everywhere; without one the size
// is `automatic`, the local spacing, and edges up to 1.3 x it make the
// mean edge about equal to the spacing. Giving the automatic size, not
// the maximum edge length, where the thickness cap had no value made
// 60,642 interface points instead of 6,808 for Cura's nozzle at K = 16
// (planes; samples reach 8 % of its box) and 4x the tetrahedra.
void InterfaceMesher::setSize(Vertex v, double automatic) const
{
  const Point& p = v->point();
  const double field = options.sizeAt ? options.sizeAt(region.origin + p.x() * e1 + p.y() * e2) : 0.0;
  if (field > 0 && std::isfinite(field))
  {
    const double wanted = std::max(kFieldAllowance * field, smallestField);
    v->info().size = options.maximumEdgeLength > 0 ? std::min(wanted, options.maximumEdgeLength) : wanted;
    v->info().allowed = v->info().size;
  }
  else if (options.maximumEdgeLength > 0)
  {
    v->info().size = v->info().allowed = options.maximumEdgeLength;
  }
  else
  {
    v->info().size = automatic;
    v->info().allowed = 1.3 * automatic;
  }
}

// Local boundary spacing at every boundary point.
void InterfaceMesher::measureSpacing()
{
  spacing.assign(n, 0.0);
  segmentCount.assign(n, 0);
  for (const auto& e : region.edges)
  {
    const double l = norm(region.points[e[1]] - region.points[e[0]]);
    for (Index v : e)
    {
      spacing[v] += l;
      ++segmentCount[v];
    }
  }
}

std::string InterfaceMesher::insertBoundary()
{
  try
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      if (segmentCount[i] == 0 && !options.keepIsolatedPoints)
      {
        continue; // a point no segment uses does not belong to the region
      }
      Vertex v = cdt.insert(to2D(region.points[i]));
      if (v->info().index >= 0)
      {
        std::ostringstream msg;
        msg << "boundary points " << v->info().index << " and " << i
            << " coincide in the plane of the interface";
        return msg.str();
      }
      v->info().index = static_cast<Index>(i);
      setSize(v, segmentCount[i] > 0 ? spacing[i] / segmentCount[i] : std::numeric_limits<double>::infinity());
      vertices[i] = v;
    }
    for (const auto& e : region.edges)
    {
      cdt.insert_constraint(vertices[e[0]], vertices[e[1]]);
    }
  }
  catch (const std::exception&)
  {
    return "boundary segments of the interface cross each other";
  }
  return {};
}

// Every segment is a constrained edge of its own.
std::string InterfaceMesher::checkSegments() const
{
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
    return "a boundary point lies on another boundary segment, or a segment is repeated";
  }
  return {};
}

// Inside: the face left of every directed segment, flooded without crossing segments.
std::string InterfaceMesher::markInside()
{
  std::vector<Face> stack;
  for (const auto& e : region.edges)
  {
    Face f;
    int i = 0;
    if (!cdt.is_edge(vertices[e[0]], vertices[e[1]], f, i))
    {
      return "internal: a boundary segment is missing from the triangulation";
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
      return "the loops are not consistently oriented (the region to their left is unbounded)";
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
      return "the loops are not consistently oriented (a segment has the region on both sides)";
    }
  }
  return {};
}

// The angle bound, the largest automatic size, the cap on new points and
// the size factor; then every bad face into the queue.
void InterfaceMesher::prepareRefinement()
{
  bound = options.minimumAngleDegrees * kPi / 180.0;
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
    if (segmentCount[i] || (options.keepIsolatedPoints && fixedSize))
    {
      smallestSize = std::min(smallestSize, vertices[i]->info().size);
    }
  }
  double meanSpacing = 0;
  for (const auto& e : region.edges)
  {
    meanSpacing += norm(region.points[e[1]] - region.points[e[0]]);
  }
  meanSpacing /= static_cast<double>(region.edges.size());
  largestSize = 1.5 * meanSpacing;
  // The cap on new points. From the smallest size at the boundary alone
  // (50 area / size^2, at most kMostNewPointsPerRegion) it let a fuzzed part cut across a slit
  // 1e-9 wide and 0.5 long refine for minutes (Release; a fuzzer timeout
  // under the sanitizers, session 35): a slit needs about length / width
  // points for the angle bound. A graded refinement needs far fewer: about
  // 2.3 area / size^2 at the target size and, where the boundary is
  // subdivided at that size (n points around), at most 0.2 n^2. So the cap
  // is also at most 50 area / target^2 or 4 n^2, whichever is more, plus
  // 20 n + 1000 (the meshes of the seven corpus and bundled runs compared
  // that session were unchanged).
  cap = static_cast<std::size_t>(std::min(kMostNewPointsPerRegion, 50.0 * area / (smallestSize * smallestSize) + 20.0 * n + 100));
  const double target = options.maximumEdgeLength > 0 ? options.maximumEdgeLength : largestSize;
  const double points = static_cast<double>(n);
  const double graded = std::max(50.0 * area / (target * target), 4.0 * points * points);
  cap = std::min(cap, static_cast<std::size_t>(std::min(kMostNewPointsPerRegion, graded + 20.0 * points + 1000)));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    consider(f);
  }
}

double InterfaceMesher::faceAllowed(Face f) const
{
  return (f->vertex(0)->info().allowed + f->vertex(1)->info().allowed + f->vertex(2)->info().allowed) / 3.0;
}

// badness: < 0 good; larger is worse. Angle deficit first, then size excess.
double InterfaceMesher::badness(Face f) const
{
  const Point& a = f->vertex(0)->point();
  const Point& b = f->vertex(1)->point();
  const Point& c = f->vertex(2)->point();
  const double angle = minimumAngle(a, b, c);
  if (angle < bound)
  {
    return 1.0 + (bound - angle);
  }
  const double longest = longestEdge(a, b, c);
  const double allowed = faceAllowed(f);
  return longest > allowed ? (longest / allowed - 1.0) * 1e-3 : -1.0;
}

void InterfaceMesher::consider(Face f)
{
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
}

// Whether a new vertex at p is acceptable, and the face that holds it:
//  * p lies strictly inside a face of the region;
//  * no vertex of its conflict zone is closer than `clearance` (no tiny
//    edges, so the refinement terminates), nor than the clearance floor;
//  * every boundary segment on the border of the conflict zone, which gets
//    p as the apex of its new triangle, gets a triangle that meets the angle
//    bound or is no worse than the one it has. Boundary segments are never
//    split, so this is what keeps the triangles on them as good as they can
//    be: a bad triangle on a segment could never be repaired.
bool InterfaceMesher::acceptable(const Point& p, Face hint, double clearance, Face& located)
{
  CDT::Locate_type lt;
  int li = 0;
  located = cdt.locate(p, lt, li, hint);
  if (lt != CDT::FACE || cdt.is_infinite(located) || !located->info().inside)
  {
    return false;
  }
  std::vector<Face> conflicts;
  std::vector<CDT::Edge> border;
  cdt.get_conflicts_and_boundary(p, std::back_inserter(conflicts), std::back_inserter(border), located);
  const double nearest = std::max(clearance, clearanceFloor);
  const double clearance2 = nearest * nearest;
  for (Face g : conflicts)
  {
    for (int i = 0; i < 3; ++i)
    {
      if (CGAL::squared_distance(p, g->vertex(i)->point()) < clearance2)
      {
        return false;
      }
    }
  }
  for (const CDT::Edge& e : border)
  {
    // e is given by the face outside the conflict zone; across it lies the
    // face in conflict that now rests on the segment
    if (!e.first->is_constrained(e.second))
    {
      continue;
    }
    const Face now = e.first->neighbor(e.second);
    const double before = minimumAngle(now->vertex(0)->point(), now->vertex(1)->point(), now->vertex(2)->point());
    const double after = minimumAngle(
      e.first->vertex(CDT::ccw(e.second))->point(), e.first->vertex(CDT::cw(e.second))->point(), p);
    if (after < bound && after < before)
    {
      return false;
    }
  }
  return true;
}

void InterfaceMesher::insertAt(const Point& p, Face located, const std::array<Vertex, 3>& around)
{
  Vertex v = cdt.insert(p, located);
  v->info().index = static_cast<Index>(n + added.size());
  double size = std::numeric_limits<double>::infinity();
  for (const Vertex& w : around)
  {
    size = std::min(size, w->info().size + gradation * std::sqrt(CGAL::squared_distance(p, w->point())));
  }
  setSize(v, std::min(size, largestSize));
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
}

// Candidates for a point that splits the face with these corners, each
// with its clearance: the circumcentre, then points on the perpendicular
// bisector of the shortest edge between the circumcentre and the apex of
// the equilateral triangle on that edge (off-centres): nearer points
// disturb less, so they fit where the circumcentre would spoil a
// boundary segment's triangle.
std::vector<std::pair<Point, double>> InterfaceMesher::splitCandidates(const std::array<Vertex, 3>& around)
{
  const Point centre = CGAL::circumcenter(around[0]->point(), around[1]->point(), around[2]->point());
  int k = 0; // the vertex opposite the shortest edge
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
  {
    const double l = CGAL::squared_distance(around[CDT::ccw(i)]->point(), around[CDT::cw(i)]->point());
    if (l < shortest)
    {
      shortest = l;
      k = i;
    }
  }
  shortest = std::sqrt(shortest);
  const Point& p = around[CDT::ccw(k)]->point();
  const Point& q = around[CDT::cw(k)]->point();
  const Point middle((p.x() + q.x()) / 2, (p.y() + q.y()) / 2);
  // unit normal of pq towards the opposite vertex (the inside of f)
  double ux = -(q.y() - p.y()) / shortest, uy = (q.x() - p.x()) / shortest;
  const Point& apex = around[k]->point();
  if ((apex.x() - middle.x()) * ux + (apex.y() - middle.y()) * uy < 0)
  {
    ux = -ux;
    uy = -uy;
  }
  const double reach = (centre.x() - middle.x()) * ux + (centre.y() - middle.y()) * uy;
  const double clearance = 0.5 * shortest;
  std::vector<std::pair<Point, double>> candidates{ { centre, clearance } }; // and their clearance
  const double nearest = 0.5 * std::sqrt(3.0) * shortest;
  if (reach > nearest)
  {
    for (int step = 1; step <= 4; ++step)
    {
      const double h = reach * std::pow(nearest / reach, step / 4.0);
      candidates.push_back({ Point(middle.x() + h * ux, middle.y() + h * uy), clearance });
    }
  }
  else
  {
    // a flat triangle (an obtuse angle near 180 degrees, as over a boundary
    // point where the boundary runs straight on) has its circumcentre
    // behind the shortest edge: try the apex of the equilateral triangle on
    // that edge, and half way to it
    for (double h : { nearest, 0.5 * nearest })
    {
      candidates.push_back({ Point(middle.x() + h * ux, middle.y() + h * uy), clearance });
    }
  }
  return candidates;
}

// Splits the worst face of the queue at its first acceptable candidate
// until none is left or the cap is reached.
void InterfaceMesher::refine()
{
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
    live.erase(it);
    if (keyOf(f) != top.second || badness(f) != top.first)
    {
      continue; // stale: the face was destroyed or changed
    }
    const std::array<Vertex, 3> around{ f->vertex(0), f->vertex(1), f->vertex(2) };
    for (const auto& [candidate, distance] : splitCandidates(around))
    {
      Face located;
      if (acceptable(candidate, f, distance, located))
      {
        insertAt(candidate, located, around);
        break;
      }
    }
  }
}

// A triangle is next to the boundary if it has a boundary point or its
// circumcircle reaches a boundary segment: only a point inside that circle
// could improve it, and such a point would spoil the segment's triangle.
bool InterfaceMesher::nextToBoundary(Face f) const
{
  const Point& a = f->vertex(0)->point();
  const Point& b = f->vertex(1)->point();
  const Point& c = f->vertex(2)->point();
  for (int i = 0; i < 3; ++i)
  {
    if (f->vertex(i)->info().index < static_cast<Index>(n))
    {
      return true;
    }
  }
  const Point centre = CGAL::circumcenter(a, b, c);
  const double radius2 = CGAL::squared_radius(a, b, c);
  for (const auto& e : region.edges)
  {
    if (CGAL::squared_distance(centre, K::Segment_2(vertices[e[0]]->point(), vertices[e[1]]->point())) < radius2)
    {
      return true;
    }
  }
  return false;
}

// Smoothing moves points of poor triangles next to the boundary, and can
// carry one of them away from it, where the refinement would have split
// it: refine such triangles now (their circumcentres are away from the
// boundary too).
void InterfaceMesher::refinePoorAwayFromBoundary()
{
  bool poorAwayFromBoundary = false;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info().inside && faceAngle(f) < bound && !nextToBoundary(f))
    {
      consider(f);
      poorAwayFromBoundary = true;
    }
  }
  if (poorAwayFromBoundary)
  {
    refine();
  }
}

void InterfaceMesher::writeOutput(InterfaceTriangulation& t) const
{
  t.newPoints.resize(added.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
  {
    const Index i = v->info().index;
    if (i >= static_cast<Index>(n))
    {
      // where smoothing left it
      t.newPoints[i - n] = region.origin + v->point().x() * e1 + v->point().y() * e2;
    }
  }
  auto at3D = [&](Index i) { return i < static_cast<Index>(n) ? region.points[i] : t.newPoints[i - n]; };
  t.minimumAngleDegrees = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!f->info().inside)
    {
      continue;
    }
    t.triangles.push_back({ f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index });
    // measured on the output in 3D: boundary points may lie off the plane
    // (snapped onto it by the cutter), so their projection can differ
    const Triangle& added3D = t.triangles.back();
    const double angle =
      triangleMinimumAngle(at3D(added3D[0]), at3D(added3D[1]), at3D(added3D[2])) * 180.0 / kPi;
    t.minimumAngleDegrees = std::min(t.minimumAngleDegrees, angle);
    if (angle < options.minimumAngleDegrees)
    {
      ++t.trianglesBelowMinimumAngle;
      t.trianglesBelowMinimumAngleAwayFromBoundary += nextToBoundary(f) ? 0 : 1;
    }
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
}
} // namespace

InterfaceTriangulationResult triangulateInterface(
  const PlanarRegion& region, const InterfaceTriangulationOptions& options)
{
  InterfaceTriangulationResult result;
  result.error = regionError(region, options);
  if (!result.error.empty())
  {
    return result;
  }
  InterfaceMesher mesher(region, options);
  mesher.measureSpacing();
  result.error = mesher.insertBoundary();
  if (result.error.empty())
  {
    result.error = mesher.checkSegments();
  }
  if (result.error.empty())
  {
    result.error = mesher.markInside();
  }
  if (!result.error.empty())
  {
    return result;
  }
  if (!options.refine)
  {
    result.ok = true; // the boundary is valid; no triangles wanted
    return result;
  }
  mesher.prepareRefinement();
  mesher.refine();
  // Smoothing: the refinement cannot move a vertex once placed, and a
  // boundary segment is never split, so triangles can stay thin where a
  // vertex sits too low over a long segment. Each new vertex of a bad
  // triangle moves, within its star, to where the worst angle of its
  // triangles is largest; then unconstrained edges are flipped where that
  // raises the smaller angle of the pair. Boundary points never move.
  if (options.smooth)
  {
    smoothBadTriangles(mesher.cdt, mesher.n, mesher.bound);
    mesher.refinePoorAwayFromBoundary();
  }
  mesher.writeOutput(result.triangulation);
  result.ok = true;
  return result;
}

PlanarRegion planarRegionOf(
  const SurfaceComplex& complex, const InterfaceRegion& region, const std::vector<Index>& points)
{
  PlanarRegion planar;
  planar.origin = complex.planes[region.planeId].origin;
  planar.normal = complex.planes[region.planeId].normal;
  std::map<Index, Index> localOf;
  for (Index p : points)
  {
    localOf[p] = static_cast<Index>(planar.points.size());
    planar.points.push_back(complex.points[p]);
  }
  for (const DirectedEdge& e : region.edges)
  {
    planar.edges.push_back({ localOf.at(e[0]), localOf.at(e[1]) });
  }
  return planar;
}
} // namespace ptm
