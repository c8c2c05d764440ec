#ifndef PTM_PHASE_LOG_H
#define PTM_PHASE_LOG_H
// What each rank does between collectives, for the scaling benchmark
// (Testing/Benchmarks/scaling.py). With the environment variable
// PTM_PHASE_LOG=DIR, every process writes DIR/rank-R.tsv: one line per
// collective call of RankCollectives and one where a phase starts (all
// ranks make the same calls in the same order, so line i of every file ends
// the same stretch of work), with the phase running, the process's
// processor seconds so far, and the bytes this rank put into the call; a
// last line when the process ends (writing and teardown). The predicted wall time on P cores is then the sum over the
// lines of the slowest rank's processor time since the line before, plus a
// model of the communication. Without the variable nothing is written.
#include <cstddef>

class vtkMultiProcessController;

namespace ptm::phases
{
// The phase now starting (a filter's RequestData calls this first); the
// phase before ends with a line of kind "phase".
void setPhase(vtkMultiProcessController* controller, const char* name);
// One collective call of kind `kind` ("allgather", "allreduce", "exchange"
// between pairs of ranks, "agree", "abort") into which this rank puts
// `bytes`.
void collective(vtkMultiProcessController* controller, const char* kind, std::size_t bytes);
} // namespace ptm::phases
#endif
