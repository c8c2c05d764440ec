#ifndef PTM_FUZZ_CLOSED_SHAPES_H
#define PTM_FUZZ_CLOSED_SHAPES_H
// Small closed surfaces built exactly in code, the starting points the
// decomposition fuzzer mutates: valid input is the interesting neighbourhood
// (random triangles are almost never closed, so they would only exercise the
// first refusals of the input check).
#include "TriangleSurface.h"

namespace ptm::fuzz
{
enum class ClosedShape
{
  Tetrahedron,
  Octahedron,
  Cube,            // 12 triangles
  LatticeCube,     // each face split into 2 x 2 squares, 48 triangles
  Icosahedron,
  Torus,           // genus 1, 6 x 3 quads
  TwoBodies,       // a cube and an octahedron apart from each other
  CubeWithCavity,  // an octahedral hole inside a cube (a nested shell)
  NearlyTouchingCubes, // two cubes one above the other, 1e-9 apart: planes through a thin gap
};
constexpr int kClosedShapeCount = 9;

// Outward oriented (normals out of the material), roughly unit sized.
TriangleSurface closedShape(ClosedShape shape);
} // namespace ptm::fuzz
#endif
