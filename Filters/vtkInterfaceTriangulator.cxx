#include "vtkInterfaceTriangulator.h"

#include "BentRegionCheck.h"
#include "ContourSubdivision.h"
#include "InterfaceTriangulation.h"
#include "PipelineRequests.h"
#include "PolyDataConversion.h"
#include "PropertyChecks.h"
#include "RankCollectives.h"
#include "SizeField.h"
#include "StageRun.h"
#include "SurfaceComplexArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

vtkStandardNewMacro(vtkInterfaceTriangulator);
vtkCxxSetObjectMacro(vtkInterfaceTriangulator, Controller, vtkMultiProcessController);

namespace
{
using RegionKey = std::tuple<long long, long long, long long>; // plane, pair[0], pair[1]

struct RegionFigures
{
  long long newPoints = 0;
  long long belowMinimumAngle = 0;
  long long belowMinimumAngleAwayFromBoundary = 0;
  long long encroached = 0;
  double minimumAngle = 180;
};

struct Done
{
  std::size_t region = 0; // index into the piece's interfaces
  RegionKey key;
  std::vector<ptm::Index> pointOfLocal; // region point -> piece point
  ptm::InterfaceTriangulation triangulation;
  int planeId;
  ptm::SubdomainPair pair;
};

// Every region of the piece triangulated from canonically ordered input
// (its points by global id, its edges sorted), so both ranks that hold a
// region get the same triangles. On a failure `error` names the region.
// Triangulates region `index` of the piece into `d`; false with `error`
// naming the region if it cannot be.
bool triangulateRegion(const ptm::ComplexPiece& piece, std::size_t index,
  const ptm::InterfaceTriangulationOptions& options, Done& d, std::string& error)
{
  const ptm::SurfaceComplex& c = piece.complex;
  const ptm::InterfaceRegion& region = c.interfaces[index];
  d.region = index;
  d.planeId = region.planeId;
  d.pair = region.pair;
  d.key = RegionKey(region.planeId, region.pair[0], region.pair[1]);
  std::vector<ptm::Index> points;
  for (const auto& e : region.edges)
  {
    points.push_back(e[0]);
    points.push_back(e[1]);
  }
  std::sort(points.begin(), points.end(),
    [&](ptm::Index a, ptm::Index b) { return piece.globalIds[a] < piece.globalIds[b]; });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  ptm::PlanarRegion planar = ptm::planarRegionOf(c, region, points);
  std::sort(planar.edges.begin(), planar.edges.end());
  try
  {
    ptm::InterfaceTriangulationResult r = ptm::triangulateInterface(planar, options);
    if (!r.ok)
    {
      std::ostringstream msg;
      msg << "interface on plane " << region.planeId << " between subdomains " << region.pair[0]
          << " and " << region.pair[1] << ": " << r.error;
      error = msg.str();
      return false;
    }
    d.triangulation = std::move(r.triangulation);
  }
  catch (const std::exception& e)
  {
    error = std::string("interface triangulation failed: ") + e.what();
    return false;
  }
  d.pointOfLocal = std::move(points);
  return true;
}

std::vector<Done> triangulateRegions(const ptm::ComplexPiece& piece,
  const ptm::InterfaceTriangulationOptions& options, std::string& error,
  const std::function<void(double)>& progress)
{
  const ptm::SurfaceComplex& c = piece.complex;
  std::vector<Done> done;
  for (std::size_t index = 0; index < c.interfaces.size(); ++index)
  {
    Done d;
    if (!triangulateRegion(piece, index, options, d, error))
    {
      break;
    }
    done.push_back(std::move(d));
    progress(static_cast<double>(done.size()) / c.interfaces.size());
  }
  return done;
}

// The triangulated regions of the piece, for the checks of BentRegionCheck.h.
std::vector<ptm::TriangulatedRegion> triangulatedRegions(const ptm::ComplexPiece& piece, const std::vector<Done>& done)
{
  std::vector<ptm::TriangulatedRegion> regions;
  for (const Done& d : done)
  {
    regions.push_back({ &piece.complex.interfaces[d.region], &d.pointOfLocal, &d.triangulation });
  }
  return regions;
}

// The keys of `found` (indices into `done`) of every rank.
std::set<RegionKey> agreedRegions(
  vtkMultiProcessController* controller, const std::vector<Done>& done, const std::vector<std::size_t>& found)
{
  std::vector<long long> mine;
  for (std::size_t r : found)
  {
    mine.insert(mine.end(), { std::get<0>(done[r].key), std::get<1>(done[r].key), std::get<2>(done[r].key) });
  }
  const std::vector<long long> all = ptm::allGatherValues(controller, mine);
  std::set<RegionKey> keys;
  for (std::size_t k = 0; k + 2 < all.size(); k += 3)
  {
    keys.insert(RegionKey(all[k], all[k + 1], all[k + 2]));
  }
  return keys;
}

// Regions bent through snapped vertices whose triangulation crosses the
// surface of a subdomain they bound (BentRegionCheck.h), learnt by every
// rank. A rank whose check throws gives no verdict but still joins the
// all-gather; the mesher checks every subdomain again.
std::set<RegionKey> bentRegionsCrossing(
  vtkMultiProcessController* controller, const ptm::ComplexPiece& piece, const std::vector<Done>& done)
{
  std::vector<std::size_t> crossing;
  try
  {
    crossing = ptm::bentRegionsCrossingSurface(piece.complex, triangulatedRegions(piece, done));
  }
  catch (const std::exception&)
  {
  }
  return agreedRegions(controller, done, crossing);
}

// The regions of every subdomain whose surface, with the interfaces as
// triangulated, crosses itself (BentRegionCheck.h:
// subdomainsCrossingThemselves), learnt by every rank. Only subdomains with
// a region holding a boundary point of global id `firstId` or more are
// checked. A rank whose check throws counts all of those as
// crossing, and still joins the all-gather.
std::set<RegionKey> regionsOfCrossingSubdomains(vtkMultiProcessController* controller,
  const ptm::ComplexPiece& piece, const std::vector<Done>& done, long long firstId)
{
  std::set<int> subdomains;
  for (const Done& d : done)
  {
    if (std::any_of(d.pointOfLocal.begin(), d.pointOfLocal.end(),
          [&](ptm::Index v) { return piece.globalIds[v] >= firstId; }))
    {
      subdomains.insert(d.pair.begin(), d.pair.end());
    }
  }
  subdomains.erase(-1);
  std::vector<int> crossing;
  try
  {
    crossing = ptm::subdomainsCrossingThemselves(piece.complex, triangulatedRegions(piece, done), subdomains);
  }
  catch (const std::exception&)
  {
    crossing.assign(subdomains.begin(), subdomains.end());
  }
  std::vector<std::size_t> found;
  for (std::size_t r = 0; r < done.size(); ++r)
  {
    for (int s : crossing)
    {
      if (done[r].pair[0] == s || done[r].pair[1] == s)
      {
        found.push_back(r);
        break;
      }
    }
  }
  return agreedRegions(controller, done, found);
}

// Bent regions that cross the surface (bentRegionsCrossing, the same on
// every rank) are triangulated again: first with the options the cutter
// checks its cuts with (automatic sizing graded from the boundary,
// unsmoothed, no size field), then, where they still cross, with no points
// inside but what the quality of 1 degree needs. On occt-Bottom with 16 and 32
// parallel planes, a region triangulated at the size asked for (270)
// crossed a surface triangle under a vertex snapped 0.12 off the plane, and
// so did the minimal triangulation; the graded one did not. A region still
// crossing after both is left to the mesher, which names the subdomain.
// `flagged`: bentRegionsCrossing of `done` as it is. Returns the number of
// regions triangulated again.
long long retriangulateCrossingRegions(vtkMultiProcessController* controller, const ptm::ComplexPiece& piece,
  std::vector<Done>& done, std::set<RegionKey> flagged)
{
  ptm::InterfaceTriangulationOptions checked; // as the cutter's check (VolumeBalancedDecomposition.cpp: partCrossesItself)
  checked.smooth = false;
  ptm::InterfaceTriangulationOptions cover = checked;
  cover.minimumAngleDegrees = 1.0;
  cover.maximumEdgeLength = std::numeric_limits<double>::max();
  long long redone = 0;
  for (const ptm::InterfaceTriangulationOptions* fallBack : { &checked, &cover })
  {
    if (fallBack != &checked)
    {
      flagged = bentRegionsCrossing(controller, piece, done);
    }
    if (flagged.empty())
    {
      break;
    }
    redone += static_cast<long long>(flagged.size());
    for (Done& d : done)
    {
      // a region the fall-back cannot triangulate keeps the triangles it had
      // (on every rank alike: the triangulation is deterministic)
      Done again;
      std::string ignored;
      if (flagged.count(d.key) && triangulateRegion(piece, d.region, *fallBack, again, ignored))
      {
        d = std::move(again);
      }
    }
  }
  return redone;
}

// Marks risky every split on an edge of a region in `regions`.
void markEdgesOfRegionsRisky(
  const ptm::ComplexPiece& piece, const std::set<RegionKey>& regions, std::vector<ptm::EdgeSplit>& splits)
{
  if (regions.empty())
  {
    return;
  }
  std::map<std::pair<ptm::Index, ptm::Index>, std::size_t> splitOf; // ends (complex points) -> split
  for (std::size_t k = 0; k < splits.size(); ++k)
  {
    splitOf[std::minmax(splits[k].ends[0], splits[k].ends[1])] = k;
  }
  for (const ptm::InterfaceRegion& region : piece.complex.interfaces)
  {
    if (!regions.count(RegionKey(region.planeId, region.pair[0], region.pair[1])))
    {
      continue;
    }
    for (const ptm::DirectedEdge& e : region.edges)
    {
      auto it = splitOf.find(std::minmax(e[0], e[1]));
      if (it != splitOf.end())
      {
        splits[it->second].risky = true;
      }
    }
  }
}

// Splits the long edges of the piece's interface loops (ContourSubdivision.h)
// and numbers the new points from piece.globalPointCount (advanced past
// them) in the order of their edges' global ids, which every rank learns:
// a rank sees only the edges of its own regions, and ids must not depend on
// which rank holds what. An edge takes the most parts any rank wants (each
// sees the surface triangles on its own side); one that any rank finds
// risky (EdgeSplit) is split by none, and so is every edge of the regions in
// `keepWhole` (the same set on every rank). Returns how many points all
// ranks added.
long long subdivideContours(vtkMultiProcessController* controller, ptm::ComplexPiece& piece,
  const ptm::ContourSubdivisionOptions& options, const std::set<RegionKey>& keepWhole)
{
  std::vector<ptm::EdgeSplit> splits = ptm::interfaceEdgeSplits(piece.complex, piece.globalIds, options);
  markEdgesOfRegionsRisky(piece, keepWhole, splits);
  std::vector<long long> mine;
  for (const ptm::EdgeSplit& s : splits)
  {
    mine.insert(mine.end(), { piece.globalIds[s.ends[0]], piece.globalIds[s.ends[1]],
                              static_cast<long long>(s.parts), s.risky ? 1LL : 0LL });
  }
  const std::vector<long long> all = ptm::allGatherValues(controller, mine);
  // edge -> (the most parts wanted, risky anywhere), then (its first id, its parts)
  std::map<std::pair<long long, long long>, std::pair<long long, long long>> agreed;
  for (std::size_t k = 0; k + 3 < all.size(); k += 4)
  {
    auto [it, inserted] = agreed.emplace(std::make_pair(all[k], all[k + 1]), std::make_pair(all[k + 2], 0LL));
    it->second.first = std::max(it->second.first, all[k + 2]);
    it->second.second = it->second.second || all[k + 3];
  }
  long long next = piece.globalPointCount;
  for (auto& [edge, value] : agreed)
  {
    const long long parts = value.second ? 1 : value.first;
    value = { next, parts };
    next += parts - 1;
  }
  for (ptm::EdgeSplit& s : splits)
  {
    ptm::splitIntoParts(
      piece.complex, s, static_cast<int>(agreed.at({ piece.globalIds[s.ends[0]], piece.globalIds[s.ends[1]] }).second));
    s.risky = false; // an edge some rank found risky is in 1 part everywhere
  }
  ptm::applyEdgeSplits(piece.complex, splits);
  for (const ptm::EdgeSplit& s : splits)
  {
    long long id = agreed.at({ piece.globalIds[s.ends[0]], piece.globalIds[s.ends[1]] }).first;
    for (std::size_t i = 0; i < s.points.size(); ++i)
    {
      piece.globalIds.push_back(id++);
    }
  }
  const long long added = next - piece.globalPointCount;
  piece.globalPointCount = next;
  return added;
}

struct Triangulated
{
  std::vector<Done> done;
  std::set<RegionKey> keepWhole; // regions whose edges were not split
  long long contourPoints = 0, redone = 0, subdivisionRetries = 0;
};

// Splits the contours (unless `subdivision` is null) and triangulates every
// region, then checks the subdomain surfaces whole. Contour subdivision
// changes the regions' triangulations beyond what the cutter checked:
//  * a region bent at a snapped vertex whose triangulation crosses the
//    surface keeps its edges whole, and everything is done again from the
//    cut complex. Its fall-back triangulations (retriangulateCrossingRegions)
//    are far coarser: on gmsh's pipe at 16 parallel planes they left two
//    subdomains with a third of their interface triangles and 6-8 x the
//    tetrahedra under 10 degrees, where the region with its contour whole
//    crosses nothing (session 33);
//  * where a subdomain then crosses itself, the regions of that subdomain
//    keep their edges whole and everything is done again, and if one still
//    crosses, no edge is split at all.
// Only subdomains with a split edge are checked whole; one that crosses
// itself as the cut left it is named by the mesher. Every rank learns the
// same regions, so neighbours stay identical.
// Returns 0, 1 on a failure (`localError`, agreed) or 2 on an abort.
int subdivideAndTriangulate(vtkAlgorithm* self, ptm::StageRun& run, vtkMultiProcessController* controller,
  ptm::ComplexPiece& piece, const ptm::ContourSubdivisionOptions* subdivision,
  const ptm::InterfaceTriangulationOptions& options, Triangulated& t, std::string& localError)
{
  const ptm::ComplexPiece cut = subdivision ? piece : ptm::ComplexPiece();
  for (;;)
  {
    t.contourPoints = 0;
    if (subdivision)
    {
      run.Step(0.05, "Splitting long contour edges");
      piece = cut;
      t.contourPoints = subdivideContours(controller, piece, *subdivision, t.keepWhole);
    }
    run.Step(0.1, "Triangulating interfaces");
    t.done = triangulateRegions(piece, options, localError,
      [self](double fraction) { self->UpdateProgress(0.1 + 0.7 * fraction); });
    if (run.FailedAnywhere(localError))
    {
      return 1;
    }
    if (run.AbortedAnywhere())
    {
      return 2;
    }
    run.Step(0.8, "Checking bent interfaces against the surface");
    const std::set<RegionKey> bent = bentRegionsCrossing(controller, piece, t.done);
    if (t.contourPoints > 0 && !std::includes(t.keepWhole.begin(), t.keepWhole.end(), bent.begin(), bent.end()))
    {
      t.keepWhole.insert(bent.begin(), bent.end()); // the same set on every rank: all go round again
      continue;
    }
    t.redone = retriangulateCrossingRegions(controller, piece, t.done, bent);
    if (t.contourPoints == 0)
    {
      return 0;
    }
    run.Step(0.85, "Checking the subdomain surfaces");
    const std::set<RegionKey> crossed =
      regionsOfCrossingSubdomains(controller, piece, t.done, cut.globalPointCount);
    if (crossed.empty())
    {
      return 0;
    }
    ++t.subdivisionRetries;
    t.keepWhole.insert(crossed.begin(), crossed.end());
    if (t.subdivisionRetries == 2)
    {
      subdivision = nullptr;
      piece = cut;
    }
  }
}

// The first global id of every region's new points, numbered from `next`
// (advanced past them) in region-key order; every rank learns every
// region's count and figures (a region on two ranks is counted once), and
// `total` sums the figures.
std::map<RegionKey, long long> firstNewIds(
  vtkMultiProcessController* controller, const std::vector<Done>& done, long long& next, RegionFigures& total)
{
  std::vector<long long> mine;
  for (const Done& d : done)
  {
    mine.push_back(std::get<0>(d.key));
    mine.push_back(std::get<1>(d.key));
    mine.push_back(std::get<2>(d.key));
    mine.push_back(static_cast<long long>(d.triangulation.newPoints.size()));
    mine.push_back(static_cast<long long>(d.triangulation.trianglesBelowMinimumAngle));
    mine.push_back(static_cast<long long>(d.triangulation.trianglesBelowMinimumAngleAwayFromBoundary));
    mine.push_back(static_cast<long long>(d.triangulation.encroachedSegmentsLeft));
    mine.push_back(std::llround(d.triangulation.minimumAngleDegrees * 1e9));
  }
  const std::vector<long long> all = ptm::allGatherValues(controller, mine);
  std::map<RegionKey, RegionFigures> regions;
  for (std::size_t k = 0; k + 7 < all.size(); k += 8)
  {
    RegionFigures f;
    f.newPoints = all[k + 3];
    f.belowMinimumAngle = all[k + 4];
    f.belowMinimumAngleAwayFromBoundary = all[k + 5];
    f.encroached = all[k + 6];
    f.minimumAngle = static_cast<double>(all[k + 7]) * 1e-9;
    regions[RegionKey(all[k], all[k + 1], all[k + 2])] = f;
  }
  std::map<RegionKey, long long> firstNewId;
  for (const auto& [key, f] : regions)
  {
    firstNewId[key] = next;
    next += f.newPoints;
    total.newPoints += f.newPoints;
    total.belowMinimumAngle += f.belowMinimumAngle;
    total.belowMinimumAngleAwayFromBoundary += f.belowMinimumAngleAwayFromBoundary;
    total.encroached += f.encroached;
    total.minimumAngle = std::min(total.minimumAngle, f.minimumAngle);
  }
  return firstNewId;
}

// The complex with every region's triangles (and their new points, numbered
// from the region's first new id) instead of its loops.
void replaceLoopsByTriangles(
  ptm::ComplexPiece& piece, const std::vector<Done>& done, const std::map<RegionKey, long long>& firstNewId)
{
  ptm::SurfaceComplex& c = piece.complex;
  if (c.trianglePlanes.size() != c.triangles.size())
  {
    c.trianglePlanes.assign(c.triangles.size(), -1);
  }
  for (const Done& d : done)
  {
    std::vector<ptm::Index> pointOf = d.pointOfLocal;
    long long id = firstNewId.at(d.key);
    for (const ptm::Vec3& p : d.triangulation.newPoints)
    {
      pointOf.push_back(static_cast<ptm::Index>(c.points.size()));
      c.points.push_back(p);
      piece.globalIds.push_back(id++);
    }
    for (const ptm::Triangle& tri : d.triangulation.triangles)
    {
      c.triangles.push_back({ pointOf[tri[0]], pointOf[tri[1]], pointOf[tri[2]] });
      c.trianglePairs.push_back(d.pair);
      c.sourceFaces.push_back(-1);
      c.trianglePlanes.push_back(d.planeId);
    }
  }
  c.interfaces.clear();
}

// The figures of every region (the same on every rank) in field data.
// `counts`: the contour points added, the subdivision's retries, the
// regions kept whole and the regions triangulated again.
void addFigures(vtkFieldData* fd, const RegionFigures& total, const std::array<long long, 4>& counts, bool anyRegion)
{
  auto addCount = [&](const char* name, long long value) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  addCount(ptm::arrays::ContourPointsAdded, counts[0]);
  addCount(ptm::arrays::ContourSubdivisionRetries, counts[1]);
  addCount(ptm::arrays::InterfacesKeptWhole, counts[2]);
  addCount(ptm::arrays::InterfacesTriangulatedAgain, counts[3]);
  addCount(ptm::arrays::InterfaceNewPoints, total.newPoints);
  addCount(ptm::arrays::InterfaceTrianglesBelowMinimumAngle, total.belowMinimumAngle);
  addCount(ptm::arrays::InterfaceTrianglesBelowMinimumAngleAwayFromBoundary, total.belowMinimumAngleAwayFromBoundary);
  addCount(ptm::arrays::EncroachedBoundarySegments, total.encroached);
  vtkNew<vtkDoubleArray> angle;
  angle->SetName(ptm::arrays::InterfaceMinimumAngle);
  angle->InsertNextValue(anyRegion ? total.minimumAngle : 0.0);
  fd->AddArray(angle);
}

// Why MaximumEdgeLength h is too small for an interface of this rank's
// piece, or nothing: where its estimated new points (2 area / h^2) pass
// kMostNewPointsPerRegion, the triangulation would stop short of h, after
// minutes (the unit ball's disc at h = 3e-4 ran past 2.5 of them; at
// h = 0.01, 78,000 points took about 3 s). Refused before any region is
// triangulated.
// The message begins "the requested size", which tetmesh.py does not cut
// again for.
std::string edgeLengthTooSmall(const ptm::ComplexPiece& piece, double h)
{
  if (!(h > 0))
  {
    return {};
  }
  const ptm::InterfaceRegion* largest = nullptr;
  double largestArea = 0;
  for (const ptm::InterfaceRegion& region : piece.complex.interfaces)
  {
    if (region.edges.empty())
    {
      continue;
    }
    // about a point of its own, where vectorArea is accurate
    const ptm::Vec3& about = piece.complex.points[region.edges[0][0]];
    const double area = ptm::norm(ptm::vectorArea(piece.complex.points, region.edges, about));
    if (area > largestArea)
    {
      largestArea = area;
      largest = &region;
    }
  }
  const double estimate = 2.0 * largestArea / (h * h);
  if (!largest || !(estimate > ptm::kMostNewPointsPerRegion))
  {
    return {};
  }
  std::ostringstream why;
  why.precision(3);
  why << "the requested size (MaximumEdgeLength " << h << ") would put about " << estimate
      << " points inside the interface between subdomains " << largest->pair[0] << " and " << largest->pair[1]
      << " (area " << largestArea << "), more than the " << ptm::kMostNewPointsPerRegion
      << " one interface may get; use a larger MaximumEdgeLength";
  return why.str();
}
} // namespace

vtkInterfaceTriangulator::vtkInterfaceTriangulator()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkInterfaceTriangulator::~vtkInterfaceTriangulator()
{
  this->SetController(nullptr);
}

int vtkInterfaceTriangulator::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  ptm::announceAnyPiece(outputVector);
  return 1;
}

std::string vtkInterfaceTriangulator::PropertyError()
{
  ptm::PropertyChecks checks("InterfaceTriangulator");
  checks.Require(this->MinimumAngle >= 1.0 && this->MinimumAngle <= 34.0, "MinimumAngle",
    "lie in [1, 34] degrees", this->MinimumAngle);
  checks.Require(this->MaximumEdgeLength >= 0.0 && std::isfinite(this->MaximumEdgeLength),
    "MaximumEdgeLength", "be 0 (automatic) or a positive length", this->MaximumEdgeLength);
  return checks.Ok() ? "" : checks.Message();
}

int vtkInterfaceTriangulator::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiProcessController* controller = this->Controller;
  ptm::StageRun run(this, controller, "InterfaceTriangulator", "interface", { output }); // StageRun.h
  ptm::ComplexPiece piece;
  if (run.PropertiesRefused(this->PropertyError()) || !run.ReadPiece(input, piece) ||
    run.FailedAnywhere(edgeLengthTooSmall(piece, this->MaximumEdgeLength)))
  {
    return run.Failure();
  }
  std::string localError;
  ptm::InterfaceTriangulationOptions options;
  options.minimumAngleDegrees = this->MinimumAngle;
  options.maximumEdgeLength = this->MaximumEdgeLength;
  const ptm::SizeField field = ptm::complexSizeField(
    this->SizeExpression, input ? input->GetFieldData() : nullptr, localError);
  // A size field must be positive where the interfaces meet the surface
  // (inside, the mesher falls back to the automatic size); a field that
  // reaches 0 at the surface would refine without end.
  std::vector<double> sizes;
  if (localError.empty() && field)
  {
    ptm::sizesAt(field, piece.complex.points, sizes, localError);
  }
  if (run.FailedAnywhere(localError))
  {
    return run.Failure();
  }
  // the field capped where the input is thinner than the size (the cutter's
  // ThicknessSamples), read alike on every rank
  options.sizeAt = ptm::boundarySizeOf(field, input ? input->GetFieldData() : nullptr);

  ptm::ContourSubdivisionOptions subdivision;
  subdivision.size = this->MaximumEdgeLength > 0 ? this->MaximumEdgeLength : piece.inputMeanEdgeLength;
  subdivision.sizeAt = options.sizeAt;
  subdivision.minimumAngleDegrees = this->MinimumAngle;
  Triangulated t;
  const int status = subdivideAndTriangulate(this, run, controller, piece,
    this->SubdivideContours && subdivision.size > 0 ? &subdivision : nullptr, options, t, localError);
  if (status != 0)
  {
    return status == 1 ? run.Failure() : run.Aborted();
  }
  std::vector<Done>& done = t.done;
  // Global ids of the new points: every rank learns every region's count.
  RegionFigures total;
  long long next = piece.globalPointCount;
  const std::map<RegionKey, long long> firstNewId = firstNewIds(controller, done, next, total);
  replaceLoopsByTriangles(piece, done, firstNewId);
  piece.globalPointCount = next;

  run.Step(0.9, "Writing the complex");
  ptm::complexToPolyData(piece, {}, output);
  vtkFieldData* fd = output->GetFieldData();
  addFigures(fd, total,
    { t.contourPoints, t.subdivisionRetries, static_cast<long long>(t.keepWhole.size()), t.redone },
    !firstNewId.empty());
  ptm::passOnFieldData(input, fd); // the cutter's facts and the size samples
  return run.Done();
}

void vtkInterfaceTriangulator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "SizeExpression: " << this->SizeExpression << "\n";
  os << indent << "SubdivideContours: " << this->SubdivideContours << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
