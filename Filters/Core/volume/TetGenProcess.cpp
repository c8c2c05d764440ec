#include "TetGenProcess.h"

#include "LibraryFolder.h"
#include "TetGenStream.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

extern char** environ;

namespace ptm
{
namespace
{
/// @name The request on the wire
/// @{
// A fixed header, then the lists in this order: the switches, the points,
// the sizes at the points, the facets (one int list: per facet its polygon
// count, per polygon its vertex count and vertices), the holes, the
// tetrahedra, the faces, the edges, addin's points. Both ends are this
// library, built once, so the layout is the machine's own.
constexpr char kRequestMagic[8] = { 'P', 'T', 'M', 'T', 'G', 'R', 'Q', '1' };

struct RequestHeader
{
  char magic[8] = {};
  double cpuSeconds = 0;
  std::int64_t switchesLength = 0;
  std::int64_t facetInts = 0;
  std::int32_t firstnumber = 0, points = 0, pointmtrs = 0, facets = 0, holes = 0, corners = 0, tetrahedra = 0,
               trifaces = 0, edges = 0;
  std::int32_t insertedPoints = -1; // -1: no addin
};

// The first list of `in` the wire does not carry, or null.
const char* uncarriedList(const tetgenio& in)
{
  if (in.pointattributelist || in.numberofpointattributes > 0 || in.pointmarkerlist || in.pointparamlist)
  {
    return "point attributes, markers or parameters";
  }
  if (in.tetrahedronattributelist || in.tetrahedronvolumelist || in.neighborlist)
  {
    return "tetrahedron attributes, volumes or neighbours";
  }
  if (in.facetmarkerlist || in.regionlist || in.facetconstraintlist || in.segmentconstraintlist)
  {
    return "facet markers, regions or constraints";
  }
  if (in.trifacemarkerlist || in.o2facelist || in.adjtetlist || in.edgemarkerlist || in.o2edgelist ||
    in.edgeadjtetlist)
  {
    return "face or edge markers or adjacencies";
  }
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    if (in.facetlist[f].numberofholes > 0)
    {
      return "holes in facets";
    }
  }
  return nullptr;
}

std::vector<int> facetInts(const tetgenio& in)
{
  std::vector<int> out;
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    const tetgenio::facet& facet = in.facetlist[f];
    out.push_back(facet.numberofpolygons);
    for (int p = 0; p < facet.numberofpolygons; ++p)
    {
      const tetgenio::polygon& polygon = facet.polygonlist[p];
      out.push_back(polygon.numberofvertices);
      out.insert(out.end(), polygon.vertexlist, polygon.vertexlist + polygon.numberofvertices);
    }
  }
  return out;
}

// send() with MSG_NOSIGNAL: a worker that died has closed its end, and a
// write() would raise SIGPIPE, which ends the rank. Not a socket (a file,
// in the tests): write().
bool sendAllBytes(int fd, const void* data, std::size_t bytes)
{
  const char* p = static_cast<const char*>(data);
  return transferAllBytes(bytes, [&](std::size_t done, std::size_t left) {
    const ssize_t sent = ::send(fd, p + done, left, MSG_NOSIGNAL);
    return sent < 0 && errno == ENOTSOCK ? ::write(fd, p + done, left) : sent;
  });
}

template <typename T>
bool sendList(int fd, const T* data, std::size_t count)
{
  return count == 0 || sendAllBytes(fd, data, sizeof(T) * count);
}

// Reads `count` values into a new[] array (tetgenio's destructor frees it
// with delete[]); null for none.
template <typename T>
bool receiveList(int fd, std::size_t count, T*& list)
{
  list = nullptr;
  if (count == 0)
  {
    return true;
  }
  list = new (std::nothrow) T[count];
  return list && readAllBytes(fd, list, sizeof(T) * count);
}

// Every facet and polygon is initialised before its counts are read, so
// that tetgenio's destructor frees a list cut short cleanly.
bool facetsFromInts(const std::vector<int>& ints, int count, tetgenio& in)
{
  in.facetlist = count > 0 ? new tetgenio::facet[static_cast<std::size_t>(count)] : nullptr;
  for (int f = 0; f < count; ++f)
  {
    tetgenio::init(&in.facetlist[f]);
  }
  in.numberoffacets = count;
  std::size_t at = 0;
  const auto next = [&](int& value) {
    if (at >= ints.size() || ints[at] < 0)
    {
      return false;
    }
    value = ints[at++];
    return true;
  };
  for (int f = 0; f < count; ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    int polygons = 0;
    if (!next(polygons))
    {
      return false;
    }
    facet.polygonlist = new tetgenio::polygon[static_cast<std::size_t>(polygons)];
    for (int p = 0; p < polygons; ++p)
    {
      tetgenio::init(&facet.polygonlist[p]);
    }
    facet.numberofpolygons = polygons;
    for (int p = 0; p < polygons; ++p)
    {
      tetgenio::polygon& polygon = facet.polygonlist[p];
      int vertices = 0;
      if (!next(vertices) || ints.size() - at < static_cast<std::size_t>(vertices))
      {
        return false;
      }
      polygon.vertexlist = new int[static_cast<std::size_t>(vertices)];
      std::copy(ints.begin() + static_cast<std::ptrdiff_t>(at),
        ints.begin() + static_cast<std::ptrdiff_t>(at + static_cast<std::size_t>(vertices)), polygon.vertexlist);
      polygon.numberofvertices = vertices;
      at += static_cast<std::size_t>(vertices);
    }
  }
  return at == ints.size();
}
/// @}

/// @name Starting the process
/// @{
bool executable(const std::string& path)
{
  return !path.empty() && ::access(path.c_str(), X_OK) == 0;
}

bool clearCloseOnExec(int fd)
{
  const int flags = ::fcntl(fd, F_GETFD);
  return flags >= 0 && ::fcntl(fd, F_SETFD, flags & ~FD_CLOEXEC) == 0;
}

// Starts `worker` on one end of a socket pair and writes the request to
// the other, which it returns. False if it could not be started (the
// caller then forks); a worker that ends before reading it all is the
// caller's to notice (no result, its wait status).
bool spawnWorker(const std::string& worker, const TetGenRequest& request, TetGenProcess& process)
{
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0)
  {
    return false;
  }
  const int phasesFd = request.phases ? ::fileno(request.phases) : -1;
  std::string socketArg = std::to_string(sockets[1]), phasesArg = std::to_string(phasesFd);
  std::vector<char*> argv = { const_cast<char*>(worker.c_str()), socketArg.data(), phasesArg.data(), nullptr };
  // the worker's signals as a fresh program's: ParaView and MPI may block
  // or ignore some (SIGPIPE, SIGXCPU would then not stop a run)
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &all);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  bool started = clearCloseOnExec(sockets[1]) && (phasesFd < 0 || clearCloseOnExec(phasesFd)) &&
    ::posix_spawn(&process.pid, worker.c_str(), nullptr, &attributes, argv.data(), environ) == 0;
  posix_spawnattr_destroy(&attributes);
  ::close(sockets[1]);
  if (!started)
  {
    ::close(sockets[0]);
    return false;
  }
  process.fd = sockets[0];
  // if the worker ends early the sending fails; the caller then finds no
  // result and reports the worker's wait status
  writeTetGenRequest(process.fd, request);
  return true;
}

bool forkChild(const TetGenRequest& request, TetGenProcess& process, std::string& error)
{
  int fds[2];
  if (::pipe(fds) != 0)
  {
    error = "cannot create a pipe for the TetGen process";
    return false;
  }
  process.pid = ::fork();
  if (process.pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    error = "cannot start a process for TetGen (fork failed)";
    return false;
  }
  if (process.pid == 0)
  {
    ::close(fds[0]);
    runTetGenChild(request, fds[1]);
  }
  ::close(fds[1]);
  process.fd = fds[0];
  return true;
}
/// @}
} // namespace

std::string tetgenWorkerPath()
{
  if (const char* chosen = std::getenv("PTM_TETGEN_WORKER"))
  {
    return executable(chosen) ? std::string(chosen) : std::string();
  }
  for (const std::string& path : { folderOfThisLibrary() + "ptm-tetgen", std::string(PTM_TETGEN_WORKER) })
  {
    if (executable(path))
    {
      return path;
    }
  }
  return "";
}

std::string tetgenForkReason()
{
  if (!tetgenWorkerPath().empty())
  {
    return "";
  }
  const char* chosen = std::getenv("PTM_TETGEN_WORKER");
  if (chosen && !*chosen)
  {
    return "";
  }
  const std::string where = chosen ? "PTM_TETGEN_WORKER names '" + std::string(chosen) + "', which is not an executable program"
                                   : "ptm-tetgen is not beside the plugin (" + folderOfThisLibrary() + ") nor where the build made it";
  return where + ": TetGen runs in forks of this rank, slower with many subdomains (1.2-1.6x on the corpus at K = 16-64) "
                 "and unsafe with InfiniBand; put ptm-tetgen beside the plugin or name it in PTM_TETGEN_WORKER";
}

bool startTetGenProcess(const TetGenRequest& request, TetGenProcess& process, std::string& error)
{
  process = TetGenProcess{};
  const std::string worker = tetgenWorkerPath();
  if (!worker.empty())
  {
    if (const char* list = uncarriedList(*request.in))
    {
      error = std::string("the TetGen request carries ") + list + ", which the TetGen process is not sent";
      return false;
    }
    if (spawnWorker(worker, request, process))
    {
      return true;
    }
  }
  return forkChild(request, process, error);
}

void runTetGenChild(const TetGenRequest& request, int fd)
{
  std::signal(SIGSEGV, SIG_DFL);
  std::signal(SIGABRT, SIG_DFL);
  std::signal(SIGBUS, SIG_DFL);
  std::signal(SIGXCPU, SIG_DFL);
  // SIGXCPU at the soft limit, SIGKILL a second later
  const rlim_t cpu = static_cast<rlim_t>(std::ceil(request.cpuSeconds));
  const rlimit limit{ cpu, cpu + 1 };
  ::setrlimit(RLIMIT_CPU, &limit);
  TetGenChildHeader h;
  try
  {
    tetgenbehavior behaviour;
    std::vector<char> text(request.switches.begin(), request.switches.end());
    text.push_back('\0');
    if (!behaviour.parse_commandline(text.data()))
    {
      h.status = 3;
    }
    else
    {
      if (request.phases && ::dup2(::fileno(request.phases), STDOUT_FILENO) >= 0)
      {
        std::setvbuf(stdout, nullptr, _IONBF, 0);
        behaviour.quiet = 0; // its phase lines only: nothing else changes
      }
      // the mesh goes to the parent from TetGen's pools (TetGenStream.h)
      const bool sent = tetrahedralizeToPipe(behaviour, *request.in, request.addin, fd);
      ::close(fd);
      ::_exit(sent ? 0 : 1);
    }
  }
  catch (int c)
  {
    h.status = 1;
    h.code = c;
  }
  catch (const std::bad_alloc&)
  {
    h.status = 2;
  }
  catch (...)
  {
    h.status = 1;
    h.code = 2;
  }
  // a failure: the header alone
  const bool ok = writeAllBytes(fd, &h, sizeof(h));
  ::close(fd);
  ::_exit(ok ? 0 : 1);
}

bool writeTetGenRequest(int fd, const TetGenRequest& r)
{
  const tetgenio& in = *r.in;
  const std::vector<int> facets = facetInts(in);
  RequestHeader h;
  std::memcpy(h.magic, kRequestMagic, sizeof(h.magic));
  h.cpuSeconds = r.cpuSeconds;
  h.switchesLength = static_cast<std::int64_t>(r.switches.size());
  h.facetInts = static_cast<std::int64_t>(facets.size());
  h.firstnumber = in.firstnumber;
  h.points = in.numberofpoints;
  h.pointmtrs = in.pointmtrlist ? in.numberofpointmtrs : 0;
  h.facets = in.numberoffacets;
  h.holes = in.numberofholes;
  h.corners = in.numberofcorners;
  h.tetrahedra = in.tetrahedronlist ? in.numberoftetrahedra : 0;
  h.trifaces = in.trifacelist ? in.numberoftrifaces : 0;
  h.edges = in.edgelist ? in.numberofedges : 0;
  h.insertedPoints = r.addin ? r.addin->numberofpoints : -1;
  const auto n = [](int count, int width) { return static_cast<std::size_t>(count) * static_cast<std::size_t>(width); };
  return sendAllBytes(fd, &h, sizeof(h)) && sendList(fd, r.switches.data(), r.switches.size()) &&
    sendList(fd, in.pointlist, n(h.points, 3)) && sendList(fd, in.pointmtrlist, n(h.points, h.pointmtrs)) &&
    sendList(fd, facets.data(), facets.size()) && sendList(fd, in.holelist, n(h.holes, 3)) &&
    sendList(fd, in.tetrahedronlist, n(h.tetrahedra, h.corners)) && sendList(fd, in.trifacelist, n(h.trifaces, 3)) &&
    sendList(fd, in.edgelist, n(h.edges, 2)) &&
    (!r.addin || sendList(fd, r.addin->pointlist, n(r.addin->numberofpoints, 3)));
}

bool readTetGenRequest(int fd, tetgenio& in, tetgenio& addin, TetGenRequest& request)
{
  RequestHeader h;
  if (!readAllBytes(fd, &h, sizeof(h)) || std::memcmp(h.magic, kRequestMagic, sizeof(h.magic)) != 0 ||
    h.switchesLength < 0 || h.switchesLength > 4096 || h.facetInts < 0 || h.points < 0 || h.pointmtrs < 0 ||
    h.facets < 0 || h.holes < 0 || h.corners < 0 || h.tetrahedra < 0 || h.trifaces < 0 || h.edges < 0)
  {
    return false;
  }
  request.cpuSeconds = h.cpuSeconds;
  request.switches.assign(static_cast<std::size_t>(h.switchesLength), '\0');
  std::vector<int> facets(static_cast<std::size_t>(h.facetInts));
  const auto n = [](int count, int width) { return static_cast<std::size_t>(count) * static_cast<std::size_t>(width); };
  in.firstnumber = h.firstnumber;
  in.numberofpoints = h.points;
  in.numberofpointmtrs = h.pointmtrs;
  in.numberofholes = h.holes;
  in.numberofcorners = h.corners;
  in.numberoftetrahedra = h.tetrahedra;
  in.numberoftrifaces = h.trifaces;
  in.numberofedges = h.edges;
  const bool read = readAllBytes(fd, request.switches.data(), request.switches.size()) &&
    receiveList(fd, n(h.points, 3), in.pointlist) && receiveList(fd, n(h.points, h.pointmtrs), in.pointmtrlist) &&
    (facets.empty() || readAllBytes(fd, facets.data(), sizeof(int) * facets.size())) &&
    facetsFromInts(facets, h.facets, in) && receiveList(fd, n(h.holes, 3), in.holelist) &&
    receiveList(fd, n(h.tetrahedra, h.corners), in.tetrahedronlist) &&
    receiveList(fd, n(h.trifaces, 3), in.trifacelist) && receiveList(fd, n(h.edges, 2), in.edgelist);
  if (!read)
  {
    return false;
  }
  request.in = &in;
  request.addin = nullptr;
  if (h.insertedPoints >= 0)
  {
    addin.firstnumber = 0;
    addin.numberofpoints = h.insertedPoints;
    if (!receiveList(fd, n(h.insertedPoints, 3), addin.pointlist))
    {
      return false;
    }
    request.addin = &addin;
  }
  return true;
}
} // namespace ptm
