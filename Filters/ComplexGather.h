#ifndef PTM_COMPLEX_GATHER_H
#define PTM_COMPLEX_GATHER_H
// Assembling the whole labeled complex on every rank from the ranks' pieces,
// in a canonical form (point index = global id; triangles deduplicated and
// sorted by their global ids), so that a computation on it gives the same
// result whatever the number of ranks. Collective.
#include "PolyDataConversion.h"

#include <string>

class vtkMultiProcessController;

namespace ptm
{
// Fails if global ids are outside [0, globalPointCount) or the pieces
// disagree on a point's coordinates.
bool allGatherComplex(vtkMultiProcessController* controller, const ComplexPiece& local,
  ComplexPiece& whole, std::string& error);
} // namespace ptm
#endif
