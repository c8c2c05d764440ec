#ifndef PTM_BENT_REGION_CHECK_H
#define PTM_BENT_REGION_CHECK_H
// Stage 2 guards: interfaces bent through snapped vertices, checked as they
// are really triangulated; and, after contour subdivision, whole subdomain
// surfaces (subdomainsCrossingThemselves, at the end).
//
// The cutter leaves input vertices that lie within its snap distance of a
// plane where they are (the input's geometry is kept), so an interface region
// through them bends a little off its plane. A surface triangle meeting such
// a region at a shallow angle may then be crossed by the region's triangles,
// and whether it is depends on the triangulation itself: on femur at K = 64
// the cutter's check of its own triangulation passed, while the
// triangulator's (other sizes, smoothing) crossed a surface triangle at 8
// degrees to the plane, and TetGen could not mesh the subdomain.
//
// Contract.
//  Input: the complex of a piece (its outer triangles, with the subdomain
//  each bounds) and the triangulations of its interface regions.
//  Output: the regions that are bent (a boundary point off the plane by more
//  than round-off) and bound a subdomain whose surface, assembled from its
//  outer triangles and the triangulated regions, intersects itself (CGAL's
//  exact predicates, among the bent regions' triangles and the outer
//  triangles in their box). A subdomain whose outer triangles the piece does
//  not hold is not checked; the rank that holds it checks it, so the union
//  over ranks does not depend on how subdomains are spread over ranks.
#include "InterfaceTriangulation.h"
#include "SurfaceComplex.h"

#include <set>
#include <vector>

namespace ptm
{
struct TriangulatedRegion
{
  const InterfaceRegion* region = nullptr;
  const std::vector<Index>* pointOfLocal = nullptr; // triangulation point -> complex point (boundary points)
  const InterfaceTriangulation* triangulation = nullptr;
};

// Whether a boundary point of the region lies off its plane beyond round-off
// (1e-10 of the region's extent).
bool regionIsBent(const SurfaceComplex& complex, const TriangulatedRegion& region);

// Indices into `regions` of the bent regions of every subdomain (held by the
// piece) whose assembled surface crosses itself, sorted.
std::vector<std::size_t> bentRegionsCrossingSurface(
  const SurfaceComplex& complex, const std::vector<TriangulatedRegion>& regions);
// The subdomains among `among` whose outer triangles the piece holds and
// whose whole assembled surface crosses itself (or could not be checked),
// sorted. Used after contour subdivision (ContourSubdivision.h), whose new
// points change the interfaces' triangulation beyond what the cutter
// checked: on netgen's part1 at K = 16 by recursive bisection a surface
// fan 7e-6 above a later plane, inside that plane's region, was crossed by
// the region's triangles only once the region's contours were split.
std::vector<int> subdomainsCrossingThemselves(
  const SurfaceComplex& complex, const std::vector<TriangulatedRegion>& regions, const std::set<int>& among);
} // namespace ptm
#endif
