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

class vtkAlgorithm;
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

// True on every rank if any rank's `algorithm` was asked to abort
// (vtkAlgorithm::CheckAbort). The caller then empties its outputs and returns
// success on every rank. VTK's own abort path (AbortOutput, which marks the
// outputs ABORTED) is switched off on every rank: it would be taken on the
// asking rank only, and that rank alone would re-execute for the filter's
// next output port request while the others wait in another collective.
// The request is honoured (AbortExecute is reset); after an abort the
// outputs stay empty until the filter is modified.
bool agreeAnyAborted(vtkMultiProcessController* controller, vtkAlgorithm* algorithm);

// Every rank's triangles, concatenated in rank order, on every rank.
TriangleSurface allGatherSurface(vtkMultiProcessController* controller, const TriangleSurface& local);

// The whole surface on every rank: the local one if every rank holds the
// same surface (bit for bit: the cutter asks every rank's upstream for the
// whole data), else every rank's piece concatenated (an upstream that
// ignores the request and stays distributed).
TriangleSurface wholeSurfaceOnEveryRank(vtkMultiProcessController* controller, const TriangleSurface& local);

// The same for values (say, samples of a size field): the local ones if
// every rank holds the same, else every rank's concatenated in rank order.
std::vector<double> wholeValuesOnEveryRank(vtkMultiProcessController* controller, const std::vector<double>& local);

// Element-wise maximum / sum over ranks of a vector of the same length on every rank.
void allReduceMax(vtkMultiProcessController* controller, std::vector<long long>& values);
void allReduceMin(vtkMultiProcessController* controller, std::vector<long long>& values);
void allReduceSum(vtkMultiProcessController* controller, std::vector<double>& values);

// For every key this rank passes, the smallest value any rank passed with
// the same key, in the order of `keys`. Keys should lie in [0, keyCount)
// (others are settled by the first or last rank, still correctly, but
// unevenly), at most once per rank, and keyCount is the same on every rank. No rank holds a
// vector of all keys: key k is settled by rank k * P / keyCount, to which
// every holder sends its (key, value) and which answers each with the
// minimum (a rendezvous, in two exchanges between pairs of ranks). A rank
// sends 16 bytes per key it holds and gets 8 back, against 8 x keyCount
// twice over for an all-reduce of a dense vector.
std::vector<long long> minimumOverHolders(vtkMultiProcessController* controller, long long keyCount,
  const std::vector<long long>& keys, const std::vector<long long>& values);

// Every rank's values concatenated in rank order; `counts` gets each rank's length.
std::vector<long long> allGatherValues(vtkMultiProcessController* controller,
  const std::vector<long long>& local, std::vector<long long>* counts = nullptr);
std::vector<double> allGatherValues(vtkMultiProcessController* controller,
  const std::vector<double>& local, std::vector<long long>* counts = nullptr);
} // namespace ptm
#endif
