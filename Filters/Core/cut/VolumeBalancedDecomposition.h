#ifndef PTM_VOLUME_BALANCED_DECOMPOSITION_H
#define PTM_VOLUME_BALANCED_DECOMPOSITION_H
// Stage 1 of the method: split a closed surface into K subdomains of equal
// measure by cutting planes, producing the labeled surface complex
// (SurfaceComplex.h) with interface regions still as boundary loops.
//
// Strategies: ParallelPlanes (K-1 parallel planes, the paper's prepartition
// along one direction) and RecursiveBisection (a part meant for k subdomains
// is cut at measure ratio floor(k/2):ceil(k/2); each plane cuts only its
// part). Plane offsets are found iteratively (regula falsi on the measure
// below the plane) until every part is within the balance tolerance.
// Subdomain numbering: along the direction for parallel planes; depth-first,
// lower side first, for recursive bisection.
#include "CutDirection.h"
#include "HalfSpaceMeasure.h"
#include "PlaneAlignment.h"
#include "PlaneSplit.h"
#include "PredictedCost.h"
#include "SurfaceInputCheck.h"
#include "SurfaceOrientation.h"

#include <functional>
#include <string>
#include <vector>

namespace ptm
{
enum class CutStrategy
{
  ParallelPlanes,
  RecursiveBisection
};

// The default of DecompositionOptions::minimumSlabThickness, a fraction of
// the mesh size. Slabs thinner than the size lie between two interfaces that
// cross the same input triangles, and fill with small, flat tetrahedra. On
// the fresh set (session 28, 2 ranks, the sweep's sizes, ParallelPlanes at
// K = 8, 16, 32, 64; Testing/Corpus/results/sweep-thin-slabs-session28.md),
// from K = 32 to 64: CGAL's pinion (thinnest slab 0.45 -> 0.22 x the size)
// 310 k -> 524 k tetrahedra, 3.9 -> 9.2 % under 10 degrees; KiCad's JST XH
// (0.33 -> 0.17 x) 130 k -> 248 k, 2.4 -> 5.6 %. Above a quarter the share
// grows too (JST XH at K = 16 -> 32, 0.67 -> 0.33 x: 1.3 -> 2.4 %), but the
// largest blow-ups are below it (USB-A at 0.14 and 0.07 x: TetGen failed on
// its slabs, 331 and 456 s of failed attempts before a recut meshed it); a
// quarter is also the floor of the contour split beside thin pieces
// (kThinPieceSpacingFraction). Recursive bisection at K = 64 gave a lower
// share on all 16 surfaces.
constexpr double kMinimumSlabThickness = 0.25;

struct DecompositionOptions
{
  int numberOfSubdomains = 2;
  CutStrategy strategy = CutStrategy::RecursiveBisection;
  CutDirection direction = CutDirection::LongestExtent;
  BalanceCriterion criterion = BalanceCriterion::Volume;
  double balanceTolerance = 0.01; // allowed relative deviation of a subdomain from its target
  double snapFraction = 0.05;     // see PlaneSplit.h; balancing may lower it to 0.001, never to 0
  // a plane whose line on an interface is within this angle of a line
  // already drawn there turns to run parallel to it, or along it
  // (PlaneAlignment.h); 0 turns that off
  double alignmentAngleDegrees = 15.0;
  // a recursive-bisection plane that would pass a hair from points or cross
  // faces at a shallow angle may tilt by up to this angle (degrees) to a
  // clearer, still balanced position; 0 keeps every normal as proposed
  double tiltDegrees = 10.0;
  InputCheckOptions inputCheck;   // see SurfaceInputCheck.h
  // BalanceCriterion::PredictedCost: the size field whose tetrahedra are
  // balanced (empty: predictUniformCost at costMaximumSize, regular
  // tetrahedra and the pieces of the input surface), no larger than
  // costMaximumSize (the mesher's largest size; 0: the input's mean edge,
  // its automatic size), sampled at about costSamples grid nodes over the
  // bounding box (PredictedCost.h: sampleCost)
  SizeFunction costSize;
  double costMaximumSize = 0;
  // without costSize: the thickness cap the boundary will follow
  // (LocalThickness.h, thicknessCappedSize, best given onLattice; empty:
  // none), which the uniform cost model then counts (PredictedCost.h,
  // predictUniformCost)
  SizeFunction costThicknessCap;
  std::size_t costSamples = 1000000;
  // Sharing the self-crossing checks of each cut among processes that all
  // run this same decomposition (every rank cuts the whole surface): of the
  // parts a cut changed, part p (its number among the parts made so far, the
  // same on every process) is checked by the process for which
  // checksPart(p) is true, and maxOverProcesses(v) returns the largest
  // v any process gave (0: none of its parts crosses itself, 1: one does,
  // kCheckFailed: its check threw). So every process takes the cut one
  // process would. A process that gets kCheckFailed throws. Both empty: one
  // process checks every part.
  std::function<bool(int)> checksPart;
  std::function<int(int)> maxOverProcesses;
  // Take the contour points inside planar faces out again after the cuts
  // (FlatCrossingRemoval.h); false keeps every crossing.
  bool removeFlatCrossings = true;
  // Optional, per input triangle: the face it belongs to (the CAD face of a
  // CAD reader's output). A contour point between triangles of two faces is
  // never taken out (FlatCrossingRemoval.h), so every piece keeps its face.
  // Empty: one face.
  std::vector<Index> faceGroups;
  // ParallelPlanes refuses, before any cut, a K whose thinnest slab would be
  // thinner than this fraction of the mesh size (costMaximumSize, or the
  // input's mean edge), naming the largest K that is not; 0 never refuses.
  // Slabs under the size but above this fraction are cut with a warning, and
  // so are all slabs under the size with a size field (costSize), which may
  // ask for much less than its cap there. See kMinimumSlabThickness.
  double minimumSlabThickness = kMinimumSlabThickness;
};

// What a process gives maxOverProcesses when its check threw.
constexpr int kCheckFailed = 2;

struct DecompositionResult
{
  bool ok = false;
  std::string error;
  // true when the options were refused before any cut, the surface being
  // fine (slabs under minimumSlabThickness)
  bool refusedBeforeCutting = false;
  // true when the cuts themselves failed (no sound or balanced plane for a
  // part), the options and the input surface being fine
  bool failedInCuts = false;
  std::vector<std::string> warnings;
  SurfaceComplex complex;
  InputCheckCounts inputCheck;
  OrientationReport orientation;
  PlaneSplitStats splitStats;
  std::vector<double> subdomainVolume;  // divergence theorem over each closed subdomain
  std::vector<double> subdomainMeasure; // by the balance criterion (PredictedCost: sample weights)
  double totalVolume = 0;               // of the oriented input surface
  double inputMeanEdgeLength = 0;       // of the merged input triangles: the default mesh size
  double maximumImbalance = 0;          // max over subdomains of |measure / target - 1|
  int alignedNormals = 0;               // cuts turned to draw a line parallel to one they nearly continued
  int alignedLines = 0;                 // ... and then turned about that line, drawing the same line
  int rejectedCuts = 0;                 // cuts whose parts crossed themselves, replaced by another
  int clearedPlanes = 0;                // cuts moved within the balance budget away from points (PlaneClearance)
  int tiltedCuts = 0;                   // cuts tilted to a clearer normal (tiltDegrees)
  std::size_t flatCrossingsRemoved = 0; // contour points inside planar faces taken out (FlatCrossingRemoval.h)
};

// The input triangles may be unmerged (STL); `sourceFaces` of the result
// refer to the input triangle indices. Checks the input with
// options.inputCheck (prepareInputSurface), then cuts the checked surface.
DecompositionResult decomposeVolumeBalanced(
  const TriangleSurface& input, const DecompositionOptions& options);

// The same, on a surface the caller already checked with options.inputCheck
// (it measured something on the checked, outward surface first, as the
// cutter does the thickness); a refused check is returned as the error.
DecompositionResult decomposeVolumeBalanced(PreparedSurface prepared, const DecompositionOptions& options);

// Human-readable names, for messages and properties.
const char* toString(CutStrategy strategy);
const char* toString(CutDirection direction);
const char* toString(BalanceCriterion criterion);
} // namespace ptm
#endif
