#include "HalfSpaceMeasure.h"
#include "PlaneSplit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ptm
{
std::vector<Index> cellPoints(const SurfaceComplex& c, int cell)
{
  std::vector<Index> points;
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][0] == cell || c.trianglePairs[i][1] == cell)
    {
      points.insert(points.end(), c.triangles[i].begin(), c.triangles[i].end());
    }
  }
  for (const auto& region : c.interfaces)
  {
    if (region.pair[0] == cell || region.pair[1] == cell)
    {
      for (const auto& e : region.edges)
      {
        points.push_back(e[0]);
      }
    }
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

std::vector<PointSpacing> shortestEdges(const SurfaceComplex& c, int cell)
{
  std::map<Index, double> shortest;
  auto touch = [&](Index a, Index b) {
    const double length = norm(c.points[a] - c.points[b]);
    for (Index v : { a, b })
    {
      auto [it, inserted] = shortest.emplace(v, length);
      it->second = inserted ? length : std::min(it->second, length);
    }
  };
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][0] == cell || c.trianglePairs[i][1] == cell)
    {
      const Triangle& t = c.triangles[i];
      touch(t[0], t[1]);
      touch(t[1], t[2]);
      touch(t[2], t[0]);
    }
  }
  for (const auto& region : c.interfaces)
  {
    if (region.pair[0] == cell || region.pair[1] == cell)
    {
      for (const auto& e : region.edges)
      {
        touch(e[0], e[1]);
      }
    }
  }
  std::vector<PointSpacing> spacing;
  for (const auto& [v, h] : shortest)
  {
    if (h > 0)
    {
      spacing.push_back({ v, h });
    }
  }
  return spacing;
}

PlaneClearance::PlaneClearance(const SurfaceComplex& c, int cell, const Vec3& normal)
  : PlaneClearance(c, shortestEdges(c, cell), normal)
{
}

PlaneClearance::PlaneClearance(const SurfaceComplex& c, const std::vector<PointSpacing>& spacing, const Vec3& normal,
  const std::vector<Index>& mustClear)
{
  this->Points.reserve(spacing.size());
  for (const PointSpacing& s : spacing)
  {
    const bool clear = std::binary_search(mustClear.begin(), mustClear.end(), s.point);
    this->Points.push_back({ dot(normal, c.points[s.point]), s.shortest, clear });
    this->LargestEdge = std::max(this->LargestEdge, s.shortest);
  }
  std::sort(this->Points.begin(), this->Points.end());
}

double PlaneClearance::at(double offset) const
{
  // only points within (best so far) x (largest edge) can lower the minimum:
  // walk outward from the offset in both directions
  double best = std::numeric_limits<double>::infinity();
  auto score = [&](const Projected& p, double d) {
    if (d > kOnPlaneFraction * p.spacing || p.mustClear)
    {
      best = std::min(best, d / p.spacing);
    }
  };
  const auto start = std::lower_bound(this->Points.begin(), this->Points.end(), Projected{ offset, 0.0, false });
  for (auto it = start; it != this->Points.end(); ++it)
  {
    const double d = it->at - offset;
    if (d >= best * this->LargestEdge)
    {
      break;
    }
    score(*it, d);
  }
  for (auto it = start; it != this->Points.begin();)
  {
    --it;
    const double d = offset - it->at;
    if (d >= best * this->LargestEdge)
    {
      break;
    }
    score(*it, d);
  }
  return best;
}

double PlaneClearance::clearestOffset(double low, double high, double preferred, double enough) const
{
  // the clearance is the lower envelope of cones |n.p - o| / h(p); its
  // maxima lie at the ends of the interval or where the rising cone of one
  // point meets the falling cone of a point above it, so those are the
  // candidates (neighbours in projection order, enough in practice)
  std::vector<double> candidates{ low, high, std::clamp(preferred, low, high) };
  const auto first =
    std::lower_bound(this->Points.begin(), this->Points.end(), Projected{ low - this->LargestEdge, 0.0, false });
  for (auto it = first; it != this->Points.end() && std::next(it) != this->Points.end(); ++it)
  {
    if (it->at > high + this->LargestEdge)
    {
      break;
    }
    const double pa = it->at, ha = it->spacing;
    const double pb = std::next(it)->at, hb = std::next(it)->spacing;
    const double meet = (pa * hb + pb * ha) / (ha + hb);
    if (meet > low && meet < high)
    {
      candidates.push_back(meet);
    }
    if (pa > low && pa < high)
    {
      candidates.push_back(pa); // through the point (and any others on the same plane)
    }
  }
  double bestOffset = std::clamp(preferred, low, high);
  double bestScore = std::min(enough, this->at(bestOffset));
  for (double o : candidates)
  {
    const double score = std::min(enough, this->at(o));
    const bool nearer = std::fabs(o - preferred) < std::fabs(bestOffset - preferred);
    if (score > bestScore || (score == bestScore && nearer))
    {
      bestScore = score;
      bestOffset = o;
    }
  }
  return bestOffset;
}

HalfSpaceMeasure::HalfSpaceMeasure(
  const SurfaceComplex& c, int cell, const Vec3& normal, BalanceCriterion criterion)
  : Complex(c)
  , Cell(cell)
  , Normal(normal)
  , Criterion(criterion == BalanceCriterion::PredictedCost ? BalanceCriterion::Volume : criterion)
{
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][0] == cell || c.trianglePairs[i][1] == cell)
    {
      this->Triangles.push_back(i);
    }
  }
  for (std::size_t r = 0; r < c.interfaces.size(); ++r)
  {
    if (c.interfaces[r].pair[0] == cell)
    {
      this->Regions.emplace_back(r, 1.0);
    }
    else if (c.interfaces[r].pair[1] == cell)
    {
      this->Regions.emplace_back(r, -1.0);
    }
  }
  // the range over the part's points, each seen once per triangle or
  // region edge: a point met twice does not change it, and collecting them
  // sorted (cellPoints) took half of predictedClearance, which builds this
  // measure for every normal tried
  this->MinOffset = std::numeric_limits<double>::infinity();
  this->MaxOffset = -std::numeric_limits<double>::infinity();
  auto extend = [&](Index p) {
    const double d = dot(normal, c.points[p]);
    this->MinOffset = std::min(this->MinOffset, d);
    this->MaxOffset = std::max(this->MaxOffset, d);
  };
  for (std::size_t i : this->Triangles)
  {
    for (Index p : c.triangles[i])
    {
      extend(p);
    }
  }
  for (const auto& region : this->Regions)
  {
    for (const auto& e : c.interfaces[region.first].edges)
    {
      extend(e[0]);
    }
  }
  if (this->Criterion == BalanceCriterion::Nodes)
  {
    std::vector<Index> surfacePoints;
    for (std::size_t i : this->Triangles)
    {
      if (c.trianglePairs[i][1] == -1)
      {
        surfacePoints.insert(surfacePoints.end(), c.triangles[i].begin(), c.triangles[i].end());
      }
    }
    std::sort(surfacePoints.begin(), surfacePoints.end());
    surfacePoints.erase(std::unique(surfacePoints.begin(), surfacePoints.end()), surfacePoints.end());
    for (Index p : surfacePoints)
    {
      this->SortedValues.push_back(dot(normal, c.points[p]));
    }
  }
  else if (this->Criterion == BalanceCriterion::BoundaryFacets)
  {
    for (std::size_t i : this->Triangles)
    {
      if (c.trianglePairs[i][1] == -1)
      {
        const auto& t = c.triangles[i];
        this->SortedValues.push_back(
          dot(normal, c.points[t[0]] + c.points[t[1]] + c.points[t[2]]) / 3.0);
      }
    }
  }
  std::sort(this->SortedValues.begin(), this->SortedValues.end());
  this->Total = this->Criterion == BalanceCriterion::Volume
    ? this->below(this->MaxOffset + 1.0 + std::fabs(this->MaxOffset))
    : static_cast<double>(this->SortedValues.size());
}

double HalfSpaceMeasure::below(double offset) const
{
  const Vec3& n = this->Normal;
  if (this->Criterion != BalanceCriterion::Volume)
  {
    return static_cast<double>(
      std::lower_bound(this->SortedValues.begin(), this->SortedValues.end(), offset) -
      this->SortedValues.begin());
  }
  const auto& c = this->Complex;
  double volume = 0;
  // flux of n (n.x - offset) through a triangle, clipped to n.x <= offset
  auto triangleFlux = [&](const Vec3& a, const Vec3& b, const Vec3& d, double sign) {
    const Vec3 corners[3] = { a, b, d };
    double g[3];
    int belowCount = 0;
    for (int k = 0; k < 3; ++k)
    {
      g[k] = dot(n, corners[k]) - offset;
      belowCount += g[k] <= 0 ? 1 : 0;
    }
    auto flux = [&](const Vec3& p, const Vec3& q, const Vec3& r) {
      const double areaN = 0.5 * dot(n, cross(q - p, r - p));
      return areaN * (dot(n, (1.0 / 3.0) * (p + q + r)) - offset);
    };
    if (belowCount == 3)
    {
      return sign * flux(a, b, d);
    }
    if (belowCount == 0)
    {
      return 0.0;
    }
    // clip polygon (convex) to g <= 0
    Vec3 poly[4];
    int count = 0;
    for (int k = 0; k < 3; ++k)
    {
      const int l = (k + 1) % 3;
      if (g[k] <= 0)
      {
        poly[count++] = corners[k];
      }
      if ((g[k] < 0 && g[l] > 0) || (g[k] > 0 && g[l] < 0))
      {
        const double t = g[k] / (g[k] - g[l]);
        poly[count++] = corners[k] + t * (corners[l] - corners[k]);
      }
    }
    double f = 0;
    for (int k = 1; k + 1 < count; ++k)
    {
      f += flux(poly[0], poly[k], poly[k + 1]);
    }
    return sign * f;
  };
  for (std::size_t i : this->Triangles)
  {
    // triangles are oriented out of pair[0]; flip where the part is pair[1]
    const auto& t = c.triangles[i];
    const double sign = c.trianglePairs[i][0] == this->Cell ? 1.0 : -1.0;
    volume += triangleFlux(c.points[t[0]], c.points[t[1]], c.points[t[2]], sign);
  }
  for (const auto& [r, sign] : this->Regions)
  {
    const InterfaceRegion& region = c.interfaces[r];
    const Vec3& nr = c.planes[region.planeId].normal;
    const double alignment = dot(n, nr);
    const Vec3 m = n - alignment * nr; // gradient of n.x within the region's plane
    const double m2 = dot(m, m);
    if (m2 < 1e-20)
    {
      // parallel to the cut: the region is wholly on one side
      const double g = dot(n, c.planes[region.planeId].origin) - offset;
      if (g < 0)
      {
        volume += sign * alignment * g * dot(nr, vectorArea(c.points, region.edges));
      }
      continue;
    }
    // Green: integral of g over the region part below = sum over its boundary
    // edges below of (m . ((q-p) x nr)) (gp^2 + gp gq + gq^2) / (6 |m|^2)
    double integral = 0;
    for (const auto& e : region.edges)
    {
      Vec3 p = c.points[e[0]], q = c.points[e[1]];
      double gp = dot(n, p) - offset, gq = dot(n, q) - offset;
      if (gp > 0 && gq > 0)
      {
        continue;
      }
      if (gp > 0 || gq > 0)
      {
        const double t = gp / (gp - gq);
        const Vec3 x = p + t * (q - p);
        if (gp > 0)
        {
          p = x;
          gp = 0;
        }
        else
        {
          q = x;
          gq = 0;
        }
      }
      integral += dot(m, cross(q - p, nr)) * (gp * gp + gp * gq + gq * gq) / (6.0 * m2);
    }
    volume += sign * alignment * integral;
  }
  return volume;
}

double HalfSpaceMeasure::offsetForFraction(double fraction, double relativeTolerance) const
{
  const double target = fraction * this->Total;
  if (this->Criterion != BalanceCriterion::Volume)
  {
    const std::size_t n = this->SortedValues.size();
    if (n < 2)
    {
      // no two neighbouring values to put the plane between (with one, the
      // clamp below would make k = 0 and read before the first value)
      return 0.5 * (this->MinOffset + this->MaxOffset);
    }
    std::size_t k = static_cast<std::size_t>(std::llround(target));
    k = std::min(std::max<std::size_t>(k, 1), n - 1);
    return 0.5 * (this->SortedValues[k - 1] + this->SortedValues[k]);
  }
  double lo = this->MinOffset, hi = this->MaxOffset;
  double flo = -target, fhi = this->Total - target;
  int side = 0;
  double x = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    x = (flo * hi - fhi * lo) / (flo - fhi);
    if (!(x > lo && x < hi))
    {
      x = 0.5 * (lo + hi);
    }
    const double fx = this->below(x) - target;
    if (std::fabs(fx) <= relativeTolerance * this->Total || hi - lo <= 1e-14 * (std::fabs(lo) + std::fabs(hi)))
    {
      break;
    }
    if (fx < 0)
    {
      lo = x;
      flo = fx;
      if (side == -1)
      {
        fhi *= 0.5;
      }
      side = -1;
    }
    else
    {
      hi = x;
      fhi = fx;
      if (side == 1)
      {
        flo *= 0.5;
      }
      side = 1;
    }
  }
  return x;
}
} // namespace ptm
