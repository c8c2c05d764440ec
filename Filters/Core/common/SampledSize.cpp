#include "SampledSize.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

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

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
// the tree holds sample indices; the points live in a vector beside it
using PointMap = CGAL::Pointer_property_map<Point>::type;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Tree = Search::Tree;
using Distance = Search::Distance;

struct Samples
{
  std::vector<Point> points;
  std::vector<double> sizes;
  PointMap map; // into `points`, made once they are all in
  std::unique_ptr<Tree> tree;

  double at(const Vec3& p) const
  {
    const Point q(p[0], p[1], p[2]);
    const Search search(*this->tree, q, kNeighbours, 0, true, Distance(this->map));
    double weighted = 0.0;
    double total = 0.0;
    for (const auto& [index, d2] : search)
    {
      if (d2 == 0.0)
      {
        return this->sizes[index];
      }
      weighted += this->sizes[index] / d2;
      total += 1.0 / d2;
    }
    return weighted / total;
  }
};
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
  auto samples = std::make_shared<Samples>();
  samples->points.reserve(n);
  samples->sizes.reserve(n);
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
    samples->points.emplace_back(s[0], s[1], s[2]);
    samples->sizes.push_back(s[3]);
  }
  samples->map = CGAL::make_property_map(samples->points);
  samples->tree = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
    boost::counting_iterator<std::size_t>(n), Tree::Splitter(), Traits(samples->map));
  samples->tree->build();
  return [samples](const Vec3& p) { return samples->at(p); };
}
} // namespace ptm
