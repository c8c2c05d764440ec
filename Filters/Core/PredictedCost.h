#ifndef PTM_PREDICTED_COST_H
#define PTM_PREDICTED_COST_H
// The meshing cost of every subdomain as a size field predicts it, so that
// subdomains can go to ranks by cost rather than volume (a field ten times
// finer at one pole put 1.30 x the mean tetrahedra on one of 2 ranks).
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
#include "InterfaceTriangulation.h" // SizeFunction
#include "SurfaceComplex.h"

#include <vector>

namespace ptm
{
struct PredictedCost
{
  std::vector<double> regularTetrahedra; // per subdomain
  std::vector<double> boundaryTriangles; // per subdomain
  std::vector<double> tetrahedra;        // per subdomain: TetGen's expected count
};

PredictedCost predictCost(const SurfaceComplex& complex, const SizeFunction& size);
} // namespace ptm
#endif
