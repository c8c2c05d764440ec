#include "vtkSurfaceRemesher.h"

#include "IsotropicRemeshing.h"
#include "PipelineRequests.h"
#include "PropertyChecks.h"
#include "SurfaceComplexArrays.h"
#include "WholeSurfaceStage.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <cmath>
#include <utility>

vtkStandardNewMacro(vtkSurfaceRemesher);
vtkCxxSetObjectMacro(vtkSurfaceRemesher, Controller, vtkMultiProcessController);

vtkSurfaceRemesher::vtkSurfaceRemesher()
  : Cache(new ptm::WholeSurfaceCache)
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkSurfaceRemesher::~vtkSurfaceRemesher()
{
  this->SetController(nullptr);
  delete this->Cache;
}

int vtkSurfaceRemesher::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

int vtkSurfaceRemesher::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  ptm::requestWholeInput(inputVector);
  return 1;
}

int vtkSurfaceRemesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  ptm::PropertyChecks checks("SurfaceRemesher");
  checks.Require(this->TargetEdgeLength >= 0 && std::isfinite(this->TargetEdgeLength), "TargetEdgeLength",
    "be 0 (automatic) or positive", this->TargetEdgeLength);
  checks.Require(this->FeatureAngle >= 0 && this->FeatureAngle <= 180, "FeatureAngle", "lie in [0, 180] degrees",
    this->FeatureAngle);
  checks.Require(this->Iterations >= 1 && this->Iterations <= 100, "Iterations", "lie in [1, 100]", this->Iterations);
  checks.Require(this->MaximumDeviation >= 0 && this->MaximumDeviation <= 1, "MaximumDeviation",
    "lie in [0, 1] (a fraction of the bounding-box diagonal; 0: not bounded)", this->MaximumDeviation);
  checks.Require(this->MaximumVolumeChange >= 0 && this->MaximumVolumeChange <= 1, "MaximumVolumeChange",
    "lie in [0, 1] (relative; 0: not bounded)", this->MaximumVolumeChange);
  if (!checks.Ok())
  {
    vtkErrorMacro(<< checks.Message());
    vtkPolyData::GetData(outputVector, 0)->Initialize();
    return 0;
  }
  ptm::WholeSurfaceStage stage;
  stage.filterName = "SurfaceRemesher";
  stage.progressText = "Remeshing";
  stage.figureNames = { ptm::arrays::RemeshEdgeLength, ptm::arrays::RemeshToInputDistance,
    ptm::arrays::InputToRemeshDistance, ptm::arrays::RemeshSampleSpacing, ptm::arrays::RemeshVolumeChange,
    ptm::arrays::RemeshFeatureEdges, ptm::arrays::RemeshCorners, ptm::arrays::RemeshSeconds };
  stage.properties = { this->TargetEdgeLength, this->FeatureAngle, static_cast<double>(this->Iterations),
    this->MaximumDeviation, this->MaximumVolumeChange };
  ptm::RemeshOptions options;
  options.targetEdgeLength = this->TargetEdgeLength;
  options.featureAngleDegrees = this->FeatureAngle;
  options.iterations = this->Iterations;
  options.maximumDeviation = this->MaximumDeviation;
  options.maximumVolumeChange = this->MaximumVolumeChange;
  stage.make = [options](const ptm::TriangleSurface& whole, const std::vector<long long>& cadFaceIds)
  {
    ptm::RemeshOptions labelled = options;
    labelled.faceLabels = cadFaceIds;
    ptm::RemeshResult r = ptm::remeshSurface(whole, labelled);
    ptm::MadeSurface made;
    made.error = r.error;
    made.surface = std::move(r.surface);
    made.cadFaceIds = std::move(r.faceLabels);
    made.figures = { r.targetEdgeLength, r.remeshToInput, r.inputToRemesh, r.sampleSpacing, r.volumeChange,
      static_cast<double>(r.featureEdges), static_cast<double>(r.corners), r.remeshSeconds + r.distanceSeconds };
    return made;
  };
  return ptm::runWholeSurfaceStage(this, this->Controller, stage, *this->Cache, inputVector, outputVector);
}

void vtkSurfaceRemesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetEdgeLength: " << this->TargetEdgeLength << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Iterations: " << this->Iterations << "\n";
  os << indent << "MaximumDeviation: " << this->MaximumDeviation << "\n";
  os << indent << "MaximumVolumeChange: " << this->MaximumVolumeChange << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
