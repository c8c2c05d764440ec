#ifndef PTM_GLOBAL_MESH_NUMBERING_H
#define PTM_GLOBAL_MESH_NUMBERING_H
// Global numbering of the assembled volume mesh, independent of the number
// of ranks: points 0..S-1 are the surface-complex points (their global ids);
// then the interior points of subdomain 0, of subdomain 1, ...; tetrahedra
// subdomain by subdomain. Each rank only needs every subdomain's counts.
#include <string>
#include <vector>

namespace ptm
{
struct GlobalMeshOffsets
{
  std::vector<long long> firstInteriorPoint; // per subdomain
  std::vector<long long> firstTetrahedron;   // per subdomain
  long long pointCount = 0;
  long long tetrahedronCount = 0;
};

// interiorPoints[s], tetrahedra[s]: counts of subdomain s (every subdomain).
GlobalMeshOffsets globalMeshOffsets(long long surfacePointCount,
  const std::vector<long long>& interiorPoints, const std::vector<long long>& tetrahedra);

// The rank that owns a point: that of the lowest subdomain touching it.
// lowestSubdomain[p] is that subdomain (or -1 if none), subdomainRank[s] its rank.
int owningRank(int lowestSubdomain, const std::vector<int>& subdomainRank);
} // namespace ptm
#endif
