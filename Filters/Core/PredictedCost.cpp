#include "PredictedCost.h"

#include <algorithm>
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

struct Density
{
  const SizeFunction& size;
  double floor;
  double x0;

  double operator()(const Vec3& p) const
  {
    double h = size(p);
    h = h > 0 && std::isfinite(h) ? std::max(h, floor) : floor;
    return 6.0 * std::sqrt(2.0) / (h * h * h);
  }

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
  if (c.points.empty() || !size)
  {
    return cost;
  }
  double x0 = std::numeric_limits<double>::infinity();
  for (const Vec3& p : c.points)
  {
    x0 = std::min(x0, p[0]);
  }
  const Density density{ size, 1e-3 * boundingBoxDiagonal(c.points), x0 };
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
} // namespace ptm
