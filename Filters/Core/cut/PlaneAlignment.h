#ifndef PTM_PLANE_ALIGNMENT_H
#define PTM_PLANE_ALIGNMENT_H
// Continuing a line already drawn on an interface instead of nearly
// continuing it.
//
// Recursive bisection gives every part its own plane. Where the plane of a
// part draws a line on one of the part's interfaces that nearly runs along a
// line an earlier plane drew there (typically the plane that cut the
// neighbouring part across that interface), the two lines cross at a tiny
// angle: sliver regions with corners of a fraction of a degree, points a
// hair apart, and boundaries that run along the next cutting line. Those
// slivers become the worst interface triangles and tetrahedra. A plane
// turned slightly so that its line is parallel to the earlier one never
// crosses it; a plane through the earlier line draws the same line.
#include "SurfaceComplex.h"

namespace ptm
{
struct NearlyContinuedLine
{
  bool found = false;
  int planeId = -1;           // the earlier plane that drew the line
  int interfacePlaneId = -1;  // the plane of the interface the line lies on
  bool boundsPart = false;    // the earlier plane is one of the part's own faces (the line is an edge of the part)
  double angleDegrees = 0;    // between the proposed line and the earlier one, in the interface
  Vec3 direction{ 0, 0, 0 };  // unit direction of the earlier line
  Vec3 linePoint{ 0, 0, 0 };  // a point of it
  Vec3 parallelNormal{ 0, 0, 0 }; // the proposed normal turned least so its line is parallel
};

// Among the lines that earlier planes (complex.planes) drew on the
// interfaces of part `cell` (an earlier plane with at least two boundary
// points of the interface on it), the one most nearly parallel to the line
// the plane with `proposedNormal` draws on the same interface, if the angle
// between the two lines is below maximumAngleDegrees.
NearlyContinuedLine findNearlyContinuedLine(
  const SurfaceComplex& complex, int cell, const Vec3& proposedNormal, double maximumAngleDegrees);
} // namespace ptm
#endif
