#include "PlaneAlignment.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace ptm
{
NearlyContinuedLine findNearlyContinuedLine(
  const SurfaceComplex& c, int cell, const Vec3& proposedNormal, double maximumAngleDegrees)
{
  NearlyContinuedLine best;
  double bestSine = std::sin(maximumAngleDegrees * kPi / 180.0);
  std::set<int> ownPlanes;
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (region.pair[0] == cell || region.pair[1] == cell)
    {
      ownPlanes.insert(region.planeId);
    }
  }
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (region.pair[0] != cell && region.pair[1] != cell)
    {
      continue;
    }
    const CuttingPlane& face = c.planes[region.planeId];
    const Vec3 proposedLine = cross(face.normal, proposedNormal);
    if (norm(proposedLine) < 1e-6)
    {
      continue; // the proposed plane is parallel to this interface
    }
    const Vec3 along = normalized(proposedLine);
    // points computed on a plane (crossings, chord points) lie on it up to
    // round-off of their coordinates
    const double onPlane = 1e-12 * std::max(largestCoordinateOf(c, region), 1e-300);
    for (std::size_t q = 0; q < c.planes.size(); ++q)
    {
      const int planeId = static_cast<int>(q);
      const CuttingPlane& plane = c.planes[q];
      const Vec3 line = cross(face.normal, plane.normal);
      const double lineLength = norm(line);
      if (planeId == region.planeId || lineLength < 1e-6)
      {
        continue;
      }
      const Vec3 direction = (1.0 / lineLength) * line;
      const double sine = norm(cross(direction, along));
      if (!(sine < bestSine))
      {
        continue;
      }
      const double offset = dot(plane.normal, plane.origin);
      int pointsOnPlane = 0;
      for (const DirectedEdge& e : region.edges)
      {
        if (std::fabs(dot(plane.normal, c.points[e[0]]) - offset) <= onPlane && ++pointsOnPlane == 2)
        {
          break;
        }
      }
      if (pointsOnPlane < 2)
      {
        continue;
      }
      bestSine = sine;
      best.found = true;
      best.planeId = planeId;
      best.interfacePlaneId = region.planeId;
      best.boundsPart = ownPlanes.count(planeId) > 0;
      best.angleDegrees = std::asin(std::min(1.0, sine)) * 180.0 / kPi;
      best.direction = direction;
      best.linePoint = pointOnBothPlanes(face.normal, dot(face.normal, face.origin), plane.normal, offset);
      best.parallelNormal = normalized(proposedNormal - dot(proposedNormal, direction) * direction);
    }
  }
  return best;
}
} // namespace ptm
