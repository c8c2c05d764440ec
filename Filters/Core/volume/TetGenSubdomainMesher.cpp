#include "TetGenSubdomainMesher.h"

#include "BoundarySliverRepair.h"
#include "Fnv1a.h"
#include "SelfIntersectionCheck.h"
#include "SizeFunction.h"
#include "TetGenProcess.h"
#include "TetGenStream.h"
#include "TetGenWatch.h"
#include "TetrahedronQuality.h"

#include <tetgen.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <csignal>
#include <cstdio>
#include <poll.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <iterator>
#include <map>
#include <memory>
#include <numeric>
#include <new>
#include <queue>
#include <set>
#include <sstream>
#include <vector>

namespace ptm
{
namespace
{
// Connected components of the triangles through shared edges.
std::vector<std::vector<Index>> shells(const TriangleSurface& s)
{
  std::map<std::pair<Index, Index>, std::vector<Index>> byEdge;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      byEdge[{ std::min(a, b), std::max(a, b) }].push_back(static_cast<Index>(t));
    }
  }
  std::vector<int> shell(s.triangles.size(), -1);
  std::vector<std::vector<Index>> out;
  for (std::size_t seed = 0; seed < s.triangles.size(); ++seed)
  {
    if (shell[seed] >= 0)
    {
      continue;
    }
    out.emplace_back();
    std::queue<Index> q;
    q.push(static_cast<Index>(seed));
    shell[seed] = static_cast<int>(out.size() - 1);
    while (!q.empty())
    {
      const Index t = q.front();
      q.pop();
      out.back().push_back(t);
      for (int k = 0; k < 3; ++k)
      {
        const Index a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
        for (Index u : byEdge[{ std::min(a, b), std::max(a, b) }])
        {
          if (shell[u] < 0)
          {
            shell[u] = shell[seed];
            q.push(u);
          }
        }
      }
    }
  }
  return out;
}

// A point strictly inside a cavity bounded by `triangles` (oriented into the
// cavity): from the centroid of the largest triangle along its normal, half
// way to the nearest other triangle hit.
bool holePoint(const TriangleSurface& s, const std::vector<Index>& triangles, Vec3& hole)
{
  Index best = triangles.front();
  double bestArea = -1;
  for (Index t : triangles)
  {
    const auto& tri = s.triangles[t];
    const double a = norm(cross(s.points[tri[1]] - s.points[tri[0]], s.points[tri[2]] - s.points[tri[0]]));
    if (a > bestArea)
    {
      bestArea = a;
      best = t;
    }
  }
  const auto& tri = s.triangles[best];
  const Vec3 o = (1.0 / 3.0) * (s.points[tri[0]] + s.points[tri[1]] + s.points[tri[2]]);
  const Vec3 d = normalized(cross(s.points[tri[1]] - s.points[tri[0]], s.points[tri[2]] - s.points[tri[0]]));
  double nearest = std::numeric_limits<double>::infinity();
  for (Index t : triangles)
  {
    if (t == best)
    {
      continue;
    }
    // Moeller-Trumbore
    const auto& u = s.triangles[t];
    const Vec3 e1 = s.points[u[1]] - s.points[u[0]], e2 = s.points[u[2]] - s.points[u[0]];
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::fabs(det) < 1e-300)
    {
      continue;
    }
    const Vec3 tv = o - s.points[u[0]];
    const double bu = dot(tv, p) / det;
    const Vec3 q = cross(tv, e1);
    const double bv = dot(d, q) / det;
    const double dist = dot(e2, q) / det;
    if (bu >= 0 && bv >= 0 && bu + bv <= 1 && dist > 0)
    {
      nearest = std::min(nearest, dist);
    }
  }
  if (!std::isfinite(nearest))
  {
    return false;
  }
  hole = o + (0.5 * nearest) * d;
  return true;
}

bool validExtraSwitches(const std::string& s)
{
  for (char ch : s)
  {
    if (!(std::strchr("OSTV", ch) || std::isdigit(static_cast<unsigned char>(ch)) || ch == '.' ||
          ch == 'e' || ch == '-' || ch == '/'))
    {
      return false;
    }
  }
  return true;
}
// The time TetGen may take on one surface: each run's limits, and the
// processor time all its runs together may use (TetMeshingOptions::
// processorBudgetSeconds), with what they have used so far.
struct TimeLimits
{
  double cpu = 0, wall = 0; // seconds per TetGen run
  double budget = 0;        // processor seconds for all runs
  double spent = 0;         // used so far: the TetGen processes' user and system time
  int stopped = 0;          // runs stopped at a limit
  // the last run stopped had recovered the boundary (TetGen's phases after
  // it are refinement and optimisation): another input order, or the
  // two-run fall-back, would be as slow (see runTetGenIsolated)
  bool stoppedAfterRecovery = false;

  // The processor-time limit of the next run, 0 if the budget cannot pay
  // for one (the kernel's limit counts whole seconds).
  double nextCpu() const
  {
    const double left = std::min(cpu, budget - spent);
    return left >= kShortestRunSeconds ? left : 0.0;
  }
};

constexpr const char* kBudgetSpent = "no TetGen run was started: the processor-time budget is spent";

// Waits for the TetGen process `pid` to end; its wait status, and the
// processor time (user and system) it used.
double reapChild(pid_t pid, int& waitStatus)
{
  rusage usage{};
  while (::wait4(pid, &waitStatus, 0, &usage) < 0 && errno == EINTR)
  {
  }
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Runs TetGen in a child process: libtet 1.5 frees its memory in
// terminatetetgen() and again in the destructor while the int it throws
// unwinds, so every TetGen failure would otherwise crash the whole
// (MPI, ParaView) process. The process (TetGenProcess.h: ptm-tetgen, or a
// fork where it is missing) sends the mesh back through a socket or pipe. On
// some inputs TetGen 1.5 loops for ever in boundary recovery (switch Y):
// a child that has used more than cpuSeconds of processor time is stopped by
// the kernel (RLIMIT_CPU, so a loaded or oversubscribed machine does not
// stop a run that is merely slow), one still running after wallSeconds is
// killed, and with an active `watch` one that stalls in boundary recovery
// is killed early (TetGenWatch.h); all three set timedOut, and the first
// two count in limits.stopped (runs stopped at the limit).
bool runTetGenIsolated(tetgenio& in, const std::string& switches, TimeLimits& limits,
  std::vector<double>& points, std::vector<int>& tets, int& status, int& code,
  bool& timedOut, std::string& error, tetgenio* addin = nullptr, const RecoveryWatch& watch = {})
{
  timedOut = false;
  limits.stoppedAfterRecovery = false;
  const double cpuSeconds = limits.nextCpu(), wallSeconds = limits.wall;
  if (cpuSeconds <= 0)
  {
    error = kBudgetSpent;
    status = 1;
    code = 0;
    return false;
  }
  // closed when the run ends, whichever way
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> phases(std::tmpfile(), &std::fclose);
  TetGenProcess process;
  if (!startTetGenProcess({ &in, addin, switches, cpuSeconds, phases.get() }, process, error))
  {
    return false;
  }
  const TetGenWait waited = waitForTetGen(process, phases.get(), wallSeconds, watch);
  if (waited != TetGenWait::Ready)
  {
    ::kill(process.pid, SIGKILL);
    ::close(process.fd);
    int ignored = 0;
    const double used = reapChild(process.pid, ignored);
    limits.spent += used;
    limits.stopped += waited == TetGenWait::WallLimit ? 1 : 0;
    limits.stoppedAfterRecovery = tetgenPhase(phases.get()) == TetGenPhase::AfterRecovery;
    std::ostringstream msg;
    if (waited == TetGenWait::StalledInRecovery)
    {
      msg.precision(3);
      msg << "TetGen stalled recovering the boundary (" << used
          << " s of processor time, most of it in boundary recovery; TetGenWatch.h) and was stopped";
    }
    else
    {
      msg << "TetGen did not finish within " << wallSeconds
          << " s and was stopped (TetGen 1.5 can loop for ever recovering the boundary of "
             "nearly degenerate input, or refine for very long next to nearly flat triangles)";
    }
    error = msg.str();
    timedOut = true;
    status = 1;
    code = 0;
    return false;
  }
  TetGenChildHeader h;
  bool received = readAllBytes(process.fd, &h, sizeof(h));
  if (received && h.status == 0)
  {
    points.resize(3 * static_cast<std::size_t>(h.points));
    tets.resize(4 * static_cast<std::size_t>(h.tets));
    received = readAllBytes(process.fd, points.data(), sizeof(double) * points.size()) &&
      readAllBytes(process.fd, tets.data(), sizeof(int) * tets.size());
  }
  ::close(process.fd);
  int waitStatus = 0;
  limits.spent += reapChild(process.pid, waitStatus);
  if (!received)
  {
    if (WIFSIGNALED(waitStatus) && WTERMSIG(waitStatus) == SIGXCPU)
    {
      ++limits.stopped;
      limits.stoppedAfterRecovery = tetgenPhase(phases.get()) == TetGenPhase::AfterRecovery;
      std::ostringstream msg;
      msg << "TetGen used more than " << std::ceil(cpuSeconds) << " s of processor time and was stopped "
          << (limits.stoppedAfterRecovery
                 ? "refining the mesh, after recovering the boundary (TetGen 1.5 can refine for very long next "
                   "to nearly flat triangles)"
                 : "(TetGen 1.5 can loop for ever recovering the boundary of nearly degenerate input)");
      error = msg.str();
      timedOut = true;
    }
    else if (WIFSIGNALED(waitStatus))
    {
      error = "TetGen crashed (signal " + std::to_string(WTERMSIG(waitStatus)) +
        ": an internal assertion, or its clean-up after an error, a defect of libtet 1.5), so "
        "its error code is lost; the usual causes are a very small input feature or two very "
        "close facets";
    }
    else
    {
      error = "the TetGen process ended without sending a mesh";
    }
    status = 1;
    code = 0;
    return false;
  }
  status = h.status;
  code = h.code;
  return true;
}

// TetGen's added points (-i): TetMeshingOptions::insidePoints.
void fillInsidePoints(const std::vector<Vec3>& points, tetgenio& addin)
{
  addin.firstnumber = 0;
  addin.numberofpoints = static_cast<int>(points.size());
  addin.pointlist = points.empty() ? nullptr : new REAL[3 * points.size()];
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    std::copy(points[i].begin(), points[i].end(), &addin.pointlist[3 * i]);
  }
}

// Why TetGen must not be given this surface with these options, before
// anything is run; empty if it may. Sets meanEdge, the mean length of the
// triangles' edges.
std::string inputError(const TriangleSurface& s, const TetMeshingOptions& options, double& meanEdge)
{
  const std::size_t n = s.points.size();
  if (s.triangles.size() < 4 || n < 4)
  {
    return "the surface has fewer than 4 triangles or points";
  }
  if (!(options.radiusEdgeRatio > 1.0) || !(options.maximumVolume >= 0) ||
    !(options.minimumDihedralAngle >= 0 && options.minimumDihedralAngle < 70) ||
    !(options.timeLimitSeconds >= 0) || !(options.processorBudgetSeconds >= 0) || options.inputOrders < 1 || options.inputOrders > kInputOrders)
  {
    return "invalid options: the radius-edge ratio must exceed 1, the maximum volume and the "
           "time limit and budget must not be negative, the minimum dihedral angle must lie in [0, 70) "
           "degrees, the input orders in [1, " + std::to_string(kInputOrders) + "]";
  }
  if (!options.pointSizes.empty() &&
    (options.pointSizes.size() != n ||
      !std::all_of(options.pointSizes.begin(), options.pointSizes.end(),
        [](double h) { return h > 0 && std::isfinite(h); })))
  {
    return "invalid options: the point sizes must be one positive, finite size per surface point";
  }
  if (!options.splittableTriangles.empty() && options.splittableTriangles.size() != s.triangles.size())
  {
    return "invalid options: the splittable triangles must be marked one per surface triangle";
  }
  if (!validExtraSwitches(options.extraSwitches))
  {
    return "extra TetGen switches '" + options.extraSwitches +
      "' refused: only O, S, T and V (with numbers) are allowed, since other switches could "
      "add points on the subdomain surface, change the numbering or skip meshing";
  }
  for (const auto& p : s.points)
  {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "a surface point has a NaN or infinite coordinate";
    }
  }
  double edgeSum = 0;
  for (const auto& t : s.triangles)
  {
    // every index checked before any point is read
    if (std::any_of(t.begin(), t.end(), [n](Index i) { return i < 0 || i >= static_cast<Index>(n); }))
    {
      return "a triangle refers to a point that does not exist";
    }
    for (int k = 0; k < 3; ++k)
    {
      edgeSum += norm(s.points[t[(k + 1) % 3]] - s.points[t[k]]);
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
      !(norm(cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]])) > 0))
    {
      return "the surface has a degenerate (zero-area) triangle";
    }
  }
  meanEdge = edgeSum / (3.0 * s.triangles.size());
  return {};
}

// TetGen's most common failure, found first with exact predicates and named
// precisely; empty if the surface does not intersect itself.
std::string selfIntersectionError(const TriangleSurface& s)
{
  const SelfIntersectionReport crossing = checkSelfIntersection(s);
  if (crossing.checked && crossing.intersects)
  {
    const Vec3& near = s.points[s.triangles[crossing.firstTriangle][0]];
    std::ostringstream msg;
    msg << "the surface intersects itself: its triangles " << crossing.firstTriangle << " and "
        << crossing.secondTriangle << (crossing.folds ? " fold onto each other at their shared edge" : " cross")
        << " near (" << near[0] << ", " << near[1] << ", " << near[2] << "); "
        << (crossing.folds ? "TetGen would fill the fold with a flat tetrahedron" : "TetGen cannot mesh it")
        << " (unless the input itself crosses, the cut made this: "
        << "another number of subdomains or the other strategy cuts it differently)";
    return msg.str();
  }
  return {};
}

// A point inside every cavity (a shell enclosing negative volume), for
// TetGen's hole list; false if one cannot be found.
bool cavityHoles(const TriangleSurface& s, std::vector<Vec3>& holes)
{
  for (const auto& shell : shells(s))
  {
    if (volumeAbout(s.points[s.triangles[shell.front()][0]], s.points, s.triangles, shell) < 0)
    {
      Vec3 hole;
      if (!holePoint(s, shell, hole))
      {
        return false;
      }
      holes.push_back(hole);
    }
  }
  return true;
}

// TetGen's switches: `mode` p meshes the surface (a PLC), r refines a mesh
// given as tetrahedra (recoverThenRefine); Y keeps the surface either way.
std::string tetgenSwitches(const TetMeshingOptions& options, double volume, char mode = 'p')
{
  std::ostringstream switches;
  switches.precision(17);
  switches << mode << "YzQ" << (options.pointSizes.empty() ? "" : "m") << (options.insidePoints.empty() ? "" : "i");
  if (options.qualityRefinement)
  {
    switches << "q" << options.radiusEdgeRatio;
    if (options.minimumDihedralAngle > 0)
    {
      switches << "/" << options.minimumDihedralAngle;
    }
  }
  switches << "a" << volume << options.extraSwitches;
  return switches.str();
}

// Limits: TetGen needs about 5 microseconds of processor time per
// tetrahedron here (190,000 per second); a run gets 2 s plus 30 us per
// expected tetrahedron (the volume estimate plus 4 per surface triangle),
// six times that, plus 0.4 ms per surface triangle, and the wall clock the
// old generous 60 s plus 10 us per tetrahedron plus ten times the processor
// limit, which only matters when the machine is swapping (a limit given in
// the options is processor time too: with 64 ranks on 2 cores a run gets a
// 32nd of a core, so the wall clock must not stop it). The term per triangle is for slabs much thinner than
// the size: under -Y TetGen's quality refinement makes slow progress there.
// OCCT's MODERN_Table_1 at K = 16 (parallel planes), subdomain 11 (20,590
// triangles, a slab 0.027 x the size thick) takes 11.7 s of refinement for
// 30,564 tetrahedra (380 us each), and the 4.5 s the tetrahedra alone gave
// stopped it in every input order and fall-back: the run failed.
TimeLimits timeLimits(const TriangleSurface& s, const TetMeshingOptions& options, double volume)
{
  const double expectedVolume = enclosedVolume(s);
  const double expectedTets = estimateTetMesh(std::fabs(expectedVolume), volume).tetrahedra +
    4.0 * static_cast<double>(s.triangles.size());
  TimeLimits limits;
  limits.cpu = options.timeLimitSeconds > 0
    ? options.timeLimitSeconds
    : 2.0 + 3e-5 * expectedTets + 4e-4 * static_cast<double>(s.triangles.size());
  limits.wall = 60.0 + 10.0 * limits.cpu + 1e-5 * expectedTets;
  limits.budget = options.processorBudgetSeconds > 0 ? options.processorBudgetSeconds
                                                     : kBudgetInRunLimits * limits.cpu;
  return limits;
}

// Why the runs gave no mesh when one was stopped at its time limit: the
// runs, the budget, the shape of the surface, and what to do.
std::string stoppedRunsError(
  const TriangleSurface& s, const TimeLimits& limits, int attempts, const std::string& last)
{
  const std::size_t flat = trianglesWithAngleUnder(s, 10.0 * kPi / 180.0);
  std::ostringstream msg;
  msg.precision(3);
  msg << "TetGen found no mesh " << (limits.nextCpu() <= 0 ? "within the processor-time budget" : "in the time")
      << " of this surface (" << attempts << " runs, " << limits.stopped << " stopped at the limit of "
      << std::ceil(limits.cpu) << " s per run, " << limits.spent << " s used of a budget of " << limits.budget
      << " s; the last: " << last << "). "
      << 100.0 * static_cast<double>(flat) / static_cast<double>(s.triangles.size())
      << " % of its triangles have an angle under 10 degrees, and TetGen 1.5 can take very long next to such "
         "triangles: remesh the input (--remesh), use a larger size or fewer subdomains, or raise the limit per "
         "run (TetGenTimeLimit, --tetgen-time-limit)";
  return msg.str();
}

// A permutation of 0..n-1 by a xorshift generator from `seed`.
void shuffle(std::vector<Index>& order, std::uint64_t seed)
{
  std::uint64_t state = seed;
  for (std::size_t i = order.size(); i > 1; --i)
  {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    std::swap(order[i - 1], order[state % i]);
  }
}

// The order in which attempt 0..kInputOrders-1 gives TetGen the n points
// and the m triangles: their own; the points reversed; the points shuffled;
// then both shuffled, with a fixed seed per attempt.
void inputOrder(std::size_t n, std::size_t m, int attempt, std::vector<Index>& points, std::vector<Index>& facets)
{
  for (std::size_t i = 0; i < n; ++i)
  {
    points[i] = static_cast<Index>(attempt == 1 ? n - 1 - i : i);
  }
  facets.resize(m);
  std::iota(facets.begin(), facets.end(), Index{ 0 });
  if (attempt >= 2)
  {
    shuffle(points, 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(attempt - 2));
  }
  if (attempt >= 3)
  {
    shuffle(facets, 0xD1B54A32D192ED03ull + static_cast<std::uint64_t>(attempt));
  }
}

// What the TetGen runs of one surface gave: the mesh of the last run in its
// input order, or why it failed.
struct TetGenRuns
{
  std::vector<double> points;
  std::vector<int> tets;
  std::vector<Index> order; // input position -> surface point
  std::string failure;
  int status = 0, code = 0;
  int attempts = 0;
  int lastOrder = 0;     // inputOrder's attempt number of the last run
  std::string tolerance; // TetGen's -T switch if the default merged points
};

// TetGen 1.5 sometimes aborts on an assertion (insphere_s: oriB != 0,
// finddirection: nonconvex, addsteiner4recoversegment) or loops for ever in
// boundary recovery for an input it meshes when the points come in another
// order. So a crash, an internal error or a run over the time limit is
// retried with the points reversed, then shuffled, then with the facets
// shuffled too (fixed seeds): still the same mesh for the same input on any
// rank. The facet order matters as much: OCCT's Top at K = 16 (parallel
// planes), subdomain 4 of 3,851 points, crashed with -pY in the first three
// orders; with Debian's tetgen it meshed in 3 of 10 random point orders, 7
// of 10 facet orders and 10 of 12 with both shuffled. Six more shuffled
// orders follow where none stalled: OCCT's fuse.brep at K = 48 (parallel
// planes), subdomain 30 of 6,062 points, crashed in the first six
// (addsteiner4recoversegment) and meshed in the seventh (Debian's tetgen
// -pY: 5 of 16 random orders), which made the run succeed. A stall costs
// the whole time limit: OCCT's mal_vis.brep at K = 48 stalled in all twelve
// orders on one subdomain (the run failed after 7 min 20 s of processor
// time on 2 ranks; with six orders after a stall, 4 min 26 s), so after a
// stall the first six are all.
TetGenRuns runInOrders(const TriangleSurface& s, const TetMeshingOptions& options, const std::vector<Vec3>& holes,
  const std::string& switches, TimeLimits& limits, int firstOrder)
{
  const std::size_t n = s.points.size();
  TetGenRuns runs;
  runs.order.resize(n);
  bool meshed = false, stalled = false;
  std::vector<Index> facets;
  for (int attempt = firstOrder; attempt < options.inputOrders && !meshed; ++attempt)
  {
    if (limits.nextCpu() <= 0)
    {
      // the last run's failure stays the one reported
      runs.failure = runs.failure.empty() ? kBudgetSpent : runs.failure;
      break;
    }
    inputOrder(n, s.triangles.size(), attempt, runs.order, facets);
    std::vector<int> position(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      position[runs.order[i]] = static_cast<int>(i);
    }
    tetgenio in;
    fillTetGenInput(s, runs.order, position, facets, holes, options.pointSizes, in);
    tetgenio addin;
    fillInsidePoints(options.insidePoints, addin);
    runs.points.clear();
    runs.tets.clear();
    runs.failure.clear();
    runs.status = runs.code = 0;
    bool timedOut = false;
    // a stall in boundary recovery is cut short (TetGenWatch.h) but in the
    // last order this loop may try, which runs to the limit as before
    RecoveryWatch watch;
    watch.active = attempt + 1 < options.inputOrders &&
      !(stalled && attempt + 1 - firstOrder >= kInputOrdersAfterAStall);
    const bool ran = runTetGenIsolated(in, switches, limits, runs.points, runs.tets, runs.status,
      runs.code, timedOut, runs.failure, options.insidePoints.empty() ? nullptr : &addin, watch);
    meshed = ran && runs.status == 0;
    runs.attempts = attempt + 1 - firstOrder;
    runs.lastOrder = attempt;
    stalled = stalled || timedOut;
    const bool retry = !ran || (runs.status == 1 && runs.code == 2);
    if (!retry || (stalled && runs.attempts >= kInputOrdersAfterAStall) || (timedOut && limits.stoppedAfterRecovery))
    {
      break;
    }
  }
  return runs;
}

// Why TetGen did not keep every surface point where it was, first in its
// output (in the input order `order`, empty: the surface's own); empty if it did.
std::string surfacePointsError(
  const TriangleSurface& s, const std::vector<double>& outPoints, const std::vector<Index>& order = {})
{
  const std::size_t n = s.points.size();
  if (static_cast<int>(outPoints.size() / 3) < static_cast<int>(n))
  {
    return "TetGen returned fewer points than the surface has";
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t i = order.empty() ? k : order[k];
    if (std::memcmp(&outPoints[3 * k], s.points[i].data(), 3 * sizeof(double)) != 0)
    {
      return "TetGen moved or reordered surface point " + std::to_string(i) +
        " (the surface may have duplicate points)";
    }
  }
  return {};
}

// TetGen merges input points closer than its tolerance (-T, 1e-8 of the
// bounding-box diagonal) as duplicates. OCCT's Bottom at K = 64 (parallel
// planes), subdomain 47 of 6,160 points, has two points 9.5e-9 of its
// diagonal apart: TetGen crashed in the first order and merged them in the
// second, which the mesh cannot keep. A run that did not keep every
// surface point is therefore repeated, in all orders, with a tolerance of
// 1e-12 (Debian's tetgen -pY then meshed 5 of 6 shuffled orders). Only
// then: the tolerance also enters TetGen's encroachment tests, so every
// other mesh stays as it was.
constexpr const char* kFineTolerance = "T1e-12";

TetGenRuns runTetGen(const TriangleSurface& s, const TetMeshingOptions& options, const std::vector<Vec3>& holes,
  const std::string& switches, TimeLimits& limits, int firstOrder)
{
  TetGenRuns runs = runInOrders(s, options, holes, switches, limits, firstOrder);
  if (runs.failure.empty() && runs.status == 0 && !surfacePointsError(s, runs.points, runs.order).empty())
  {
    const int before = runs.attempts;
    runs = runInOrders(s, options, holes, switches + kFineTolerance, limits, firstOrder);
    runs.attempts += before;
    runs.tolerance = kFineTolerance;
  }
  return runs;
}

// Why the runs gave no mesh, and TetGen's code for it; empty if they gave one.
std::string runsError(const TetGenRuns& runs, const std::string& switches, int& tetgenCode)
{
  if (!runs.failure.empty())
  {
    tetgenCode = runs.code;
    return runs.failure + (runs.attempts > 1 ? " (also in " + std::to_string(runs.attempts - 1) +
                                                 " other orders of the points and facets)"
                                             : "");
  }
  if (runs.status == 1)
  {
    tetgenCode = runs.code;
    return "TetGen failed with code " + std::to_string(runs.code) + ": " + describeTetGenError(runs.code);
  }
  if (runs.status == 2)
  {
    tetgenCode = 1;
    return "TetGen ran out of memory";
  }
  if (runs.status == 3)
  {
    return "TetGen did not accept the switches '" + switches + "'";
  }
  return {};
}

// Back to the surface's own order: input position k is surface point order[k].
void restoreSurfaceOrder(TetGenRuns& runs, std::size_t n)
{
  std::vector<double> surfaceFirst(runs.points);
  for (std::size_t k = 0; k < n && 3 * k + 2 < runs.points.size(); ++k)
  {
    std::copy_n(&runs.points[3 * k], 3, &surfaceFirst[3 * runs.order[k]]);
  }
  runs.points.swap(surfaceFirst);
  for (int& v : runs.tets)
  {
    if (v >= 0 && static_cast<std::size_t>(v) < n)
    {
      v = static_cast<int>(runs.order[v]);
    }
  }
}


// The switches of the first run of recoverThenRefine: the surface recovered
// (-pY), nothing refined.
std::string recoverySwitches(const TetMeshingOptions& options)
{
  return "pYzQ" + options.extraSwitches;
}

// The switches of the second run of recoverThenRefine: those of the one
// run, in r mode. The inside points (-i) are not inserted in this fall-back:
// a sliver repair cavity meshed only so is not improved, and not kept.
std::string refinementSwitches(const TetMeshingOptions& options, double volume)
{
  TetMeshingOptions refine = options;
  refine.insidePoints.clear();
  return tetgenSwitches(refine, volume, 'r');
}

// The input of the second run of recoverThenRefine: the first run's mesh
// (surface points first, in the surface's order), the surface triangles as
// the faces -Y keeps, and with a size field a size at every point: a point
// the first run added inside gets the mean size of the surface points it
// shares a tetrahedron with (the mean of all, if none).
void fillRefinementInput(const TriangleSurface& s, const TetGenRuns& first, const std::vector<double>& sizes,
  tetgenio& in)
{
  const std::size_t total = first.points.size() / 3, n = s.points.size();
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(total);
  in.pointlist = new REAL[first.points.size()];
  std::copy(first.points.begin(), first.points.end(), in.pointlist);
  in.numberofcorners = 4;
  in.numberoftetrahedra = static_cast<int>(first.tets.size() / 4);
  in.tetrahedronlist = new int[first.tets.size()];
  std::copy(first.tets.begin(), first.tets.end(), in.tetrahedronlist);
  in.numberoftrifaces = static_cast<int>(s.triangles.size());
  in.trifacelist = new int[3 * s.triangles.size()];
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    std::copy(s.triangles[t].begin(), s.triangles[t].end(), &in.trifacelist[3 * t]);
  }
  // every triangle edge a segment too: with the faces alone, -rY gave the
  // spool's subdomain 544 boundary faces, but not the 544 it was given
  std::set<std::pair<Index, Index>> edges;
  for (const auto& t : s.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
  }
  in.numberofedges = static_cast<int>(edges.size());
  in.edgelist = new int[2 * edges.size()];
  int* e = in.edgelist;
  for (const auto& edge : edges)
  {
    *e++ = static_cast<int>(edge.first);
    *e++ = static_cast<int>(edge.second);
  }
  if (sizes.empty())
  {
    return;
  }
  std::vector<double> sum(total, 0.0), count(total, 0.0);
  for (std::size_t t = 0; t + 3 < first.tets.size(); t += 4)
  {
    for (int a = 0; a < 4; ++a)
    {
      for (int b = 0; b < 4; ++b)
      {
        const std::size_t va = first.tets[t + a], vb = first.tets[t + b];
        if (va >= n && vb < n)
        {
          sum[va] += sizes[vb];
          count[va] += 1;
        }
      }
    }
  }
  const double mean = std::accumulate(sizes.begin(), sizes.end(), 0.0) / static_cast<double>(n);
  in.numberofpointmtrs = 1;
  in.pointmtrlist = new REAL[total];
  for (std::size_t i = 0; i < total; ++i)
  {
    in.pointmtrlist[i] = i < n ? sizes[i] : (count[i] > 0 ? sum[i] / count[i] : mean);
  }
}

// TetGen 1.5 can recover a surface (-pY) that it then fails to refine in
// the same run: CGAL's spool from the corpus at K = 64 (recursive
// bisection), subdomain 16 of 274 points, aborts in locate()
// (searchtet->ver != 4) with -q or -a in the first three point orders, while -pY
// alone meshes it (adding one point inside), and a second run refining that
// mesh (-rY with the same -q, -a, -m) gives 1,135 tetrahedra with the
// surface kept. So a crash or stall of the one-run mesh is retried so: the
// surface recovered first, then refined. Both runs are deterministic, so the
// mesh is still the same on any rank.
TetGenRuns recoverThenRefine(const TriangleSurface& s, const TetMeshingOptions& options,
  const std::vector<Vec3>& holes, double volume, TimeLimits& limits, int firstOrder)
{
  TetMeshingOptions recoverOnly;
  recoverOnly.qualityRefinement = false;
  recoverOnly.extraSwitches = options.extraSwitches;
  TetGenRuns first = runTetGen(s, recoverOnly, holes, recoverySwitches(options), limits, firstOrder);
  if (!first.failure.empty() || first.status != 0)
  {
    return first;
  }
  if (first.lastOrder != 0)
  {
    restoreSurfaceOrder(first, s.points.size());
  }
  TetGenRuns second;
  second.tolerance = first.tolerance;
  second.lastOrder = first.lastOrder;
  second.failure = surfacePointsError(s, first.points);
  if (!second.failure.empty())
  {
    return second;
  }
  tetgenio in;
  fillRefinementInput(s, first, options.pointSizes, in);
  second.order.resize(s.points.size());
  std::iota(second.order.begin(), second.order.end(), Index{ 0 });
  second.attempts = 1;
  bool timedOut = false;
  runTetGenIsolated(in, refinementSwitches(options, volume) + first.tolerance, limits, second.points,
    second.tets, second.status, second.code, timedOut, second.failure);
  return second;
}

// The orientation of every tetrahedron by CGAL's exact predicate (1, -1, 0
// for flat). A float determinant misjudges nearly flat tetrahedra: OCCT's
// Top at K = 32 (parallel planes), subdomain 11, had one of exact volume
// -2.7e-16 whose float volume came out +8.1e-16, and turning the
// tetrahedra by the float sign folded the mesh (two faces with both
// tetrahedra on one side, found by the corpus sweep's independent check).
std::vector<signed char> exactOrientations(const std::vector<double>& outPoints, const std::vector<int>& outTets)
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  auto point = [&](int v) { return Point(outPoints[3 * v], outPoints[3 * v + 1], outPoints[3 * v + 2]); };
  std::vector<signed char> sign(outTets.size() / 4);
  for (std::size_t t = 0; t < sign.size(); ++t)
  {
    const int* v = &outTets[4 * t];
    sign[t] = static_cast<signed char>(CGAL::orientation(point(v[0]), point(v[1]), point(v[2]), point(v[3])));
  }
  return sign;
}

// The mesh of TetGen's output, every tetrahedron positively oriented. TetGen
// gives all its tetrahedra one orientation, so one of the other orientation
// (or flat) is a defect of the mesh: `error` says so.
void convertMesh(
  const std::vector<double>& outPoints, const std::vector<int>& outTets, TetMesh& mesh, std::string& error)
{
  const int outPointCount = static_cast<int>(outPoints.size() / 3);
  const int outTetCount = static_cast<int>(outTets.size() / 4);
  mesh.points.resize(static_cast<std::size_t>(outPointCount));
  for (int i = 0; i < outPointCount; ++i)
  {
    mesh.points[i] = { outPoints[3 * i], outPoints[3 * i + 1], outPoints[3 * i + 2] };
  }
  const std::vector<signed char> sign = exactOrientations(outPoints, outTets);
  const auto positive = std::count(sign.begin(), sign.end(), 1);
  const signed char majority = 2 * positive >= outTetCount ? 1 : -1;
  const auto wrong = outTetCount - std::count(sign.begin(), sign.end(), majority);
  if (wrong > 0)
  {
    error = "TetGen's mesh has " + std::to_string(wrong) +
      " tetrahedra turned against the others or flat (it folds over itself; a defect of libtet 1.5 on this surface)";
  }
  mesh.tets.resize(static_cast<std::size_t>(outTetCount));
  for (int t = 0; t < outTetCount; ++t)
  {
    std::array<Index, 4> v;
    for (int k = 0; k < 4; ++k)
    {
      v[k] = outTets[4 * t + k];
    }
    if (majority < 0)
    {
      std::swap(v[2], v[3]);
    }
    mesh.tets[t] = v;
  }
}

bool contains(const std::vector<Triangle>& sorted, const Triangle& key)
{
  return std::binary_search(sorted.begin(), sorted.end(), key);
}

// The faces used by one tetrahedron only, corners sorted, in sorted order;
// with `below` >= 0, only faces whose corners are all points under `below`
// (the surface's points, which TetGen's output lists first). All faces
// take 4 keys of 24 bytes per tetrahedron (480 MB for a rank's half of the
// 10 M ball), and their sort took 4 % of a rank's processor time on the
// 2.4 M ball.
std::vector<Triangle> boundaryFaces(const TetMesh& mesh, Index below = -1)
{
  std::vector<Triangle> faces;
  for (const auto& t : mesh.tets)
  {
    for (const Triangle& f : outwardTetrahedronFaces(t))
    {
      const Triangle key = sortedCorners(f);
      if (below < 0 || key[2] < below)
      {
        faces.push_back(key);
      }
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<Triangle> boundary;
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundary.push_back(faces[i]);
    }
    i = j;
  }
  return boundary;
}

// The faces of the tetrahedra whose sorted corners are in `keys`, turned
// outward (the tetrahedra are positively oriented).
std::vector<Triangle> outwardFaces(const TetMesh& mesh, const std::vector<Triangle>& keys)
{
  std::vector<Triangle> faces;
  for (const auto& t : mesh.tets)
  {
    for (const Triangle& f : outwardTetrahedronFaces(t))
    {
      if (contains(keys, sortedCorners(f)))
      {
        faces.push_back(f);
      }
    }
  }
  return faces;
}

// Whether p lies on triangle t of `s` up to `tolerance` (distance from its
// plane) and a relative 1e-9 of its barycentric coordinates.
bool liesOn(const TriangleSurface& s, const Triangle& t, const Vec3& p, double tolerance)
{
  const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
  const Vec3 n = cross(b - a, c - a);
  const double twiceArea = norm(n);
  if (!(std::fabs(dot(p - a, n)) <= tolerance * twiceArea))
  {
    return false;
  }
  const double u = dot(cross(c - b, p - b), n), v = dot(cross(a - c, p - c), n), w = dot(cross(b - a, p - a), n);
  const double slack = -1e-9 * twiceArea * twiceArea;
  return u >= slack && v >= slack && w >= slack;
}

// TetGen 1.5 with -Y still splits a facet where it cannot recover it
// otherwise: OCCT's Top at K = 32 (parallel planes), subdomain 19, had two
// coplanar outer triangles replaced by four around a point it put on them
// (3,580 boundary faces for 3,578). On a subdomain's outer boundary, which
// no neighbour shares, that keeps the mesh conforming and the point on the
// input surface, so it is accepted where every split triangle is one of
// `splittable`, every new face lies on a split triangle (its corners within
// 1e-12 of the surface's bounding-box diagonal of its plane, or
// 100 roundings of its coordinates: roundOffTolerance) and the new
// faces have the split triangles' area; `why` says what failed otherwise.
// `boundary` and `sortedInput` are the sorted keys of the mesh's boundary
// faces and of the surface's triangles.
bool acceptSplitFaces(const TriangleSurface& s, const std::vector<char>& splittable,
  const std::vector<Triangle>& boundary, const std::vector<Triangle>& sortedInput, TetMeshingResult& r,
  std::string& why)
{
  double missingArea = 0, newArea = 0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
  {
    if (contains(boundary, sortedCorners(s.triangles[t])))
    {
      continue;
    }
    if (!splittable[t])
    {
      why = "; it split a triangle a neighbouring subdomain shares";
      return false;
    }
    r.splitTriangles.push_back(static_cast<Index>(t));
    const Triangle& tri = s.triangles[t];
    missingArea += norm(cross(s.points[tri[1]] - s.points[tri[0]], s.points[tri[2]] - s.points[tri[0]]));
  }
  std::vector<Triangle> added;
  std::copy_if(boundary.begin(), boundary.end(), std::back_inserter(added),
    [&](const Triangle& f) { return !contains(sortedInput, f); });
  const double tolerance = roundOffTolerance(s.points, 1e-12);
  for (const Triangle& f : outwardFaces(r.mesh, added))
  {
    const Vec3 &a = r.mesh.points[f[0]], &b = r.mesh.points[f[1]], &c = r.mesh.points[f[2]];
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    Index parent = -1;
    for (Index t : r.splitTriangles)
    {
      const Triangle& tri = s.triangles[t];
      if (liesOn(s, tri, centroid, tolerance) && liesOn(s, tri, a, tolerance) && liesOn(s, tri, b, tolerance) &&
        liesOn(s, tri, c, tolerance))
      {
        parent = t;
        break;
      }
    }
    if (parent < 0)
    {
      why = "; a face it made lies on none of the triangles it split";
      return false;
    }
    r.splitFaces.push_back(f);
    r.splitFaceParents.push_back(parent);
    newArea += norm(cross(b - a, c - a));
  }
  if (!(std::fabs(newArea - missingArea) <= 1e-9 * missingArea))
  {
    why = "; the faces it made do not cover the triangles it split";
    return false;
  }
  return true;
}

// The faces used by one tetrahedron only must be the input triangles, or
// (acceptSplitFaces) splittable ones split by TetGen. The faces among the
// surface's points are looked at first: where those used once are exactly
// the input triangles, these form a closed surface, and any other boundary
// face (through a point TetGen added) would bound a second region, which
// volumeError refuses. Only otherwise are all faces needed.
std::string boundaryError(const TriangleSurface& s, const std::vector<char>& splittable, TetMeshingResult& r)
{
  std::vector<Triangle> input;
  for (const auto& t : s.triangles)
  {
    input.push_back(sortedCorners(t));
  }
  std::sort(input.begin(), input.end());
  if (boundaryFaces(r.mesh, static_cast<Index>(s.points.size())) == input)
  {
    return {};
  }
  const std::vector<Triangle> boundary = boundaryFaces(r.mesh);
  std::string why;
  if (!splittable.empty() && acceptSplitFaces(s, splittable, boundary, input, r, why))
  {
    return {};
  }
  r.splitTriangles.clear();
  r.splitFaces.clear();
  r.splitFaceParents.clear();
  return "TetGen's mesh boundary differs from the input surface (" + std::to_string(boundary.size()) +
    " boundary faces for " + std::to_string(input.size()) + " input triangles" + why + ")";
}

// The tetrahedra must fill exactly the volume the surface encloses. TetGen
// 1.5 can return a mesh whose boundary is right but which folds over itself
// (inverted tetrahedra: the sum of their volumes comes out too large): CGAL's
// oblong from the corpus, 64 parallel slabs, one slab thinner than the size
// gave a mesh of 6e15 for a volume of 2e5. (convertMesh now refuses
// inverted tetrahedra first; this check stays for overlaps it cannot see.) Such a mesh
// is refused like a crash, so the caller's fall-backs run.
std::string volumeError(const TriangleSurface& s, const TetMesh& mesh)
{
  const double enclosed = enclosedVolume(s);
  double filled = 0;
  for (const auto& t : mesh.tets)
  {
    filled += sixTimesVolumeAbout(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]) / 6.0;
  }
  if (!(std::fabs(filled - std::fabs(enclosed)) <= 1e-9 * std::fabs(enclosed)))
  {
    std::ostringstream msg;
    msg << "TetGen's tetrahedra fill a volume of " << filled << " where the surface encloses " << std::fabs(enclosed)
        << ": its mesh folds over itself (a defect of libtet 1.5 on this surface)";
    return msg.str();
  }
  return {};
}
// The mesh of TetGen's runs (in the surface's order) checked against the
// contract: every surface point kept, the boundary the surface (or split
// splittable triangles), the filled volume the enclosed one. Fills r.mesh
// and its split faces; returns why the mesh breaks the contract (empty: it
// does not).
std::string meshError(
  const TriangleSurface& s, const std::vector<char>& splittable, const TetGenRuns& runs, TetMeshingResult& r)
{
  std::string error = surfacePointsError(s, runs.points);
  if (!error.empty())
  {
    return error;
  }
  convertMesh(runs.points, runs.tets, r.mesh, error);
  if (error.empty())
  {
    error = boundaryError(s, splittable, r);
  }
  if (error.empty())
  {
    error = volumeError(s, r.mesh);
  }
  return error;
}

// Input orders in which a mesh that changed the surface is tried
// (meshClosedSurface): the canonical, reversed and two shuffled orders.
constexpr int kOrdersForAChangedSurface = 4;

// One mesh of the surface from input order `firstOrder` on (runTetGen, then
// recoverThenRefine where every order crashed or stalled), checked against
// the contract (meshError). `lastOrder` is the order of the last run;
// `contractBroken` says TetGen gave a mesh that meshError refused.
TetMeshingResult meshFromOrder(const TriangleSurface& s, const TetMeshingOptions& options,
  const std::vector<Vec3>& holes, double volume, TimeLimits& limits, int firstOrder, int& lastOrder,
  bool& contractBroken)
{
  TetMeshingResult r;
  r.switchesUsed = tetgenSwitches(options, volume);
  TetGenRuns runs = runTetGen(s, options, holes, r.switchesUsed, limits, firstOrder);
  r.switchesUsed += runs.tolerance;
  // (a run stopped while refining would be as slow refining in a second run)
  if (!runs.failure.empty() && !limits.stoppedAfterRecovery)
  {
    TetGenRuns twoRuns = recoverThenRefine(s, options, holes, volume, limits, firstOrder);
    if (twoRuns.failure.empty() && twoRuns.status == 0)
    {
      runs = std::move(twoRuns);
      r.switchesUsed =
        recoverySwitches(options) + runs.tolerance + ", then " + refinementSwitches(options, volume) + runs.tolerance;
      r.recoveredThenRefined = true;
    }
  }
  r.attempts = runs.attempts;
  lastOrder = runs.lastOrder;
  r.error = runsError(runs, r.switchesUsed, r.tetgenCode);
  if (!r.error.empty())
  {
    return r;
  }
  if (runs.lastOrder != 0)
  {
    restoreSurfaceOrder(runs, s.points.size());
  }
  r.error = meshError(s, options.splittableTriangles, runs, r);
  contractBroken = !r.error.empty();
  r.ok = !contractBroken;
  return r;
}
} // namespace

std::string describeTetGenError(int code)
{
  switch (code)
  {
    case 1: return "out of memory";
    case 2: return "internal error in TetGen";
    case 3: return "the surface intersects itself";
    case 4: return "a very small input feature was detected (smaller than TetGen's tolerance)";
    case 5: return "two very close input facets were detected";
    case 10: return "invalid input (TetGen rejected the surface)";
    default: return "unknown TetGen error";
  }
}

TetMeshingResult meshClosedSurface(const TriangleSurface& s, const TetMeshingOptions& options)
{
  TetMeshingResult r;
  double meanEdge = 0;
  r.error = inputError(s, options, meanEdge);
  if (!r.error.empty())
  {
    return r;
  }
  const double volume =
    options.maximumVolume > 0 ? options.maximumVolume : regularTetrahedronVolume(meanEdge);
  r.error = options.surfaceKnownValid ? std::string() : selfIntersectionError(s);
  if (!r.error.empty())
  {
    r.tetgenCode = 3;
    return r;
  }
  std::vector<Vec3> holes;
  if (!cavityHoles(s, holes))
  {
    r.error = "could not find a point inside a cavity of the surface";
    return r;
  }
  TimeLimits limits = timeLimits(s, options, volume);
  // TetGen 1.5 can mesh a surface and still break the contract in one input
  // order only: OpenSCAD's difference-tests.scad at K = 16 (bisection), subdomain 13
  // of 1,346 refined triangles, got a point on an interface edge (its two
  // triangles split into four) in the canonical order, and Debian's tetgen
  // -pY kept every triangle in 6 of 12 shuffled orders (5 crashed). Such a
  // mesh is retried in the next orders, like a crash, so the caller does
  // not fall back to the unrefined surface; up to kOrdersForAChangedSurface
  // only: OCCT's Top subdomain of SplittableTrianglesMayBeSplitOthersNot
  // is split in all twelve (33 s instead of 3 s in the unit test).
  int firstOrder = 0, attempts = 0;
  for (;;)
  {
    int lastOrder = 0;
    bool contractBroken = false;
    TetMeshingResult attempt = meshFromOrder(s, options, holes, volume, limits, firstOrder, lastOrder, contractBroken);
    attempts += attempt.attempts;
    if (attempt.ok || !contractBroken || lastOrder + 1 >= std::min(options.inputOrders, kOrdersForAChangedSurface))
    {
      r = std::move(attempt);
      break;
    }
    firstOrder = lastOrder + 1;
  }
  r.attempts = attempts;
  r.processorSeconds = limits.spent;
  r.processorBudgetSeconds = limits.budget;
  r.outOfTime = !r.ok && limits.nextCpu() <= 0;
  if (!r.ok && limits.stopped > 0)
  {
    r.error = stoppedRunsError(s, limits, attempts, r.error);
  }
  if (r.ok && r.splitTriangles.empty())
  {
    TetMeshingOptions resolved = options;
    resolved.maximumVolume = volume;
    r.sliverRepairPoints = repairBoundarySlivers(s, resolved, r.mesh);
  }
  return r;
}
TetMeshEstimate estimateTetMesh(double volume, double maximumVolume)
{
  return volume > 0 && maximumVolume > 0 ? estimateTetMeshOfRegular(volume / maximumVolume) : TetMeshEstimate{};
}

TetMeshEstimate estimateTetMeshOfRegular(double regularTetrahedra)
{
  TetMeshEstimate e;
  if (regularTetrahedra > 0)
  {
    e.tetrahedra = 2.0 * regularTetrahedra;
    e.bytes = 220.0 * e.tetrahedra;
  }
  return e;
}

long long machineIdentity()
{
  char name[256] = {};
  ::gethostname(name, sizeof(name) - 1);
  return static_cast<long long>(fnv1a(kFnv1aOffset, name, std::strlen(name)) >> 1);
}

double physicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0.0;
}
} // namespace ptm
