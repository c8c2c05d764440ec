#include "ContourSubdivision.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ptm
{
namespace
{
using UndirectedEdge = std::array<Index, 2>;

UndirectedEdge undirected(Index a, Index b)
{
  return a < b ? UndirectedEdge{ a, b } : UndirectedEdge{ b, a };
}

// The size wanted at p: the field where it is set, positive and below
// `size`, never under size / 1000 (a field near 0 must not split an edge
// into millions of parts); `size` elsewhere.
double localSize(const ContourSubdivisionOptions& options, const Vec3& p)
{
  if (!options.sizeAt)
  {
    return options.size;
  }
  const double field = options.sizeAt(p);
  return field > 0 && field < options.size ? std::max(field, 1e-3 * options.size) : options.size;
}

// The points of one edge's split, from `from` to `to` (none if it is short).
std::vector<Vec3> splitPoints(const Vec3& from, const Vec3& to, const ContourSubdivisionOptions& options)
{
  const Vec3 d = to - from;
  const double parts = std::round(norm(d) / localSize(options, from + 0.5 * d));
  std::vector<Vec3> points;
  for (int i = 1; parts >= 2 && i < static_cast<int>(parts); ++i)
  {
    points.push_back(from + (static_cast<double>(i) / parts) * d);
  }
  return points;
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
  std::map<UndirectedEdge, EdgeSplit> byIds; // keyed by the ends' global ids
  for (const InterfaceRegion& region : complex.interfaces)
  {
    for (const DirectedEdge& e : region.edges)
    {
      const bool firstSmaller = globalIds[e[0]] < globalIds[e[1]];
      const Index a = firstSmaller ? e[0] : e[1], b = firstSmaller ? e[1] : e[0];
      const UndirectedEdge key{ globalIds[a], globalIds[b] };
      if (byIds.count(key))
      {
        continue;
      }
      std::vector<Vec3> points = splitPoints(complex.points[a], complex.points[b], options);
      if (!points.empty())
      {
        byIds[key] = EdgeSplit{ { a, b }, std::move(points) };
      }
    }
  }
  std::vector<EdgeSplit> splits;
  splits.reserve(byIds.size());
  for (auto& [key, split] : byIds)
  {
    splits.push_back(std::move(split));
  }
  return splits;
}

void applyEdgeSplits(SurfaceComplex& c, const std::vector<EdgeSplit>& splits)
{
  std::map<UndirectedEdge, std::pair<const EdgeSplit*, Index>> splitOf; // the split and its first point
  for (const EdgeSplit& s : splits)
  {
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
