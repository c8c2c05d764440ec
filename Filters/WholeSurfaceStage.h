#ifndef PTM_WHOLE_SURFACE_STAGE_H
#define PTM_WHOLE_SURFACE_STAGE_H
// The RequestData of a filter that replaces the whole input surface by a new
// one made with serial CGAL (vtkAlphaWrapFilter, vtkSurfaceRemesher),
// written once:
//
//  * every rank asks its upstream for the whole surface (RequestUpdateExtent:
//    ptm::requestWholeInput), so a reader fails on every rank alike;
//  * rank 0 alone makes the new surface (the work is serial and would cost
//    the same on every rank) and sends it to the others, so the output does
//    not depend on the number of ranks; a failure there fails every rank
//    with rank 0's message;
//  * piece 0 of a request gets the whole surface, other pieces are empty (as
//    the OFF reader does), and every piece gets the figures in field data;
//  * a re-execution for another piece with the same input and properties
//    reuses the last result (all ranks agree on that): ParaView asks for
//    piece r of n, the cutter for piece 0 of 1, and wrapping again made
//    tetmesh's cut stage on the OCCT bottle 26 s instead of 0.7 s.
#include "TriangleSurface.h"

#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkInformationVector;
class vtkMultiProcessController;

namespace ptm
{
// What the filter's core call made from the whole surface (on rank 0).
struct MadeSurface
{
  std::string error; // empty: made
  std::vector<std::string> warnings;
  TriangleSurface surface;
  std::vector<double> figures; // one value per name of WholeSurfaceStage::figureNames
  std::vector<long long> cadFaceIds; // per triangle of `surface`, or empty
};

struct WholeSurfaceStage
{
  std::string filterName;              // for messages: "<filterName> failed: ..."
  const char* progressText = "";       // while rank 0 works
  std::vector<const char*> figureNames; // field data arrays of one double each
  std::vector<double> properties;      // the filter's property values: the cache key with the input
  // The input's CADFaceId per triangle of the whole surface (empty when it
  // has none), and the made surface's in MadeSurface::cadFaceIds, which
  // becomes its cell data CADFaceId (the cutter carries it to the mesher's
  // boundary port).
  std::function<MadeSurface(const TriangleSurface& whole, const std::vector<long long>& cadFaceIds)> make;
};

// The last result of a filter and what it was made from.
struct WholeSurfaceCache
{
  bool valid = false;
  TriangleSurface input;
  std::vector<double> properties;
  TriangleSurface made;
  std::vector<double> figures;
  std::vector<long long> madeCADFaceIds;
};

// Collective; RequestData's return value (0 on a failure, reported on every
// rank through `filter`).
int runWholeSurfaceStage(vtkAlgorithm* filter, vtkMultiProcessController* controller,
  const WholeSurfaceStage& stage, WholeSurfaceCache& cache, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector);
} // namespace ptm
#endif
