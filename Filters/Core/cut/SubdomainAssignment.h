#ifndef PTM_SUBDOMAIN_ASSIGNMENT_H
#define PTM_SUBDOMAIN_ASSIGNMENT_H
// Which MPI rank meshes which subdomain.
#include <vector>

namespace ptm
{
// With as many subdomains as ranks, subdomain s goes to rank s. With more
// (over-decomposition), longest first: in order of decreasing measure (the
// cutter's predicted tetrahedra; ties by subdomain number) each subdomain
// goes to the rank with the least measure so far (the lowest rank of equal
// ones). Every rank's total then lies within one subdomain's measure of the
// mean, and the largest subdomains are spread first, which contiguous
// blocks of the numbering (the rule until session 52) could not do: with
// 16 subdomains on 2 ranks the one freedom of blocks is where to split, and
// on 30 whole tetmesh.py runs (10 real surfaces, K = 16 on 2 ranks and 37
// on 3) max/mean tetrahedra per rank went from 1.075 to 1.037 (mean) and
// 1.221 to 1.141 (worst), better on 22 and worse on 8
// (Testing/Corpus/results/assignment-longest-first-session52.md). What is
// left is the prediction's own error. A rank's subdomains are then not
// neighbours: more of its surface is shared with other ranks, which a
// solver on the pieces pays in halo exchange (with one subdomain per rank
// nothing changes). Fewer subdomains than ranks leaves ranks idle.
std::vector<int> assignSubdomainsToRanks(const std::vector<double>& measures, int ranks);
} // namespace ptm
#endif
