#ifndef PTM_STRAIGHT_CONTOUR_POINTS_H
#define PTM_STRAIGHT_CONTOUR_POINTS_H
// Stage 3, last step: every point in the middle of a straight contour is
// kept on the inner side of the input surface, by a few units in the last
// place.
//
// Why. A contour is where a cutting plane crosses an input triangle. The
// points splitting a contour edge (ContourSubdivision.h), and those the
// relaxation slides along a straight contour, lie on the segment a-b
// between their two contour neighbours only up to one rounding. Measured on
// CGAL's itemb at K = 64 (recursive bisection, 3 ranks, --size 0.04947):
// such a point v, 1.1e-16 from the line and outside both the input
// triangle's plane and the interface, and TetGen (-pYz) joined a and b
// directly and filled the needle between that edge and v with two flat
// tetrahedra, one under the two interface triangles at v and one under the
// two surface triangles. Its optimisation split them with a point 6e-6 from
// v: four tetrahedra of 0.01-0.07 degrees, which the sliver repair could not
// improve (its cavity got the same needle). `tetgen -pYz` on that
// subdomain's surface alone gives 0.0146 degrees, and 1.80 with v moved
// 2e-16 inside the input plane; the neighbour across the interface, which
// has the same input plane, meshed as before either way. (A box of two
// subdomains with its contour point outside both planes gave TetGen no
// needle: outside is necessary, not sufficient.)
//
// Contract. `complex` is a triangulated complex (interfaces triangulated:
// every triangle a surface or an interface triangle, surface triangles
// oriented out of their subdomain). A contour edge has a surface triangle
// and an interface triangle on it. A point with exactly two contour edges,
// to a and b, lying within rounding of the segment between them (its
// distance from the line at most 64 units in the last place of its largest
// coordinate, strictly between a and b), is in the middle of a straight
// chain; the chain runs on through such points to its two ends, which this
// stage never moves. Each such point v is tested with CGAL's exact
// orientation against every surface triangle at it that has a or b as a
// corner, in the plane it has with v and that neighbour replaced by the
// chain's ends (the input triangle's plane up to rounding, and one that
// does not move when other points of the chain do). Where v lies strictly
// outside any, it is moved across the contour within the cutting plane of
// an interface triangle on its contour edges, against the mean outward
// normal of those surface triangles (along minus that normal where the
// complex names no plane), by 2^k units in the last place of its largest
// coordinate, k = 0, 1, ..., until no test has it outside, but never by
// more than 1e-13 of that coordinate (then it stays). Everything else is
// unchanged; the same complex gives the same points anywhere, so every rank
// holding the whole complex moves the same points alike. Returns how many
// points moved.
#include "SurfaceComplex.h"

#include <cstddef>

namespace ptm
{
std::size_t keepStraightContourPointsInside(SurfaceComplex& complex);
} // namespace ptm
#endif
