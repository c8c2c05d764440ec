#include "SubdomainAssignment.h"

#include <algorithm>
#include <cmath>
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
  std::vector<double> cost(measures); // one that is not a positive number weighs nothing (and sorts last)
  for (double& c : cost)
  {
    c = std::isfinite(c) ? std::max(c, 0.0) : 0.0;
  }
  std::vector<int> order(K);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
  std::vector<double> load(ranks, 0.0);
  for (int s : order)
  {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[s] = r;
    load[r] += cost[s];
  }
  return owner;
}
} // namespace ptm
