#include "PredictedCost.h"

#include <algorithm>
#include <memory>
#include <array>
#include <cmath>
#include <limits>

namespace ptm
{
namespace
{
// 8-point Gauss-Legendre on [-1, 1]
constexpr std::array<double, 4> kNodes{ 0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
  0.9602898564975363 };
constexpr std::array<double, 4> kWeights{ 0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
  0.1012285362903763 };

// The smallest size the model counts: a thousandth of the bounding box's diagonal.
double sizeFloor(const std::vector<Vec3>& points)
{
  return 1e-3 * boundingBoxDiagonal(points);
}

// The cost grid's step: about `gridPoints` nodes over the box.
double gridStep(const Box& box, std::size_t gridPoints)
{
  const Vec3 extent = box.hi - box.lo;
  return std::cbrt(std::max(extent[0] * extent[1] * extent[2], 1e-30) / static_cast<double>(gridPoints));
}

// Regular tetrahedra of edge h per unit volume, h floored (and a size that
// is not positive and finite taken as the floor).
double densityOfSize(double h, double floor)
{
  h = h > 0 && std::isfinite(h) ? std::max(h, floor) : floor;
  return 1.0 / regularTetrahedronVolume(h);
}

struct Density
{
  const SizeFunction& size;
  double floor;
  double x0;

  double operator()(const Vec3& p) const { return this->ofSize(size(p)); }

  double ofSize(double h) const { return densityOfSize(h, floor); }

  // W(p): the density integrated along x from x0 to p's x
  double alongX(const Vec3& p) const
  {
    const double half = 0.5 * (p[0] - this->x0), middle = 0.5 * (p[0] + this->x0);
    double sum = 0;
    for (std::size_t k = 0; k < kNodes.size(); ++k)
    {
      for (double sign : { -1.0, 1.0 })
      {
        sum += kWeights[k] * (*this)({ middle + sign * half * kNodes[k], p[1], p[2] });
      }
    }
    return half * sum;
  }

  // equilateral triangles of edge h that cover the triangle abc, signed
  // along `normal` (a fan triangle of an interface loop may count negative)
  double faceCount(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) const
  {
    const double area = 0.5 * dot(cross(b - a, c - a), normal);
    const double perArea = ((*this)(0.5 * (a + b)) + (*this)(0.5 * (b + c)) + (*this)(0.5 * (c + a))) / 3.0;
    // density is 6 sqrt(2) / h^3; a triangle of edge h covers sqrt(3) / 4 h^2
    const double inverseH = std::cbrt(perArea / (6.0 * std::sqrt(2.0)));
    return area * 4.0 / std::sqrt(3.0) * inverseH * inverseH;
  }

  // the flux of (W, 0, 0) through the triangle abc (signed by its orientation)
  double flux(const Vec3& a, const Vec3& b, const Vec3& c) const
  {
    const double areaX = 0.5 * cross(b - a, c - a)[0];
    if (areaX == 0)
    {
      return 0;
    }
    const double mean =
      (this->alongX(0.5 * (a + b)) + this->alongX(0.5 * (b + c)) + this->alongX(0.5 * (c + a))) / 3.0;
    return areaX * mean;
  }
};
} // namespace

PredictedCost predictCost(const SurfaceComplex& c, const SizeFunction& size)
{
  PredictedCost cost;
  std::vector<double>& count = cost.regularTetrahedra;
  std::vector<double>& faces = cost.boundaryTriangles;
  count.assign(c.subdomainCount, 0.0);
  faces.assign(c.subdomainCount, 0.0);
  cost.tetrahedra.assign(c.subdomainCount, 0.0);
  cost.inputPieces.assign(c.subdomainCount, 0.0);
  if (c.points.empty() || !size)
  {
    return cost;
  }
  double x0 = std::numeric_limits<double>::infinity();
  for (const Vec3& p : c.points)
  {
    x0 = std::min(x0, p[0]);
  }
  const Density density{ size, sizeFloor(c.points), x0 };
  auto add = [&](const SubdomainPair& pair, double flux) {
    if (pair[0] >= 0 && pair[0] < c.subdomainCount)
    {
      count[pair[0]] += flux;
    }
    if (pair[1] >= 0 && pair[1] < c.subdomainCount)
    {
      count[pair[1]] -= flux;
    }
  };
  auto addFaces = [&](const SubdomainPair& pair, double n) {
    for (int s : pair)
    {
      if (s >= 0 && s < c.subdomainCount)
      {
        faces[s] += n;
      }
    }
  };
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    const Vec3 &a = c.points[c.triangles[i][0]], &b = c.points[c.triangles[i][1]], &d = c.points[c.triangles[i][2]];
    const int inside = c.trianglePairs[i][0];
    if (c.trianglePairs[i][1] < 0 && inside >= 0 && inside < c.subdomainCount)
    {
      cost.inputPieces[inside] += 1.0;
    }
    add(c.trianglePairs[i], density.flux(a, b, d));
    const Vec3 normal = cross(b - a, d - a);
    const double length = norm(normal);
    addFaces(c.trianglePairs[i], length > 0 ? density.faceCount(a, b, d, (1.0 / length) * normal) : 0.0);
  }
  for (const InterfaceRegion& region : c.interfaces)
  {
    const CuttingPlane& plane = c.planes[region.planeId];
    double flux = 0, n = 0;
    for (const DirectedEdge& e : region.edges)
    {
      flux += density.flux(plane.origin, c.points[e[0]], c.points[e[1]]);
      n += density.faceCount(plane.origin, c.points[e[0]], c.points[e[1]], plane.normal);
    }
    add(region.pair, flux);
    addFaces(region.pair, std::fabs(n));
  }
  // a field that jumps (not positive somewhere, so floored) defeats the
  // quadrature and can give a part a negative count: never ship one
  for (double& n : count)
  {
    n = std::isfinite(n) ? std::max(n, 0.0) : 0.0;
  }
  // TetGen's count, calibrated on the ball graded ten times pole to pole
  // (K = 16, least squares over the subdomains): 0.74 x the regular
  // tetrahedra plus 6.25 per triangle of edge h on the subdomain's whole
  // boundary (outer and interfaces), which the finer boundary and the
  // grading next to it add. Measured/predicted then lies in 0.83-1.12 per
  // subdomain, against 0.79-2.52 for the regular tetrahedra alone.
  for (int s = 0; s < c.subdomainCount; ++s)
  {
    faces[s] = std::isfinite(faces[s]) ? faces[s] : 0.0;
    cost.tetrahedra[s] = 0.74 * count[s] + 6.25 * faces[s];
  }
  return cost;
}

namespace
{
// The z of the crossings of the column (x, y) with the triangles, signed
// by the z component of their outward normals (+1 leaving, -1 entering,
// going up), per column of an nx x ny grid.
using Crossings = std::vector<std::vector<std::pair<double, int>>>;

Crossings columnCrossings(
  const TriangleSurface& s, const Vec3& origin, double stepX, double stepY, int nx, int ny)
{
  Crossings columns(static_cast<std::size_t>(nx) * ny);
  for (const Triangle& t : s.triangles)
  {
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    const double twiceArea = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (twiceArea == 0)
    {
      continue; // vertical: no column crosses it (but along an edge)
    }
    const int i0 = std::max(0, static_cast<int>(std::ceil((std::min({ a[0], b[0], c[0] }) - origin[0]) / stepX)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::floor((std::max({ a[0], b[0], c[0] }) - origin[0]) / stepX)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((std::min({ a[1], b[1], c[1] }) - origin[1]) / stepY)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::floor((std::max({ a[1], b[1], c[1] }) - origin[1]) / stepY)));
    for (int i = i0; i <= i1; ++i)
    {
      for (int j = j0; j <= j1; ++j)
      {
        const double x = origin[0] + i * stepX, y = origin[1] + j * stepY;
        // barycentric coordinates of (x, y) in the projected triangle
        const double u = ((b[0] - x) * (c[1] - y) - (c[0] - x) * (b[1] - y)) / twiceArea;
        const double v = ((c[0] - x) * (a[1] - y) - (a[0] - x) * (c[1] - y)) / twiceArea;
        const double w = 1.0 - u - v;
        if (u < 0 || v < 0 || w < 0)
        {
          continue;
        }
        columns[static_cast<std::size_t>(i) * ny + j].emplace_back(
          u * a[2] + v * b[2] + w * c[2], twiceArea > 0 ? 1 : -1);
      }
    }
  }
  return columns;
}

// The size at the nodes of a lattice twice as coarse as the sample grid,
// evaluated once each when first needed, and trilinear in between: a
// field interpolated between samples (SizeArray) costs several
// microseconds a point, and a million grid nodes took 8-11 s of the cut;
// an eighth of them take about 1 s. Lattice nodes where the field is not
// a size (outside the body, say) are left out of the mean.
class CoarseSizes
{
public:
  CoarseSizes(const SizeFunction& size, const Vec3& low, const Vec3& spacing, const Vec3& extent)
    : Size(size)
    , Low(low)
    , Spacing(spacing)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Count[k] = static_cast<int>(std::ceil(extent[k] / spacing[k])) + 2;
    }
    this->Values.assign(static_cast<std::size_t>(this->Count[0]) * this->Count[1] * this->Count[2],
      std::numeric_limits<double>::quiet_NaN());
  }

  double at(const Vec3& p) const
  {
    int base[3];
    double t[3];
    for (int k = 0; k < 3; ++k)
    {
      const double f = (p[k] - this->Low[k]) / this->Spacing[k];
      base[k] = std::clamp(static_cast<int>(std::floor(f)), 0, this->Count[k] - 2);
      t[k] = std::clamp(f - base[k], 0.0, 1.0);
    }
    double h = 0, valid = 0;
    for (int c = 0; c < 8; ++c)
    {
      const int d[3] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
      const double weight = (d[0] ? t[0] : 1 - t[0]) * (d[1] ? t[1] : 1 - t[1]) * (d[2] ? t[2] : 1 - t[2]);
      const double value = weight == 0 ? 0.0 : this->node(base[0] + d[0], base[1] + d[1], base[2] + d[2]);
      if (value > 0 && std::isfinite(value))
      {
        h += weight * value;
        valid += weight;
      }
    }
    return valid > 0 ? h / valid : this->Size(p);
  }

private:
  double node(int i, int j, int l) const
  {
    double& value = this->Values[(static_cast<std::size_t>(l) * this->Count[1] + j) * this->Count[0] + i];
    if (std::isnan(value))
    {
      value = this->Size(this->Low + Vec3{ i * this->Spacing[0], j * this->Spacing[1], l * this->Spacing[2] });
    }
    return value;
  }

  const SizeFunction Size; // a copy: onLattice keeps it beyond the caller's field
  Vec3 Low;
  Vec3 Spacing;
  int Count[3] = { 0, 0, 0 };
  mutable std::vector<double> Values;
};
} // namespace

SizeFunction cappedSize(const SizeFunction& size, double cap)
{
  if (!(cap > 0) || !size)
  {
    return size;
  }
  return [size, cap](const Vec3& p) {
    const double h = size(p);
    return h > cap ? cap : h;
  };
}

CostSamples sampleCost(const TriangleSurface& closed, const SizeFunction& size, std::size_t gridPoints, double baseSize)
{
  CostSamples samples;
  if (closed.points.empty() || gridPoints == 0)
  {
    return samples;
  }
  const Box box = boxOf(closed.points);
  const Vec3 low = box.lo, extent = box.hi - box.lo;
  const double step = gridStep(box, gridPoints);
  if (!(step > 0) || !std::isfinite(step))
  {
    return samples;
  }
  // Columns at the middles of an nx x ny partition of the box (a hair
  // off, to keep them off the round coordinates of CAD vertices and
  // edges), so the columns' areas add up to the box's; along each column
  // the inside intervals are known exactly and shared out evenly among
  // the nodes of a z grid in them (one node at the middle of an interval
  // shorter than the grid step): the weights add up to the volume up to
  // the midpoint rule across columns.
  const int nx = std::max(1, static_cast<int>(std::lround(extent[0] / step)));
  const int ny = std::max(1, static_cast<int>(std::lround(extent[1] / step)));
  const double stepX = std::max(extent[0], step) / nx, stepY = std::max(extent[1], step) / ny;
  const Vec3 origin = low + Vec3{ (0.5 + 1.234567e-4) * stepX, (0.5 + 2.345678e-4) * stepY, 0.0 };
  const Crossings columns = columnCrossings(closed, origin, stepX, stepY, nx, ny);
  const double z0 = low[2] + (0.5 + 3.456789e-4) * step;
  const Density density{ size, sizeFloor(closed.points), low[0] };
  const CoarseSizes coarse(size, low, { 2 * stepX, 2 * stepY, 2 * step }, extent);
  const double base = baseSize > 0 ? density.ofSize(baseSize) : 0.0;
  for (std::size_t k = 0; k < columns.size(); ++k)
  {
    std::vector<std::pair<double, int>> hits = columns[k];
    std::sort(hits.begin(), hits.end());
    const double x = origin[0] + static_cast<double>(k / ny) * stepX;
    const double y = origin[1] + static_cast<double>(k % ny) * stepY;
    int winding = 0; // below the lowest crossing: outside
    for (std::size_t h = 0; h + 1 < hits.size(); ++h)
    {
      winding -= hits[h].second; // entering through a face whose normal points down
      const double bottom = hits[h].first, top = hits[h + 1].first;
      if (winding <= 0 || !(top > bottom))
      {
        continue;
      }
      std::vector<double> zs;
      for (int l = std::max(0, static_cast<int>(std::ceil((bottom - z0) / step))); z0 + l * step <= top; ++l)
      {
        zs.push_back(z0 + l * step);
      }
      if (zs.empty())
      {
        zs.push_back(0.5 * (bottom + top));
      }
      const double share = stepX * stepY * (top - bottom) / static_cast<double>(zs.size());
      for (double z : zs)
      {
        const Vec3 p{ x, y, z };
        const double weight = share * ((size ? density.ofSize(coarse.at(p)) : 1.0) - base);
        if (base > 0 && !(weight > 0))
        {
          continue;
        }
        samples.points.push_back(p);
        samples.weights.push_back(weight);
      }
    }
  }
  samples.cells.assign(samples.points.size(), 0);
  samples.spacing = step;
  return samples;
}

double volumeFractionForCost(const CostSamples& samples, const SurfaceComplex& complex, int cell,
  const Vec3& normal, double fraction)
{
  std::vector<std::pair<double, double>> mine; // (n.p, weight)
  double sampled = 0;
  for (std::size_t i = 0; i < samples.points.size(); ++i)
  {
    if (samples.cells[i] == cell)
    {
      mine.emplace_back(dot(normal, samples.points[i]), samples.weights[i]);
      sampled += samples.weights[i];
    }
  }
  const HalfSpaceMeasure volume(complex, cell, normal, BalanceCriterion::Volume);
  const double perVolume = volume.total() > 0 ? samples.perVolume : 0.0;
  const double total = sampled + perVolume * volume.total();
  if ((mine.size() < 2 && !(perVolume > 0)) || !(total > 0) || !(samples.spacing > 0))
  {
    return fraction;
  }
  // each sample stands for its grid cell, spread evenly over a spacing
  // along the normal: the weight below then grows continuously with the
  // offset, also for a normal along the grid, whose samples lie in layers
  // (found on the bracket: a part's fine end only two layers thick got 58 %
  // of its cost instead of 50 % from the layer-by-layer steps)
  const double r = 0.5 * samples.spacing;
  auto weightBelow = [&](double offset) {
    double w = perVolume > 0 ? perVolume * volume.below(offset) : 0.0;
    for (const auto& [t, weight] : mine)
    {
      w += weight * std::clamp((offset - (t - r)) / (2 * r), 0.0, 1.0);
    }
    return w;
  };
  const double wanted = fraction * total;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  if (perVolume > 0)
  {
    low = volume.minimumOffset();
    high = volume.maximumOffset();
  }
  for (const auto& sample : mine)
  {
    low = std::min(low, sample.first - r);
    high = std::max(high, sample.first + r);
  }
  for (int step = 0; step < 60; ++step)
  {
    const double middle = 0.5 * (low + high);
    (weightBelow(middle) < wanted ? low : high) = middle;
  }
  const double offset = 0.5 * (low + high);
  const double share = volume.total() > 0 ? volume.below(offset) / volume.total() : fraction;
  // keep both parts: never a fraction a part cannot be cut at
  return std::clamp(share, 0.02 * fraction, 1.0 - 0.02 * (1.0 - fraction));
}

void moveSamples(CostSamples& samples, int cell, const Vec3& normal, double offset, int below, int above)
{
  for (std::size_t i = 0; i < samples.points.size(); ++i)
  {
    if (samples.cells[i] == cell)
    {
      samples.cells[i] = dot(normal, samples.points[i]) < offset ? below : above;
    }
  }
}

SizeFunction onLattice(const SizeFunction& field, const std::vector<Vec3>& points, double finest)
{
  if (!field || points.empty())
  {
    return field;
  }
  const Box box = boxOf(points);
  const Vec3 extent = box.hi - box.lo;
  const double volume =
    std::max(extent[0], finest) * std::max(extent[1], finest) * std::max(extent[2], finest);
  const double spacing = std::max(finest, std::cbrt(volume / kLatticeNodes));
  auto lattice = std::make_shared<CoarseSizes>(field, box.lo, Vec3{ spacing, spacing, spacing }, extent);
  return [lattice](const Vec3& p) { return lattice->at(p); };
}

namespace
{
// h, or no more than the thickness cap where there is one.
SizeFunction uniformSize(double h, const SizeFunction& thicknessCap)
{
  if (!thicknessCap)
  {
    return [h](const Vec3&) { return h; };
  }
  return [h, thicknessCap](const Vec3& p) { return std::min(h, thicknessCap(p)); };
}
} // namespace

PredictedCost predictUniformCost(const SurfaceComplex& c, double h, const SizeFunction& thicknessCap)
{
  PredictedCost cost = predictCost(c, uniformSize(h, thicknessCap));
  // Fitted on real parts at one size (least squares of the relative error
  // over 160 subdomains: 10 surfaces of the corpus and the unseen set at
  // K = 16 by bisection, the sweep's sizes): 2.9 x the regular tetrahedra
  // plus 4.3 per piece of the input surface. There the input's own small
  // triangles, which the boundary keeps however small, drive TetGen's
  // count; the field model above, fitted on a smooth ball, leaves them out
  // (its outer-surface terms: predicted / measured 0.23-1.09, median per
  // surface; this model 0.42-1.20, Prusa's M3x10 screw 0.27 -> 1.20: the
  // eight subdomains of its thread hold 1,466-2,429 input pieces each,
  // those of the head 26-72). Adding the pieces to the field model
  // instead, with or without its area term, shared the subdomains out worse
  // than volume on OpenSCAD's CSG and FreeCAD's test_holes00 (2 ranks, 1.02
  // -> 1.12 and 1.24 -> 1.34); this model, fitted without the surface it
  // was tried on, never did there, at 2, 4 or 8 ranks. On 14 surfaces
  // outside the fit it changed 2-rank balances little (1.064 -> 1.066 mean
  // by bisection), worse on 4 by up to 0.06 and better on Cura's nozzle
  // (1.139 -> 1.011): Testing/Corpus/results/balance-k16-session22.md.
  for (int s = 0; s < c.subdomainCount; ++s)
  {
    cost.tetrahedra[s] =
      kUniformCostPerRegularTetrahedron * cost.regularTetrahedra[s] + kUniformCostPerInputPiece * cost.inputPieces[s];
  }
  return cost;
}

CostSamples sampleUniformCost(
  const TriangleSurface& closed, double h, std::size_t gridPoints, const SizeFunction& thicknessCap)
{
  CostSamples samples;
  if (thicknessCap)
  {
    samples = sampleCost(closed, uniformSize(h, thicknessCap), gridPoints, h);
  }
  else if (!closed.points.empty() && gridPoints > 0)
  {
    samples.spacing = gridStep(boxOf(closed.points), gridPoints); // the spread of the pieces' samples
  }
  for (double& w : samples.weights)
  {
    w *= kUniformCostPerRegularTetrahedron;
  }
  samples.perVolume = kUniformCostPerRegularTetrahedron * densityOfSize(h, sizeFloor(closed.points));
  for (const Triangle& t : closed.triangles)
  {
    samples.points.push_back((1.0 / 3.0) * (closed.points[t[0]] + closed.points[t[1]] + closed.points[t[2]]));
    samples.weights.push_back(kUniformCostPerInputPiece);
    samples.cells.push_back(0);
  }
  return samples;
}

} // namespace ptm
