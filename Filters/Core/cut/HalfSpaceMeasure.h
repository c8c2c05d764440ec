#ifndef PTM_HALF_SPACE_MEASURE_H
#define PTM_HALF_SPACE_MEASURE_H
// How much of one part of a surface complex lies below a plane, for placing
// cutting planes so that parts get equal shares.
//
// Volume: by the divergence theorem with the field F(x) = n (n.x - c), whose
// divergence is 1 and which vanishes on the plane n.x = c, so the unknown cap
// of the cut contributes nothing: the volume below is the flux of F through
// the part's boundary faces clipped to the half-space below. Interface
// regions (polygons with holes) are integrated through their boundary edges
// with Green's theorem, using an in-plane field that vanishes on the cut too.
// Nodes / BoundaryFacets: counts of surface points / surface triangles
// (by centroid) below. PredictedCost: as Volume (see the enum).
#include "SurfaceComplex.h"

#include <string>
#include <vector>

namespace ptm
{
enum class BalanceCriterion
{
  Volume,
  BoundaryFacets,
  Nodes,
  // the tetrahedra TetGen is predicted to make, for a size field or one
  // size (PredictedCost.h, cost samples); the cuts are made by volume at
  // the volume fraction that splits the part's cost as wanted, so this
  // class measures it as Volume
  PredictedCost
};

class HalfSpaceMeasure
{
public:
  HalfSpaceMeasure(const SurfaceComplex& complex, int cell, const Vec3& normal,
    BalanceCriterion criterion);

  // Measure of the part below n.x = offset.
  double below(double offset) const;
  // Measure of the whole part.
  double total() const { return this->Total; }
  // Range of n.x over the part's points.
  double minimumOffset() const { return this->MinOffset; }
  double maximumOffset() const { return this->MaxOffset; }

  // The offset where the part below holds `fraction` of the total: a root of
  // below(c) - fraction * total(), to `relativeTolerance` of the total, found
  // by bracketing regula falsi (Illinois). Counts are step functions: the
  // offset is put half way between the two neighbouring points or centroids.
  double offsetForFraction(double fraction, double relativeTolerance) const;

private:
  const SurfaceComplex& Complex;
  int Cell;
  Vec3 Normal;
  BalanceCriterion Criterion;
  std::vector<std::size_t> Triangles;
  std::vector<std::pair<std::size_t, double>> Regions; // region, +1 or -1 (outward sign)
  std::vector<double> SortedValues;                    // projections, for the count criteria
  double Total = 0;
  double MinOffset = 0;
  double MaxOffset = 0;
};

// How far the plane n.x = offset keeps from the points of part `cell`: the
// smallest |n.p - offset| / h(p) over its points p, h(p) the shortest edge of
// the part at p (surface triangle edges and interface boundary edges), over
// the points not on the plane (within round-off, kOnPlaneFraction h(p)): a
// plane a hair off a point scores about 0; one a tenth of the edges away,
// 0.1. The contour of a plane at clearance s crosses the edges at p at
// least s h(p) from p, so it has no segment much shorter than s times the
// local edge (long thin triangles crossed near their sharp corner aside).
struct PointSpacing
{
  Index point;
  double shortest; // the shortest edge of the part at the point, > 0
};

// h(p) of every point of part `cell` (points whose shortest edge has zero
// length left out), by point index.
std::vector<PointSpacing> shortestEdges(const SurfaceComplex& complex, int cell);

class PlaneClearance
{
public:
  PlaneClearance(const SurfaceComplex& complex, int cell, const Vec3& normal);
  // The same from the part's shortestEdges, found once for every normal
  // tried (finding them for each took 6 % of a K = 64 run on one rank).
  // Points in `mustClear` (sorted) count even where they lie on the plane:
  // a cut through them pinched the part (the bottom of a notch), so the
  // plane must keep off them.
  PlaneClearance(const SurfaceComplex& complex, const std::vector<PointSpacing>& spacing, const Vec3& normal,
    const std::vector<Index>& mustClear = {});
  double at(double offset) const;
  // The offset in [low, high] of largest clearance, clearances above `enough`
  // counting as `enough`; of equal ones the nearest to `preferred`.
  double clearestOffset(double low, double high, double preferred, double enough) const;

private:
  struct Projected
  {
    double at;      // n.p
    double spacing; // h(p)
    bool mustClear; // no exemption on the plane
    bool operator<(const Projected& o) const { return at < o.at; }
  };
  std::vector<Projected> Points; // sorted by n.p
  double LargestEdge = 0;
};

// Every point of the part (surface and interface boundary points), sorted.
std::vector<Index> cellPoints(const SurfaceComplex& complex, int cell);
} // namespace ptm
#endif
