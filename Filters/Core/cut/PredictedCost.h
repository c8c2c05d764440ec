#ifndef PTM_PREDICTED_COST_H
#define PTM_PREDICTED_COST_H
// The meshing cost of every subdomain as a size field, or one size,
// predicts it, so that subdomains go to ranks by cost rather than volume (a
// field ten times finer at one pole put 1.30 x the mean tetrahedra on one
// of 2 ranks; the fine thread of a screw at one size, 1.82 x).
//
// Contract.
//  Input: a labeled complex whose subdomains are closed (surface triangles,
//  interface triangles or interface loops, as the cutter leaves it) and a
//  size field h (edge length wanted at a point).
//  Output: per subdomain, the regular tetrahedra of edge h that fill it
//  (the integral of 6 sqrt(2) / h^3 over it), the equilateral triangles of
//  edge h that cover its whole boundary (outer faces and interfaces), and
//  from the two the tetrahedra TetGen is expected to make, the cost used to
//  share subdomains out: TetGen's time is about proportional to its count.
//  The weights of that model were fitted by measurement (PredictedCost.cpp).
//  Method: the divergence theorem with F = (W, 0, 0), W(x, y, z) the integral
//  of the density along x from the complex's smallest x (8-point
//  Gauss-Legendre), over every face with a 3-point (degree 2) rule; an
//  interface loop is taken as the fan of signed triangles from its plane's
//  origin, which covers the region exactly once. Values of h that are not
//  positive, or below 1e-3 of the complex's diagonal, count as that floor
//  (as in the interface mesher); a count the quadrature of such a jump
//  makes negative is 0. The same complex and field always give the same
//  numbers.
#include "HalfSpaceMeasure.h"
#include "SizeFunction.h"
#include "SurfaceComplex.h"

#include <vector>

namespace ptm
{
struct PredictedCost
{
  std::vector<double> regularTetrahedra; // per subdomain
  std::vector<double> boundaryTriangles; // per subdomain
  std::vector<double> inputPieces;       // per subdomain: pieces of input triangles on its boundary
  std::vector<double> tetrahedra;        // per subdomain: TetGen's expected count
};

PredictedCost predictCost(const SurfaceComplex& complex, const SizeFunction& size);

// The same for one size h everywhere (no size field), with TetGen's count
// from a model fitted on real CAD and scanned parts: the regular
// tetrahedra and the pieces of the input surface, which the boundary keeps
// however small they are against h (PredictedCost.cpp).
// With `thicknessCap` (LocalThickness.h: thicknessCappedSize, +inf where it
// gives no cap) the regular tetrahedra are those of min(h, cap): the walls
// the boundary is spaced finer for cost more.
PredictedCost predictUniformCost(const SurfaceComplex& complex, double h, const SizeFunction& thicknessCap = nullptr);
// Its weights: TetGen's tetrahedra per regular tetrahedron of edge h and
// per piece of an input triangle.
constexpr double kUniformCostPerRegularTetrahedron = 2.9;
constexpr double kUniformCostPerInputPiece = 4.3;

// The field no larger than `cap` (the mesher's largest size: it never
// meshes coarser); `size` itself when cap is not positive.
SizeFunction cappedSize(const SizeFunction& size, double cap);

// A field that is slow to evaluate, as a cost estimate needs it: its values
// at the nodes of a lattice of about kLatticeNodes over the points'
// bounding box, no finer than `finest`, computed when first needed and
// interpolated between them. The values must be positive and finite. The
// thickness cap is such a field (a search over its samples): evaluated at
// every quadrature point and cost sample it made Prusa's rr-vc-300 bed cut
// in 32 s instead of 0.6 s.
constexpr double kLatticeNodes = 30000;
SizeFunction onLattice(const SizeFunction& field, const std::vector<Vec3>& points, double finest);

// Cost samples, for cutting by cost (BalanceCriterion::PredictedCost): the
// nodes of a regular grid inside a closed surface, each weighted by the
// regular tetrahedra of the field in its grid cell (cell volume x 6 sqrt(2)
// / h^3, h floored as above), and the part of the complex each lies in.
// The grid has about `gridPoints` nodes over the bounding box, shifted off
// round coordinates; a node is inside where the winding number of the
// surface's crossings along its z column is positive (robust to nested
// shells; a column through an edge, which the shift makes unlikely, may
// misplace the nodes of one column, an error of one sample in a cost
// estimate). Deterministic.
struct CostSamples
{
  std::vector<Vec3> points;
  std::vector<double> weights;
  std::vector<int> cells; // the part of the complex being cut each lies in (0 at first)
  double spacing = 0;     // of the grid
  // cost per unit volume on top of the weights, counted on a part's exact
  // volume (HalfSpaceMeasure) rather than by grid nodes (sampleUniformCost)
  double perVolume = 0;
};
// With `baseSize`, each node weighs only what its density exceeds that of
// the size baseSize (never below 0), and nodes of no excess are left out.
CostSamples sampleCost(
  const TriangleSurface& closed, const SizeFunction& size, std::size_t gridPoints, double baseSize = 0);

// The samples of predictUniformCost's model, for cutting by cost without a
// size field: kUniformCostPerRegularTetrahedron x the regular tetrahedra of
// the size h as perVolume, the thickness cap's excess over them (where it
// asks for less than h) as the grid nodes of sampleCost, and the centroid of
// every triangle of `closed` (an input triangle: a cut splits it into
// pieces on both sides, counted here once on the side of its centroid)
// weighted by kUniformCostPerInputPiece. The volume term is exact: counted
// on grid nodes, two unit cubes 12 triangles each, one offset by (3, 0.2,
// 0.1), weighed 24,233 and 25,089 (3.5 % apart, one column of 57 more each
// way), and the plane of K = 2 went 0.027 into the second cube instead of
// between them, its thin wedge meshed at 0.29 degrees.
CostSamples sampleUniformCost(
  const TriangleSurface& closed, double h, std::size_t gridPoints, const SizeFunction& thicknessCap = nullptr);

// For a cut of part `cell` by planes of normal n: the fraction of the
// part's volume below the offset where `fraction` of its samples' weight
// lies below, so a cutter that balances volume can balance cost. Without
// samples in the part, `fraction` itself.
double volumeFractionForCost(const CostSamples& samples, const SurfaceComplex& complex, int cell,
  const Vec3& normal, double fraction);

// After part `cell` was cut by n.x = offset: its samples go to `below` or `above`.
void moveSamples(CostSamples& samples, int cell, const Vec3& normal, double offset, int below, int above);
} // namespace ptm
#endif
