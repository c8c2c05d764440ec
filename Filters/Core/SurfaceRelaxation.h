#ifndef PTM_SURFACE_RELAXATION_H
#define PTM_SURFACE_RELAXATION_H
// Stage 3 of the method: improve the triangles of the labeled complex near
// the cuts by moving nodes only; topology, node count, ids and labels never
// change.
//
// Every triangle belongs to a patch: the input surface (PlaneId -1) or one
// cutting plane. An edge is a feature edge if its triangles lie in different
// patches (surface contours, lines where two planes meet) or if it is a
// surface edge sharper than the feature angle. A node with no feature edge
// moves within its patch (projected back onto the original surface, or kept
// in its plane); a node with exactly two feature edges slides along its
// feature curve (projected onto the original curve); any other node (corners,
// where several features meet) stays put. A move is smoothing towards the
// centroid of the node's neighbours, scaled by the relaxation factor, and is
// kept only if no incident triangle inverts or degenerates and the worst angle
// around the node does not get worse (else half and quarter steps are tried).
// Nodes are visited in order of index, so the same complex gives the same
// result anywhere.
#include "SurfaceComplex.h"

#include <string>

namespace ptm
{
struct RelaxationOptions
{
  int iterations = 10;
  double relaxationFactor = 0.5;     // (0, 1]
  double featureAngleDegrees = 30.0; // dihedral deviation that makes a surface edge a feature
  bool nearCutsOnly = true;          // only nodes within `rings` rings of a cut node
  int rings = 3;
};

struct TriangleQualityFigures
{
  std::size_t triangles = 0;
  double minimumAngleDegrees = 0;
  double shareBelow10Degrees = 0; // fraction of triangles whose smallest angle is under 10 degrees
  double shareBelow20Degrees = 0;
};

struct RelaxationResult
{
  bool ok = false;
  std::string error;
  TriangleQualityFigures before, after;
  std::size_t freeNodes = 0;    // movable within a patch
  std::size_t slidingNodes = 0; // movable along a feature curve
  std::size_t fixedNodes = 0;
  std::size_t acceptedMoves = 0;
  std::size_t rejectedMoves = 0;
};

TriangleQualityFigures triangleQuality(const SurfaceComplex& complex);

// The complex must have its interfaces triangulated (no loops left) and
// trianglePlanes filled for interface triangles.
RelaxationResult relaxSurfaceComplex(SurfaceComplex& complex, const RelaxationOptions& options);
} // namespace ptm
#endif
