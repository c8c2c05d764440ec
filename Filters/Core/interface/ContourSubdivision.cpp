#include "ContourSubdivision.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ptm
{
namespace
{
// The points that split from-to into `parts` equal parts.
std::vector<Vec3> pointsInParts(const Vec3& from, const Vec3& to, int parts)
{
  const Vec3 d = to - from;
  std::vector<Vec3> points;
  for (int i = 1; i < parts; ++i)
  {
    points.push_back(from + (static_cast<double>(i) / parts) * d);
  }
  return points;
}

// The parts edge {a, b} is split into (ContourSubdivision.h): at the local
// size, or finer across a thin surface triangle on it (`across`: the third
// corners of the surface triangles this rank holds on the edge).
int wantedParts(const SurfaceComplex& c, Index a, Index b, const std::vector<Index>& across,
  const ContourSubdivisionOptions& options)
{
  const Vec3 &pa = c.points[a], &pb = c.points[b];
  const double local = cappedSizeAt(options.sizeAt, options.size, pa + 0.5 * (pb - pa));
  double spacing = local;
  const double bound = options.minimumAngleDegrees * kPi / 180.0;
  for (Index x : across)
  {
    const Vec3& px = c.points[x];
    if (triangleMinimumAngle(pa, pb, px) < bound)
    {
      // the refinement splits the triangle's other edges at the distance of
      // the corner across (SegmentSpacing), so the contour takes the
      // smallest of the three: a wedge with its sharp corner at a contour
      // end has its third corner far from the contour, not its width
      const double width =
        std::min({ distanceToSegment(px, pa, pb), distanceToSegment(pa, pb, px), distanceToSegment(pb, px, pa) });
      spacing = std::min(spacing, std::max(kThinPieceSpacingFraction * local, width));
    }
  }
  const double parts = std::round(norm(pb - pa) / spacing);
  return parts >= 2 ? static_cast<int>(std::min(parts, 1e6)) : 1;
}

// The third corner of every surface triangle on each of `edges`.
std::map<UndirectedEdge, std::vector<Index>> cornersAcross(
  const SurfaceComplex& c, const std::map<UndirectedEdge, bool>& edges)
{
  std::map<UndirectedEdge, std::vector<Index>> across;
  for (const Triangle& t : c.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const UndirectedEdge e = undirected(t[k], t[(k + 1) % 3]);
      if (edges.count(e))
      {
        across[e].push_back(t[(k + 2) % 3]);
      }
    }
  }
  return across;
}

// sin of the angle under which a face on a split edge makes the split risky
// (EdgeSplit::risky): far above the 1e-13 or so at which one rounding of a
// split point can push a face across its neighbour, far below the angles of
// faces that merely meet the plane at a slant
constexpr double kRiskySine = 1e-6;

double sineBetween(const Vec3& unitA, const Vec3& b)
{
  const double length = norm(b);
  return length > 0 ? norm(cross(unitA, b)) / length : 0.0;
}

// Marks the splits whose edge has a surface triangle or a second plane
// within kRiskySine of one of its regions' planes.
//
// Not marked (session 33): edges of a region the cut bent at a vertex it
// snapped onto the plane without moving it, next to a surface triangle
// within 30 degrees of the plane. Such a vertex used to keep every edge of
// its region whole, because a new triangulation of the bent region crossed
// that triangle (CGAL's rotor, 16 parallel planes). The interface stage now
// checks the regions as triangulated instead: a bent region that crosses
// the surface (bentRegionsCrossingSurface) keeps its edges whole, and so do
// the regions of a split subdomain that crosses itself
// (subdomainsCrossingThemselves, BentRegionCheck.h; both in
// vtkInterfaceTriangulator.cxx). The blanket rule had left contour edges 10
// sizes long across the thin pins of KiCad's DPDT switch (16 parallel
// planes): fans of needles on the pins' faces and tetrahedra of 0.08
// degrees, 3.8 % under 10 degrees; split, 0.90 degrees and 2.2 %.
void markRisky(const SurfaceComplex& c, std::map<UndirectedEdge, EdgeSplit>& byPoints)
{
  std::map<UndirectedEdge, std::vector<int>> planesOf;
  for (const InterfaceRegion& region : c.interfaces)
  {
    for (const DirectedEdge& e : region.edges)
    {
      auto it = byPoints.find(undirected(e[0], e[1]));
      if (it != byPoints.end())
      {
        std::vector<int>& planes = planesOf[it->first];
        if (std::find(planes.begin(), planes.end(), region.planeId) == planes.end())
        {
          planes.push_back(region.planeId);
        }
      }
    }
  }
  for (const auto& [edge, planes] : planesOf)
  {
    for (std::size_t i = 0; i < planes.size(); ++i)
    {
      for (std::size_t j = i + 1; j < planes.size(); ++j)
      {
        byPoints[edge].risky = byPoints[edge].risky ||
          sineBetween(c.planes[planes[i]].normal, c.planes[planes[j]].normal) < kRiskySine;
      }
    }
  }
  for (const Triangle& t : c.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      auto it = planesOf.find(undirected(t[k], t[(k + 1) % 3]));
      if (it == planesOf.end())
      {
        continue;
      }
      const Vec3 normal = cross(c.points[t[1]] - c.points[t[0]], c.points[t[2]] - c.points[t[0]]);
      for (int plane : it->second)
      {
        byPoints[it->first].risky = byPoints[it->first].risky || sineBetween(c.planes[plane].normal, normal) < kRiskySine;
      }
    }
  }
}

// Complex indices of a split's points, from its end `a` to the other.
std::vector<Index> chainFrom(Index a, const EdgeSplit& split, Index firstPoint)
{
  std::vector<Index> chain(split.points.size());
  for (std::size_t i = 0; i < chain.size(); ++i)
  {
    chain[i] = firstPoint + static_cast<Index>(i);
  }
  if (a != split.ends[0])
  {
    std::reverse(chain.begin(), chain.end());
  }
  return chain;
}

// Replaces triangle t by the fan from its corner across edge k (k, k+1),
// the chain running along that edge; the first fan triangle takes slot t.
void fanTriangle(SurfaceComplex& c, std::size_t t, int k, const std::vector<Index>& chain)
{
  const Triangle tri = c.triangles[t];
  const Index x = tri[k], y = tri[(k + 1) % 3], z = tri[(k + 2) % 3];
  std::vector<Index> along{ x };
  along.insert(along.end(), chain.begin(), chain.end());
  along.push_back(y);
  const bool planes = c.trianglePlanes.size() == c.triangles.size();
  for (std::size_t i = 0; i + 1 < along.size(); ++i)
  {
    const Triangle piece{ along[i], along[i + 1], z };
    if (i == 0)
    {
      c.triangles[t] = piece;
      continue;
    }
    c.triangles.push_back(piece);
    c.trianglePairs.push_back(c.trianglePairs[t]);
    c.sourceFaces.push_back(c.sourceFaces[t]);
    if (planes)
    {
      c.trianglePlanes.push_back(c.trianglePlanes[t]);
    }
  }
}
} // namespace

std::vector<EdgeSplit> interfaceEdgeSplits(
  const SurfaceComplex& complex, const std::vector<Index>& globalIds, const ContourSubdivisionOptions& options)
{
  std::map<UndirectedEdge, bool> regionEdges; // -> whether its first end has the smaller global id
  for (const InterfaceRegion& region : complex.interfaces)
  {
    for (const DirectedEdge& e : region.edges)
    {
      const UndirectedEdge key = undirected(e[0], e[1]);
      regionEdges[key] = globalIds[key[0]] < globalIds[key[1]];
    }
  }
  const std::map<UndirectedEdge, std::vector<Index>> across = cornersAcross(complex, regionEdges);
  std::map<UndirectedEdge, EdgeSplit> byPoints; // keyed by the ends' complex indices
  for (const auto& [edge, firstSmaller] : regionEdges)
  {
    const Index a = firstSmaller ? edge[0] : edge[1], b = firstSmaller ? edge[1] : edge[0];
    auto corners = across.find(edge);
    const int parts =
      wantedParts(complex, a, b, corners == across.end() ? std::vector<Index>() : corners->second, options);
    EdgeSplit& split = byPoints[edge];
    split.ends = { a, b };
    splitIntoParts(complex, split, parts);
  }
  markRisky(complex, byPoints);
  std::map<UndirectedEdge, EdgeSplit> byIds; // sorted by the ends' global ids
  for (auto& [key, split] : byPoints)
  {
    byIds[{ globalIds[split.ends[0]], globalIds[split.ends[1]] }] = std::move(split);
  }
  std::vector<EdgeSplit> splits;
  splits.reserve(byIds.size());
  for (auto& [key, split] : byIds)
  {
    splits.push_back(std::move(split));
  }
  return splits;
}

void splitIntoParts(const SurfaceComplex& complex, EdgeSplit& split, int parts)
{
  split.parts = parts;
  split.points = pointsInParts(complex.points[split.ends[0]], complex.points[split.ends[1]], parts);
}

void applyEdgeSplits(SurfaceComplex& c, const std::vector<EdgeSplit>& splits)
{
  std::map<UndirectedEdge, std::pair<const EdgeSplit*, Index>> splitOf; // the split and its first point
  for (const EdgeSplit& s : splits)
  {
    if (s.risky || s.parts < 2)
    {
      continue;
    }
    splitOf[undirected(s.ends[0], s.ends[1])] = { &s, static_cast<Index>(c.points.size()) };
    c.points.insert(c.points.end(), s.points.begin(), s.points.end());
  }
  if (splitOf.empty())
  {
    return;
  }
  for (InterfaceRegion& region : c.interfaces)
  {
    std::vector<DirectedEdge> edges;
    for (const DirectedEdge& e : region.edges)
    {
      auto it = splitOf.find(undirected(e[0], e[1]));
      if (it == splitOf.end())
      {
        edges.push_back(e);
        continue;
      }
      Index from = e[0];
      for (Index p : chainFrom(e[0], *it->second.first, it->second.second))
      {
        edges.push_back({ from, p });
        from = p;
      }
      edges.push_back({ from, e[1] });
    }
    region.edges = std::move(edges);
  }
  // The fans' own triangles are visited too (appended), so a triangle with
  // two split edges is split at the second one in the fan triangle keeping it.
  for (std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Triangle& tri = c.triangles[t];
      auto it = splitOf.find(undirected(tri[k], tri[(k + 1) % 3]));
      if (it != splitOf.end())
      {
        fanTriangle(c, t, k, chainFrom(tri[k], *it->second.first, it->second.second));
        k = -1; // slot t holds a new triangle: look at its edges again
      }
    }
  }
}
} // namespace ptm
