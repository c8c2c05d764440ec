#ifndef PTM_SUBDOMAIN_SURFACE_H
#define PTM_SUBDOMAIN_SURFACE_H
// The closed surface of one subdomain, taken from the labeled complex in a
// canonical form: points sorted by global id, each triangle rotated to start
// at its smallest global id, triangles sorted. Whichever rank extracts it and
// whatever order the complex piece had, the result is the same, so meshing
// it gives the same tetrahedra on 1, 2 or N ranks.
#include "SurfaceComplex.h"

#include <string>

namespace ptm
{
struct SubdomainSurface
{
  TriangleSurface surface;        // outward oriented
  std::vector<Index> globalIds;   // of surface.points
  std::vector<Index> sourceFaces; // per triangle: input triangle, -1 on interfaces
  std::vector<int> otherSide;     // per triangle: the subdomain across it, -1 outside
};

// Fails if the subdomain has no triangles, if loops are still untriangulated
// interfaces, or if its surface is not closed (an edge not used by exactly two
// of its triangles in opposite directions).
bool extractSubdomainSurface(const SurfaceComplex& complex, const std::vector<Index>& globalIds,
  int subdomain, SubdomainSurface& out, std::string& error);
} // namespace ptm
#endif
