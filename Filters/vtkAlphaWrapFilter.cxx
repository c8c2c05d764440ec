#include "vtkAlphaWrapFilter.h"

#include "AlphaWrap.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "SurfaceComplexArrays.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <cmath>
#include <exception>

// The last wrap, its input and the properties it was made with.
class vtkAlphaWrapCache
{
public:
  bool valid = false;
  ptm::TriangleSurface input;
  double relativeAlpha = 0, relativeOffset = 0;
  ptm::TriangleSurface wrapped;
  std::vector<double> figures;
};

vtkStandardNewMacro(vtkAlphaWrapFilter);
vtkCxxSetObjectMacro(vtkAlphaWrapFilter, Controller, vtkMultiProcessController);

namespace
{
void addValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}
} // namespace

vtkAlphaWrapFilter::vtkAlphaWrapFilter()
  : Cache(new vtkAlphaWrapCache)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkAlphaWrapFilter::~vtkAlphaWrapFilter()
{
  this->SetController(nullptr);
  delete this->Cache;
}

int vtkAlphaWrapFilter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

// As the cutter: every rank asks for the whole surface, so a reader fails on
// every rank alike and every rank holds the same input.
int vtkAlphaWrapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  ptm::requestWholeInput(inputVector);
  return 1;
}

int vtkAlphaWrapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  vtkMultiProcessController* controller = this->Controller;

  ptm::PropertyChecks checks("AlphaWrap");
  checks.Require(this->RelativeAlpha >= 1e-4 && this->RelativeAlpha <= 1.0, "RelativeAlpha",
    "lie in [1e-4, 1] (a fraction of the bounding-box diagonal)", this->RelativeAlpha);
  checks.Require(this->RelativeOffset >= 1e-6 && this->RelativeOffset <= 0.1, "RelativeOffset",
    "lie in [1e-6, 0.1] (a fraction of the bounding-box diagonal)", this->RelativeOffset);
  if (!checks.Ok())
  {
    vtkErrorMacro(<< checks.Message());
    return 0;
  }
  this->SetProgressText("Gathering the surface");
  const ptm::TriangleSurface whole =
    ptm::wholeSurfaceOnEveryRank(controller, ptm::triangleSurfaceFromPolyData(input));
  if (ptm::agreeAnyAborted(controller, this))
  {
    return 1;
  }

  // Reuse the last wrap when every rank has it for this input (collective).
  vtkAlphaWrapCache& cache = *this->Cache;
  std::vector<long long> reuse = { cache.valid && cache.relativeAlpha == this->RelativeAlpha &&
      cache.relativeOffset == this->RelativeOffset && cache.input.points == whole.points &&
      cache.input.triangles == whole.triangles
    ? 1
    : 0 };
  ptm::allReduceMin(controller, reuse);
  if (reuse[0] == 0 && !this->Wrap(whole))
  {
    return 0;
  }
  const int piece = ptm::requestedPiece(outInfo);
  if (piece == 0)
  {
    ptm::triangleSurfaceToPolyData(cache.wrapped, output);
  }
  const std::vector<double>& figures = cache.figures;
  vtkFieldData* fd = output->GetFieldData();
  addValue(fd, ptm::arrays::WrapAlpha, figures[0]);
  addValue(fd, ptm::arrays::WrapOffset, figures[1]);
  addValue(fd, ptm::arrays::WrapToInputDistance, figures[2]);
  addValue(fd, ptm::arrays::InputToWrapDistance, figures[3]);
  addValue(fd, ptm::arrays::WrapSampleSpacing, figures[4]);
  addValue(fd, ptm::arrays::WrapSeconds, figures[5]);
  return 1;
}

bool vtkAlphaWrapFilter::Wrap(const ptm::TriangleSurface& whole)
{
  vtkMultiProcessController* controller = this->Controller;
  vtkAlphaWrapCache& cache = *this->Cache;
  cache.valid = false;
  // Rank 0 wraps; the others wait in the agreement below.
  this->SetProgressText("Wrapping");
  ptm::AlphaWrapResult wrap;
  std::string localError, message;
  if (ptm::rankOf(controller) == 0)
  {
    ptm::AlphaWrapOptions options;
    options.relativeAlpha = this->RelativeAlpha;
    options.relativeOffset = this->RelativeOffset;
    try
    {
      wrap = ptm::alphaWrapSurface(whole, options);
      localError = wrap.ok ? "" : wrap.error;
    }
    catch (const std::exception& e)
    {
      localError = std::string("unexpected failure while wrapping: ") + e.what();
    }
    for (const std::string& w : wrap.warnings)
    {
      vtkWarningMacro(<< w);
    }
  }
  if (!ptm::agreeAllSucceeded(controller, localError.empty(), localError, message))
  {
    vtkErrorMacro("AlphaWrap failed: " << message);
    return false;
  }
  // Rank 0's wrap and figures to every rank (the others contribute nothing).
  cache.wrapped = ptm::allGatherSurface(controller, wrap.surface);
  cache.figures = { wrap.alpha, wrap.offset, wrap.wrapToInput, wrap.inputToWrap, wrap.sampleSpacing,
    wrap.wrapSeconds + wrap.distanceSeconds };
  ptm::allReduceSum(controller, cache.figures);
  cache.input = whole;
  cache.relativeAlpha = this->RelativeAlpha;
  cache.relativeOffset = this->RelativeOffset;
  cache.valid = true;
  return true;
}

void vtkAlphaWrapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RelativeAlpha: " << this->RelativeAlpha << "\n";
  os << indent << "RelativeOffset: " << this->RelativeOffset << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
