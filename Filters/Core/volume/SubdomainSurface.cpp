#include "SubdomainSurface.h"

#include <algorithm>
#include <sstream>
#include <tuple>

namespace ptm
{
bool extractSubdomainSurface(const SurfaceComplex& c, const std::vector<Index>& globalIds,
  int s, SubdomainSurface& out, std::string& error)
{
  out = SubdomainSurface();
  for (const auto& region : c.interfaces)
  {
    if (region.pair[0] == s || region.pair[1] == s)
    {
      std::ostringstream msg;
      msg << "subdomain " << s
          << " still has untriangulated interface loops: run InterfaceTriangulator first";
      error = msg.str();
      return false;
    }
  }
  auto gid = [&](Index p) { return globalIds.empty() ? p : globalIds[p]; };
  struct Face
  {
    std::array<Index, 3> ids;    // global ids, smallest first
    std::array<Index, 3> points; // the complex's points, in the same order
    Index source;
    int other;
  };
  std::vector<Face> faces;
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    const auto& pair = c.trianglePairs[i];
    if (pair[0] != s && pair[1] != s)
    {
      continue;
    }
    Triangle t = c.triangles[i];
    if (pair[1] == s)
    {
      std::swap(t[1], t[2]);
    }
    std::array<Index, 3> g{ gid(t[0]), gid(t[1]), gid(t[2]) };
    const int first = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
    std::rotate(g.begin(), g.begin() + first, g.end());
    std::rotate(t.begin(), t.begin() + first, t.end());
    faces.push_back({ g, t, c.sourceFaces.empty() ? -1 : c.sourceFaces[i], pair[0] == s ? pair[1] : pair[0] });
  }
  if (faces.empty())
  {
    std::ostringstream msg;
    msg << "subdomain " << s << " has no triangles in this piece";
    error = msg.str();
    return false;
  }
  std::sort(faces.begin(), faces.end(),
    [](const Face& a, const Face& b) { return a.ids < b.ids; });

  // closedness: every directed edge matched by its reverse exactly once
  // (sorted vectors, not maps: with maps for the edges and points this
  // function took 0.38 s of each rank on the 10 M ball at K = 2, in the
  // relaxer and the mesher, most of it in the maps)
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * faces.size());
  for (const Face& f : faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(f.ids[k], f.ids[(k + 1) % 3]);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::size_t bad = 0;
  for (auto e = edges.begin(); e != edges.end();)
  {
    const auto same = std::upper_bound(e, edges.end(), *e);
    const auto reverse = std::equal_range(edges.begin(), edges.end(), std::make_pair(e->second, e->first));
    bad += (same - e != 1 || reverse.second - reverse.first != 1) ? 1 : 0;
    e = same;
  }
  if (bad > 0)
  {
    std::ostringstream msg;
    msg << "the surface of subdomain " << s << " is not closed: " << bad
        << " edges are not shared by exactly two consistently oriented triangles";
    error = msg.str();
    return false;
  }

  // the subdomain's points in global id order, each at the complex point
  // it first has among the faces; only its own faces are looked at (a map
  // of every point of the complex, made for each subdomain, took 13 % of a
  // K = 64 run on one rank)
  std::vector<std::pair<Index, Index>> pointOfGlobal; // global id, complex point
  pointOfGlobal.reserve(3 * faces.size());
  for (const Face& f : faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      pointOfGlobal.emplace_back(f.ids[k], f.points[k]);
    }
  }
  std::stable_sort(pointOfGlobal.begin(), pointOfGlobal.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  pointOfGlobal.erase(std::unique(pointOfGlobal.begin(), pointOfGlobal.end(),
                        [](const auto& a, const auto& b) { return a.first == b.first; }),
    pointOfGlobal.end());
  for (const auto& [g, p] : pointOfGlobal)
  {
    out.globalIds.push_back(g);
    out.surface.points.push_back(c.points[p]);
  }
  auto localOf = [&](Index g) {
    return static_cast<Index>(std::lower_bound(out.globalIds.begin(), out.globalIds.end(), g) - out.globalIds.begin());
  };
  for (const Face& f : faces)
  {
    out.surface.triangles.push_back({ localOf(f.ids[0]), localOf(f.ids[1]), localOf(f.ids[2]) });
    out.sourceFaces.push_back(f.source);
    out.otherSide.push_back(f.other);
  }
  return true;
}
} // namespace ptm
