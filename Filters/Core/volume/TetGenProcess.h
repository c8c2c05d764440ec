#ifndef PTM_TETGEN_PROCESS_H
#define PTM_TETGEN_PROCESS_H
// The process every TetGen run happens in (TetGenSubdomainMesher.cpp says
// why TetGen never runs in the caller's process).
//
// Why a process of its own, started from a small program, and not a fork of
// the caller.
//  * Forking an MPI rank is unsafe on the clusters pvserver runs on. Open
//    MPI's documentation asks MPI programs not to fork (for UCX and
//    Libfabric); ibv_fork_init(3) says why on InfiniBand: after a fork the
//    rank's writes to memory registered for RDMA land in copies the network
//    card does not see, unless the child execs at once. And in the child of
//    a process with threads (PMIx's, ParaView's) a lock may stay held that
//    no thread will release. posix_spawn execs at once, with nothing of the
//    rank.
//  * A fork starts with every resident page of the rank mapped, shared but
//    counted in the child's resident size: on the 9.8 M ball at K = 2 on 2
//    ranks the child's peak, 969 / 939 MB, was each rank's peak by
//    /usr/bin/time, and 170 / 132 MB of it were the rank's pages (session
//    36, VmRSS sampled every 0.25 s). `ptm-tetgen` holds only libtet and the
//    request: 843 / 844 MB. The memory the rank and its TetGen process take
//    together is not smaller: 1322 / 1246 MB at that peak, about 40 MB more
//    than with the fork, whose shared pages counted once.
//  * A fork is slow: it copies the page tables of a rank of 300-500 MB, and
//    the rank then copies every page it writes while the child lives. The
//    volume meshing stage of whole tetmesh.py runs (alternated, session 36):
//    CGAL's anchor at K = 64 on 2 ranks 4.8-4.9 s -> 1.8 s, fandisk at
//    K = 16 3.2-3.3 s -> 2.0 s, CGAL's rotor at K = 64 on 8 ranks (on 2
//    cores) 6.6-7.0 s -> 2.6-2.8 s; the same meshes.
//
// Contract.
//  * startTetGenProcess starts `ptm-tetgen` (tetgenWorkerPath) with one
//    end of a socket pair and hands it the request: `in`, `addin`, the
//    switches and the processor-time limit. Carried are the fields the
//    mesher fills (points, sizes at the points, facets of polygons, holes,
//    tetrahedra, faces, edges, and addin's points); a request with any other
//    list set (markers, regions, attributes) is refused before a process
//    starts. Where no worker is found, or it cannot be started, the caller is
//    forked instead and the child runs the same runTetGenChild.
//  * Either way the process writes exactly what runTetGenChild writes
//    (TetGenStream.h: a header, then the points and the tetrahedra) to the
//    returned descriptor, and TetGen's phase lines to `phases` (if given),
//    then ends. The caller reads, reaps the process and closes the
//    descriptor. The same request gives the same mesh bit for bit in either
//    kind of process (TetGenProcess tests in TetGenSubdomainMesherTest.cpp).
#include <cstdio>
#include <string>
#include <sys/types.h>

class tetgenio; // tetgen.h: only pointers here, so the filters include this header without libtet's

namespace ptm
{
// What the TetGen process is asked to do.
struct TetGenRequest
{
  tetgenio* in = nullptr;     // the surface (-p) or mesh (-r)
  tetgenio* addin = nullptr;  // points to insert (-i), or null
  std::string switches;       // TetGen's command line, without the dash
  double cpuSeconds = 0;      // its processor-time limit (RLIMIT_CPU)
  std::FILE* phases = nullptr; // where its phase lines go, or null
};

// A started TetGen process.
struct TetGenProcess
{
  pid_t pid = -1;
  int fd = -1; // its result arrives here
};

// The worker program to run: $PTM_TETGEN_WORKER if set (empty: always fork),
// else `ptm-tetgen` beside the library this code is in (the plugin), else
// where the build made it; empty if none of these is an executable file.
std::string tetgenWorkerPath();

// Why TetGen will run in forks of this process rather than in ptm-tetgen,
// for a warning: the program is not where it is looked for, or
// $PTM_TETGEN_WORKER names no program. Empty if it will run in ptm-tetgen,
// or if PTM_TETGEN_WORKER is set empty (a fork asked for).
std::string tetgenForkReason();

// Starts the process and hands it the request. False, with `error`, if no
// process could be started or the request carries fields the worker does
// not (see above).
bool startTetGenProcess(const TetGenRequest& request, TetGenProcess& process, std::string& error);

// The body of the TetGen process: meshes request.in under the limit,
// writes the result to `fd`, and ends the process (ptm-tetgen's main and
// the forked child both end here).
[[noreturn]] void runTetGenChild(const TetGenRequest& request, int fd);

// The request on the wire: what startTetGenProcess sends the worker. False
// if the other end closed first.
bool writeTetGenRequest(int fd, const TetGenRequest& request);

// ptm-tetgen's side: reads a request writeTetGenRequest wrote to `fd` into
// `in` and `addin` (used if request.addin is set); false if it is cut short
// or malformed.
bool readTetGenRequest(int fd, tetgenio& in, tetgenio& addin, TetGenRequest& request);
} // namespace ptm
#endif
