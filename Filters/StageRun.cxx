#include "StageRun.h"

#include "PhaseLog.h"
#include "RankCollectives.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkMultiProcessController.h"
#include "vtkPolyData.h"

namespace ptm
{
StageRun::StageRun(vtkAlgorithm* filter, vtkMultiProcessController* controller, std::string filterName,
  const char* phase, std::initializer_list<vtkDataObject*> outputs)
  : Filter(filter)
  , Communicator(controller)
  , FilterName(std::move(filterName))
  , Outputs(outputs)
  , RankId(rankOf(controller))
{
  phases::setPhase(controller, phase);
  this->Filter->UpdateProgress(0.0);
}

bool StageRun::PropertiesRefused(const std::string& propertyError)
{
  if (propertyError.empty())
  {
    return false;
  }
  vtkErrorWithObjectMacro(this->Filter, << propertyError);
  return true;
}

bool StageRun::ReadPiece(vtkPolyData* input, ComplexPiece& piece)
{
  std::string localError;
  if (!complexFromPolyData(input, piece, localError))
  {
    localError = this->FilterName + ": " + localError;
  }
  return !this->FailedAnywhere(localError);
}

bool StageRun::FailedAnywhere(const std::string& localError)
{
  std::string message;
  if (agreeAllSucceeded(this->Communicator, localError.empty(), localError, message))
  {
    return false;
  }
  vtkErrorWithObjectMacro(this->Filter, << this->FilterName << " failed: " << message);
  return true;
}

bool StageRun::AbortedAnywhere()
{
  return agreeAnyAborted(this->Communicator, this->Filter);
}

void StageRun::Step(double progress, const char* text)
{
  this->Filter->SetProgressText(text);
  this->Filter->UpdateProgress(progress);
}

int StageRun::Failure()
{
  this->EmptyOutputs();
  return 0;
}

int StageRun::Aborted()
{
  this->EmptyOutputs();
  return 1;
}

int StageRun::Done()
{
  this->Filter->UpdateProgress(1.0);
  return 1;
}

void StageRun::EmptyOutputs()
{
  for (vtkDataObject* output : this->Outputs)
  {
    if (output)
    {
      output->Initialize();
    }
  }
}

std::vector<int> ownedSubdomains(const ComplexPiece& piece, int rank)
{
  std::vector<int> mine;
  for (int s = 0; s < piece.complex.subdomainCount; ++s)
  {
    if (piece.subdomainRank[s] == rank)
    {
      mine.push_back(s);
    }
  }
  return mine;
}

void writeOwnedFaces(const ComplexPiece& piece, int rank, vtkPolyData* output)
{
  std::vector<int> keep = ownedSubdomains(piece, rank);
  if (keep.empty())
  {
    keep.push_back(-1); // an empty list would keep every face
  }
  complexToPolyData(piece, keep, output);
}
} // namespace ptm
