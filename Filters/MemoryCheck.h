#ifndef PTM_MEMORY_CHECK_H
#define PTM_MEMORY_CHECK_H
// Whether the mesh a size asks for can fit in the memory of the machines
// the ranks run on. The cutter asks it first, from the whole volume shared
// evenly, so a size typed ten times too small is refused within seconds
// (the bracket at --size 0.001 ran its interface triangulations for over
// two minutes before; at 0.01 the mesher refused it after 13.7 s of
// surface stages), and again after the cuts with the tetrahedra predicted
// for each rank (which counts a size field); the mesher asks it once more
// with each rank's subdomains.
// Collective: every rank must call it, in the same order.
#include <string>
#include <vector>

class vtkMultiProcessController;

namespace ptm
{
// Why meshes of rankRegular[r] regular tetrahedra of the size on rank r
// (the volume over TetGen's -a bound, or a size field's
// PredictedCost::regularTetrahedra) cannot fit, or nothing: the estimated
// meshes (estimateTetMeshOfRegular) of the ranks that share a machine
// against that machine's physical memory. The same answer on every rank
// (all of it is gathered). `requested` names the size in the message
// ("MaximumVolume 1.2e-07"); the message begins "the requested size" and
// names no subdomain, so tetmesh.py does not cut again for it.
// With `lowerBound` the counts are only a floor (a size field's prediction
// floors the size at 1e-3 of the diagonal: PredictedCost.cpp) and the
// message says "at least" instead of "about".
std::string memoryShortfall(vtkMultiProcessController* controller, const std::vector<double>& rankRegular,
  const std::string& requested, bool lowerBound = false);

// The regular tetrahedra of each of `ranks` ranks: those of the subdomains
// assigned to it (subdomainRank, as the cutter writes it) summed.
std::vector<double> regularPerRank(
  const std::vector<double>& subdomainRegular, const std::vector<int>& subdomainRank, int ranks);
} // namespace ptm
#endif
