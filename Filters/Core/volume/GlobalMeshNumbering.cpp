#include "GlobalMeshNumbering.h"

namespace ptm
{
GlobalMeshOffsets globalMeshOffsets(long long surfacePointCount,
  const std::vector<long long>& interiorPoints, const std::vector<long long>& tetrahedra)
{
  GlobalMeshOffsets o;
  long long point = surfacePointCount, tet = 0;
  for (std::size_t s = 0; s < interiorPoints.size(); ++s)
  {
    o.firstInteriorPoint.push_back(point);
    o.firstTetrahedron.push_back(tet);
    point += interiorPoints[s];
    tet += s < tetrahedra.size() ? tetrahedra[s] : 0;
  }
  o.pointCount = point;
  o.tetrahedronCount = tet;
  return o;
}

int owningRank(int lowestSubdomain, const std::vector<int>& subdomainRank)
{
  if (lowestSubdomain < 0 || lowestSubdomain >= static_cast<int>(subdomainRank.size()))
  {
    return -1;
  }
  return subdomainRank[lowestSubdomain];
}
} // namespace ptm
