#include "SurfaceComplex.h"

#include <algorithm>
#include <map>

namespace ptm
{
bool chainLoops(const std::vector<DirectedEdge>& edges, std::vector<std::vector<Index>>& loops)
{
  loops.clear();
  std::vector<DirectedEdge> sorted = edges;
  std::sort(sorted.begin(), sorted.end());
  std::vector<bool> used(sorted.size(), false);
  auto firstOutgoing = [&](Index from) -> std::size_t {
    auto it = std::lower_bound(sorted.begin(), sorted.end(), DirectedEdge{ from, INT64_MIN });
    for (; it != sorted.end() && (*it)[0] == from; ++it)
    {
      const std::size_t k = static_cast<std::size_t>(it - sorted.begin());
      if (!used[k])
      {
        return k;
      }
    }
    return sorted.size();
  };
  for (std::size_t start = 0; start < sorted.size(); ++start)
  {
    if (used[start])
    {
      continue;
    }
    std::vector<Index> loop;
    std::size_t k = start;
    const Index first = sorted[start][0];
    while (true)
    {
      used[k] = true;
      loop.push_back(sorted[k][0]);
      const Index next = sorted[k][1];
      if (next == first)
      {
        break;
      }
      k = firstOutgoing(next);
      if (k == sorted.size())
      {
        return false;
      }
    }
    loops.push_back(std::move(loop));
  }
  return true;
}

Vec3 vectorArea(const std::vector<Vec3>& points, const std::vector<DirectedEdge>& edges)
{
  Vec3 a{ 0, 0, 0 };
  for (const auto& e : edges)
  {
    a = a + cross(points[e[0]], points[e[1]]);
  }
  return 0.5 * a;
}

namespace
{
// Adds every face's divergence-theorem flux (field x / 3) to the labels on
// its two sides: + for the side its normal points out of, - for the other.
template <typename Add>
void addFluxes(const SurfaceComplex& c, Add&& add)
{
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    const auto& t = c.triangles[i];
    const double flux = dot(c.points[t[0]], cross(c.points[t[1]], c.points[t[2]])) / 6.0;
    add(c.trianglePairs[i][0], flux);
    add(c.trianglePairs[i][1], -flux);
  }
  for (const auto& region : c.interfaces)
  {
    const Vec3& origin = c.planes[region.planeId].origin;
    const double flux = dot(origin, vectorArea(c.points, region.edges)) / 3.0;
    add(region.pair[0], flux);
    add(region.pair[1], -flux);
  }
}
} // namespace

std::vector<double> subdomainVolumes(const SurfaceComplex& c)
{
  std::vector<double> v(c.subdomainCount, 0.0);
  addFluxes(c, [&](int s, double value) {
    if (s >= 0 && s < c.subdomainCount)
    {
      v[s] += value;
    }
  });
  return v;
}

double labelVolume(const SurfaceComplex& c, int label)
{
  double v = 0;
  addFluxes(c, [&](int s, double value) {
    if (s == label)
    {
      v += value;
    }
  });
  return v;
}

std::vector<Index> regionPoints(const InterfaceRegion& region)
{
  std::vector<Index> points;
  for (const DirectedEdge& e : region.edges)
  {
    points.insert(points.end(), e.begin(), e.end());
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

std::vector<Triangle> subdomainTriangles(const SurfaceComplex& c, int s)
{
  std::vector<Triangle> out;
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][0] == s)
    {
      out.push_back(c.triangles[i]);
    }
    else if (c.trianglePairs[i][1] == s)
    {
      const auto& t = c.triangles[i];
      out.push_back({ t[0], t[2], t[1] });
    }
  }
  return out;
}
} // namespace ptm
