#ifndef PTM_RANK_COLLECTIVES_H
#define PTM_RANK_COLLECTIVES_H
// The collective steps every distributed filter of the plugin shares: all
// ranks agree to fail or abort together (never one rank alone, which would
// deadlock the others in their next collective), and surfaces are gathered.
// Every function here is collective: all ranks must call it in the same
// order. A null controller or a single process means serial.
#include "TriangleSurface.h"

#include <string>
#include <vector>

class vtkMultiProcessController;

namespace ptm
{
int rankOf(vtkMultiProcessController* controller);
int rankCount(vtkMultiProcessController* controller);

// True on every rank if every rank passed true. When some rank failed, every
// rank gets in `message` the messages of the failing ranks ("rank r: ...").
bool agreeAllSucceeded(
  vtkMultiProcessController* controller, bool localOk, const std::string& localError,
  std::string& message);

// True on every rank if any rank asks to abort.
bool agreeAnyAborted(vtkMultiProcessController* controller, bool localAbort);

// Every rank's triangles, concatenated in rank order, on every rank.
TriangleSurface allGatherSurface(vtkMultiProcessController* controller, const TriangleSurface& local);

// Element-wise maximum / sum over ranks of a vector of the same length on every rank.
void allReduceMax(vtkMultiProcessController* controller, std::vector<long long>& values);
void allReduceMin(vtkMultiProcessController* controller, std::vector<long long>& values);
void allReduceSum(vtkMultiProcessController* controller, std::vector<double>& values);

// Every rank's values concatenated in rank order; `counts` gets each rank's length.
std::vector<long long> allGatherValues(vtkMultiProcessController* controller,
  const std::vector<long long>& local, std::vector<long long>* counts = nullptr);
std::vector<double> allGatherValues(vtkMultiProcessController* controller,
  const std::vector<double>& local, std::vector<long long>* counts = nullptr);
} // namespace ptm
#endif
