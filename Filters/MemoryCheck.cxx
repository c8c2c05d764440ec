#include "MemoryCheck.h"

#include "RankCollectives.h"
#include "TetGenSubdomainMesher.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace ptm
{
std::vector<double> regularPerRank(
  const std::vector<double>& subdomainRegular, const std::vector<int>& subdomainRank, int ranks)
{
  std::vector<double> perRank(static_cast<std::size_t>(std::max(ranks, 0)), 0.0);
  for (std::size_t s = 0; s < subdomainRegular.size() && s < subdomainRank.size(); ++s)
  {
    if (subdomainRank[s] >= 0 && subdomainRank[s] < ranks)
    {
      perRank[subdomainRank[s]] += subdomainRegular[s];
    }
  }
  return perRank;
}

std::string memoryShortfall(vtkMultiProcessController* controller, const std::vector<double>& rankRegular,
  const std::string& requested, bool lowerBound)
{
  const std::vector<long long> machine = allGatherValues(controller, std::vector<long long>{ machineIdentity() });
  const std::vector<long long> memory =
    allGatherValues(controller, std::vector<long long>{ static_cast<long long>(physicalMemoryBytes()) });
  std::map<long long, std::vector<int>> ranksOfMachine;
  for (int r = 0; r < static_cast<int>(machine.size()); ++r)
  {
    ranksOfMachine[machine[r]].push_back(r);
  }
  for (const auto& [id, onIt] : ranksOfMachine)
  {
    double tetrahedra = 0, bytes = 0, available = 0;
    for (int r : onIt)
    {
      const TetMeshEstimate estimate =
        estimateTetMeshOfRegular(r < static_cast<int>(rankRegular.size()) ? rankRegular[r] : 0.0);
      tetrahedra += estimate.tetrahedra;
      bytes += estimate.bytes;
      const double reported = static_cast<double>(memory[r]);
      available = available > 0 && reported > 0 ? std::min(available, reported) : reported;
    }
    if (available > 0 && bytes > available)
    {
      std::ostringstream why;
      why.precision(3);
      const char* howMany = lowerBound ? "at least " : "about ";
      why << "the requested size (" << requested << ") would give " << howMany << tetrahedra << " tetrahedra on the "
          << onIt.size() << " rank" << (onIt.size() > 1 ? "s" : "") << " of one machine (rank";
      for (std::size_t k = 0; k < onIt.size() && k < 8; ++k)
      {
        why << (k ? ", " : " ") << onIt[k];
      }
      why << (onIt.size() > 8 ? ", ..." : "") << "), " << howMany << bytes / 1e9 << " GB, more than its "
          << available / 1e9 << " GB of memory; use a larger size or more machines";
      return why.str();
    }
  }
  return {};
}
} // namespace ptm
