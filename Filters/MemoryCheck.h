#ifndef PTM_MEMORY_CHECK_H
#define PTM_MEMORY_CHECK_H
// Whether the mesh a size asks for can fit in the memory of the machines
// the ranks run on. The cutter asks it first, from the whole volume shared
// evenly, so a size typed ten times too small is refused within seconds
// (the bracket at --size 0.001 ran its interface triangulations for over
// two minutes before; at 0.01 the mesher refused it after 13.7 s of
// surface stages); the mesher asks it again with each rank's subdomains.
// Collective: every rank must call it, in the same order.
#include <string>
#include <vector>

class vtkMultiProcessController;

namespace ptm
{
// Why meshes of rankVolume[r] on rank r, at most maximumVolume per
// tetrahedron (TetGen's -a), cannot fit, or nothing: the estimated meshes
// (estimateTetMesh) of the ranks that share a machine against that
// machine's physical memory. The same answer on every rank (all of it is
// gathered). `requested` names the size in the message ("MaximumVolume
// 1.2e-07"); the message names no subdomain or interface, so tetmesh.py
// does not cut again for it.
std::string memoryShortfall(vtkMultiProcessController* controller, const std::vector<double>& rankVolume,
  double maximumVolume, const std::string& requested);
} // namespace ptm
#endif
