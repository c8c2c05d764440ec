#include "SurfaceRelaxation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace ptm
{
namespace
{
constexpr double kDegree = kPi / 180.0;
// a node whose worst incident angle is below this gets the directed search
constexpr double kPoorAngleDegrees = 20.0;

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

enum class NodeKind
{
  Free,
  Sliding,
  Fixed
};
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

RelaxationResult relaxSurfaceComplex(SurfaceComplex& c, const RelaxationOptions& options)
{
  RelaxationResult result;
  if (!c.interfaces.empty())
  {
    result.error = "the interfaces are not triangulated yet: run InterfaceTriangulator first";
    return result;
  }
  if (options.iterations < 0 || !(options.relaxationFactor > 0 && options.relaxationFactor <= 1) ||
    !(options.featureAngleDegrees >= 0 && options.featureAngleDegrees <= 180) || options.rings < 0)
  {
    result.error = "invalid relaxation options: iterations >= 0, relaxation factor in (0, 1], "
                   "feature angle in [0, 180] degrees";
    return result;
  }
  result.before = triangleQuality(c);
  const std::size_t n = c.points.size();
  const std::size_t nt = c.triangles.size();
  auto patchOf = [&](std::size_t t) { return c.trianglePlanes.empty() ? -1 : c.trianglePlanes[t]; };

  // adjacency
  std::vector<std::vector<std::size_t>> trianglesOf(n);
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> edgeTriangles;
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = c.triangles[t][k], b = c.triangles[t][(k + 1) % 3];
      trianglesOf[a].push_back(t);
      edgeTriangles[{ std::min(a, b), std::max(a, b) }].push_back(t);
    }
  }
  std::vector<Vec3> normals(nt);
  for (std::size_t t = 0; t < nt; ++t)
  {
    const auto& tri = c.triangles[t];
    normals[t] = normalized(cross(c.points[tri[1]] - c.points[tri[0]], c.points[tri[2]] - c.points[tri[0]]));
  }
  // feature edges
  const double cosFeature = std::cos(options.featureAngleDegrees * kDegree);
  std::vector<std::vector<Index>> featureNeighbours(n);
  std::vector<std::set<Index>> neighbours(n);
  std::map<std::pair<Index, Index>, std::vector<int>> featureKind;
  for (const auto& [edge, ts] : edgeTriangles)
  {
    neighbours[edge.first].insert(edge.second);
    neighbours[edge.second].insert(edge.first);
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
      featureNeighbours[edge.first].push_back(edge.second);
      featureNeighbours[edge.second].push_back(edge.first);
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
  }
  std::vector<NodeKind> kind(n, NodeKind::Fixed);
  std::vector<int> patch(n, -2);
  for (std::size_t v = 0; v < n; ++v)
  {
    if (trianglesOf[v].empty())
    {
      continue;
    }
    patch[v] = patchOf(trianglesOf[v][0]);
    const std::size_t f = featureNeighbours[v].size();
    kind[v] = f == 0 ? NodeKind::Free : f == 2 ? NodeKind::Sliding : NodeKind::Fixed;
    if (kind[v] == NodeKind::Sliding)
    {
      // a node slides only along one feature curve that runs straight on
      // through it: where a contour meets a surface crease, or where the curve
      // turns by more than the feature angle, sliding would leave the plane or
      // cut the corner, so the node is a corner and stays put
      const Index a = featureNeighbours[v][0], b = featureNeighbours[v][1];
      const Index w = static_cast<Index>(v);
      const auto& kindA = featureKind[{ std::min(w, a), std::max(w, a) }];
      const auto& kindB = featureKind[{ std::min(w, b), std::max(w, b) }];
      const Vec3 ta = normalized(c.points[a] - c.points[v]), tb = normalized(c.points[b] - c.points[v]);
      const bool straightOn = dot(ta, tb) <= -cosFeature;
      if (kindA != kindB || !straightOn)
      {
        kind[v] = NodeKind::Fixed;
      }
    }
  }
  // region: nodes within `rings` rings of a node on a cutting plane
  std::vector<char> active(n, 1);
  if (options.nearCutsOnly)
  {
    std::vector<int> distance(n, -1);
    std::vector<Index> front;
    for (std::size_t t = 0; t < nt; ++t)
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

  const std::vector<Vec3> original = c.points;
  // projection targets from the original geometry
  auto projectFree = [&](Index v, const Vec3& q) -> Vec3 {
    if (patch[v] >= 0)
    {
      const CuttingPlane& plane = c.planes[patch[v]];
      return q - dot(plane.normal, q - plane.origin) * plane.normal;
    }
    // original surface triangles of the node's two rings
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
  };
  auto projectSliding = [&](Index v, const Vec3& q) -> Vec3 {
    // the original feature curve through the node, two edges each way
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
  };
  auto worstAngle = [&](Index v) {
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t t : trianglesOf[v])
    {
      const auto& tri = c.triangles[t];
      worst = std::min(worst, triangleMinimumAngle(c.points[tri[0]], c.points[tri[1]], c.points[tri[2]]));
    }
    return worst;
  };
  auto valid = [&](Index v) {
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
  };

  for (int iteration = 0; iteration < options.iterations; ++iteration)
  {
    for (std::size_t v = 0; v < n; ++v)
    {
      if (!active[v] || kind[v] == NodeKind::Fixed || trianglesOf[v].empty())
      {
        continue;
      }
      // smoothing target: the centroid of the neighbours (along the curve for sliding nodes)
      Vec3 target{ 0, 0, 0 };
      const auto& along = kind[v] == NodeKind::Sliding ? featureNeighbours[v]
                                                      : std::vector<Index>(neighbours[v].begin(), neighbours[v].end());
      for (Index w : along)
      {
        target = target + c.points[w];
      }
      target = (1.0 / static_cast<double>(along.size())) * target;
      const Vec3 start = c.points[v];
      const double before = worstAngle(static_cast<Index>(v));
      bool accepted = false;
      for (double step = options.relaxationFactor; step > options.relaxationFactor / 8; step *= 0.5)
      {
        const Vec3 q = start + step * (target - start);
        c.points[v] = kind[v] == NodeKind::Sliding ? projectSliding(static_cast<Index>(v), q)
                                                   : projectFree(static_cast<Index>(v), q);
        if (valid(static_cast<Index>(v)) && worstAngle(static_cast<Index>(v)) >= before)
        {
          accepted = true;
          break;
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
      const double current = worstAngle(static_cast<Index>(v));
      if (current < kPoorAngleDegrees * kDegree)
      {
        const Vec3 from = c.points[v];
        Vec3 best = from;
        double bestAngle = current;
        for (Index w : along)
        {
          for (double fraction : { 0.05, 0.15, 0.3 })
          {
            const Vec3 q = from + fraction * (c.points[w] - from);
            c.points[v] = kind[v] == NodeKind::Sliding ? projectSliding(static_cast<Index>(v), q)
                                                       : projectFree(static_cast<Index>(v), q);
            if (valid(static_cast<Index>(v)))
            {
              const double angle = worstAngle(static_cast<Index>(v));
              if (angle > bestAngle)
              {
                bestAngle = angle;
                best = c.points[v];
              }
            }
          }
        }
        c.points[v] = best;
        accepted = accepted || bestAngle > current;
      }
      if (accepted)
      {
        ++result.acceptedMoves;
      }
      else
      {
        ++result.rejectedMoves;
      }
    }
  }
  result.after = triangleQuality(c);
  result.ok = true;
  return result;
}
} // namespace ptm
