#ifndef PTM_SURFACE_RELAXATION_H
#define PTM_SURFACE_RELAXATION_H
// Stage 3 of the method: improve the triangles of the labeled complex near
// the cuts by moving nodes only; topology, node count, ids and labels never
// change.
//
// Two modes (issue #18, "exact geometry by default"):
//
// * KeepSurface (default): the union of the triangles of every subdomain is
//   kept as a point set, so every volume changes by round-off only. A node
//   moves only where the move keeps each incident triangle on the same
//   surface, decided with CGAL's exact predicates on the original
//   coordinates for surface triangles; interface triangles lie in their
//   cutting plane by the complex's contract, up to the rounding of points
//   computed on an inclined plane, so they count as in it when all their
//   points lie within 1e-13 of the bounding-box diagonal of it:
//   (a) all incident triangles exactly coplanar and forming closed fans
//       (an interface node inside its interface, a surface node inside a
//       planar part of the input): it moves within that plane;
//   (b) the incident triangles lie in exactly two planes, and exactly two
//       incident edges run along the line where they meet, one on each side
//       of the node (a straight feature edge, a straight contour between an
//       interface and a planar part of the surface, a straight line where
//       two planes meet): it slides along that line, strictly between those
//       two neighbours;
//   (c) any other node stays put (a node on a curved surface, a corner).
//   Moved positions are computed as origin + s u (+ t w) from the original
//   coordinates of fixed points of the plane or line, so they lie on it up
//   to one rounding, with no drift over the sweeps. A move keeps every
//   incident triangle's orientation (no triangle inverts or degenerates), so
//   each fan covers the same polygon.
// * SmoothSurface: the earlier behaviour: every node with no feature edge
//   moves within its patch (projected back onto the original surface
//   triangles, or kept in its plane), a node with two feature edges of one
//   curve slides along it (projected onto the original curve), corners stay.
//   The projection cuts the corners of curved surfaces, so volumes change
//   (3e-5 to 2.2 % on real CAD parts); a node may move at most
//   maximumSurfaceDeviation x the bounding-box diagonal from where it was,
//   which bounds the distance between the two surfaces in both directions.
//
// In both modes a move is smoothing towards the centroid of the node's
// neighbours (along the line for sliding nodes), scaled by the relaxation
// factor, kept only if no incident triangle inverts or degenerates and the
// worst angle around the node does not get worse (else half and quarter
// steps); a node whose worst angle stays under 20 degrees then tries short
// moves towards each neighbour. Nodes are visited in order of index, so the
// same complex gives the same result anywhere.
//
// Last, in both modes and whatever the iterations, the points in the middle
// of a straight contour that rounding left outside the input surface are
// moved inside it by a few units in the last place
// (StraightContourPoints.h; at most 1e-13 of their coordinates, the one
// departure from KeepSurface's point set), where TetGen made needles.
#include "SurfaceComplex.h"

#include <functional>
#include <string>
#include <vector>

namespace ptm
{
enum class RelaxationMode
{
  KeepSurface = 0,  // the surface of every subdomain stays the same point set
  SmoothSurface = 1 // smoothing + projection; may move the surface
};

struct RelaxationOptions
{
  RelaxationMode mode = RelaxationMode::KeepSurface;
  int iterations = 10;
  double relaxationFactor = 0.5;     // (0, 1]
  double featureAngleDegrees = 30.0; // SmoothSurface: dihedral deviation that makes a surface edge a feature
  bool nearCutsOnly = true;          // only nodes within `rings` rings of a cut node
  int rings = 3;
  // SmoothSurface: farthest a node may move from its original position,
  // relative to the bounding-box diagonal (moves farther are rejected)
  double maximumSurfaceDeviation = 0.01;
  // The check after relaxation that no subdomain crosses itself may be
  // shared out among processes that all hold the same complex:
  // checksSubdomain(s) says whether this process checks subdomain s, and
  // unionOverProcesses(points) returns every process's points concatenated
  // (a collective call: every process makes it once per round, the same
  // number of rounds). Both empty (default): this process checks all.
  std::function<bool(int)> checksSubdomain;
  std::function<std::vector<Index>(const std::vector<Index>&)> unionOverProcesses;
  // The moves may be shared out the same way: the movable nodes fall into
  // groups connected through movable neighbours only, and no group sees
  // another's moves (a node's move depends on its neighbours alone), so
  // process `process` of `processes` relaxes only the groups assigned to it
  // (largest first, each to the least loaded process) and
  // gatherOverProcesses(values) returns every process's values concatenated
  // in process order (a collective call, once per relaxation). Every process
  // then holds what one process relaxing everything would, bit for bit.
  // processes <= 1 (default): this process relaxes all.
  int processes = 1;
  int process = 0;
  std::function<std::vector<double>(const std::vector<double>&)> gatherOverProcesses;
};

struct TriangleQualityFigures
{
  std::size_t triangles = 0;
  double minimumAngleDegrees = 0;
  double shareBelow10Degrees = 0; // fraction of triangles whose smallest angle is under 10 degrees
  double shareBelow20Degrees = 0;
};

// How far a relaxed complex is from the one it came from.
struct SurfaceChangeFigures
{
  double volumeChange = 0;                 // (V after - V before) / V before, the whole enclosed volume
  double maximumSubdomainVolumeChange = 0; // the largest |dV| / V over the subdomains
  // largest distance from a point of one complex to the other (all triangles:
  // surface and interfaces), sampled at vertices and triangle centroids,
  // relative to the bounding-box diagonal of the complex before
  double deviationOutputToInput = 0;
  double deviationInputToOutput = 0;
  double boundingBoxDiagonal = 0;
};

struct RelaxationResult
{
  bool ok = false;
  std::string error;
  TriangleQualityFigures before, after;
  SurfaceChangeFigures change;
  std::size_t freeNodes = 0;    // movable within a patch (KeepSurface: within a plane)
  std::size_t slidingNodes = 0; // movable along a feature curve (KeepSurface: along a straight line)
  std::size_t fixedNodes = 0;
  std::size_t acceptedMoves = 0;
  std::size_t rejectedMoves = 0;
  std::size_t movesBeyondDeviation = 0; // SmoothSurface: trial positions refused by maximumSurfaceDeviation
  std::size_t undoneMoves = 0; // nodes put back because their moves made a subdomain cross itself
  // points of straight contours moved a few units in the last place to the
  // inner side of the input surface, last (StraightContourPoints.h)
  std::size_t contourPointsPulledInside = 0;
};

TriangleQualityFigures triangleQuality(const SurfaceComplex& complex);

// Volume change and two-sided sampled distance between two complexes with
// the same triangles (before and after relaxation).
SurfaceChangeFigures surfaceChange(const SurfaceComplex& before, const SurfaceComplex& after);

// The complex must have its interfaces triangulated (no loops left) and
// trianglePlanes filled for interface triangles.
RelaxationResult relaxSurfaceComplex(SurfaceComplex& complex, const RelaxationOptions& options);
} // namespace ptm
#endif
