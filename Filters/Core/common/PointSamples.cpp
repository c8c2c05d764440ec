#include "PointSamples.h"

#include <boost/iterator/counting_iterator.hpp>

namespace ptm
{
PointSamples::PointSamples(const std::vector<double>& xyzv)
{
  const std::size_t n = xyzv.size() / 4;
  this->Points.reserve(n);
  this->Values.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    this->Points.emplace_back(xyzv[4 * i], xyzv[4 * i + 1], xyzv[4 * i + 2]);
    this->Values.push_back(xyzv[4 * i + 3]);
  }
  this->Map = CGAL::make_property_map(this->Points);
  this->KdTree = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
    boost::counting_iterator<std::size_t>(n), Tree::Splitter(), Traits(this->Map));
  this->KdTree->build();
}
} // namespace ptm
