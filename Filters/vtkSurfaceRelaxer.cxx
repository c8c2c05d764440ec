#include "vtkSurfaceRelaxer.h"

#include "ComplexGather.h"
#include "PhaseLog.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "SurfaceComplexArrays.h"
#include "SurfaceRelaxation.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <exception>

namespace
{
// The figures of the relaxation as one-value arrays of the output's field data.
void addRelaxationFields(vtkFieldData* fd, const ptm::RelaxationResult& result, int mode)
{
  auto addValue = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  addValue("MinimumAngleBefore", result.before.minimumAngleDegrees);
  addValue("MinimumAngleAfter", result.after.minimumAngleDegrees);
  addValue("ShareBelow10DegreesBefore", result.before.shareBelow10Degrees);
  addValue("ShareBelow10DegreesAfter", result.after.shareBelow10Degrees);
  addValue("ShareBelow20DegreesBefore", result.before.shareBelow20Degrees);
  addValue("ShareBelow20DegreesAfter", result.after.shareBelow20Degrees);
  addValue("MovedNodeCount", static_cast<double>(result.acceptedMoves));
  // what the relaxation did to the geometry (~1e-15 in KeepSurface mode)
  addValue("RelaxationMode", static_cast<double>(mode));
  addValue("VolumeChange", result.change.volumeChange);
  addValue("MaximumSubdomainVolumeChange", result.change.maximumSubdomainVolumeChange);
  addValue("SurfaceDeviationOutputToInput", result.change.deviationOutputToInput);
  addValue("SurfaceDeviationInputToOutput", result.change.deviationInputToOutput);
  addValue("FreeNodeCount", static_cast<double>(result.freeNodes));
  addValue("SlidingNodeCount", static_cast<double>(result.slidingNodes));
  addValue("FixedNodeCount", static_cast<double>(result.fixedNodes));
}
} // namespace

vtkStandardNewMacro(vtkSurfaceRelaxer);
vtkCxxSetObjectMacro(vtkSurfaceRelaxer, Controller, vtkMultiProcessController);

vtkSurfaceRelaxer::vtkSurfaceRelaxer()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkSurfaceRelaxer::~vtkSurfaceRelaxer()
{
  this->SetController(nullptr);
}

int vtkSurfaceRelaxer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

int vtkSurfaceRelaxer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* controller = this->Controller;
  ptm::phases::setPhase(controller, "relax"); // PhaseLog.h
  const int rank = ptm::rankOf(controller);
  std::string message, localError;
  // Every rank takes the same branch: a failure anywhere fails all, an abort
  // asked on any rank aborts all.
  auto failedEverywhere = [&]() {
    if (ptm::agreeAllSucceeded(controller, localError.empty(), localError, message))
    {
      return false;
    }
    vtkErrorMacro(<< message);
    output->Initialize();
    return true;
  };
  auto abortedEverywhere = [&]() {
    if (!ptm::agreeAnyAborted(controller, this))
    {
      return false;
    }
    output->Initialize();
    return true;
  };

  this->UpdateProgress(0.0);
  // nonsense property values (the same on every rank, so every rank stops)
  ptm::PropertyChecks checks("SurfaceRelaxer");
  checks.Require(this->Mode == KEEP_SURFACE || this->Mode == SMOOTH_SURFACE, "Mode",
    "be 0 (KeepSurface) or 1 (SmoothSurface)", this->Mode);
  checks.Require(this->MaximumSurfaceDeviation >= 0.0 && this->MaximumSurfaceDeviation <= 1.0,
    "MaximumSurfaceDeviation", "lie in [0, 1] (relative to the bounding-box diagonal)",
    this->MaximumSurfaceDeviation);
  checks.Require(this->NumberOfIterations >= 0 && this->NumberOfIterations <= 1000,
    "NumberOfIterations", "lie in [0, 1000]", this->NumberOfIterations);
  checks.Require(this->RelaxationFactor >= 0.01 && this->RelaxationFactor <= 1.0,
    "RelaxationFactor", "lie in [0.01, 1]", this->RelaxationFactor);
  checks.Require(this->FeatureAngle >= 0.0 && this->FeatureAngle <= 180.0, "FeatureAngle",
    "lie in [0, 180] degrees", this->FeatureAngle);
  checks.Require(this->Region == NEAR_CUTS || this->Region == EVERYWHERE, "Region",
    "be 0 (NearCuts) or 1 (Everywhere)", this->Region);
  if (!checks.Ok())
  {
    vtkErrorMacro(<< checks.Message());
    output->Initialize();
    return 0;
  }
  this->SetProgressText("Gathering the complex");
  ptm::ComplexPiece piece;
  if (!ptm::complexFromPolyData(input, piece, localError))
  {
    localError = "SurfaceRelaxer: " + localError;
  }
  if (failedEverywhere())
  {
    return 0;
  }
  ptm::ComplexPiece whole;
  if (!ptm::allGatherComplex(controller, piece, whole, localError))
  {
    localError = "SurfaceRelaxer: " + localError;
  }
  if (failedEverywhere())
  {
    return 0;
  }
  if (abortedEverywhere())
  {
    return 1;
  }
  this->UpdateProgress(0.2);
  this->SetProgressText(
    this->Mode == KEEP_SURFACE ? "Relaxing (keeping the surface)" : "Relaxing (smoothing the surface)");

  ptm::RelaxationOptions options;
  options.mode = this->Mode == SMOOTH_SURFACE ? ptm::RelaxationMode::SmoothSurface : ptm::RelaxationMode::KeepSurface;
  options.maximumSurfaceDeviation = this->MaximumSurfaceDeviation;
  options.iterations = this->NumberOfIterations;
  options.relaxationFactor = this->RelaxationFactor;
  options.featureAngleDegrees = this->FeatureAngle;
  options.nearCutsOnly = this->Region == NEAR_CUTS;
  ptm::RelaxationResult result;
  try
  {
    result = ptm::relaxSurfaceComplex(whole.complex, options);
    localError = result.ok ? "" : "SurfaceRelaxer: " + result.error;
  }
  catch (const std::exception& e)
  {
    localError = std::string("SurfaceRelaxer: unexpected failure: ") + e.what();
  }
  if (failedEverywhere())
  {
    return 0;
  }
  if (abortedEverywhere())
  {
    return 1;
  }
  this->UpdateProgress(0.9);
  this->SetProgressText("Writing the complex");

  std::vector<int> mine;
  for (int s = 0; s < whole.complex.subdomainCount; ++s)
  {
    if (whole.subdomainRank[s] == rank)
    {
      mine.push_back(s);
    }
  }
  if (mine.empty())
  {
    mine.push_back(-1);
  }
  ptm::complexToPolyData(whole, mine, output);
  vtkFieldData* fd = output->GetFieldData();
  addRelaxationFields(fd, result, this->Mode);
  ptm::passOnFieldData(input, fd); // the earlier stages' facts and the size samples
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSurfaceRelaxer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == KEEP_SURFACE ? "KeepSurface" : "SmoothSurface") << "\n";
  os << indent << "MaximumSurfaceDeviation: " << this->MaximumSurfaceDeviation << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "RelaxationFactor: " << this->RelaxationFactor << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Region: " << this->Region << "\n";
}
