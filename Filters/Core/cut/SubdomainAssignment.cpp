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
  const double total = std::accumulate(measures.begin(), measures.end(), 0.0);
  double before = 0;
  for (int s = 0; s < K; ++s)
  {
    const double middle = before + 0.5 * measures[s];
    before += measures[s];
    const int r = total > 0 ? static_cast<int>(ranks * middle / total) : s * ranks / K;
    owner[s] = std::min(std::max(r, 0), ranks - 1);
  }
  return owner;
}
} // namespace ptm
