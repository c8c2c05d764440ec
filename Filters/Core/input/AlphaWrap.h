#ifndef PTM_ALPHA_WRAP_H
#define PTM_ALPHA_WRAP_H
// Wrapping a dirty surface into a closed one the mesher accepts.
//
// Real models are often open, non-manifold or self-intersecting (see the dirty
// candidates of Testing/Corpus/MANIFEST.md); the input check refuses them.
// CGAL's 3D alpha wrapping (CGAL::alpha_wrap_3, CGAL 5.5) turns any triangle
// soup into a watertight, 2-manifold, non-self-intersecting surface that
// encloses it at about `offset` from it and does not enter cavities or gaps
// narrower than about `alpha`. The price is fidelity: the wrap is not the input
// surface, so this reports how far apart they are, in both directions:
//   wrapToInput  largest distance from a point of the wrap to the input
//                (about `offset` everywhere the wrap hugs the input);
//   inputToWrap  largest distance from a point of the input to the wrap
//                (large where the wrap skipped something: a gap narrower than
//                alpha, or inner walls of a non-manifold model).
// Both are measured on samples (CGAL's grid sampling of both surfaces, spacing
// `sampleSpacing`) against an AABB tree of the other surface, so each is the
// true maximum to within the spacing.
//
// A hollow skin is refused: where the input is open with a hole wider than
// alpha, the wrap goes in through the hole and wraps the surface from both
// sides, into a shell about 2 x offset thick instead of the solid the input
// bounds (assimp's sphereWithHole: 0.099 enclosed where the ball holds 14.1).
// The thickness sizing then meshes that shell finely (over 600 s; CGAL's
// blobby_3cc: 7.3 M tetrahedra). An open input (an edge of one triangle)
// whose wrap has a small mean thickness, 2 x enclosed volume / area (a shell
// of thickness t and area A encloses t A / 2), is such a skin; see
// kSkinThicknessInOffsets. A closed input cannot be entered, so a closed
// thin wall is never taken for one (OCCT's bottle, walls 0.6 thick: 23
// offsets).
//
// Deterministic: the same input and options give the same wrap bit for bit.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
// A wrap whose mean thickness (2 x volume / area) is under this many offsets
// is a skin. Measured at the default alpha and offset on 17 dirty models of
// CGAL's demo data and assimp's test models (session 27): the 13 open ones
// with holes wider than alpha 2.0-4.3 offsets (elephant-with-holes 4.28,
// lion-head 3.73, sphereWithHole 2.08), the 4 self-intersecting or
// non-manifold solids 118-348 offsets (man, bull, camel, diplodocus). An
// open input with walls thinner than about 8 offsets (1/375 of the
// diagonal) whose holes alpha does not enter would be taken for a skin too;
// AllowSkin meshes it.
constexpr double kSkinThicknessInOffsets = 10.0;

struct AlphaWrapOptions
{
  // Both relative to the input's bounding-box diagonal. Measured on the OCCT
  // bottle tessellated at 1/200 of its diagonal (94; 3,450 triangles, two of
  // them crossing): alpha 1/100 gives 43,102 triangles in 8.7 s, wrap within
  // 0.79 of the input and the input within 0.63 of the wrap (the thread is
  // rounded); 1/50 gives 19,940 triangles in 3.0 s, 1.40 and 0.87. The
  // offset 1/3000 is where the wrap lies where it hugs the input.
  double relativeAlpha = 1.0 / 100.0;
  double relativeOffset = 1.0 / 3000.0;
  // true: a hollow skin (see above) is returned with a warning instead of
  // refused, for a user who wants an open sheet meshed as a thin solid
  bool allowSkin = false;
};

struct AlphaWrapResult
{
  bool ok = false;
  std::string error;
  std::vector<std::string> warnings;
  TriangleSurface surface; // closed, 2-manifold, oriented outward
  double alpha = 0;        // absolute values used
  double offset = 0;
  double wrapToInput = 0;  // largest distance, see above
  double inputToWrap = 0;
  double sampleSpacing = 0;
  double meanThickness = 0; // 2 x enclosed volume / area of the wrap
  std::size_t inputTriangles = 0;   // usable (non-degenerate, finite) input triangles
  std::size_t skippedTriangles = 0; // repeated corner or index out of range: not wrapped
  std::size_t inputBorderEdges = 0; // edges of one usable input triangle: where the input is open
  double wrapSeconds = 0;     // CGAL::alpha_wrap_3
  double distanceSeconds = 0; // sampling and the two distance measures
};

AlphaWrapResult alphaWrapSurface(const TriangleSurface& input, const AlphaWrapOptions& options);
} // namespace ptm
#endif
