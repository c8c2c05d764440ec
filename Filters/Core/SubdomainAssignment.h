#ifndef PTM_SUBDOMAIN_ASSIGNMENT_H
#define PTM_SUBDOMAIN_ASSIGNMENT_H
// Which MPI rank meshes which subdomain.
#include <vector>

namespace ptm
{
// With as many subdomains as ranks, subdomain s goes to rank s. With more
// (over-decomposition), largest measure first onto the least loaded rank
// (ties: lower subdomain, lower rank), so that every rank's total is
// balanced. Fewer subdomains than ranks leaves ranks idle.
std::vector<int> assignSubdomainsToRanks(const std::vector<double>& measures, int ranks);
} // namespace ptm
#endif
