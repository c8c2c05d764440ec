#ifndef PTM_POLY_DATA_CONVERSION_H
#define PTM_POLY_DATA_CONVERSION_H
// Conversions between vtkPolyData and the plain-C++ types of the core.
#include "SurfaceComplex.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPolyData;

namespace ptm
{
// The triangles of any polygonal data (polygons triangulated, strips split;
// lines and vertices ignored).
TriangleSurface triangleSurfaceFromPolyData(vtkPolyData* input);

// The other way: `output` gets the surface's points (double) and triangles,
// nothing else (readers and filters add their own arrays).
void triangleSurfaceToPolyData(const TriangleSurface& surface, vtkPolyData* output);

// What a rank holds of the labeled complex, with the complex-wide facts
// carried in field data.
struct ComplexPiece
{
  SurfaceComplex complex;         // local point indices; planes and subdomainCount complex-wide
  std::vector<Index> globalIds;   // global id of every local point
  std::vector<int> subdomainRank; // owner of every subdomain
  std::vector<double> subdomainVolume;
  std::vector<double> subdomainMeasure;
  std::vector<int> planeSubdomainCount;
  Index globalPointCount = 0;
  double inputMeanEdgeLength = 0; // the input surface's mean edge: default mesh size for every stage
};

// Writes the faces of the piece (triangles, and interface regions as closed
// poly-lines) with the arrays of SurfaceComplexArrays.h. Only faces whose
// pair contains a subdomain in `keep` are written (all faces if keep is empty);
// `globalIds` gives each complex point's global id (identity if empty).
void complexToPolyData(const ComplexPiece& piece, const std::vector<int>& keep, vtkPolyData* output);

// Copies the arrays of arrays::PassedOn that `input` has from its field data
// to `output` (the facts of earlier stages a filter carries on).
void passOnFieldData(vtkPolyData* input, vtkFieldData* output);

// Reads a piece written by complexToPolyData (or by a later stage). Fails with
// a message naming the missing or inconsistent array.
bool complexFromPolyData(vtkPolyData* input, ComplexPiece& piece, std::string& error);
} // namespace ptm
#endif
