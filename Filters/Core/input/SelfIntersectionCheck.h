#ifndef PTM_SELF_INTERSECTION_CHECK_H
#define PTM_SELF_INTERSECTION_CHECK_H
// Whether a closed triangle surface intersects itself, with CGAL's exact
// predicates (Polygon_mesh_processing::does_self_intersect). Two triangles
// that meet only along their shared edge or corner do not count, unless
// they fold onto each other there: in one plane to round-off, on the same
// side of the edge (a wedge or slit of no thickness, which CGAL counts only
// when exactly coplanar).
#include "TriangleSurface.h"

#include <string>
#include <utility>
#include <vector>

namespace ptm
{
struct SelfIntersectionReport
{
  bool checked = false;        // false if the surface could not be turned into a mesh
  bool intersects = false;
  std::size_t pairs = 0;       // intersecting triangle pairs (up to `limit`)
  Index firstTriangle = -1;    // one pair, for the message
  Index secondTriangle = -1;
  std::vector<std::pair<Index, Index>> crossings; // every pair found (up to `limit`)
  std::size_t folds = 0;       // of the pairs, those folded at a shared edge
  std::string note;            // why it could not be checked
};

SelfIntersectionReport checkSelfIntersection(const TriangleSurface& surface, std::size_t limit = 1);

// Only pairs of the triangles listed in `among` (indices into
// surface.triangles): where the rest is known not to cross itself and the
// listed ones are all that may touch what changed.
SelfIntersectionReport checkSelfIntersection(
  const TriangleSurface& surface, const std::vector<Index>& among, std::size_t limit = 1);

// As the above, on a patch cut out of a closed surface (some of its
// triangles, sharing the points they share there). Orienting a soup splits
// the points where fans of the patch meet, and two triangles that meet at a
// split point would count as crossing: if that splits a corner of a
// triangle of `among`, `checked` is false and the caller checks the whole
// surface.
SelfIntersectionReport checkPatchSelfIntersection(
  const TriangleSurface& patch, const std::vector<Index>& among, std::size_t limit = 1);
} // namespace ptm
#endif
