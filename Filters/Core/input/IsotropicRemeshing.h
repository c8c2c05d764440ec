#ifndef PTM_ISOTROPIC_REMESHING_H
#define PTM_ISOTROPIC_REMESHING_H
// Remeshing the input surface into triangles of about one edge length, an
// explicit mode that moves the surface (issue #18, the third way it names).
//
// CAD exports tessellate with long thin triangles (fans on cylinders and
// fillets, needles a thousandth as wide as long). The default pipeline
// keeps every input triangle exactly, so every plane that crosses a needle
// leaves a contour edge as short as the needle is wide (1e-4 of a 2.4 edge
// on OCCT's Top at K = 32), and TetGen meets those with flat tetrahedra or
// fails. CGAL's isotropic remeshing (Polygon_mesh_processing::
// isotropic_remeshing) replaces them with triangles of about
// targetEdgeLength, its vertices projected back onto the input. Sharp edges
// (faces meeting at more than featureAngleDegrees) are kept as polylines:
// their vertices only slide along them, and the corners where such lines
// meet or turn do not move at all. The rest of the surface moves by about
// the sagitta of the new edges on curved faces, and more where the input has
// features smaller than the edge length; so this reports, and bounds, how
// far the remeshed surface is from the input in both directions (sampled,
// SurfaceDistance.h) and the change of the enclosed volume.
//
// Contract: the input is a closed, oriented, edge-manifold triangle surface
// (what the cutter's input check accepts; a soup is refused with a pointer
// to AlphaWrap). The output is closed and oriented like the input; it fails
// (nothing is handed on) if it crosses itself or strays further than
// maximumDeviation after its halvings. Deterministic: the same input and options give the
// same surface.
#include "TriangleSurface.h"

#include <string>
#include <vector>

namespace ptm
{
struct RemeshOptions
{
  // absolute; 0: the input's mean edge length (what the mesher's volume
  // bound defaults to)
  double targetEdgeLength = 0;
  double featureAngleDegrees = 30;  // sharp edges: their faces' normals differ by more
  int iterations = 3;               // CGAL's split, collapse, flip and smoothing rounds
  double maximumDeviation = 0;      // bound on both distances / bounding-box diagonal; 0: not bounded
  // bound on |V remeshed - V input| / V input; 0: not bounded. The distance
  // bound alone let OCCT's hammer.iges lose 4.3 % of its volume (edge 824,
  // 0.005 of the diagonal allowed 1,900) and its screw.step 2.5 %.
  double maximumVolumeChange = 0;
  // Where the result strays beyond either bound or crosses itself, the
  // edge length is halved and the input remeshed again, at most this often
  // (the sagitta on curved faces falls about 4 x per halving, and walls
  // thinner than about the edge length make it cross itself). OCCT's Top,
  // a cover 171 across with walls about 4 thick, crosses itself at edge
  // lengths 20, 10, 5 and 2.5 and not at 1.25; the corpus sweep's size for
  // it is 154. A failed attempt at a large edge length is cheap (few
  // triangles; its measure stops at the first sample beyond the bound).
  int halvings = 6;
  // Per input triangle, a label to keep (its CAD face); empty: none. Edges
  // between triangles of different labels are kept like sharp edges, and
  // every new triangle takes the label of the face it was made in.
  std::vector<long long> faceLabels;
  // About this many grid samples per surface for the two distances (plus
  // every corner, edge midpoint and centroid; SurfaceDistance.h). The unit
  // tests take fewer: on their 188-triangle cylinder of needles each query
  // searches many long boxes (6 s a test in Release, 2 minutes with ASan).
  double distanceSamples = 4e5;
};

struct RemeshResult
{
  bool ok = false;
  std::string error;
  TriangleSurface surface;
  double targetEdgeLength = 0;      // the one used (after halvings)
  int attempts = 0;                 // remeshings made (1 + halvings used)
  std::size_t featureEdges = 0;     // input edges kept as sharp-feature polylines
  std::size_t corners = 0;          // input vertices that did not move
  double remeshToInput = 0;         // largest distance from the new surface to the input
  double inputToRemesh = 0;         // largest distance from the input to the new surface
  double sampleSpacing = 0;         // the two distances are exact to within this
  double boundingBoxDiagonal = 0;   // of the input
  double volumeChange = 0;          // (V new - V input) / V input
  double remeshSeconds = 0;
  double distanceSeconds = 0;
  std::vector<long long> faceLabels; // per triangle of `surface`, when options.faceLabels was given
};

RemeshResult remeshSurface(const TriangleSurface& input, const RemeshOptions& options);
} // namespace ptm
#endif
