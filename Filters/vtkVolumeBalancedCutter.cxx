#include "vtkVolumeBalancedCutter.h"

#include "PolyDataConversion.h"
#include "RankCollectives.h"
#include "SubdomainAssignment.h"
#include "SurfaceComplexArrays.h"
#include "VolumeBalancedDecomposition.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <exception>
#include <sstream>

vtkStandardNewMacro(vtkVolumeBalancedCutter);
vtkCxxSetObjectMacro(vtkVolumeBalancedCutter, Controller, vtkMultiProcessController);

vtkVolumeBalancedCutter::vtkVolumeBalancedCutter()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkVolumeBalancedCutter::~vtkVolumeBalancedCutter()
{
  this->SetController(nullptr);
}

int vtkVolumeBalancedCutter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(
    vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkVolumeBalancedCutter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* controller = this->Controller;
  const int rank = ptm::rankOf(controller);
  const int ranks = ptm::rankCount(controller);
  std::string message;

  this->UpdateProgress(0.0);
  this->SetProgressText("Gathering the surface");
  const ptm::TriangleSurface local = ptm::triangleSurfaceFromPolyData(input);
  const ptm::TriangleSurface surface = ptm::allGatherSurface(controller, local);
  if (ptm::agreeAnyAborted(controller, this->CheckAbort()))
  {
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(0.1);

  ptm::DecompositionOptions options;
  options.numberOfSubdomains = this->NumberOfSubdomains > 0 ? this->NumberOfSubdomains : ranks;
  options.strategy = this->Strategy == PARALLEL_PLANES ? ptm::CutStrategy::ParallelPlanes
                                                       : ptm::CutStrategy::RecursiveBisection;
  options.direction = static_cast<ptm::CutDirection>(this->Direction);
  options.criterion = static_cast<ptm::BalanceCriterion>(this->BalanceCriterion);
  options.balanceTolerance = this->BalanceTolerance;

  this->SetProgressText("Cutting");
  ptm::DecompositionResult result;
  std::string localError;
  try
  {
    if (surface.triangles.empty())
    {
      localError = "the input has no triangles (is the reader's file empty or not a surface?)";
    }
    else
    {
      result = ptm::decomposeVolumeBalanced(surface, options);
      localError = result.ok ? "" : result.error;
    }
  }
  catch (const std::exception& e)
  {
    localError = std::string("unexpected failure while cutting: ") + e.what();
  }
  if (!ptm::agreeAllSucceeded(controller, localError.empty(), localError, message))
  {
    vtkErrorMacro("VolumeBalancedCutter failed: " << message);
    output->Initialize();
    return 0;
  }
  for (const std::string& warning : result.warnings)
  {
    if (rank == 0)
    {
      vtkWarningMacro(<< warning);
    }
  }
  if (ptm::agreeAnyAborted(controller, this->CheckAbort()))
  {
    output->Initialize();
    return 1;
  }
  this->UpdateProgress(0.8);
  this->SetProgressText("Writing the complex");

  ptm::ComplexPiece piece;
  piece.subdomainVolume = result.subdomainVolume;
  piece.subdomainMeasure = result.subdomainMeasure;
  piece.subdomainRank = ptm::assignSubdomainsToRanks(result.subdomainMeasure, ranks);
  piece.globalPointCount = static_cast<ptm::Index>(result.complex.points.size());
  piece.inputMeanEdgeLength = result.inputMeanEdgeLength;
  piece.complex = std::move(result.complex);
  std::vector<int> mine;
  for (int s = 0; s < piece.complex.subdomainCount; ++s)
  {
    if (piece.subdomainRank[s] == rank)
    {
      mine.push_back(s);
    }
  }
  if (mine.empty())
  {
    mine.push_back(-1); // keep nothing: this rank owns no subdomain
  }
  ptm::complexToPolyData(piece, mine, output);

  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkStringArray> criterion;
  criterion->SetName(ptm::arrays::BalanceCriterionName);
  criterion->InsertNextValue(ptm::toString(options.criterion));
  fd->AddArray(criterion);
  vtkNew<vtkDoubleArray> imbalance;
  imbalance->SetName(ptm::arrays::MaximumImbalance);
  imbalance->InsertNextValue(result.maximumImbalance);
  fd->AddArray(imbalance);

  this->UpdateProgress(1.0);
  return 1;
}

void vtkVolumeBalancedCutter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSubdomains: " << this->NumberOfSubdomains << "\n";
  os << indent << "Strategy: " << this->Strategy << "\n";
  os << indent << "Direction: " << this->Direction << "\n";
  os << indent << "BalanceCriterion: " << this->BalanceCriterion << "\n";
  os << indent << "BalanceTolerance: " << this->BalanceTolerance << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
