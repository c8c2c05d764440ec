#ifndef PTM_POINT_SAMPLES_H
#define PTM_POINT_SAMPLES_H
// Points with one value each (x, y, z, value per sample) in a CGAL k-d tree
// of their indices, for nearest-sample queries: the size field given by
// samples (SampledSize) and the thickness cap (LocalThickness). The tree is
// built at construction, not lazily inside the first query, so queries
// only read it; the same samples give the same tree on every rank.
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Splitters.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace ptm
{
class PointSamples
{
public:
  using Kernel = CGAL::Simple_cartesian<double>;
  using Point = Kernel::Point_3;
  // the tree holds sample indices; the points live in a vector beside it
  using PointMap = CGAL::Pointer_property_map<Point>::type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
  // the tree type of both CGAL::Orthogonal_k_neighbor_search<Traits> and
  // CGAL::Orthogonal_incremental_neighbor_search<Traits>
  using Tree = CGAL::Kd_tree<Traits, CGAL::Sliding_midpoint<Traits>, CGAL::Tag_true, CGAL::Tag_false>;

  // `xyzv`: 4 doubles per sample; the caller checks the values
  explicit PointSamples(const std::vector<double>& xyzv);
  PointSamples(const PointSamples&) = delete; // the map points into Points
  PointSamples& operator=(const PointSamples&) = delete;

  const Tree& tree() const { return *this->KdTree; }
  const PointMap& map() const { return this->Map; }
  double value(std::size_t i) const { return this->Values[i]; }
  std::size_t size() const { return this->Values.size(); }

private:
  std::vector<Point> Points;
  std::vector<double> Values;
  PointMap Map;
  std::unique_ptr<Tree> KdTree;
};
} // namespace ptm
#endif
