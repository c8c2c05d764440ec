#include "BentRegionCheck.h"

#include "SelfIntersectionCheck.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace ptm
{
namespace
{
// One subdomain's surface: its outer triangles and its regions' triangles
// (turned outward), with the triangles of bent regions and the outer ones in
// their box listed in `near`.
struct AssembledSurface
{
  TriangleSurface surface;
  std::vector<Index> near;
  std::unordered_map<Index, Index> local;

  Index point(const SurfaceComplex& c, Index v)
  {
    auto [it, inserted] = local.emplace(v, static_cast<Index>(surface.points.size()));
    if (inserted)
    {
      surface.points.push_back(c.points[v]);
    }
    return it->second;
  }
};

void addRegion(const SurfaceComplex& c, const TriangulatedRegion& r, int subdomain, bool bent,
  AssembledSurface& a)
{
  std::vector<Index> ids;
  for (Index v : *r.pointOfLocal)
  {
    ids.push_back(a.point(c, v));
  }
  for (const Vec3& p : r.triangulation->newPoints)
  {
    ids.push_back(static_cast<Index>(a.surface.points.size()));
    a.surface.points.push_back(p);
  }
  const bool outward = r.region->pair[0] == subdomain;
  for (const Triangle& t : r.triangulation->triangles)
  {
    if (bent)
    {
      a.near.push_back(static_cast<Index>(a.surface.triangles.size()));
    }
    a.surface.triangles.push_back(outward ? Triangle{ ids[t[0]], ids[t[1]], ids[t[2]] }
                                          : Triangle{ ids[t[0]], ids[t[2]], ids[t[1]] });
  }
}

// The surface of `subdomain`: its outer triangles held by the piece and its
// regions `mine` (of `regions`) turned outward. `near` lists the triangles
// of the regions flagged in `bent` and the outer ones in their box.
AssembledSurface assembleSubdomain(const SurfaceComplex& c, const std::vector<TriangulatedRegion>& regions,
  const std::vector<char>& bent, const std::vector<std::size_t>& mine, int subdomain)
{
  AssembledSurface a;
  Box bentBox;
  for (std::size_t r : mine)
  {
    if (bent[r])
    {
      for (Index v : *regions[r].pointOfLocal)
      {
        bentBox.add(c.points[v]);
      }
    }
    addRegion(c, regions[r], subdomain, bent[r] != 0, a);
  }
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][0] != subdomain || c.trianglePairs[i][1] != -1)
    {
      continue;
    }
    const Triangle& t = c.triangles[i];
    Box box;
    for (Index v : t)
    {
      box.add(c.points[v]);
    }
    if (box.overlaps(bentBox))
    {
      a.near.push_back(static_cast<Index>(a.surface.triangles.size()));
    }
    a.surface.triangles.push_back({ a.point(c, t[0]), a.point(c, t[1]), a.point(c, t[2]) });
  }
  return a;
}

// Whether the surface of `subdomain` crosses itself near its bent regions.
bool crossesNearBentRegions(const SurfaceComplex& c, const std::vector<TriangulatedRegion>& regions,
  const std::vector<char>& bent, const std::vector<std::size_t>& mine, int subdomain)
{
  const AssembledSurface a = assembleSubdomain(c, regions, bent, mine, subdomain);
  const SelfIntersectionReport report = checkSelfIntersection(a.surface, a.near);
  return !report.checked || report.intersects;
}

// subdomain -> indices into `regions` of its regions
std::map<int, std::vector<std::size_t>> regionsBySubdomain(const std::vector<TriangulatedRegion>& regions)
{
  std::map<int, std::vector<std::size_t>> regionsOf;
  for (std::size_t r = 0; r < regions.size(); ++r)
  {
    for (int s : regions[r].region->pair)
    {
      if (s >= 0)
      {
        regionsOf[s].push_back(r);
      }
    }
  }
  return regionsOf;
}

// The subdomains among `among` whose outer triangles the piece holds.
std::set<int> heldSubdomains(const SurfaceComplex& c, const std::set<int>& among)
{
  std::set<int> held;
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][1] == -1 && among.count(c.trianglePairs[i][0]))
    {
      held.insert(c.trianglePairs[i][0]);
    }
  }
  return held;
}
} // namespace

bool regionIsBent(const SurfaceComplex& c, const TriangulatedRegion& r)
{
  const CuttingPlane& plane = c.planes[r.region->planeId];
  Box box;
  for (Index v : *r.pointOfLocal)
  {
    box.add(c.points[v]);
  }
  const double roundOff = 1e-10 * norm(box.hi - box.lo);
  for (Index v : *r.pointOfLocal)
  {
    if (std::fabs(dot(plane.normal, c.points[v] - plane.origin)) > roundOff)
    {
      return true;
    }
  }
  return false;
}

std::vector<std::size_t> bentRegionsCrossingSurface(
  const SurfaceComplex& c, const std::vector<TriangulatedRegion>& regions)
{
  std::vector<char> bent(regions.size(), 0);
  std::set<int> withBent;
  for (std::size_t r = 0; r < regions.size(); ++r)
  {
    bent[r] = regionIsBent(c, regions[r]) ? 1 : 0;
    for (int s : regions[r].region->pair)
    {
      if (s >= 0 && bent[r])
      {
        withBent.insert(s);
      }
    }
  }
  const std::map<int, std::vector<std::size_t>> regionsOf = regionsBySubdomain(regions);
  std::set<std::size_t> flagged;
  for (int s : heldSubdomains(c, withBent))
  {
    if (crossesNearBentRegions(c, regions, bent, regionsOf.at(s), s))
    {
      for (std::size_t r : regionsOf.at(s))
      {
        if (bent[r])
        {
          flagged.insert(r);
        }
      }
    }
  }
  return { flagged.begin(), flagged.end() };
}

std::vector<int> subdomainsCrossingThemselves(
  const SurfaceComplex& c, const std::vector<TriangulatedRegion>& regions, const std::set<int>& among)
{
  const std::map<int, std::vector<std::size_t>> regionsOf = regionsBySubdomain(regions);
  const std::vector<char> none(regions.size(), 0);
  std::vector<int> crossing;
  for (int s : heldSubdomains(c, among))
  {
    auto it = regionsOf.find(s);
    const AssembledSurface a =
      assembleSubdomain(c, regions, none, it == regionsOf.end() ? std::vector<std::size_t>() : it->second, s);
    const SelfIntersectionReport report = checkSelfIntersection(a.surface);
    if (!report.checked || report.intersects)
    {
      crossing.push_back(s);
    }
  }
  return crossing;
}
} // namespace ptm
