#include "vtkAlphaWrapFilter.h"

#include "AlphaWrap.h"
#include "PipelineRequests.h"
#include "PropertyChecks.h"
#include "SurfaceComplexArrays.h"
#include "WholeSurfaceStage.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <utility>

vtkStandardNewMacro(vtkAlphaWrapFilter);
vtkCxxSetObjectMacro(vtkAlphaWrapFilter, Controller, vtkMultiProcessController);

vtkAlphaWrapFilter::vtkAlphaWrapFilter()
  : Cache(new ptm::WholeSurfaceCache)
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
  ptm::PropertyChecks checks("AlphaWrap");
  checks.Require(this->RelativeAlpha >= 1e-4 && this->RelativeAlpha <= 1.0, "RelativeAlpha",
    "lie in [1e-4, 1] (a fraction of the bounding-box diagonal)", this->RelativeAlpha);
  checks.Require(this->RelativeOffset >= 1e-6 && this->RelativeOffset <= 0.1, "RelativeOffset",
    "lie in [1e-6, 0.1] (a fraction of the bounding-box diagonal)", this->RelativeOffset);
  if (!checks.Ok())
  {
    vtkErrorMacro(<< checks.Message());
    vtkPolyData::GetData(outputVector, 0)->Initialize();
    return 0;
  }
  ptm::WholeSurfaceStage stage;
  stage.filterName = "AlphaWrap";
  stage.progressText = "Wrapping";
  stage.figureNames = { ptm::arrays::WrapAlpha, ptm::arrays::WrapOffset, ptm::arrays::WrapToInputDistance,
    ptm::arrays::InputToWrapDistance, ptm::arrays::WrapSampleSpacing, ptm::arrays::WrapSeconds,
    ptm::arrays::WrapMeanThickness };
  stage.properties = { this->RelativeAlpha, this->RelativeOffset, static_cast<double>(this->AllowSkin) };
  ptm::AlphaWrapOptions options;
  options.relativeAlpha = this->RelativeAlpha;
  options.relativeOffset = this->RelativeOffset;
  options.allowSkin = this->AllowSkin != 0;
  stage.make = [options](const ptm::TriangleSurface& whole, const std::vector<long long>&)
  {
    ptm::AlphaWrapResult wrap = ptm::alphaWrapSurface(whole, options);
    ptm::MadeSurface made;
    made.error = wrap.ok ? "" : wrap.error;
    made.warnings = wrap.warnings;
    made.surface = std::move(wrap.surface);
    made.figures = { wrap.alpha, wrap.offset, wrap.wrapToInput, wrap.inputToWrap, wrap.sampleSpacing,
      wrap.wrapSeconds + wrap.distanceSeconds, wrap.meanThickness };
    return made;
  };
  return ptm::runWholeSurfaceStage(this, this->Controller, stage, *this->Cache, inputVector, outputVector);
}

void vtkAlphaWrapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RelativeAlpha: " << this->RelativeAlpha << "\n";
  os << indent << "RelativeOffset: " << this->RelativeOffset << "\n";
  os << indent << "AllowSkin: " << this->AllowSkin << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
