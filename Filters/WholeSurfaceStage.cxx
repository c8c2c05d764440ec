#include "WholeSurfaceStage.h"

#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "RankCollectives.h"

#include "vtkAlgorithm.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <exception>

namespace ptm
{
namespace
{
// Rank 0 makes the surface, every rank gets it and its figures; false on
// every rank if rank 0 failed.
bool makeOnRankZero(vtkAlgorithm* filter, vtkMultiProcessController* controller, const WholeSurfaceStage& stage,
  const TriangleSurface& whole, WholeSurfaceCache& cache)
{
  cache.valid = false;
  filter->SetProgressText(stage.progressText);
  MadeSurface made;
  if (rankOf(controller) == 0)
  {
    try
    {
      made = stage.make(whole);
    }
    catch (const std::exception& e)
    {
      made.error = std::string("unexpected failure: ") + e.what();
    }
    for (const std::string& w : made.warnings)
    {
      vtkWarningWithObjectMacro(filter, << w);
    }
  }
  std::string message;
  if (!agreeAllSucceeded(controller, made.error.empty(), made.error, message))
  {
    vtkErrorWithObjectMacro(filter, << stage.filterName << " failed: " << message);
    return false;
  }
  // rank 0's surface and figures to every rank (the others contribute nothing)
  cache.made = allGatherSurface(controller, made.surface);
  cache.figures = made.figures;
  cache.figures.resize(stage.figureNames.size(), 0.0);
  allReduceSum(controller, cache.figures);
  cache.input = whole;
  cache.properties = stage.properties;
  cache.valid = true;
  return true;
}
} // namespace

int runWholeSurfaceStage(vtkAlgorithm* filter, vtkMultiProcessController* controller,
  const WholeSurfaceStage& stage, WholeSurfaceCache& cache, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  filter->SetProgressText("Gathering the surface");
  const TriangleSurface whole = wholeSurfaceOnEveryRank(controller, triangleSurfaceFromPolyData(input));
  if (agreeAnyAborted(controller, filter))
  {
    return 1;
  }
  std::vector<long long> reuse = { cache.valid && cache.properties == stage.properties &&
      cache.input.points == whole.points && cache.input.triangles == whole.triangles
    ? 1
    : 0 };
  allReduceMin(controller, reuse);
  if (reuse[0] == 0 && !makeOnRankZero(filter, controller, stage, whole, cache))
  {
    return 0;
  }
  if (requestedPiece(outputVector->GetInformationObject(0)) == 0)
  {
    triangleSurfaceToPolyData(cache.made, output);
  }
  for (std::size_t i = 0; i < stage.figureNames.size(); ++i)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(stage.figureNames[i]);
    a->InsertNextValue(cache.figures[i]);
    output->GetFieldData()->AddArray(a);
  }
  return 1;
}
} // namespace ptm
