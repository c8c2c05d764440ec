#include "SurfaceRelaxation.h"

#include "SelfIntersectionCheck.h"
#include "StraightContourPoints.h"
#include "SubdomainSurface.h"
#include "UnionFind.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <map>
#include <set>

namespace ptm
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;

constexpr double kDegree = kPi / 180.0;
// a node whose worst incident angle is below this gets the directed search
constexpr double kPoorAngleDegrees = 20.0;

Point3 toCgal(const Vec3& p)
{
  return { p[0], p[1], p[2] };
}

Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

// Enclosed volume of the outer surface (triangles facing the outside), a
// closed surface: about one of its corners (sixTimesVolumeAbout).
double outerSurfaceVolume(const SurfaceComplex& c)
{
  std::vector<Index> outer;
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if (c.trianglePairs[t][1] == -1)
    {
      outer.push_back(static_cast<Index>(t));
    }
  }
  return outer.empty() ? 0.0 : volumeAbout(c.points[c.triangles[outer[0]][0]], c.points, c.triangles, outer);
}

// A sample this close to a triangle (a fraction of the bounding box's
// diagonal) is on the surface: the figure issue #18 asks every output
// boundary point to meet.
constexpr double kOnSurfaceFraction = 1e-12;

// Largest distance from the vertices and triangle centroids of `from` to
// the triangles of `to` (CGAL AABB tree). When both have the same triangles
// on the same point indices (a complex before and after relaxation), a
// triangle none of whose points moved lies in both, so only moved points
// and the centroids of triangles with a moved point are sampled (sampling
// all took 6.7 % of a K = 64 run on one rank, ball of 23,592 triangles).
// Each query starts from the nearest point of the triangles at the corners
// of the sample's own triangle in `to`, which are at most a move away,
// instead of CGAL's search tree of hints: queries and that tree took 0.3 s
// of 0.5 on the 10 M ball at K = 2. A sample no farther from that point
// than the largest distance so far, or within kOnSurfaceFraction of the
// surface, is not queried at all: with the exact relaxer every sample lies
// on the surface up to round-off, nearly always on one of those triangles,
// and the tree's query of a point on the surface falls back to exact
// arithmetic at every box it touches (session 38: KiCad's XSON-16 at 64
// parallel planes, relaxation 16.4 s on one rank, 43 % of the run's
// samples in those queries; 8.7 s with the sample's own triangle as the
// only hint and no round-off allowance; 4.0 s so).
double sampledDistance(const SurfaceComplex& from, const SurfaceComplex& to)
{
  using CgalTriangle = Kernel::Triangle_3;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<CgalTriangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  if (to.triangles.empty())
  {
    return 0;
  }
  const bool sameTriangles = from.triangles == to.triangles && from.points.size() == to.points.size();
  auto moved = [&](Index v) { return !sameTriangles || from.points[v] != to.points[v]; };
  // built at the first sample the hints do not settle: most runs of the
  // exact relaxer need none
  std::vector<CgalTriangle> triangles;
  std::unique_ptr<Tree> tree;
  auto searchTree = [&]() -> Tree& {
    if (!tree)
    {
      for (const Triangle& t : to.triangles)
      {
        triangles.emplace_back(toCgal(to.points[t[0]]), toCgal(to.points[t[1]]), toCgal(to.points[t[2]]));
      }
      tree = std::make_unique<Tree>(triangles.begin(), triangles.end());
      if (!sameTriangles)
      {
        tree->accelerate_distance_queries();
      }
    }
    return *tree;
  };
  const std::vector<std::vector<std::size_t>> around =
    sameTriangles ? trianglesAtPoints(to.triangles, to.points.size()) : std::vector<std::vector<std::size_t>>{};
  const double roundOff = kOnSurfaceFraction * boundingBoxDiagonal(to.points);
  const double onSurface = roundOff * roundOff;
  double worst = 0;
  auto sample = [&](const Vec3& p, std::size_t own) {
    if (!sameTriangles)
    {
      worst = std::max(worst, searchTree().squared_distance(toCgal(p)));
      return;
    }
    Vec3 hint = p;
    double nearest = std::numeric_limits<double>::max();
    for (Index corner : to.triangles[own])
    {
      for (std::size_t k : around[corner])
      {
        const Triangle& t = to.triangles[k];
        const Vec3 q = closestPointOnTriangle(p, to.points[t[0]], to.points[t[1]], to.points[t[2]]);
        const Vec3 d = p - q;
        if (dot(d, d) < nearest)
        {
          nearest = dot(d, d);
          hint = q;
        }
      }
    }
    if (nearest <= std::max(worst, onSurface))
    {
      // the surface is no farther than the hint: it cannot raise the largest
      // distance, or the sample is on the surface up to round-off, and the
      // hint's distance bounds its own
      worst = std::max(worst, nearest);
      return;
    }
    worst = std::max(worst, searchTree().squared_distance(toCgal(p), toCgal(hint)));
  };
  std::vector<char> used(from.points.size(), 0);
  for (std::size_t i = 0; i < from.triangles.size(); ++i)
  {
    const Triangle& t = from.triangles[i];
    if (!moved(t[0]) && !moved(t[1]) && !moved(t[2]))
    {
      continue;
    }
    sample((1.0 / 3.0) * (from.points[t[0]] + from.points[t[1]] + from.points[t[2]]), i);
    for (Index v : t)
    {
      if (!used[v] && moved(v))
      {
        used[v] = 1;
        sample(from.points[v], i);
      }
    }
  }
  return std::sqrt(worst);
}

enum class NodeKind
{
  Free,
  Sliding,
  Fixed
};

// Where a node may go in KeepSurface mode: origin + s u + t w (a plane) or
// origin + s u (a line), from original coordinates of points exactly on it.
struct ExactFrame
{
  Vec3 origin{ 0, 0, 0 }, u{ 0, 0, 0 }, w{ 0, 0, 0 };
  Index lineEnds[2] = { -1, -1 }; // the node's neighbours on its line
};

class Relaxer
{
public:
  Relaxer(SurfaceComplex& complex, const RelaxationOptions& options)
    : c(complex)
    , options(options)
    , original(complex.points)
  {
  }
  void run(RelaxationResult& result);

private:
  SurfaceComplex& c;
  const RelaxationOptions& options;
  const std::vector<Vec3> original;
  std::vector<std::vector<std::size_t>> trianglesOf;
  std::vector<std::vector<Index>> neighbours; // sorted
  std::vector<Vec3> normals;                  // of the original triangles
  std::vector<NodeKind> kind;
  std::vector<std::vector<Index>> along; // where the smoothing target comes from
  std::vector<char> active;
  // SmoothSurface
  std::vector<int> patch;
  std::vector<std::vector<Index>> featureNeighbours;
  std::map<UndirectedEdge, std::vector<int>> featureKind;
  double maximumMove = std::numeric_limits<double>::infinity();
  std::size_t movesBeyondDeviation = 0;
  // KeepSurface
  std::vector<ExactFrame> frames;
  // how far an interface point may lie from its cutting plane and still
  // count as on it: 1e-13 of the bounding-box diagonal, 1000 times the
  // rounding of a coordinate near the origin, and 10 times under the 1e-12
  // the tests allow; far from the origin 100 roundings of the coordinates
  // (roundOffTolerance)
  double planeTolerance = 0;

  int patchOf(std::size_t t) const { return c.trianglePlanes.empty() ? -1 : c.trianglePlanes[t]; }
  void buildAdjacency();
  void classifyByFeatures();
  void classifyExactly();
  NodeKind exactKind(Index v, ExactFrame& frame) const;
  void markRegion();
  Vec3 projectOntoSurface(Index v, const Vec3& q) const;
  Vec3 projectOntoCurve(Index v, const Vec3& q) const;
  bool projectExactly(Index v, const Vec3& q, Vec3& p) const;
  bool tryPosition(Index v, const Vec3& q);
  bool withinDeviation(Index v) const;
  double worstAngle(Index v) const;
  bool valid(Index v) const;
  bool relaxNode(Index v);
  bool movable(std::size_t v) const
  {
    return active[v] && kind[v] != NodeKind::Fixed && !trianglesOf[v].empty();
  }
  std::vector<char> nodesOfThisProcess() const;
  void shareMoves(const std::vector<char>& mine, RelaxationResult& result);
};

void Relaxer::buildAdjacency()
{
  const std::size_t n = c.points.size(), nt = c.triangles.size();
  trianglesOf = trianglesAtPoints(c.triangles, n);
  neighbours.assign(n, {});
  normals.resize(nt);
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Triangle& tri = c.triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      neighbours[tri[k]].push_back(tri[(k + 1) % 3]);
      neighbours[tri[k]].push_back(tri[(k + 2) % 3]);
    }
    normals[t] = normalized(cross(c.points[tri[1]] - c.points[tri[0]], c.points[tri[2]] - c.points[tri[0]]));
  }
  // sorted and unique, as a set per point gave them (its nodes took 0.08 s
  // of the relaxer on the 10 M ball at K = 2)
  for (auto& around : neighbours)
  {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
}

// SmoothSurface: an edge is a feature edge if its triangles lie in different
// patches (contours, plane-plane lines) or it is a surface edge sharper than
// the feature angle. No feature edge: free; two feature edges of one curve
// running straight on: sliding; otherwise fixed.
void Relaxer::classifyByFeatures()
{
  const std::size_t n = c.points.size();
  const std::vector<EdgeOfTriangle> edges = edgesOfTriangles(c.triangles);
  const double cosFeature = std::cos(options.featureAngleDegrees * kDegree);
  featureNeighbours.assign(n, {});
  std::vector<std::size_t> ts; // the triangles at one edge: a run of `edges`
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    ts.push_back(static_cast<std::size_t>(edges[e].triangle));
    if (e + 1 < edges.size() && edges[e + 1].edge == edges[e].edge)
    {
      continue;
    }
    const UndirectedEdge edge = edges[e].edge;
    bool feature = ts.size() != 2;
    for (std::size_t i = 1; i < ts.size() && !feature; ++i)
    {
      feature = patchOf(ts[i]) != patchOf(ts[0]);
    }
    if (!feature && patchOf(ts[0]) < 0)
    {
      // two surface triangles: oriented consistently when they belong to the same
      // subdomain; compare normals up to orientation otherwise
      const double d = dot(normals[ts[0]], normals[ts[1]]);
      const bool sameSide = c.trianglePairs[ts[0]][0] == c.trianglePairs[ts[1]][0];
      feature = (sameSide ? d : std::fabs(d)) < cosFeature;
    }
    if (feature)
    {
      featureNeighbours[edge[0]].push_back(edge[1]);
      featureNeighbours[edge[1]].push_back(edge[0]);
      // which patches meet along it: a contour {-1, p}, a plane-plane line
      // {p, q}, a sharp surface crease {-1, -1}
      std::vector<int> meeting;
      for (std::size_t t : ts)
      {
        meeting.push_back(patchOf(t));
      }
      std::sort(meeting.begin(), meeting.end());
      featureKind[edge] = meeting;
    }
    ts.clear();
  }
  kind.assign(n, NodeKind::Fixed);
  patch.assign(n, -2);
  along.assign(n, {});
  for (std::size_t v = 0; v < n; ++v)
  {
    if (trianglesOf[v].empty())
    {
      continue;
    }
    patch[v] = patchOf(trianglesOf[v][0]);
    const std::size_t f = featureNeighbours[v].size();
    kind[v] = f == 0 ? NodeKind::Free : f == 2 ? NodeKind::Sliding : NodeKind::Fixed;
    along[v] = kind[v] == NodeKind::Sliding ? featureNeighbours[v] : neighbours[v];
    if (kind[v] == NodeKind::Sliding)
    {
      // a node slides only along one feature curve that runs straight on
      // through it: where a contour meets a surface crease, or where the curve
      // turns by more than the feature angle, sliding would leave the plane or
      // cut the corner, so the node is a corner and stays put
      const Index a = featureNeighbours[v][0], b = featureNeighbours[v][1];
      const Index w = static_cast<Index>(v);
      const auto& kindA = featureKind[undirected(w, a)];
      const auto& kindB = featureKind[undirected(w, b)];
      const Vec3 ta = normalized(c.points[a] - c.points[v]), tb = normalized(c.points[b] - c.points[v]);
      if (kindA != kindB || dot(ta, tb) > -cosFeature)
      {
        kind[v] = NodeKind::Fixed;
      }
    }
  }
}

// KeepSurface: cases (a), (b), (c) of the header. The planes of a node's
// star: surface triangles grouped by exact coplanarity (CGAL's exact
// orientation on the original coordinates); interface triangles by their
// cutting plane, whose points lie on it by the complex's contract but only
// up to rounding (a point computed on an inclined plane is almost never
// exactly coplanar with three others: with the exact test alone no interface
// node of recursive bisection on the ball moved at all). Those must lie
// within planeTolerance of it, else the node is fixed.
NodeKind Relaxer::exactKind(Index v, ExactFrame& frame) const
{
  auto P = [&](Index i) { return toCgal(original[i]); };
  struct StarPlane
  {
    int cut = -1;     // the cutting plane of interface triangles, -1 on the surface
    Triangle ref{};   // surface: a triangle exactly in the plane
  };
  auto onPlane = [&](const StarPlane& plane, Index w) {
    if (plane.cut >= 0)
    {
      const CuttingPlane& cut = c.planes[plane.cut];
      return std::fabs(dot(cut.normal, original[w] - cut.origin)) <= planeTolerance;
    }
    return CGAL::orientation(P(plane.ref[0]), P(plane.ref[1]), P(plane.ref[2]), P(w)) == CGAL::COPLANAR;
  };
  std::vector<StarPlane> planes;
  std::vector<int> group;
  for (std::size_t t : trianglesOf[v])
  {
    const Triangle& tri = c.triangles[t];
    if (CGAL::collinear(P(tri[0]), P(tri[1]), P(tri[2])))
    {
      return NodeKind::Fixed; // a degenerate triangle spans no plane
    }
    const StarPlane own{ patchOf(t), tri };
    if (own.cut >= 0 && !(onPlane(own, tri[0]) && onPlane(own, tri[1]) && onPlane(own, tri[2])))
    {
      return NodeKind::Fixed; // an interface point snapped off its plane
    }
    int g = -1;
    for (std::size_t k = 0; k < planes.size() && g < 0; ++k)
    {
      const bool same = own.cut >= 0 ? planes[k].cut == own.cut
                                     : planes[k].cut < 0 && onPlane(planes[k], tri[0]) &&
          onPlane(planes[k], tri[1]) && onPlane(planes[k], tri[2]);
      g = same ? static_cast<int>(k) : g;
    }
    if (g < 0)
    {
      if (planes.size() == 2)
      {
        return NodeKind::Fixed; // three or more planes: a corner or a curved surface
      }
      planes.push_back(own);
      g = static_cast<int>(planes.size()) - 1;
    }
    group.push_back(g);
  }
  // In each plane the star must be closed fans, except across the edges on
  // the line where two planes meet: every other edge v-w is used as often
  // from v to w as from w to v by the plane's triangles. Otherwise moving v
  // would move an open edge of the plane's part, and change its polygon.
  std::map<std::pair<int, Index>, int> balance;
  for (std::size_t i = 0; i < group.size(); ++i)
  {
    const Triangle& tri = c.triangles[trianglesOf[v][i]];
    const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
    balance[{ group[i], tri[(k + 1) % 3] }] += 1;
    balance[{ group[i], tri[(k + 2) % 3] }] -= 1;
  }
  std::set<Index> onLine;
  for (const auto& [key, count] : balance)
  {
    const Index w = key.second;
    if (planes.size() == 2 && onPlane(planes[0], w) && onPlane(planes[1], w))
    {
      onLine.insert(w);
    }
    else if (count != 0)
    {
      return NodeKind::Fixed;
    }
  }
  if (planes.size() == 1)
  {
    // (a): origin + s u + t w with u, w edges of a triangle exactly in the
    // plane, or the cutting plane's basis
    frame.origin = original[v];
    if (planes[0].cut >= 0)
    {
      planeBasis(c.planes[planes[0].cut].normal, frame.u, frame.w);
    }
    else
    {
      const Triangle& ref = planes[0].ref;
      frame.u = original[ref[1]] - original[ref[0]];
      frame.w = original[ref[2]] - original[ref[0]];
    }
    return NodeKind::Free;
  }
  // (b): exactly two edges on the line, the node strictly between their ends
  // (and on the line a b within planeTolerance where a plane is a cut)
  if (onLine.size() != 2)
  {
    return NodeKind::Fixed;
  }
  const Index a = *onLine.begin(), b = *onLine.rbegin();
  if (planes[0].cut < 0 && planes[1].cut < 0)
  {
    if (!CGAL::collinear_are_strictly_ordered_along_line(P(a), P(v), P(b)))
    {
      return NodeKind::Fixed;
    }
  }
  else
  {
    const Vec3 ab = original[b] - original[a];
    const double t = dot(original[v] - original[a], ab) / dot(ab, ab);
    if (!(t > 0 && t < 1) || norm(original[a] + t * ab - original[v]) > planeTolerance)
    {
      return NodeKind::Fixed;
    }
  }
  frame.origin = original[a];
  frame.u = original[b] - original[a];
  frame.lineEnds[0] = a;
  frame.lineEnds[1] = b;
  return NodeKind::Sliding;
}

void Relaxer::classifyExactly()
{
  const std::size_t n = c.points.size();
  kind.assign(n, NodeKind::Fixed);
  frames.assign(n, {});
  along.assign(n, {});
  for (std::size_t v = 0; v < n; ++v)
  {
    if (trianglesOf[v].empty() || !active[v])
    {
      continue;
    }
    kind[v] = exactKind(static_cast<Index>(v), frames[v]);
    if (kind[v] == NodeKind::Sliding)
    {
      along[v] = { frames[v].lineEnds[0], frames[v].lineEnds[1] };
    }
    else if (kind[v] == NodeKind::Free)
    {
      along[v] = neighbours[v];
    }
  }
}

// Region: nodes within `rings` rings of a node on a cutting plane.
void Relaxer::markRegion()
{
  const std::size_t n = c.points.size();
  active.assign(n, 1);
  if (!options.nearCutsOnly)
  {
    return;
  }
  std::vector<int> distance(n, -1);
  std::vector<Index> front;
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    if (patchOf(t) >= 0)
    {
      for (Index v : c.triangles[t])
      {
        if (distance[v] < 0)
        {
          distance[v] = 0;
          front.push_back(v);
        }
      }
    }
  }
  for (int ring = 0; ring < options.rings; ++ring)
  {
    std::vector<Index> next;
    for (Index v : front)
    {
      for (Index w : neighbours[v])
      {
        if (distance[w] < 0)
        {
          distance[w] = ring + 1;
          next.push_back(w);
        }
      }
    }
    front.swap(next);
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    active[v] = distance[v] >= 0;
  }
}

// SmoothSurface, free node: the nearest point of the original surface
// triangles of the node's two rings, or of its plane.
Vec3 Relaxer::projectOntoSurface(Index v, const Vec3& q) const
{
  if (patch[v] >= 0)
  {
    const CuttingPlane& plane = c.planes[patch[v]];
    return q - dot(plane.normal, q - plane.origin) * plane.normal;
  }
  Vec3 best = q;
  double bestDistance = std::numeric_limits<double>::infinity();
  auto consider = [&](Index w) {
    for (std::size_t t : trianglesOf[w])
    {
      if (patchOf(t) >= 0)
      {
        continue;
      }
      const auto& tri = c.triangles[t];
      const Vec3 x = closestPointOnTriangle(q, original[tri[0]], original[tri[1]], original[tri[2]]);
      const double d = norm(x - q);
      if (d < bestDistance)
      {
        bestDistance = d;
        best = x;
      }
    }
  };
  consider(v);
  for (Index w : neighbours[v])
  {
    consider(w);
  }
  return best;
}

// SmoothSurface, sliding node: the nearest point of the original feature
// curve through the node, two edges each way.
Vec3 Relaxer::projectOntoCurve(Index v, const Vec3& q) const
{
  Vec3 best = q;
  double bestDistance = std::numeric_limits<double>::infinity();
  auto segment = [&](Index a, Index b) {
    const Vec3 x = closestPointOnSegment(q, original[a], original[b]);
    const double d = norm(x - q);
    if (d < bestDistance)
    {
      bestDistance = d;
      best = x;
    }
  };
  // only segments of the same curve: past a corner w the next feature edge
  // may be another curve (a crease leaving the plane)
  auto kindOf = [&](Index a, Index b) -> const std::vector<int>& {
    return featureKind.at({ std::min(a, b), std::max(a, b) });
  };
  for (Index w : featureNeighbours[v])
  {
    segment(v, w);
    for (Index u : featureNeighbours[w])
    {
      if (u != v && kindOf(w, u) == kindOf(v, w))
      {
        segment(w, u);
      }
    }
  }
  return best;
}

// KeepSurface: the point of the node's plane or line nearest q, as
// origin + s u (+ t w). A sliding node must stay strictly between its two
// neighbours on the line (as they are now: they may slide too).
bool Relaxer::projectExactly(Index v, const Vec3& q, Vec3& p) const
{
  const ExactFrame& f = frames[v];
  const Vec3 d = q - f.origin;
  if (kind[v] == NodeKind::Free)
  {
    const double uu = dot(f.u, f.u), uw = dot(f.u, f.w), ww = dot(f.w, f.w);
    const double du = dot(d, f.u), dw = dot(d, f.w);
    const double det = uu * ww - uw * uw;
    if (!(det > 0))
    {
      return false;
    }
    const double s = (ww * du - uw * dw) / det, t = (uu * dw - uw * du) / det;
    p = f.origin + (s * f.u + t * f.w);
    return true;
  }
  const double uu = dot(f.u, f.u);
  const double s = dot(d, f.u) / uu;
  const double sa = dot(c.points[f.lineEnds[0]] - f.origin, f.u) / uu;
  const double sb = dot(c.points[f.lineEnds[1]] - f.origin, f.u) / uu;
  if (!(s > std::min(sa, sb) && s < std::max(sa, sb)))
  {
    return false;
  }
  p = f.origin + s * f.u;
  return true;
}

// Puts node v at the projection of q; false if the position is not allowed
// (the caller restores the node).
bool Relaxer::tryPosition(Index v, const Vec3& q)
{
  Vec3 p;
  if (options.mode == RelaxationMode::KeepSurface)
  {
    if (!projectExactly(v, q, p))
    {
      return false;
    }
  }
  else
  {
    p = kind[v] == NodeKind::Sliding ? projectOntoCurve(v, q) : projectOntoSurface(v, q);
  }
  c.points[v] = p;
  if (!valid(v))
  {
    return false;
  }
  if (options.mode == RelaxationMode::SmoothSurface && !withinDeviation(v))
  {
    ++movesBeyondDeviation;
    return false;
  }
  return true;
}

// SmoothSurface: the node's new star stays within maximumMove of the
// original complex and the original star within maximumMove of the new one,
// sampled like surfaceChange (centroids, the node) plus the midpoints of the
// node's edges, against the original triangles of the node's two rings (a
// distance to a subset bounds the distance to the whole). Bounding the
// node's displacement instead would also stop moves within a plane, which
// change nothing: with 1 % of the diagonal it halved the thin triangles
// removed on the box with K = 7.
bool Relaxer::withinDeviation(Index v) const
{
  // Fast and exact: the linear map from each old triangle to its new one
  // moves every point by at most the largest move of its corners, so when no
  // corner of the star is farther than the bound from where it was, neither
  // star is farther than the bound from the other. This skips the sampled
  // test below for most moves (on the bracket, K = 4, the relaxation took
  // 2.25 s with the sampled test alone).
  double largestMove = 0;
  for (std::size_t t : trianglesOf[v])
  {
    for (Index w : c.triangles[t])
    {
      largestMove = std::max(largestMove, norm(c.points[w] - original[w]));
    }
  }
  if (largestMove <= maximumMove)
  {
    return true;
  }
  auto distanceTo = [](const Vec3& p, const std::vector<Vec3>& points, const std::vector<std::size_t>& ts,
                      const std::vector<Triangle>& triangles) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t : ts)
    {
      const Triangle& tri = triangles[t];
      best = std::min(best, norm(p - closestPointOnTriangle(p, points[tri[0]], points[tri[1]], points[tri[2]])));
    }
    return best;
  };
  std::vector<std::size_t> ring = trianglesOf[v];
  for (Index w : neighbours[v])
  {
    ring.insert(ring.end(), trianglesOf[w].begin(), trianglesOf[w].end());
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  const auto& star = trianglesOf[v];
  if (distanceTo(original[v], c.points, star, c.triangles) > maximumMove)
  {
    return false;
  }
  for (std::size_t t : star)
  {
    const Triangle& tri = c.triangles[t];
    const Vec3 now = (1.0 / 3.0) * (c.points[tri[0]] + c.points[tri[1]] + c.points[tri[2]]);
    const Vec3 was = (1.0 / 3.0) * (original[tri[0]] + original[tri[1]] + original[tri[2]]);
    if (distanceTo(now, original, ring, c.triangles) > maximumMove ||
      distanceTo(was, c.points, star, c.triangles) > maximumMove)
    {
      return false;
    }
    for (Index w : tri)
    {
      if (w != v && distanceTo(0.5 * (c.points[v] + c.points[w]), original, ring, c.triangles) > maximumMove)
      {
        return false;
      }
    }
  }
  return true;
}

double Relaxer::worstAngle(Index v) const
{
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t t : trianglesOf[v])
  {
    const auto& tri = c.triangles[t];
    worst = std::min(worst, triangleMinimumAngle(c.points[tri[0]], c.points[tri[1]], c.points[tri[2]]));
  }
  return worst;
}

// No incident triangle inverted (against its original normal) or shrunk to
// under 1e-6 of its original area.
bool Relaxer::valid(Index v) const
{
  for (std::size_t t : trianglesOf[v])
  {
    const auto& tri = c.triangles[t];
    const Vec3 area2 = cross(c.points[tri[1]] - c.points[tri[0]], c.points[tri[2]] - c.points[tri[0]]);
    const double a = norm(area2);
    const Vec3 o = cross(original[tri[1]] - original[tri[0]], original[tri[2]] - original[tri[0]]);
    if (!(a > 1e-6 * norm(o)) || dot(area2, normals[t]) <= 0)
    {
      return false;
    }
  }
  return true;
}

// One node, one sweep: a smoothing step, then for a node still poor a
// directed search. True if the node moved.
bool Relaxer::relaxNode(Index v)
{
  // smoothing target: the centroid of the neighbours (along the curve for sliding nodes)
  Vec3 target{ 0, 0, 0 };
  for (Index w : along[v])
  {
    target = target + c.points[w];
  }
  target = (1.0 / static_cast<double>(along[v].size())) * target;
  const Vec3 start = c.points[v];
  const double before = worstAngle(v);
  double current = before; // the worst angle where the node now is
  bool accepted = false;
  for (double step = options.relaxationFactor; step > options.relaxationFactor / 8; step *= 0.5)
  {
    if (tryPosition(v, start + step * (target - start)))
    {
      const double angle = worstAngle(v);
      if (angle >= before)
      {
        accepted = true;
        current = angle;
        break;
      }
    }
  }
  if (!accepted)
  {
    c.points[v] = start;
  }
  // Smoothing alone leaves thin triangles whose nodes are pinned to a
  // curve or sit next to one (the centroid is not where the worst angle
  // improves). Where the worst angle around the node is still poor, try
  // short moves towards each neighbour (along the curve for sliding
  // nodes) and keep the one that raises the worst angle most.
  if (current < kPoorAngleDegrees * kDegree)
  {
    const Vec3 from = c.points[v];
    Vec3 best = from;
    double bestAngle = current;
    for (Index w : along[v])
    {
      for (double fraction : { 0.05, 0.15, 0.3 })
      {
        if (tryPosition(v, from + fraction * (c.points[w] - from)))
        {
          const double angle = worstAngle(v);
          if (angle > bestAngle)
          {
            bestAngle = angle;
            best = c.points[v];
          }
        }
        c.points[v] = from;
      }
    }
    c.points[v] = best;
    accepted = accepted || bestAngle > current;
  }
  return accepted;
}

void Relaxer::run(RelaxationResult& result)
{
  const std::size_t n = c.points.size();
  buildAdjacency();
  markRegion();
  if (options.mode == RelaxationMode::KeepSurface)
  {
    planeTolerance = roundOffTolerance(original, 1e-13);
    classifyExactly();
  }
  else
  {
    classifyByFeatures();
    maximumMove = options.maximumSurfaceDeviation * boundingBoxDiagonal(original);
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    if (trianglesOf[v].empty() || !active[v])
    {
      continue;
    }
    result.freeNodes += kind[v] == NodeKind::Free;
    result.slidingNodes += kind[v] == NodeKind::Sliding;
    result.fixedNodes += kind[v] == NodeKind::Fixed;
  }
  const std::vector<char> mine = nodesOfThisProcess();
  for (int iteration = 0; iteration < options.iterations; ++iteration)
  {
    for (std::size_t v = 0; v < n; ++v)
    {
      if (!mine[v])
      {
        continue;
      }
      if (relaxNode(static_cast<Index>(v)))
      {
        ++result.acceptedMoves;
      }
      else
      {
        ++result.rejectedMoves;
      }
    }
  }
  result.movesBeyondDeviation = movesBeyondDeviation;
  if (options.processes > 1 && options.gatherOverProcesses)
  {
    shareMoves(mine, result);
  }
}

// The movable nodes this process relaxes (RelaxationOptions::processes):
// all of them on one process, else the groups of movable nodes connected
// through movable neighbours assigned to it, largest first (ties by their
// first node), each to the least loaded process (ties to the lowest).
std::vector<char> Relaxer::nodesOfThisProcess() const
{
  const std::size_t n = c.points.size();
  std::vector<char> mine(n, 0);
  for (std::size_t v = 0; v < n; ++v)
  {
    mine[v] = movable(v);
  }
  if (options.processes <= 1 || !options.gatherOverProcesses)
  {
    return mine;
  }
  UnionFind groups(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    for (Index w : neighbours[v])
    {
      if (mine[v] && mine[w])
      {
        groups.unite(v, static_cast<std::size_t>(w));
      }
    }
  }
  // the groups numbered in the order of their first node, and their sizes
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> groupOfRoot(n, kNone), sizes;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (mine[v])
    {
      std::size_t& g = groupOfRoot[groups.find(v)];
      if (g == kNone)
      {
        g = sizes.size();
        sizes.push_back(0);
      }
      ++sizes[g];
    }
  }
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
  std::vector<std::size_t> load(static_cast<std::size_t>(options.processes), 0);
  std::vector<int> owner(sizes.size(), 0);
  for (std::size_t g : order)
  {
    const auto least = std::min_element(load.begin(), load.end()) - load.begin();
    load[least] += sizes[g];
    owner[g] = static_cast<int>(least);
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    mine[v] = mine[v] && owner[groupOfRoot[groups.find(v)]] == options.process;
  }
  return mine;
}

// Every process's moved nodes and counts to every process: the nodes of
// `mine` whose coordinates changed (bit for bit) as (index, x, y, z), then
// (-1, accepted, rejected, beyond the deviation).
void Relaxer::shareMoves(const std::vector<char>& mine, RelaxationResult& result)
{
  std::vector<double> local;
  for (std::size_t v = 0; v < mine.size(); ++v)
  {
    if (mine[v] && std::memcmp(&c.points[v], &original[v], sizeof(Vec3)) != 0)
    {
      local.insert(local.end(), { static_cast<double>(v), c.points[v][0], c.points[v][1], c.points[v][2] });
    }
  }
  local.insert(local.end(), { -1.0, static_cast<double>(result.acceptedMoves),
                              static_cast<double>(result.rejectedMoves), static_cast<double>(movesBeyondDeviation) });
  const std::vector<double> all = options.gatherOverProcesses(local);
  result.acceptedMoves = result.rejectedMoves = result.movesBeyondDeviation = 0;
  for (std::size_t i = 0; i + 3 < all.size(); i += 4)
  {
    if (all[i] < 0)
    {
      result.acceptedMoves += static_cast<std::size_t>(all[i + 1]);
      result.rejectedMoves += static_cast<std::size_t>(all[i + 2]);
      result.movesBeyondDeviation += static_cast<std::size_t>(all[i + 3]);
    }
    else
    {
      c.points[static_cast<std::size_t>(all[i])] = Vec3{ all[i + 1], all[i + 2], all[i + 3] };
    }
  }
}

// The triangles of `surface` that have a moved point (`moved`) or whose box
// reaches the box of one that has: all a moved point can make cross.
// One box around all moved triangles took in nearly every triangle of a
// subdomain cut on several sides.
std::vector<Index> trianglesNearMoved(const TriangleSurface& surface, const std::vector<char>& moved)
{
  using IndexBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<IndexBox> movedBoxes, allBoxes;
  for (std::size_t i = 0; i < surface.triangles.size(); ++i)
  {
    const Triangle& t = surface.triangles[i];
    const CGAL::Bbox_3 box = toCgal(surface.points[t[0]]).bbox() + toCgal(surface.points[t[1]]).bbox() +
      toCgal(surface.points[t[2]]).bbox();
    allBoxes.emplace_back(box, i);
    if (moved[i])
    {
      movedBoxes.emplace_back(box, i);
    }
  }
  std::vector<char> near(moved);
  if (!movedBoxes.empty())
  {
    CGAL::box_intersection_d(movedBoxes.begin(), movedBoxes.end(), allBoxes.begin(), allBoxes.end(),
      [&](const IndexBox&, const IndexBox& other) { near[other.info()] = 1; });
  }
  std::vector<Index> list;
  for (std::size_t i = 0; i < near.size(); ++i)
  {
    if (near[i])
    {
      list.push_back(static_cast<Index>(i));
    }
  }
  return list;
}

// The moved points of the triangles of subdomain s that cross others of
// it, added to `back`.
void crossingMovedPoints(const SurfaceComplex& c, const std::vector<Vec3>& original,
  const std::vector<Index>& identity, int s, std::set<Index>& back)
{
  SubdomainSurface extracted;
  std::string unused;
  if (!extractSubdomainSurface(c, identity, s, extracted, unused))
  {
    return; // no triangles, or not closed: nothing the check could say
  }
  const TriangleSurface& surface = extracted.surface;
  auto complexPoint = [&](Index local) { return extracted.globalIds[local]; };
  auto wasMoved = [&](Index local) { return c.points[complexPoint(local)] != original[complexPoint(local)]; };
  std::vector<char> moved(surface.triangles.size(), 0);
  for (std::size_t i = 0; i < surface.triangles.size(); ++i)
  {
    for (Index v : surface.triangles[i])
    {
      moved[i] = moved[i] || wasMoved(v);
    }
  }
  const std::vector<Index> near = trianglesNearMoved(surface, moved);
  if (near.empty())
  {
    return;
  }
  const SelfIntersectionReport report = checkSelfIntersection(surface, near, 64);
  for (const auto& [f, g] : report.crossings)
  {
    for (Index i : { f, g })
    {
      for (Index v : surface.triangles[i])
      {
        if (wasMoved(v))
        {
          back.insert(complexPoint(v));
        }
      }
    }
  }
}

// Moves that made a subdomain's surface cross itself are undone: every
// moved node of a crossing triangle goes back where it was, until no
// subdomain crosses itself (a few rounds; the complex before relaxation is
// the one the triangulator checked). KeepSurface moves keep each fan's
// polygon, but a fan counts as in its plane within planeTolerance, so a
// move next to a point computed a hair off an inclined plane can cross a
// surface triangle that meets the plane at a shallow angle: on occt-Bottom
// cut by 16 parallel planes (the core alone, with the interfaces at the
// sweep's size) one node was put back. Checked with CGAL's exact predicates
// among the triangles of moved nodes and those whose boxes reach theirs.
// With options.checksSubdomain, each process checks its share of the
// subdomains and the points to put back are the union over processes, so
// every process puts back the same points as one process checking all.
// Returns the number of nodes put back; `error` is set (on every process)
// where a check failed on any. A process that comes with `error` already
// set (its relaxation failed) still makes the collective calls, so the
// others learn of it instead of waiting for it.
std::size_t undoCrossingMoves(
  SurfaceComplex& c, const std::vector<Vec3>& original, const RelaxationOptions& options, std::string& error)
{
  std::size_t undone = 0;
  int subdomains = 0; // the labels in use (a piece's complex may not set subdomainCount)
  for (const SubdomainPair& pair : c.trianglePairs)
  {
    subdomains = std::max({ subdomains, pair[0] + 1, pair[1] + 1 });
  }
  std::vector<Index> identity(c.points.size()); // complex points are their own ids here
  for (std::size_t v = 0; v < identity.size(); ++v)
  {
    identity[v] = static_cast<Index>(v);
  }
  constexpr Index kFailed = -1; // sent instead of points where a check threw
  for (int round = 0; round < 4; ++round)
  {
    std::set<Index> back;
    try
    {
      for (int s = 0; s < subdomains && error.empty(); ++s)
      {
        if (!options.checksSubdomain || options.checksSubdomain(s))
        {
          crossingMovedPoints(c, original, identity, s, back);
        }
      }
    }
    catch (const std::exception& e)
    {
      error = std::string("the check for crossings after relaxation failed: ") + e.what();
    }
    if (!error.empty())
    {
      back = { kFailed };
    }
    if (options.unionOverProcesses)
    {
      const std::vector<Index> all = options.unionOverProcesses({ back.begin(), back.end() });
      back = std::set<Index>(all.begin(), all.end());
    }
    if (back.count(kFailed))
    {
      if (error.empty())
      {
        error = "the check for crossings after relaxation failed on another process";
      }
      return undone;
    }
    if (back.empty())
    {
      break;
    }
    for (Index v : back)
    {
      c.points[v] = original[v];
    }
    undone += back.size();
  }
  return undone;
}
} // namespace

TriangleQualityFigures triangleQuality(const SurfaceComplex& c)
{
  TriangleQualityFigures q;
  q.triangles = c.triangles.size();
  q.minimumAngleDegrees = c.triangles.empty() ? 0 : 180;
  std::size_t below10 = 0, below20 = 0;
  for (const auto& t : c.triangles)
  {
    const double a = triangleMinimumAngle(c.points[t[0]], c.points[t[1]], c.points[t[2]]) / kDegree;
    q.minimumAngleDegrees = std::min(q.minimumAngleDegrees, a);
    below10 += a < 10 ? 1 : 0;
    below20 += a < 20 ? 1 : 0;
  }
  if (q.triangles > 0)
  {
    q.shareBelow10Degrees = static_cast<double>(below10) / q.triangles;
    q.shareBelow20Degrees = static_cast<double>(below20) / q.triangles;
  }
  return q;
}

SurfaceChangeFigures surfaceChange(const SurfaceComplex& before, const SurfaceComplex& after)
{
  SurfaceChangeFigures f;
  const double v0 = outerSurfaceVolume(before), v1 = outerSurfaceVolume(after);
  f.volumeChange = v0 != 0 ? (v1 - v0) / v0 : 0;
  const std::vector<double> s0 = subdomainVolumes(before), s1 = subdomainVolumes(after);
  for (std::size_t s = 0; s < s0.size() && s < s1.size(); ++s)
  {
    if (s0[s] != 0)
    {
      f.maximumSubdomainVolumeChange = std::max(f.maximumSubdomainVolumeChange, std::fabs((s1[s] - s0[s]) / s0[s]));
    }
  }
  f.boundingBoxDiagonal = boundingBoxDiagonal(before.points);
  if (f.boundingBoxDiagonal > 0)
  {
    f.deviationOutputToInput = sampledDistance(after, before) / f.boundingBoxDiagonal;
    f.deviationInputToOutput = sampledDistance(before, after) / f.boundingBoxDiagonal;
  }
  return f;
}

RelaxationResult relaxSurfaceComplex(SurfaceComplex& c, const RelaxationOptions& options)
{
  RelaxationResult result;
  if (!c.interfaces.empty())
  {
    result.error = "the interfaces are not triangulated yet: run InterfaceTriangulator first";
    return result;
  }
  const bool knownMode = options.mode == RelaxationMode::KeepSurface || options.mode == RelaxationMode::SmoothSurface;
  if (!knownMode || options.iterations < 0 || !(options.relaxationFactor > 0 && options.relaxationFactor <= 1) ||
    !(options.featureAngleDegrees >= 0 && options.featureAngleDegrees <= 180) || options.rings < 0 ||
    !(options.maximumSurfaceDeviation >= 0))
  {
    result.error = "invalid relaxation options: mode KeepSurface or SmoothSurface, iterations >= 0, relaxation "
                   "factor in (0, 1], feature angle in [0, 180] degrees, rings >= 0, maximum surface "
                   "deviation >= 0";
    return result;
  }
  result.before = triangleQuality(c);
  const SurfaceComplex before = c;
  try
  {
    Relaxer(c, options).run(result);
  }
  catch (const std::exception& e)
  {
    result.error = std::string("relaxation failed: ") + e.what();
  }
  result.undoneMoves = undoCrossingMoves(c, before.points, options, result.error);
  if (!result.error.empty())
  {
    return result;
  }
  result.contourPointsPulledInside = keepStraightContourPointsInside(c);
  result.after = triangleQuality(c);
  result.change = surfaceChange(before, c);
  result.ok = true;
  return result;
}
} // namespace ptm
