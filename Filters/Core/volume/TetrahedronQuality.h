#ifndef PTM_TETRAHEDRON_QUALITY_H
#define PTM_TETRAHEDRON_QUALITY_H
// Dihedral-angle quality of a tetrahedral mesh, computed by the mesher in
// one pass over each subdomain's tetrahedra as they are made, so a summary
// needs neither ParaView's Mesh Quality filter (which crashes on a rank's
// empty piece) nor a second pass over the mesh.
#include "TetGenSubdomainMesher.h"

namespace ptm
{
struct DihedralQuality
{
  long long tetrahedra = 0;
  long long below10Degrees = 0;          // tetrahedra whose smallest dihedral angle is under 10 degrees
  double minimumDihedralDegrees = 180.0; // over all of them (180 for none)
};

DihedralQuality dihedralQuality(const TetMesh& mesh);
// ... of the tetrahedra `tets` (indices into mesh.tets) only
DihedralQuality dihedralQuality(const TetMesh& mesh, const std::vector<Index>& tets);

// The smallest dihedral angle of one tetrahedron, in degrees (0 if flat).
double smallestDihedralDegrees(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
} // namespace ptm
#endif
