#include "WholeSurfaceStage.h"

#include "CADFaceIds.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "RankCollectives.h"
#include "SurfaceComplexArrays.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
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
  const TriangleSurface& whole, const std::vector<long long>& cadFaceIds, WholeSurfaceCache& cache)
{
  cache.valid = false;
  filter->SetProgressText(stage.progressText);
  MadeSurface made;
  if (rankOf(controller) == 0)
  {
    try
    {
      made = stage.make(whole, cadFaceIds);
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
  cache.madeCADFaceIds = allGatherValues(controller, made.cadFaceIds);
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
  const TriangleSurface local = triangleSurfaceFromPolyData(input);
  const TriangleSurface whole = wholeSurfaceOnEveryRank(controller, local);
  const vtkSmartPointer<vtkIdTypeArray> table =
    gatherCADFaceTable(controller, input, local.triangles.size(), whole.triangles.size());
  std::vector<long long> cadFaceIds;
  for (vtkIdType t = 0; table && t < table->GetNumberOfTuples(); ++t)
  {
    cadFaceIds.push_back(table->GetValue(t));
  }
  if (agreeAnyAborted(controller, filter))
  {
    return 1;
  }
  std::vector<long long> reuse = { cache.valid && cache.properties == stage.properties &&
      cache.input.points == whole.points && cache.input.triangles == whole.triangles
    ? 1
    : 0 };
  allReduceMin(controller, reuse);
  if (reuse[0] == 0 && !makeOnRankZero(filter, controller, stage, whole, cadFaceIds, cache))
  {
    return 0;
  }
  if (requestedPiece(outputVector->GetInformationObject(0)) == 0)
  {
    triangleSurfaceToPolyData(cache.made, output);
    if (cache.madeCADFaceIds.size() == cache.made.triangles.size() && !cache.made.triangles.empty())
    {
      vtkNew<vtkIdTypeArray> ids;
      ids->SetName(arrays::CADFaceId);
      ids->SetNumberOfTuples(static_cast<vtkIdType>(cache.madeCADFaceIds.size()));
      for (std::size_t t = 0; t < cache.madeCADFaceIds.size(); ++t)
      {
        ids->SetValue(static_cast<vtkIdType>(t), cache.madeCADFaceIds[t]);
      }
      output->GetCellData()->AddArray(ids);
    }
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
