#ifndef PTM_SUBDOMAIN_ASSIGNMENT_H
#define PTM_SUBDOMAIN_ASSIGNMENT_H
// Which MPI rank meshes which subdomain.
#include <vector>

namespace ptm
{
// With as many subdomains as ranks, subdomain s goes to rank s. With more
// (over-decomposition), the subdomains, which the cutter numbers so that
// neighbours have near numbers, are split into contiguous blocks of about
// equal total measure: subdomain s goes to the rank in whose share of the
// cumulative measure the middle of s falls. Every rank's total then differs
// from the mean by at most one subdomain's measure, and neighbouring
// subdomains mostly share a rank. Fewer subdomains than ranks leaves ranks idle.
std::vector<int> assignSubdomainsToRanks(const std::vector<double>& measures, int ranks);
} // namespace ptm
#endif
