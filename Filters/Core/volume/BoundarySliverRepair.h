#ifndef PTM_BOUNDARY_SLIVER_REPAIR_H
#define PTM_BOUNDARY_SLIVER_REPAIR_H
// Stage 4b: the flat tetrahedra TetGen leaves against a kept surface
// (switch Y), broken up by meshing small cavities around them again with a
// point inside each.
//
// With -Y TetGen may not split a surface triangle, so a flat tetrahedron
// lying on the surface stays wherever the point TetGen would insert, its
// circumcentre, lies outside the subdomain or encroaches on the surface:
// an "ear" (two surface triangles across a nearly flat edge) or a "wedge"
// (one surface triangle). On the corpus at K = 16 (2 ranks) one with two
// surface faces is the worst tetrahedron of 8 of 12 runs (CGAL's fandisk,
// eight, elephant and part, both strategies; femur and the triple torus
// have a wedge or an interior one). A point inside the subdomain just
// above such a tetrahedron can remove it without touching the surface.
//
// Contract of repairBoundarySlivers: `mesh` is TetGen's mesh of `surface`
// (surface points first with the same indices, positively oriented
// tetrahedra). Where a tetrahedron with a face on the surface, then (a
// second round, on the mesh the first left) one with only corners there,
// then (a third) one of the flattest few of either kind with a tiny edge,
// has a dihedral angle under options.sliverRepairAngle (and is no corner of
// the surface itself, see boundarySliverPoints), the tetrahedra within two
// rings of it form a cavity, grown until its boundary is a closed manifold
// surface. All cavities are meshed again in one meshClosedSurface run, their
// boundaries kept (-Y) and the points of boundarySliverPoints inserted first
// (-i). Each connected part of the cavity takes its new tetrahedra if their
// smallest dihedral angle is larger than the part's and either they have no
// more tetrahedra under 10 degrees or none under sliverRepairAngle (the
// part's sliver is gone; a few more tetrahedra between that angle and 10
// degrees are the lesser harm). The surface, every point on a part's
// boundary and every tetrahedron outside the parts taken stay as they were;
// interior points inside those parts are replaced by TetGen's. Returns the
// points inserted (0: the mesh is unchanged). Same input, same mesh.
#include "TetGenSubdomainMesher.h"

#include <vector>

namespace ptm
{
struct BoundarySliverPoint
{
  Vec3 point;
  Index tetrahedron; // the flat tetrahedron it breaks up (index into mesh.tets)
};

// The two kinds of flat tetrahedra the repair works on, in two rounds.
enum class SliverKind
{
  // a face on the surface (an ear or a wedge): the point goes above it
  OnTheSurface,
  // no face on the surface, but a corner or more there, which TetGen -Y
  // cannot move (a sliver between contour and boundary points): the point
  // goes at its centroid. This second round runs on the mesh the first
  // left, so its cavities do not merge with the first's, which are kept or
  // not part by part (in one round, KiCad's crystal HC49 at K = 16 fell
  // from 3.97 to 2.17 degrees: a part of the first kind, merged, was
  // judged as a whole)
  HeldByCorners,
  // either of the two, but with an edge under a tenth of its mean edge,
  // which the first two rounds skip: the point goes where its kind puts
  // it. The repair takes only the flattest few of them in each subdomain
  // (BoundarySliverRepair.cpp, kTinyEdgeRoundPoints), in a third round on
  // the mesh the second left, for the same reason as above:
  // run with the first (session 38), these cavities merged with others into
  // parts judged as a whole, and KiCad's AAVID heat sink at K = 16 kept a
  // part of 14,314 tetrahedra at 0.027 degrees that the first round alone
  // had raised to 0.065
  WithATinyEdge
};

// For each tetrahedron of `kind` with a dihedral angle under
// `angleDegrees`, one point. OnTheSurface: its centroid moved along the
// mean inward normal of its surface faces, half its mean edge (for a
// wedge, one face on the surface, at most halfway to its circumsphere).
// HeldByCorners: its centroid. Tetrahedra with an edge under a tenth of
// their mean edge are WithATinyEdge's only, placed as their own kind would
// be (until session 38 they were skipped: two points that close leave no
// room for a point between them, but a point beside the short edge can
// still turn the tetrahedron's flat angle elsewhere). Skipped: tetrahedra
// with two surface faces meeting at an angle under `angleDegrees` (the
// surface itself is that sharp there, as where a plane meets the input at a
// shallow angle; no point can help).
std::vector<BoundarySliverPoint> boundarySliverPoints(const TriangleSurface& surface, const TetMesh& mesh,
  double angleDegrees, SliverKind kind = SliverKind::OnTheSurface);

int repairBoundarySlivers(const TriangleSurface& surface, const TetMeshingOptions& options, TetMesh& mesh);
} // namespace ptm
#endif
