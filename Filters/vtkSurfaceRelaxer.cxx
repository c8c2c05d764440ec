#include "vtkSurfaceRelaxer.h"

#include "ComplexGather.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "StageRun.h"
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
// Every rank holds the whole complex here; the work is shared out. The
// moves: each rank relaxes its share of the groups of movable nodes
// (RelaxationOptions::processes) and the moved nodes are gathered from all.
// The check that relaxation made no subdomain cross itself: each rank checks
// the subdomains it owns (the cutter's assignment; every K-th by rank if
// there is none), and the points to put back are gathered from all. Every
// rank ends with what a single process doing everything would.
void shareOut(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& whole, int rank, ptm::RelaxationOptions& options)
{
  const int ranks = ptm::rankCount(controller);
  if (ranks < 2)
  {
    return;
  }
  const std::vector<int> owner = whole.subdomainRank;
  options.checksSubdomain = [owner, rank, ranks](int s) {
    return s < static_cast<int>(owner.size()) ? owner[s] == rank : s % ranks == rank;
  };
  options.unionOverProcesses = [controller](const std::vector<ptm::Index>& points) {
    const std::vector<long long> all =
      ptm::allGatherValues(controller, std::vector<long long>(points.begin(), points.end()));
    return std::vector<ptm::Index>(all.begin(), all.end());
  };
  options.processes = ranks;
  options.process = rank;
  options.gatherOverProcesses = [controller](const std::vector<double>& values) {
    return ptm::allGatherValues(controller, values);
  };
}

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
  // nodes put back because their moves made a subdomain cross itself
  addValue("UndoneMoveCount", static_cast<double>(result.undoneMoves));
  // straight-contour points moved to the inside by rounding (StraightContourPoints.h)
  addValue("ContourPointsPulledInside", static_cast<double>(result.contourPointsPulledInside));
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

std::string vtkSurfaceRelaxer::PropertyError()
{
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
  return checks.Ok() ? "" : checks.Message();
}

int vtkSurfaceRelaxer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  ptm::StageRun run(this, this->Controller, "SurfaceRelaxer", "relax", { output }); // StageRun.h
  ptm::ComplexPiece piece, whole;
  if (run.PropertiesRefused(this->PropertyError()) || !run.ReadPiece(input, piece))
  {
    return run.Failure();
  }
  run.Step(0.05, "Gathering the complex");
  std::string localError;
  ptm::allGatherComplex(this->Controller, piece, whole, localError);
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  if (run.AbortedAnywhere())
  {
    return run.Aborted();
  }
  run.Step(0.2,
    this->Mode == KEEP_SURFACE ? "Relaxing (keeping the surface)" : "Relaxing (smoothing the surface)");
  ptm::RelaxationOptions options;
  options.mode = this->Mode == SMOOTH_SURFACE ? ptm::RelaxationMode::SmoothSurface : ptm::RelaxationMode::KeepSurface;
  options.maximumSurfaceDeviation = this->MaximumSurfaceDeviation;
  options.iterations = this->NumberOfIterations;
  options.relaxationFactor = this->RelaxationFactor;
  options.featureAngleDegrees = this->FeatureAngle;
  options.nearCutsOnly = this->Region == NEAR_CUTS;
  shareOut(this->Controller, whole, run.Rank(), options);
  ptm::RelaxationResult result;
  try
  {
    result = ptm::relaxSurfaceComplex(whole.complex, options);
    localError = result.ok ? "" : result.error;
  }
  catch (const std::exception& e)
  {
    localError = std::string("unexpected failure: ") + e.what();
  }
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  if (run.AbortedAnywhere())
  {
    return run.Aborted();
  }
  run.Step(0.9, "Writing the complex");
  ptm::writeOwnedFaces(whole, run.Rank(), output);
  vtkFieldData* fd = output->GetFieldData();
  addRelaxationFields(fd, result, this->Mode);
  ptm::passOnFieldData(input, fd); // the earlier stages' facts and the size samples
  return run.Done();
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
