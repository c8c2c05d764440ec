#include "SurfaceOrientation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <sstream>
#include <unordered_map>

namespace ptm
{
namespace
{
struct EdgeUse
{
  Index triangle;
  bool forward; // stored as (min, max) in the triangle's direction
};

std::uint64_t edgeKey(Index a, Index b, Index pointCount)
{
  const Index lo = std::min(a, b), hi = std::max(a, b);
  return static_cast<std::uint64_t>(lo) * static_cast<std::uint64_t>(pointCount) +
    static_cast<std::uint64_t>(hi);
}

// (a, b, c) -> (c, b, a): turned back, an inside-out file's triangle is the
// outward file's exactly (same first corner), so both mesh alike bit for bit
// (the thickness rays start from the corners in order).
void reverse(Triangle& t)
{
  std::swap(t[0], t[2]);
}
} // namespace

std::size_t mergeDuplicatePoints(TriangleSurface& s, std::size_t& droppedTriangles,
  std::vector<Index>& sourceOfTriangle, double relativeTolerance)
{
  const std::size_t n = s.points.size();
  Vec3 lo = n ? s.points[0] : Vec3{ 0, 0, 0 }, hi = lo;
  for (const auto& p : s.points)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double tolerance = relativeTolerance * norm(hi - lo);
  // Points within the tolerance of an earlier point are merged into it: a
  // hash grid with cells of the tolerance's size, searched 3x3x3 around a point.
  std::vector<Index> representative(n);
  std::unordered_map<std::uint64_t, std::vector<Index>> grid;
  const double cell = tolerance > 0 ? tolerance : 1.0;
  auto cellOf = [&](const Vec3& p, int k) {
    return static_cast<std::int64_t>(std::floor((p[k] - lo[k]) / cell));
  };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>(i) * 73856093u ^ static_cast<std::uint64_t>(j) * 19349663u ^
      static_cast<std::uint64_t>(k) * 83492791u;
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec3& p = s.points[i];
    const std::int64_t ci = cellOf(p, 0), cj = cellOf(p, 1), ck = cellOf(p, 2);
    Index found = -1;
    for (std::int64_t di = -1; di <= 1 && found < 0; ++di)
    {
      for (std::int64_t dj = -1; dj <= 1 && found < 0; ++dj)
      {
        for (std::int64_t dk = -1; dk <= 1 && found < 0; ++dk)
        {
          auto it = grid.find(key(ci + di, cj + dj, ck + dk));
          if (it == grid.end())
          {
            continue;
          }
          for (Index j : it->second)
          {
            const Vec3 d = s.points[j] - p;
            if (std::fabs(d[0]) <= tolerance && std::fabs(d[1]) <= tolerance &&
              std::fabs(d[2]) <= tolerance)
            {
              found = j;
              break;
            }
          }
        }
      }
    }
    if (found >= 0)
    {
      representative[i] = found;
    }
    else
    {
      representative[i] = static_cast<Index>(i);
      grid[key(ci, cj, ck)].push_back(static_cast<Index>(i));
    }
  }
  // renumber the kept points in their original order, dropping unused ones
  std::vector<Index> newIndex(n, -1);
  std::vector<Triangle> triangles;
  droppedTriangles = 0;
  sourceOfTriangle.clear();
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    Triangle tri;
    for (int c = 0; c < 3; ++c)
    {
      tri[c] = representative[s.triangles[t][c]];
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      ++droppedTriangles;
      continue;
    }
    triangles.push_back(tri);
    sourceOfTriangle.push_back(static_cast<Index>(t));
  }
  std::vector<char> used(n, 0);
  for (const auto& t : triangles)
  {
    for (Index v : t)
    {
      used[v] = 1;
    }
  }
  std::vector<Vec3> points;
  std::size_t merged = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (representative[i] != static_cast<Index>(i))
    {
      ++merged;
    }
    else if (used[i])
    {
      newIndex[i] = static_cast<Index>(points.size());
      points.push_back(s.points[i]);
    }
  }
  for (auto& t : triangles)
  {
    for (auto& v : t)
    {
      v = newIndex[v];
    }
  }
  s.points.swap(points);
  s.triangles.swap(triangles);
  return merged;
}

double windingNumber(const TriangleSurface& s, const std::vector<Index>& triangles, const Vec3& p)
{
  // Van Oosterom-Strackee solid angle of each triangle seen from p.
  double total = 0;
  for (Index t : triangles)
  {
    const Vec3 a = s.points[s.triangles[t][0]] - p;
    const Vec3 b = s.points[s.triangles[t][1]] - p;
    const Vec3 c = s.points[s.triangles[t][2]] - p;
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator =
      la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * 3.14159265358979323846);
}

OrientationResult orientShells(TriangleSurface& s)
{
  OrientationResult result;
  auto& report = result.report;
  const Index pointCount = static_cast<Index>(s.points.size());
  const std::size_t triangleCount = s.triangles.size();

  std::unordered_map<std::uint64_t, std::vector<EdgeUse>> edges;
  edges.reserve(triangleCount * 2);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Index a = s.triangles[t][c], b = s.triangles[t][(c + 1) % 3];
      edges[edgeKey(a, b, pointCount)].push_back({ static_cast<Index>(t), a < b });
    }
  }
  std::size_t open = 0, nonManifold = 0;
  for (const auto& [key, uses] : edges)
  {
    if (uses.size() == 1)
    {
      ++open;
    }
    else if (uses.size() > 2)
    {
      ++nonManifold;
    }
  }
  if (open > 0 || nonManifold > 0)
  {
    std::ostringstream msg;
    msg << "the surface is not closed and edge-manifold: " << open
        << " boundary edges (used by one triangle) and " << nonManifold
        << " non-manifold edges (used by more than two triangles)";
    result.error = msg.str();
    return result;
  }

  // Propagate orientation through shared edges, shell by shell.
  std::vector<int> shell(triangleCount, -1);
  std::vector<char> flip(triangleCount, 0);
  int shellCount = 0;
  for (std::size_t seed = 0; seed < triangleCount; ++seed)
  {
    if (shell[seed] >= 0)
    {
      continue;
    }
    std::queue<Index> queue;
    shell[seed] = shellCount;
    queue.push(static_cast<Index>(seed));
    while (!queue.empty())
    {
      const Index t = queue.front();
      queue.pop();
      for (int c = 0; c < 3; ++c)
      {
        const Index a = s.triangles[t][c], b = s.triangles[t][(c + 1) % 3];
        const auto& uses = edges[edgeKey(a, b, pointCount)];
        const EdgeUse& mine = uses[0].triangle == t ? uses[0] : uses[1];
        const EdgeUse& other = uses[0].triangle == t ? uses[1] : uses[0];
        // consistent neighbours traverse the shared edge in opposite directions
        const bool mineForward = mine.forward != static_cast<bool>(flip[t]);
        const char neededFlip = (other.forward == mineForward) ? 1 : 0;
        if (shell[other.triangle] < 0)
        {
          shell[other.triangle] = shellCount;
          flip[other.triangle] = neededFlip;
          queue.push(other.triangle);
        }
        else if (flip[other.triangle] != neededFlip)
        {
          result.error = "a shell of the surface is not orientable (Moebius-like)";
          return result;
        }
      }
    }
    ++shellCount;
  }
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    if (flip[t])
    {
      reverse(s.triangles[t]);
      ++report.reorientedTriangles;
    }
  }

  std::vector<std::vector<Index>> shellTriangles(shellCount);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    shellTriangles[shell[t]].push_back(static_cast<Index>(t));
  }
  std::vector<double> volume(shellCount, 0.0);
  for (int k = 0; k < shellCount; ++k)
  {
    // about a point of the shell, for accuracy far from the origin
    const Vec3 o = s.points[s.triangles[shellTriangles[k][0]][0]];
    for (Index t : shellTriangles[k])
    {
      const auto& tri = s.triangles[t];
      volume[k] += sixTimesVolumeAbout(o, s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]);
    }
    volume[k] /= 6.0;
  }
  // Nesting depth: how many other shells contain a point of this shell.
  std::vector<int> depth(shellCount, 0);
  if (shellCount > 1)
  {
    for (int k = 0; k < shellCount; ++k)
    {
      const auto& tri = s.triangles[shellTriangles[k][0]];
      const Vec3 probe = (1.0 / 3.0) * (s.points[tri[0]] + s.points[tri[1]] + s.points[tri[2]]);
      for (int j = 0; j < shellCount; ++j)
      {
        if (j != k && std::fabs(windingNumber(s, shellTriangles[j], probe)) > 0.5)
        {
          ++depth[k];
        }
      }
    }
  }
  for (int k = 0; k < shellCount; ++k)
  {
    const bool cavity = depth[k] % 2 == 1;
    report.cavityCount += cavity ? 1 : 0;
    if ((volume[k] < 0) != cavity)
    {
      for (Index t : shellTriangles[k])
      {
        reverse(s.triangles[t]);
      }
      volume[k] = -volume[k];
      ++report.invertedShells;
    }
  }
  report.shellCount = static_cast<std::size_t>(shellCount);
  report.triangleShell = shell;
  report.shellVolume = volume;
  result.ok = true;
  return result;
}
} // namespace ptm
