#include "SubdomainAssignment.h"

#include <algorithm>
#include <numeric>

namespace ptm
{
std::vector<int> assignSubdomainsToRanks(const std::vector<double>& measures, int ranks)
{
  const int K = static_cast<int>(measures.size());
  std::vector<int> owner(K, 0);
  if (ranks <= 1)
  {
    return owner;
  }
  if (K <= ranks)
  {
    std::iota(owner.begin(), owner.end(), 0);
    return owner;
  }
  std::vector<int> order(K);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](int a, int b) { return measures[a] > measures[b]; });
  std::vector<double> load(ranks, 0.0);
  for (int s : order)
  {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[s] = r;
    load[r] += measures[s];
  }
  return owner;
}
} // namespace ptm
