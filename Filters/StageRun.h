#ifndef PTM_STAGE_RUN_H
#define PTM_STAGE_RUN_H
// The skeleton every stage filter's RequestData follows (issue #19), written
// once:
//
//   ptm::StageRun run(this, controller, "SurfaceRelaxer", "relax", { output });
//   if (run.PropertiesRefused(this->PropertyError()))   return run.Failure();
//   if (!run.ReadPiece(input, piece))                   return run.Failure();
//   run.Step(0.2, "Relaxing");
//   ... the core call, setting localError on a failure ...
//   if (run.FailedAnywhere(localError))                 return run.Failure();
//   if (run.AbortedAnywhere())                          return run.Aborted();
//   ... write the rank's owned part (ownedSubdomains) ...
//   return run.Done();
//
// Every step after which a rank can fail or be aborted is agreed across
// ranks (RankCollectives.h), so all ranks leave together: a failure anywhere
// is reported on every rank ("<filter> failed: rank r: ..."), an abort asked
// on any rank empties every rank's outputs, and no rank is left waiting in a
// collective the others never reach. Property values are the same on every
// rank, so they are refused without communicating. The phase name starts
// the filter's stretch of the per-rank phase log (PhaseLog.h).
#include "PolyDataConversion.h"

#include <initializer_list>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkMultiProcessController;
class vtkPolyData;

namespace ptm
{
class StageRun
{
public:
  StageRun(vtkAlgorithm* filter, vtkMultiProcessController* controller, std::string filterName,
    const char* phase, std::initializer_list<vtkDataObject*> outputs);

  /// @name Agreement: each returns the same answer on every rank
  /// @{
  // True (after reporting it) if `propertyError` is not empty.
  bool PropertiesRefused(const std::string& propertyError);
  // Reads this rank's piece of the labeled complex; false on every rank if
  // any rank's input is not one (the missing array named).
  bool ReadPiece(vtkPolyData* input, ComplexPiece& piece);
  // True if any rank's `localError` is not empty; every rank then reports
  // the failing ranks' messages.
  bool FailedAnywhere(const std::string& localError);
  // True if any rank was asked to abort.
  bool AbortedAnywhere();
  /// @}

  /// @name Progress and the way out
  /// @{
  void Step(double progress, const char* text);
  int Failure(); // outputs emptied; RequestData's 0
  int Aborted(); // outputs emptied; RequestData's 1 (an abort is not an error)
  int Done();    // progress 1; RequestData's 1
  /// @}

  int Rank() const { return this->RankId; }
  vtkMultiProcessController* Controller() const { return this->Communicator; }

private:
  void EmptyOutputs();

  vtkAlgorithm* Filter;
  vtkMultiProcessController* Communicator;
  std::string FilterName;
  std::vector<vtkDataObject*> Outputs;
  int RankId = 0;
};

// The subdomains `rank` owns (piece.subdomainRank), in increasing order.
std::vector<int> ownedSubdomains(const ComplexPiece& piece, int rank);

// Writes the faces of the subdomains `rank` owns (none if it owns none).
void writeOwnedFaces(const ComplexPiece& piece, int rank, vtkPolyData* output);
} // namespace ptm
#endif
