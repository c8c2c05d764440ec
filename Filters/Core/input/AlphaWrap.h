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
// Deterministic: the same input and options give the same wrap bit for bit.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
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
  std::size_t inputTriangles = 0;   // usable (non-degenerate, finite) input triangles
  std::size_t skippedTriangles = 0; // repeated corner or index out of range: not wrapped
  double wrapSeconds = 0;     // CGAL::alpha_wrap_3
  double distanceSeconds = 0; // sampling and the two distance measures
};

AlphaWrapResult alphaWrapSurface(const TriangleSurface& input, const AlphaWrapOptions& options);
} // namespace ptm
#endif
