#ifndef PTM_FUZZ_FUZZED_SURFACE_H
#define PTM_FUZZ_FUZZED_SURFACE_H
// Fuzz bytes as a small triangle surface for the cutting core.
//
// Mostly: one of the closed shapes (ClosedShapes.h) followed by a list of
// edits, so inputs stay near valid surfaces where the interesting geometry is:
// points moved a little, onto lattice values, onto other points or onto the
// line through two others (coincident, coplanar, collinear), triangles
// flipped, dropped, duplicated or rewired (also to indices that do not exist),
// triangles and edges split (the surface stays closed), a shifted copy added
// (second body, or overlapping), and the whole surface scaled (to extreme
// magnitudes too), stretched, rotated or moved far from the origin.
// Otherwise: free-form points on a small lattice and triangles between them.
//
// Sizes are capped so that one decomposition stays far below a second.
#include "TriangleSurface.h"

#include <fuzzer/FuzzedDataProvider.h>

namespace ptm::fuzz
{
constexpr std::size_t kMaxFuzzedPoints = 200;
constexpr std::size_t kMaxFuzzedTriangles = 400;
constexpr int kMaxFuzzedEdits = 40;

TriangleSurface fuzzedSurface(FuzzedDataProvider& bytes);
} // namespace ptm::fuzz
#endif
