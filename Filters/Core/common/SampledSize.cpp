#include "SampledSize.h"

#include "PointSamples.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace ptm
{
namespace
{
// Shepard's interpolation over this many nearest samples: enough that the
// field is smooth between surface samples, few enough to stay local.
constexpr unsigned kNeighbours = 8;

using Search = CGAL::Orthogonal_k_neighbor_search<PointSamples::Traits>;

double interpolatedAt(const PointSamples& samples, const Vec3& p)
{
  const PointSamples::Point q(p[0], p[1], p[2]);
  const Search search(samples.tree(), q, kNeighbours, 0, true, Search::Distance(samples.map()));
  double weighted = 0.0;
  double total = 0.0;
  for (const auto& [index, d2] : search)
  {
    if (d2 == 0.0)
    {
      return samples.value(index);
    }
    weighted += samples.value(index) / d2;
    total += 1.0 / d2;
  }
  return weighted / total;
}
} // namespace

SizeFunction sampledSize(const std::vector<double>& xyzh, const std::string& name, std::string& error)
{
  error.clear();
  const std::size_t n = xyzh.size() / 4;
  if (n == 0)
  {
    error = name + " has no values (the size source has no points)";
    return {};
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* s = &xyzh[4 * i];
    if (!(s[3] > 0) || !std::isfinite(s[3]))
    {
      std::ostringstream msg;
      msg.precision(9);
      msg << name << " is " << s[3] << " at (" << s[0] << ", " << s[1] << ", " << s[2]
          << "); sizes must be positive and finite";
      error = msg.str();
      return {};
    }
  }
  auto samples = std::make_shared<const PointSamples>(xyzh);
  return [samples](const Vec3& p) { return interpolatedAt(*samples, p); };
}
} // namespace ptm
