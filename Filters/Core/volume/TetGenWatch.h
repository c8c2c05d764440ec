#ifndef PTM_TETGEN_WATCH_H
#define PTM_TETGEN_WATCH_H
// Waiting for a TetGen process (TetGenProcess.h) to send its result, and
// stopping it early where it stalls in boundary recovery.
//
// Why. TetGen 1.5 can loop for ever recovering the segments of a surface it
// meshes at once in another input order (session 41: a gmsh ball of 5e5
// tetrahedra cut into 64 subdomains, subdomain 17 of 1,191 points: the
// canonical order never left "Recovering segments", the reversed one meshed
// it in 0.12 s). Until then such a run went on to its processor-time limit
// (2 s + a share per tetrahedron and triangle: 3.2 s there), which made that
// subdomain's rank take 3.2 s where the other 63 took 0.2-0.4 s.
//
// How. TetGen prints its phases as it goes (TetGenProcess.h, `phases`):
// "Recovering boundaries..." when boundary recovery starts and "Removing
// exterior tetrahedra ..." when it is over. On 229 runs that recovered,
// measured with tetgen -V on their dumped input (113 subdomains and
// sliver-repair cavities of that ball; 116 subdomains of fandisk, OCCT's
// Pump_TopCover, FreeCAD's CAP_50SGV, MCAD's gear, the triple torus and
// Cura's nozzle at K = 16), recovery took at most 0.56 x the processor time
// of the phases before it (Delaunay and surface mesh). A run whose processor
// time in recovery exceeds RecoveryWatch::factor (10) x what it had used
// when recovery was first seen, and at least floorSeconds (0.5), is taken to
// stall: it is stopped for the caller to try another input order. What it
// had used includes the process's start and the request's reading, so the
// bound is looser still. On that subdomain 17 recovery started at 0.09 s, so
// the run stops after about 1 s, not 4. The processor time is the process's
// own (/proc/PID/stat), so an oversubscribed machine, where a run is merely
// slow, does not stop it. The last input order a caller tries runs without
// the watch, to its limit, so a slow recovery the watch misjudges costs
// time, never the mesh.
#include "TetGenProcess.h"

#include <cstdio>

namespace ptm
{
// When a run counts as stalled in boundary recovery.
struct RecoveryWatch
{
  bool active = false;       // false: no watch, only the wall-clock limit
  double factor = 10.0;      // x the processor time used when recovery was first seen
  double floorSeconds = 0.5; // never less than this in recovery
};

// Where a run is, from the phase lines TetGen has written to `phases` so
// far (a temporary file its process writes its standard output to,
// unbuffered, so a run the kernel stops keeps every line; read with pread,
// so the offset stays): TetGen 1.5 prints "Recovering boundaries..." when
// boundary recovery starts and "Removing exterior tetrahedra ..." right
// after it, then "Refining mesh...". Null: BeforeRecovery.
enum class TetGenPhase
{
  BeforeRecovery,
  InRecovery,
  AfterRecovery
};
TetGenPhase tetgenPhase(std::FILE* phases);

enum class TetGenWait
{
  Ready,             // the result (or the end of the stream) is there to read
  WallLimit,         // wallSeconds passed first
  StalledInRecovery  // the watch stopped waiting (the process still runs)
};

// Waits for data on process.fd. `phases` is the file TetGen's phase lines go
// to (read with pread, so the process's writes are not disturbed; null: no
// watch). The caller kills and reaps the process on anything but Ready.
TetGenWait waitForTetGen(const TetGenProcess& process, std::FILE* phases, double wallSeconds,
  const RecoveryWatch& watch);
} // namespace ptm
#endif
