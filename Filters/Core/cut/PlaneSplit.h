#ifndef PTM_PLANE_SPLIT_H
#define PTM_PLANE_SPLIT_H
// Splitting one part of a labeled surface complex by one plane.
//
// During decomposition the labels of the complex are part ("cell") ids. The
// part `cell` is bounded by surface triangles labeled {cell, -1} and by
// interface regions whose pair contains `cell`. splitCell cuts exactly these
// faces (no other part is touched) by the plane normal . x = offset:
//  * every vertex gets a side: below, above, or on the plane. A vertex within
//    snapFraction x (its shortest incident edge) of the plane counts as on
//    it, so the contour runs through it instead of leaving a sliver; one
//    inside the object (a point of earlier chords) also moves onto it along
//    those chords, so interfaces stay flat;
//  * an edge whose ends are strictly on opposite sides is split at one new
//    point, computed once from the edge's ends, so every face sharing the
//    edge shares the point;
//  * surface triangles crossing the plane are split into triangles (a quad
//    piece along its shorter diagonal); triangles lying in the plane go to
//    the side their normal points away from (the material side);
//  * interface regions of earlier planes are split along the line where
//    their plane meets this one; the chords inside a region get new points
//    at about the local boundary spacing, exactly on the line where the two
//    planes meet, shared by the region pieces and the new interface;
//  * the new interface region (pair {below, above}, normal = plane normal) is
//    bounded by the edges left open by the faces now labeled `below`; a
//    plane through the gap between two bodies of the part leaves none, which
//    is a valid cut with no interface;
//  * a split whose interface touches itself (pinchedPoints) or that leaves
//    the tip of a dent on or through the plane under the new interface
//    (coveredPokes, touchingSide) fails with those points listed, for the
//    caller to split again otherwise.
#include "SurfaceComplex.h"

#include <string>
#include <vector>

namespace ptm
{
// A point within this fraction of its shortest edge of a plane lies on it up
// to round-off (4e-16 to 2e-14 seen where cuts run through earlier lines):
// the contour runs through it, as through the grid points of a box cut on
// its grid lines, which leaves no short segment at all.
constexpr double kOnPlaneFraction = 1e-9;

struct PlaneSplitOptions
{
  // 0.05: measured on the test surfaces (60 decompositions incl. the CAD
  // bracket), 0.1 tilted interfaces into nearly parallel faces (2 self-
  // intersections) and 0 left near-degenerate slivers (7); 0.05 left none.
  double snapFraction = 0.05;
  // Vertices never snapped (sorted): where snapping one made a part's surface
  // touch or cross itself (see pinchedPoints, coveredPokes), the caller
  // splits again without it.
  std::vector<Index> keepOffPlane;
};

struct PlaneSplitStats
{
  std::size_t splitTriangles = 0;
  std::size_t snappedPoints = 0; // vertices off the plane treated as on it
  std::size_t unsnappedPoints = 0; // ... not, after all: their neighbours all lay across the plane
  std::size_t movedOntoPlane = 0; // ... of them moved onto it along one of their edges
  std::size_t chordPoints = 0;   // new points on lines where two planes meet
  // edges split within 10 % / 1 % of their length from an end: the contour
  // passes that close to a vertex, leaving a short segment and thin pieces
  std::size_t crossingsWithin10Percent = 0;
  std::size_t crossingsWithin1Percent = 0;
  std::size_t interfaceEdges = 0; // boundary edges of the new interface (0: the plane
                                  // passes between bodies of the part, no interface)
  // Points where a boundary of an interface of the two new parts touches
  // itself (two edges leave the point): the part's surface is pinched there,
  // its two sheets meet at one point and CGAL counts that as a self-
  // intersection. Seen where a plane passes near a saddle vertex of a
  // coarse surface (the 19-vertex triple torus of CGAL's data at K = 4) and
  // the vertex was snapped onto it: the two branches of the contour then
  // cross at the vertex. The split fails with these points listed.
  std::vector<Index> pinchedPoints;
  bool pinchedOnPlane = false; // one of them lies exactly on the plane (not snapped)
  bool pinchedAtNotch = false;  // they are the ends of edges at the bottom of a notch (notchInPlane)
  // Snapped vertices off the plane whose faces all went across and cross
  // the new interface (a dent's tip within the snapping distance): the split
  // fails with them listed, to be made again with them in keepOffPlane.
  std::vector<Index> coveredPokes;
  // A vertex on the plane up to round-off whose faces all lie on one side
  // (+1 above, -1 below), under the new interface: the part touches itself
  // there (femur at K = 48, parallel planes: the clearance search put the
  // plane through the tip of a dent). The split fails; the caller moves the
  // plane a hair away from that side. Also a snapped vertex a hair across
  // the plane from all its faces, over round-off and under a thousandth of
  // its shortest edge (TetGen's example at K = 64, parallel planes), with
  // its distance: the caller moves the plane that much further.
  Index touchingPoint = -1;
  int touchingSide = 0;
  double touchingDistance = 0; // 0 for a vertex on the plane up to round-off
};

// Returns false with a message if the part's faces do not form a closed
// surface or the plane does not produce a consistent interface.
bool splitCell(SurfaceComplex& complex, int cell, const Vec3& normal, double offset, int planeId,
  int below, int above, const PlaneSplitOptions& options, PlaneSplitStats& stats,
  std::string& error);
} // namespace ptm
#endif
