#include "VolumeBalancedDecomposition.h"

#include "FlatCrossingRemoval.h"

#include "InterfaceTriangulation.h"
#include "InterfaceTriangulationCache.h"
#include "SelfIntersectionCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace ptm
{
const char* toString(CutStrategy s)
{
  return s == CutStrategy::ParallelPlanes ? "ParallelPlanes" : "RecursiveBisection";
}

const char* toString(CutDirection d)
{
  switch (d)
  {
    case CutDirection::X: return "X";
    case CutDirection::Y: return "Y";
    case CutDirection::Z: return "Z";
    case CutDirection::LongestExtent: return "LongestExtent";
    case CutDirection::Inertia: return "Inertia";
  }
  return "?";
}

const char* toString(BalanceCriterion c)
{
  switch (c)
  {
    case BalanceCriterion::Volume: return "Volume";
    case BalanceCriterion::BoundaryFacets: return "BoundaryFacets";
    case BalanceCriterion::Nodes: return "Nodes";
    case BalanceCriterion::PredictedCost: return "PredictedCost";
  }
  return "?";
}

namespace
{
// Clearances (PlaneClearance) for choosing a tilted normal: 0.5 is as clear
// as the search asks for; from 0.2 on the proposed normal is kept unsearched;
// a tilted one must be 1.5 times as clear to replace it.
constexpr double kEnoughClearance = 0.5;
constexpr double kGoodClearance = 0.2;
constexpr double kClearlyBetter = 1.5;
// Measure of each final subdomain by the criterion.
std::vector<double> measureSubdomains(const SurfaceComplex& c, BalanceCriterion criterion,
  const std::vector<double>& volumes)
{
  if (criterion == BalanceCriterion::Volume)
  {
    return volumes;
  }
  std::vector<double> m(c.subdomainCount, 0.0);
  if (criterion == BalanceCriterion::BoundaryFacets)
  {
    for (std::size_t i = 0; i < c.triangles.size(); ++i)
    {
      if (c.trianglePairs[i][1] == -1)
      {
        m[c.trianglePairs[i][0]] += 1;
      }
    }
    return m;
  }
  std::vector<std::vector<Index>> nodes(c.subdomainCount);
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    if (c.trianglePairs[i][1] == -1)
    {
      auto& list = nodes[c.trianglePairs[i][0]];
      list.insert(list.end(), c.triangles[i].begin(), c.triangles[i].end());
    }
  }
  for (int s = 0; s < c.subdomainCount; ++s)
  {
    std::sort(nodes[s].begin(), nodes[s].end());
    m[s] = static_cast<double>(std::unique(nodes[s].begin(), nodes[s].end()) - nodes[s].begin());
  }
  return m;
}

// Why the options cannot be used, or empty.
std::string optionError(const DecompositionOptions& options)
{
  if (options.numberOfSubdomains < 1)
  {
    return "the number of subdomains must be at least 1";
  }
  if (!(options.balanceTolerance > 0 && options.balanceTolerance < 1))
  {
    return "the balance tolerance must lie strictly between 0 and 1";
  }
  if (!(options.snapFraction >= 0 && options.snapFraction < 0.5))
  {
    return "the snap fraction must lie in [0, 0.5)";
  }
  if (!(options.alignmentAngleDegrees >= 0 && options.alignmentAngleDegrees <= 45))
  {
    return "the plane alignment angle must lie in [0, 45] degrees";
  }
  if (!(options.tiltDegrees >= 0 && options.tiltDegrees <= 30))
  {
    return "the plane tilt angle must lie in [0, 30] degrees";
  }
  return std::string();
}

// Whether labelled volumes that should add up to `whole` do, up to the
// round-off of the divergence sums: relative to each term (bounded by
// |p|^3) and absolute in the subnormal range. The fuzzer found a cut of a
// 7-point surface (K = 4, snap fraction 0.49) whose parts together enclosed
// 0.4 % more than the input: the snapped interface overlapped the part.
bool volumesAddUp(const SurfaceComplex& c, double parts, double whole)
{
  double largest = 0;
  for (const Vec3& p : c.points)
  {
    largest = std::max(largest, largestCoordinate(p));
  }
  std::size_t terms = c.triangles.size();
  for (const InterfaceRegion& region : c.interfaces)
  {
    terms += region.edges.size();
  }
  const double tolerance = 1e-9 * std::fabs(whole) +
    1e-13 * static_cast<double>(terms) * largest * largest * largest +
    64.0 * static_cast<double>(terms) * std::numeric_limits<double>::denorm_min();
  return std::fabs(parts - whole) <= tolerance;
}

// Whether a region's boundary has a point of the cut: numbered
// `firstNewPoint` or above (points are appended as a cut makes them).
bool hasPointFrom(const InterfaceRegion& region, Index firstNewPoint)
{
  return std::any_of(region.edges.begin(), region.edges.end(),
    [&](const DirectedEdge& e) { return e[0] >= firstNewPoint || e[1] >= firstNewPoint; });
}

// Where the faces of a cut's new interface lie: within the box of its
// boundary points and within the slab of the plane they span, [low, high]
// along the normal (up to round-off; the interface bends only through
// boundary points left off the plane, and its inner points and triangles lie
// between those). A face that crosses the new interface reaches into both.
// The box alone let an inclined cut through a ball check nearly the whole
// part: the box of an inclined disc holds most of the ball.
struct CutZone
{
  int planeId = -1;
  Box box;
  Vec3 normal{ 0, 0, 0 };
  double low = 0, high = 0;
  bool reaches(const Box& b) const
  {
    if (!box.overlaps(b))
    {
      return false;
    }
    double lo = 0, hi = 0; // the range of normal . x over the corners of b
    for (int k = 0; k < 3; ++k)
    {
      lo += std::min(normal[k] * b.lo[k], normal[k] * b.hi[k]);
      hi += std::max(normal[k] * b.lo[k], normal[k] * b.hi[k]);
    }
    return hi >= low && lo <= high;
  }
};

// The zone of the interfaces plane `planeId` made (an empty box if none),
// widened by 1e-9 of its box's diagonal for round-off.
CutZone cutZoneOf(const SurfaceComplex& c, int planeId)
{
  CutZone zone;
  zone.planeId = planeId;
  zone.normal = c.planes[planeId].normal;
  zone.low = std::numeric_limits<double>::infinity();
  zone.high = -zone.low;
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (region.planeId != planeId)
    {
      continue;
    }
    for (const DirectedEdge& e : region.edges)
    {
      const Vec3& p = c.points[e[0]];
      zone.box.add(p);
      zone.low = std::min(zone.low, dot(zone.normal, p));
      zone.high = std::max(zone.high, dot(zone.normal, p));
    }
  }
  const double margin = 1e-9 * norm(zone.box.hi - zone.box.lo);
  zone.low -= margin;
  zone.high += margin;
  return zone;
}

// The interface regions of a part and what a cut did to them. A region of
// one of the cut's two parts that reaches into the zone of the new interface
// (`cut`) may have been split by the cut, and is triangulated anew as a
// whole (missed at first: a piece of example005's first interface crossed a
// surface triangle far from the cut that split it, K = 10); so may a region
// another part shares with them, or one that got a point of the cut (at
// index `firstNewPoint` or above) on an edge it shares with a split one. A
// flat one is a section of the part by its plane, which no face of the part
// crosses, however it is triangulated, but for the faces of bent regions. A
// region bent through points left off its plane (snapped vertices of the
// input, moved chord points) differs from the section only around those
// points: within the box of the surface triangles at each (`zones`), where
// the section runs through these triangles and the region's boundary runs
// through the point.
struct PartRegions
{
  std::vector<const InterfaceRegion*> regions;
  std::vector<std::vector<Index>> points;
  std::vector<Box> boxes;
  std::vector<Box> zones;
  std::vector<Index> zonePoints; // the point of each zone
  // the new interface bends (a region of the cut's plane has points off it);
  // its bent points get no zone of their own: its faces, and every face
  // that may cross them, reach into the cut's zone, which is near for the
  // cut's two parts (hasCut)
  bool cutBent = false;
  bool hasCut = false;
  CutZone cut;
};

PartRegions regionsOfPart(
  const SurfaceComplex& c, int cell, const CutZone& cut, int below, int above, Index firstNewPoint)
{
  PartRegions r;
  const double roundOff = 1e-10 * norm(cut.box.hi - cut.box.lo);
  const bool cutPart = cell == below || cell == above;
  std::vector<char> changed;
  std::vector<Box> changedBoxes;
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (region.pair[0] != cell && region.pair[1] != cell)
    {
      continue;
    }
    r.regions.push_back(&region);
    r.points.push_back(regionPoints(region));
    Box box;
    for (Index v : r.points.back())
    {
      box.add(c.points[v]);
    }
    r.boxes.push_back(box);
    const bool shared = region.pair[0] == below || region.pair[0] == above || region.pair[1] == below ||
      region.pair[1] == above;
    changed.push_back((cutPart || shared || hasPointFrom(region, firstNewPoint)) && cut.reaches(box));
    if (changed.back())
    {
      changedBoxes.push_back(box);
    }
  }
  // The bent points of a changed region, and of every region reaching into
  // a changed one: a flat region is the section only where no bent face of
  // the part pokes through its plane (TCMT1107_4, K = 16: a flat interface
  // that got a point was triangulated anew across a bent one's triangles).
  std::unordered_map<Index, std::size_t> zoneOf;
  for (std::size_t k = 0; k < r.regions.size(); ++k)
  {
    const bool nearChanged = changed[k] ||
      std::any_of(changedBoxes.begin(), changedBoxes.end(), [&](const Box& b) { return b.overlaps(r.boxes[k]); });
    if (!nearChanged)
    {
      continue;
    }
    const CuttingPlane& plane = c.planes[r.regions[k]->planeId];
    const bool ofTheCut = r.regions[k]->planeId == cut.planeId;
    for (Index v : r.points[k])
    {
      const bool bent = std::fabs(dot(plane.normal, c.points[v] - plane.origin)) > roundOff;
      r.cutBent |= bent && ofTheCut;
      if (bent && !ofTheCut && !zoneOf.count(v))
      {
        zoneOf.emplace(v, r.zones.size());
        r.zones.emplace_back();
        r.zones.back().add(c.points[v]);
        r.zonePoints.push_back(v);
      }
    }
  }
  for (std::size_t i = 0; i < c.triangles.size() && !zoneOf.empty(); ++i)
  {
    const Triangle& t = c.triangles[i];
    if (c.trianglePairs[i][0] != cell || c.trianglePairs[i][1] != -1)
    {
      continue;
    }
    for (Index v : t)
    {
      const auto it = zoneOf.find(v);
      for (Index w : t)
      {
        if (it != zoneOf.end())
        {
          r.zones[it->second].add(c.points[w]);
        }
      }
    }
  }
  return r;
}

// Appends the triangulation of region k of part `cell` to `part`. False if
// it cannot be triangulated.
bool appendRegion(const SurfaceComplex& c, int cell, const PartRegions& r, std::size_t k,
  const InterfaceTriangulationOptions& options, InterfaceTriangulationCache& triangulations,
  std::unordered_map<Index, Index>& local, TriangleSurface& part)
{
  const InterfaceRegion& region = *r.regions[k];
  const auto found = triangulations.triangulate(planarRegionOf(c, region, r.points[k]), options);
  const InterfaceTriangulationResult& tr = *found;
  if (!tr.ok)
  {
    return false;
  }
  std::vector<Index> ids;
  for (Index v : r.points[k])
  {
    auto [it, inserted] = local.emplace(v, static_cast<Index>(part.points.size()));
    if (inserted)
    {
      part.points.push_back(c.points[v]);
    }
    ids.push_back(it->second);
  }
  for (const Vec3& p : tr.triangulation.newPoints)
  {
    ids.push_back(static_cast<Index>(part.points.size()));
    part.points.push_back(p);
  }
  const bool outward = region.pair[0] == cell;
  for (const Triangle& t : tr.triangulation.triangles)
  {
    part.triangles.push_back(
      outward ? Triangle{ ids[t[0]], ids[t[1]], ids[t[2]] } : Triangle{ ids[t[0]], ids[t[2]], ids[t[1]] });
  }
  return true;
}

// Moves the triangles of `all` reaching into a zone (`inZone` of their
// box) into `part`, listed in `near`, with the faces at their corners (to
// close the fans there, which CGAL needs to see two faces meet); with
// `whole`, every triangle.
template <typename InZone>
void selectNear(TriangleSurface&& all, const InZone& inZone, bool whole, TriangleSurface& part,
  std::vector<Index>& near)
{
  std::vector<char> isNear(all.triangles.size(), 0), atNearCorner(all.points.size(), 0);
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
  {
    Box box;
    for (Index v : all.triangles[i])
    {
      box.add(all.points[v]);
    }
    isNear[i] = inZone(box);
    for (Index v : all.triangles[i])
    {
      atNearCorner[v] |= isNear[i];
    }
  }
  part.points = std::move(all.points);
  for (std::size_t i = 0; i < all.triangles.size(); ++i)
  {
    const Triangle& t = all.triangles[i];
    if (isNear[i])
    {
      near.push_back(static_cast<Index>(part.triangles.size()));
    }
    if (whole || atNearCorner[t[0]] || atNearCorner[t[1]] || atNearCorner[t[2]])
    {
      part.triangles.push_back(t);
    }
  }
}

// Each zone grown by the boxes of the triangles of `surface` at its point
// (`zoneAt`: the zone of a point of `surface`).
void growZones(const TriangleSurface& surface, const std::unordered_map<Index, std::size_t>& zoneAt,
  std::vector<Box>& zones)
{
  for (const Triangle& t : surface.triangles)
  {
    for (Index v : t)
    {
      const auto it = zoneAt.find(v);
      for (Index w : t)
      {
        if (it != zoneAt.end())
        {
          zones[it->second].add(surface.points[w]);
        }
      }
    }
  }
}

// The surface of part `cell` as triangles, for partCrossesItself: its
// surface triangles and the regions reaching into a zone as the
// triangulator refines them, unsmoothed (smoothing took a third of the
// cutter's time: ball of 41,000 triangles, K = 16, 10.5 s). Refined to the
// minimum angle alone, without the size bound, the cutter was 2.6 x faster
// (parallel planes, a ball of 23,592 triangles at K = 64) but judged cuts
// of OCCT's Bottom differently, and the run at K = 32 with parallel planes
// then failed in TetGen. The zones are grown by the region triangles at
// their points too (where interfaces meet inside the object a point has no
// surface triangle). The faces reaching into a zone are listed in `near`;
// without `whole` the rest is left out (but the faces at their corners,
// which close their fans for CGAL). With it, the regions far from every
// zone are triangulated the least refined way (they only close the
// surface). False if a region cannot be triangulated.
bool partSurface(const SurfaceComplex& c, int cell, const PartRegions& r, bool whole,
  InterfaceTriangulationCache& triangulations, TriangleSurface& part, std::vector<Index>& near)
{
  InterfaceTriangulationOptions refined;
  refined.smooth = false;
  std::vector<Box> zones = r.zones;
  auto inZone = [&](const Box& box) {
    return (r.hasCut && r.cut.reaches(box)) ||
      std::any_of(zones.begin(), zones.end(), [&](const Box& z) { return z.overlaps(box); });
  };
  std::unordered_map<Index, Index> local;
  TriangleSurface all;
  std::vector<char> appended(r.regions.size(), 0);
  auto appendNearRegions = [&]() {
    for (std::size_t k = 0; k < r.regions.size(); ++k)
    {
      if (!appended[k] && inZone(r.boxes[k]))
      {
        appended[k] = 1;
        if (!appendRegion(c, cell, r, k, refined, triangulations, local, all))
        {
          return false;
        }
      }
    }
    return true;
  };
  if (!appendNearRegions())
  {
    return false;
  }
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    const Triangle& t = c.triangles[i];
    if (c.trianglePairs[i][0] == cell && c.trianglePairs[i][1] == -1)
    {
      Triangle ids{};
      for (int j = 0; j < 3; ++j)
      {
        ids[j] = local.emplace(t[j], static_cast<Index>(all.points.size())).first->second;
        if (ids[j] == static_cast<Index>(all.points.size()))
        {
          all.points.push_back(c.points[t[j]]);
        }
      }
      all.triangles.push_back(ids);
    }
  }
  std::unordered_map<Index, std::size_t> zoneAt;
  for (std::size_t z = 0; z < zones.size(); ++z)
  {
    const auto it = local.find(r.zonePoints[z]);
    if (it != local.end())
    {
      zoneAt.emplace(it->second, z);
    }
  }
  growZones(all, zoneAt, zones);
  if (!appendNearRegions())
  {
    return false;
  }
  InterfaceTriangulationOptions cover;
  cover.minimumAngleDegrees = 1.0;
  cover.maximumEdgeLength = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < r.regions.size() && whole; ++k)
  {
    if (!appended[k] && !appendRegion(c, cell, r, k, cover, triangulations, local, all))
    {
      return false;
    }
  }
  selectNear(std::move(all), inZone, whole, part, near);
  return true;
}

// Whether the surface of part `cell` crosses itself where a cut of `below`
// and `above` changed it (within `cut`, the zone of the new interface),
// checked with CGAL's exact predicates: the faces reaching into the zones
// of regionsOfPart, and for the two new parts into the cut's zone. Farther
// faces are as they were, already checked (with the input or the parent
// part). Only the near faces are handed to CGAL when they form a polygon
// mesh by themselves: building the whole part for every check made the
// cutter's time grow with K (a ball of 23,592 triangles, K = 64, recursive
// bisection: 62 % of 8.6 s; the neighbours of a part cut early are whole
// halves). A region that cannot be triangulated counts as crossing.
bool partCrossesItself(const SurfaceComplex& c, int cell, const CutZone& cut, int below, int above,
  Index firstNewPoint, InterfaceTriangulationCache& triangulations)
{
  PartRegions r = regionsOfPart(c, cell, cut, below, above, firstNewPoint);
  if (r.zones.empty() && !r.cutBent)
  {
    return false;
  }
  // the new interface's zone too: without it the check let through cuts
  // the whole-part check had refused, and CGAL's spool at K = 64 with
  // parallel planes then had a subdomain crossing itself (OpenSCAD's
  // example005 one TetGen could not mesh); with it both mesh as before
  r.hasCut = cell == below || cell == above;
  r.cut = cut;
  TriangleSurface patch;
  std::vector<Index> near;
  if (!partSurface(c, cell, r, false, triangulations, patch, near))
  {
    return true;
  }
  SelfIntersectionReport report = checkPatchSelfIntersection(patch, near);
  if (report.checked)
  {
    return report.intersects;
  }
  TriangleSurface part;
  near.clear();
  if (!partSurface(c, cell, r, true, triangulations, part, near))
  {
    return true;
  }
  report = checkSelfIntersection(part, near);
  return !report.checked || report.intersects;
}

// What every process found in a check shared among them
// (DecompositionOptions::checksPart): the largest `found` over the
// processes (options.maxOverProcesses; `found` alone without it), 0 none
// crossing, 1 one. Throws `failure` (with `why`, this process's reason, or
// "on another process") where a process's check threw (kCheckFailed).
int agreeOnCheck(const DecompositionOptions& options, int found, const std::string& why, const std::string& failure)
{
  if (options.maxOverProcesses)
  {
    found = options.maxOverProcesses(found);
  }
  if (found >= kCheckFailed)
  {
    throw std::runtime_error(failure + (why.empty() ? std::string(" on another process") : ": " + why));
  }
  return found;
}

// Splits a copy of the complex by the plane n . x = at; `missing` is the
// volume the part below lacks, `area` the cross-section (the rate at
// which the volume changes with the offset).
struct Trial
{
  bool ok = false;
  SurfaceComplex complex;
  PlaneSplitStats stats;
  double missing = 0, area = 0;
  double offset = 0; // of the split actually made (a pinch may move it a hair)
  std::vector<Index> notchPoints; // ends of notch bottoms a trial plane ran along (sorted)
  Vec3 normal{ 0, 0, 0 };
  double error = std::numeric_limits<double>::infinity();
};

// Cuts `cell` so that the part below holds `fraction` of its measure. The
// offset from the measure function is only a start: snapping vertices onto
// the plane moves volume, so the split is tried on a copy, measured, and the
// offset corrected (Newton with the cross-section area) until the part
// below is within a quarter of the tolerance of one subdomain; if snapping
// makes that impossible, it is halved step by step down to 0.001 (never 0:
// a vertex a hair's breadth from the plane would leave a degenerate sliver).
// Each trial splits a copy of the complex; only run() changes it, once.
struct PartCut
{
  PartCut(SurfaceComplex& complex, const DecompositionOptions& options, DecompositionResult& result,
    int cell, double fraction, int parts, int below, int above, double solveTolerance,
    InterfaceTriangulationCache& triangulations);
  bool run(const Vec3& proposedNormal, std::string& error);

  Trial tryCut(const Vec3& n, double at, double snap);
  Trial clearestBalancedCut(const Vec3& n, Trial&& balanced, double& at);
  double clearanceBudget() const
  {
    return 0.8 * allowed / (1.0 + std::log(static_cast<double>(parts)));
  }
  double predictedClearance(const Vec3& n) const;
  Vec3 clearerNormal(const Vec3& normal, const NearlyContinuedLine& continued) const;
  Trial balancedCut(const Vec3& n, double& at, bool& tooThin);
  bool interfacesValid(const Trial& trial) const;
  bool soundParts(const Trial& trial) const;
  bool anyPartCrosses(const SurfaceComplex& trialComplex, const std::set<int>& parts, const CutZone& cut) const;
  Trial soundCutInstead(Trial&& unsound, const Vec3& proposed);
  bool cutAlongEarlierLine(const NearlyContinuedLine& continued, const Vec3& normal,
    const Vec3& proposedNormal, double bestOffset, Trial& best);

  SurfaceComplex& c;
  const DecompositionOptions& options;
  DecompositionResult& result;
  const int cell, parts, below, above;
  const double fraction, solveTolerance;
  const int planeId;
  const bool volumeCriterion;
  double target = 0;          // volume wanted below the plane
  double allowed = 0;         // its error allowed: a quarter of the tolerance of one subdomain
  Vec3 centroid{ 0, 0, 0 };   // of the part's points: each plane's origin is put nearest to it
  std::vector<PointSpacing> spacing; // of the part, for PlaneClearance
  std::string lastError;
  InterfaceTriangulationCache& triangulations; // the decomposition's, for the checks of trials
};

PartCut::PartCut(SurfaceComplex& complex, const DecompositionOptions& options_,
  DecompositionResult& result_, int cell_, double fraction_, int parts_, int below_, int above_,
  double solveTolerance_, InterfaceTriangulationCache& triangulations_)
  : c(complex)
  , options(options_)
  , result(result_)
  , cell(cell_)
  , parts(parts_)
  , below(below_)
  , above(above_)
  , fraction(fraction_)
  , solveTolerance(solveTolerance_)
  , planeId(static_cast<int>(complex.planes.size()))
  , volumeCriterion(options_.criterion == BalanceCriterion::Volume ||
      options_.criterion == BalanceCriterion::PredictedCost)
  , triangulations(triangulations_)
{
  const double cellVolume = volumeCriterion ? labelVolume(c, cell) : 0.0;
  target = fraction * cellVolume;
  allowed = 0.25 * options.balanceTolerance * cellVolume / parts;
  const std::vector<Index> points = cellPoints(c, cell);
  for (Index p : points)
  {
    centroid = centroid + c.points[p];
  }
  centroid = (1.0 / std::max<double>(1.0, static_cast<double>(points.size()))) * centroid;
  spacing = shortestEdges(c, cell);
}

// A split that pinches a part (PlaneSplitStats::pinchedPoints) or leaves
// a snapped vertex poking through its new interface (coveredPokes) is tried
// again without snapping those vertices; one pinched at a vertex
// exactly on the plane is tried again a hair off it (a thousandth of the
// mean edge), and so is one whose surface touches the new interface at a
// vertex on the plane (touchingSide: moved so the vertex lies on its
// faces' side). The balance loops correct the offset, and the clearance
// search below moves it further, off the bottom of a notch the plane ran
// along too: Trial::notchPoints count for it even on the plane. (Counting
// the points of every pinch so, OCCT's Bottom at K = 16 with recursive
// bisection had other cuts, and TetGen crashed on one subdomain.) Never
// shipped pinched: on the triple torus (19 vertices) such cuts made 1 to 2
// of K subdomains self-intersecting at K = 4, 6, 8, 9, 10, 11, 12, 16, 20,
// 24, 32, 48, 64.
Trial PartCut::tryCut(const Vec3& n, double at, double snap)
{
  Trial trial;
  PlaneSplitOptions splitOptions;
  splitOptions.snapFraction = snap;
  std::vector<Index> notches;
  for (int attempt = 0; attempt < 8; ++attempt)
  {
    trial.complex = c;
    trial.stats = PlaneSplitStats();
    trial.offset = at;
    trial.normal = n;
    CuttingPlane plane;
    plane.normal = n;
    plane.origin = centroid - (dot(n, centroid) - at) * n;
    plane.cutSubdomainCount = parts;
    trial.complex.planes.push_back(plane);
    splitOptions.snapFraction = snap;
    if (splitCell(trial.complex, cell, n, at, planeId, below, above, splitOptions, trial.stats, lastError))
    {
      trial.ok = true;
      break;
    }
    if (trial.stats.pinchedPoints.empty() && trial.stats.coveredPokes.empty() && trial.stats.touchingSide == 0)
    {
      return trial;
    }
    if (trial.stats.pinchedOnPlane)
    {
      at += 1e-3 * result.inputMeanEdgeLength;
    }
    at -= trial.stats.touchingSide * (1e-3 * result.inputMeanEdgeLength + trial.stats.touchingDistance);
    std::vector<Index>& keep = splitOptions.keepOffPlane;
    keep.insert(keep.end(), trial.stats.pinchedPoints.begin(), trial.stats.pinchedPoints.end());
    keep.insert(keep.end(), trial.stats.coveredPokes.begin(), trial.stats.coveredPokes.end());
    std::sort(keep.begin(), keep.end());
    keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
    if (trial.stats.pinchedAtNotch)
    {
      notches.insert(notches.end(), trial.stats.pinchedPoints.begin(), trial.stats.pinchedPoints.end());
    }
  }
  if (!trial.ok)
  {
    return trial;
  }
  std::sort(notches.begin(), notches.end());
  notches.erase(std::unique(notches.begin(), notches.end()), notches.end());
  trial.notchPoints = std::move(notches);
  trial.missing = volumeCriterion ? labelVolume(trial.complex, below) - target : 0.0;
  trial.error = std::fabs(trial.missing);
  trial.area = trial.stats.interfaceEdges == 0
    ? 0.0
    : std::fabs(dot(n, vectorArea(trial.complex.points, trial.complex.interfaces.back().edges)));
  return trial;
}

// Within the balance budget, the offset that keeps the plane farthest
// from the part's points (PlaneClearance): the balanced offset alone
// lands on points of round coordinates on CAD parts (planes through
// vertices, faces lying in the plane) and crosses thin triangles near
// their corners, leaving contour segments of a hair's length and sliver
// triangles for TetGen. The volume is linear in the offset near the
// balanced one (slope: the cross-section area), so the offsets whose
// error stays within a budget form an interval; the split at the clearest
// offset in it is made and kept only if really balanced. The budget is
// 0.8 of the allowed error over 1 + ln(parts): with parallel planes the
// error of each slab is passed on to the rest, and the last slabs add up
// 1/(K-1) + 1/(K-2) + ... of them, about ln K; at 0.8 of the allowed error
// alone, the triple torus by 64 parallel planes reached an imbalance of
// 0.0081 against the tolerance of 0.01. Points exactly on the plane do not
// lower the clearance (a plane through a face is a clean cut), except the
// ends of a notch bottom a trial ran along: OpenSCAD's example024 at K = 16
// (parallel planes) had its plane put back a thousandth of an edge off the
// bottom of a notch, and TetGen crashed on the sliver layer left between
// notch and interface.
Trial PartCut::clearestBalancedCut(const Vec3& n, Trial&& balanced, double& at)
{
  const double budget = clearanceBudget();
  const double low = at + std::min(0.0, (-budget - balanced.missing) / balanced.area);
  const double high = at + std::max(0.0, (budget - balanced.missing) / balanced.area);
  const PlaneClearance clearance(c, spacing, n, balanced.notchPoints);
  const double clearest = clearance.clearestOffset(low, high, at, kEnoughClearance);
  if (clearest == at || !(clearance.at(clearest) > clearance.at(at)))
  {
    return std::move(balanced);
  }
  Trial moved = tryCut(n, clearest, options.snapFraction);
  if (moved.ok && moved.error <= allowed)
  {
    ++result.clearedPlanes;
    at = moved.offset;
    return moved;
  }
  return std::move(balanced);
}

// The clearance (PlaneClearance) the cut with normal n can reach, predicted
// without splitting: the balanced offset from the measure function, the
// budget window of clearestBalancedCut around it (its width from the
// measure's slope, the cross-section area), and the clearest offset in it.
// Below 0 where the plane would miss the part.
double PartCut::predictedClearance(const Vec3& n) const
{
  const HalfSpaceMeasure measure(c, cell, n, options.criterion);
  const double at = measure.offsetForFraction(fraction, solveTolerance);
  const double span = measure.maximumOffset() - measure.minimumOffset();
  if (!(at > measure.minimumOffset() && at < measure.maximumOffset()) || !(span > 0))
  {
    return -1.0;
  }
  const double step = 1e-4 * span;
  const double area = (measure.below(at + step) - measure.below(at - step)) / (2.0 * step);
  const double budget = clearanceBudget();
  const double half = area > 0 ? std::min(budget / area, 0.5 * span) : 0.0;
  const PlaneClearance clearance(c, spacing, n);
  return std::min(kEnoughClearance,
    clearance.at(clearance.clearestOffset(at - half, at + half, at, kEnoughClearance)));
}

// Tilting a plane by a few degrees keeps its parts balanced and nearly as
// compact, but can take it off the faces it would cross at a shallow angle
// and off the points it would pass a hair from: on the triple torus at
// K = 64 (recursive bisection), 21 of 63 cuts had a clearance under 0.05,
// and the worst tetrahedra (0.008 degrees) lay in the wedge where a cut
// crossed an input edge running at 0.29 degrees to it. When the proposed
// normal's clearance is poor, normals tilted by up to tiltDegrees in eight
// directions are scored by predictedClearance, and the clearest one is
// taken if it is clearly better. A normal turned parallel to an earlier
// line (PlaneAlignment) is kept: tilted about that line, it made interface
// triangles with angles of 1e-13 degrees on the unit tests' surfaces.
Vec3 PartCut::clearerNormal(const Vec3& normal, const NearlyContinuedLine& continued) const
{
  if (!volumeCriterion || !(options.tiltDegrees > 0) || continued.found)
  {
    return normal;
  }
  double bestScore = predictedClearance(normal);
  if (bestScore >= kGoodClearance)
  {
    return normal;
  }
  Vec3 u{ 0, 0, 0 }, v{ 0, 0, 0 };
  planeBasis(normal, u, v);
  const int directions = 8;
  Vec3 best = normal;
  for (double fraction : { 0.3, 0.6, 1.0 })
  {
    const double tilt = fraction * options.tiltDegrees * kPi / 180.0;
    for (int k = 0; k < directions; ++k)
    {
      const double azimuth = 2.0 * kPi * k / directions;
      const Vec3 sideways = std::cos(azimuth) * u + std::sin(azimuth) * v;
      const Vec3 n = normalized(std::cos(tilt) * normal + std::sin(tilt) * sideways);
      const double score = predictedClearance(n);
      if (score > kClearlyBetter * bestScore && score > bestScore)
      {
        bestScore = score;
        best = n;
      }
    }
  }
  return best;
}

// The balanced cut with normal n: the offset from the measure function,
// corrected by Newton steps on the real split, with snapping reduced
// when it keeps the balance out of reach. No trial at all if the part
// has no extent along n (tooThin). A measure whose total is not positive
// is no guide (OpenFOAM's bullet at K = 40 by bisection: -1.4e-8 along the
// normal of its 33rd cut, for a part made with +2.2e-8; every such run
// failed, saying the subdomains were too many): the trials then start
// from the middle of the part and the bisection on the real split below
// finds the plane. So does a guide that lands on an end of the part,
// which no fraction between 0 and 1 can do: OpenFOAM's flange at K = 64
// by bisection (PredictedCost, session 44) had the measure of the part
// its 53rd cut split solve the fraction 0.258 to the part's top, and the
// run failed the same way.
Trial PartCut::balancedCut(const Vec3& n, double& at, bool& tooThin)
{
  const HalfSpaceMeasure measure(c, cell, n, options.criterion);
  const double middle = 0.5 * (measure.minimumOffset() + measure.maximumOffset());
  const double guided = measure.total() > 0 ? measure.offsetForFraction(fraction, solveTolerance) : middle;
  const bool inside = guided > measure.minimumOffset() && guided < measure.maximumOffset();
  double offset = inside ? guided : middle;
  Trial best;
  at = offset;
  tooThin = !(offset > measure.minimumOffset() && offset < measure.maximumOffset());
  if (tooThin)
  {
    return best;
  }
  auto keepIfBetter = [&](Trial&& trial) {
    if (trial.ok && trial.error < best.error)
    {
      at = trial.offset;
      best = std::move(trial);
    }
  };
  const double smallestSnap = std::min(options.snapFraction, 0.001);
  for (double snap = options.snapFraction;; snap = std::max(0.5 * snap, smallestSnap))
  {
    for (int attempt = 0; attempt < 4; ++attempt)
    {
      Trial trial = tryCut(n, offset, snap);
      const bool ok = trial.ok;
      const double missing = trial.missing, area = trial.area;
      offset = trial.ok ? trial.offset : offset;
      keepIfBetter(std::move(trial));
      if (!ok || best.error <= allowed || !(area > 0))
      {
        break;
      }
      offset -= missing / area;
    }
    if (best.error <= allowed || snap <= smallestSnap)
    {
      break;
    }
  }
  // Safety net: if the measure function's start led nowhere (seen with a
  // part of two bodies bounded by two nearly parallel interfaces, where
  // the start fell in the gap between them), bisect on the real split.
  if (volumeCriterion && best.error > allowed)
  {
    double lo = measure.minimumOffset(), hi = measure.maximumOffset();
    for (int step = 0; step < 60 && best.error > allowed; ++step)
    {
      const double middle = 0.5 * (lo + hi);
      Trial trial = tryCut(n, middle, options.snapFraction);
      if (!trial.ok)
      {
        break;
      }
      (trial.missing < 0 ? lo : hi) = middle;
      keepIfBetter(std::move(trial));
    }
  }
  if (volumeCriterion && best.ok && best.error <= allowed && best.area > 0)
  {
    best = clearestBalancedCut(n, std::move(best), at);
  }
  return best;
}

// The interfaces of the two new parts must still be triangulable (closed
// loops that neither cross nor touch); an aligned cut that is not falls
// back to the one it improves on.
bool PartCut::interfacesValid(const Trial& trial) const
{
  const SurfaceComplex& t = trial.complex;
  for (const InterfaceRegion& region : t.interfaces)
  {
    if (region.pair[0] != below && region.pair[0] != above && region.pair[1] != below &&
      region.pair[1] != above)
    {
      continue;
    }
    InterfaceTriangulationOptions check;
    check.refine = false;
    if (!triangulateInterface(planarRegionOf(t, region, regionPoints(region)), check).ok)
    {
      return false;
    }
  }
  return true;
}

// Neither new part may cross itself. Their interfaces must be triangulable
// (closed loops that neither cross nor touch; a cheap check of the
// boundaries, always made). And where the split snapped points onto the
// plane without moving them (vertices of the input) or moved chord points,
// the interfaces bend and may cross a face at a shallow angle (the triple
// torus at K = 14, example002 at K = 12): then the parts near the new
// interface are checked with CGAL, when the input is checked too and the
// complex is within the input check's size limit. A split that snapped and
// moved nothing has flat interfaces made of the plane's section of the part,
// which no face of the part crosses; checking those too made CGAL's knot2
// (11,520 triangles) at K = 64 take 4.5 s instead of 0.8 s.
bool PartCut::soundParts(const Trial& trial) const
{
  if (!interfacesValid(trial))
  {
    return false;
  }
  const double before = labelVolume(c, cell);
  if (!volumesAddUp(trial.complex,
        labelVolume(trial.complex, below) + labelVolume(trial.complex, above), before))
  {
    return false;
  }
  if (!options.inputCheck.checkSelfIntersections ||
    trial.complex.triangles.size() > options.inputCheck.selfIntersectionLimit)
  {
    return true;
  }
  // The parts across the interfaces the cut split changed too: their side
  // of a split region is triangulated anew (example005 at K = 10: a piece of
  // the first interface crossed a surface triangle of the part on its other
  // side, never checked).
  const CutZone cut = cutZoneOf(trial.complex, planeId);
  if (!(cut.box.lo[0] <= cut.box.hi[0]))
  {
    return true; // no interface: the plane passed between bodies of the part
  }
  std::set<int> parts{ below, above };
  // So do the parts of a region that got a point of this cut without being
  // split (an edge it shares with a split region was split): a region of
  // another plane bent at the new point may fold onto a neighbour (FreeCAD's
  // TCMT1107_4, K = 16, bisection: plane 10 split an edge where planes 0 and
  // 5 meet, bent off plane 5, and subdomain 4's plane-5 interface then
  // crossed its plane-6 one; no check saw it).
  const Index firstNewPoint = static_cast<Index>(c.points.size());
  for (const InterfaceRegion& region : trial.complex.interfaces)
  {
    const bool gotPoint = hasPointFrom(region, firstNewPoint);
    for (int k = 0; k < 2; ++k)
    {
      const int other = region.pair[1 - k];
      if ((gotPoint || region.pair[k] == below || region.pair[k] == above) && other >= 0)
      {
        parts.insert(other);
      }
    }
  }
  return !anyPartCrosses(trial.complex, parts, cut);
}

// Whether one of `parts` crosses itself (partCrossesItself), with the checks
// shared among processes where options.checksPart is set (see there).
bool PartCut::anyPartCrosses(const SurfaceComplex& trialComplex, const std::set<int>& parts, const CutZone& cut) const
{
  int found = 0;
  std::string why;
  try
  {
    for (auto it = parts.begin(); it != parts.end() && found == 0; ++it)
    {
      if ((!options.checksPart || options.checksPart(*it)) &&
        partCrossesItself(
          trialComplex, *it, cut, below, above, static_cast<Index>(c.points.size()), triangulations))
      {
        found = 1;
      }
    }
  }
  catch (const std::exception& e)
  {
    if (!options.maxOverProcesses)
    {
      throw;
    }
    found = kCheckFailed; // still joins the collective, so no process waits for this one
    why = e.what();
  }
  return agreeOnCheck(options, found, why, "the check that a cut's parts do not cross themselves failed") == 1;
}

// A cut whose parts cross themselves is never shipped. Seen only where
// vertices snapped onto the plane stay off it (vertices of the input do
// not move), so the interface bends through them while a surface
// triangle at a shallow angle to the plane passes under it: on the
// triple torus at K = 14 and the OpenSCAD example002 at K = 12, whose
// edges of about 10 units snap vertices up to 0.5 off the plane. First
// the same plane without snapping, then the balanced cuts across the
// proposed normal and the three axes, each with and without snapping;
// if none is sound, the decomposition fails with a message.
Trial PartCut::soundCutInstead(Trial&& unsound, const Vec3& proposed)
{
  ++result.rejectedCuts;
  std::vector<std::pair<Vec3, bool>> tries{ { unsound.normal, false } };
  for (const Vec3& n : { proposed, Vec3{ 1, 0, 0 }, Vec3{ 0, 1, 0 }, Vec3{ 0, 0, 1 } })
  {
    tries.push_back({ n, true });
  }
  for (const auto& [n, balance] : tries)
  {
    double offset = unsound.offset;
    bool thin = false;
    Trial trial = balance ? balancedCut(n, offset, thin) : Trial();
    if (balance && trial.ok && soundParts(trial))
    {
      return trial;
    }
    if (balance && (thin || !trial.ok))
    {
      continue;
    }
    Trial plain = tryCut(n, offset, 0.0);
    if (plain.ok && plain.error <= 2.0 * allowed && soundParts(plain))
    {
      return plain;
    }
  }
  lastError = "no balanced cut of a part kept both halves free of self-intersections";
  return Trial();
}

// Within half the surface's mean edge of the earlier line (and not on an
// edge of the part), a parallel line would leave a thin strip of poor
// triangles beside it: draw the very same line instead. A plane through
// that line rarely balances the part at first, so it turns about the
// line until it does (secant steps on the angle, at most the alignment
// angle). Accepted within half the tolerance of one subdomain, so that
// the errors of all levels of bisection still add up to less than the
// tolerance.
bool PartCut::cutAlongEarlierLine(const NearlyContinuedLine& continued, const Vec3& normal,
  const Vec3& proposedNormal, double bestOffset, Trial& best)
{
  bool alongLine = false;
  const double lineOffset = dot(normal, continued.linePoint);
  const bool nearLine = volumeCriterion && continued.found && !continued.boundsPart && best.ok &&
    std::fabs(bestOffset - lineOffset) < 0.5 * result.inputMeanEdgeLength;
  // First the earlier plane itself, when it is also within the alignment
  // angle of the proposed one: where several parts are cut by nearly one
  // plane (the four quarters of a ball, say), turning each through one
  // earlier line still leaves its other lines a hair apart; the same plane
  // leaves none.
  if (nearLine)
  {
    const CuttingPlane& earlier = c.planes[continued.planeId];
    const double cosine = dot(earlier.normal, proposedNormal);
    if (std::fabs(cosine) >= std::cos(options.alignmentAngleDegrees * kPi / 180.0))
    {
      const Vec3 n = cosine < 0 ? -1.0 * earlier.normal : earlier.normal;
      Trial same = tryCut(n, dot(n, earlier.origin), options.snapFraction);
      if (same.ok && same.error <= 2.0 * allowed && interfacesValid(same))
      {
        best = std::move(same);
        alongLine = true;
        ++result.alignedLines;
      }
    }
  }
  if (nearLine && !alongLine)
  {
    const Vec3 sideways = cross(continued.direction, normal);
    const double largestTurn = options.alignmentAngleDegrees * kPi / 180.0;
    Trial aligned;
    double angle0 = 0, missing0 = 0, angle1 = 0, missing1 = 0;
    for (int step = 0; step < 10 && aligned.error > allowed; ++step)
    {
      double angle = 0; // first the plane through the line as it is
      if (step == 1)
      {
        angle = 1e-3; // then a small turn, for the secant
      }
      else if (step > 1)
      {
        if (missing1 == missing0)
        {
          break;
        }
        angle = angle1 - missing1 * (angle1 - angle0) / (missing1 - missing0);
      }
      if (!(std::fabs(angle) <= largestTurn))
      {
        break;
      }
      const Vec3 n = normalized(std::cos(angle) * normal + std::sin(angle) * sideways);
      Trial trial = tryCut(n, dot(n, continued.linePoint), options.snapFraction);
      if (!trial.ok)
      {
        break;
      }
      angle0 = angle1;
      missing0 = missing1;
      angle1 = angle;
      missing1 = trial.missing;
      if (trial.error < aligned.error)
      {
        aligned = std::move(trial);
      }
    }
    if (aligned.ok && aligned.error <= 2.0 * allowed && interfacesValid(aligned))
    {
      best = std::move(aligned);
      alongLine = true;
      ++result.alignedLines;
    }
  }
  return alongLine;
}

bool PartCut::run(const Vec3& proposedNormal, std::string& error)
{
  // A plane whose line on one of the part's interfaces nearly runs along
  // a line already drawn there turns so that the two are parallel and
  // never cross at a tiny angle (PlaneAlignment.h).
  const NearlyContinuedLine continued =
    findNearlyContinuedLine(c, cell, proposedNormal, options.alignmentAngleDegrees);
  const Vec3 normal =
    clearerNormal(continued.found ? continued.parallelNormal : proposedNormal, continued);
  result.tiltedCuts += normal != proposedNormal && !continued.found ? 1 : 0;

  double bestOffset = 0;
  bool tooThin = false;
  Trial best = balancedCut(normal, bestOffset, tooThin);
  if (tooThin)
  {
    error = "the subdomains are too many for this surface: a part cannot be cut further";
    return false;
  }
  const bool alongLine = cutAlongEarlierLine(continued, normal, proposedNormal, bestOffset, best);
  if (continued.found && !alongLine && !(best.ok && interfacesValid(best)))
  {
    // the parallel cut is no good either: the plane the part asked for
    Trial proposed = balancedCut(proposedNormal, bestOffset, tooThin);
    if (proposed.ok)
    {
      best = std::move(proposed);
    }
  }
  if (continued.found)
  {
    ++result.alignedNormals;
  }
  if (best.ok && !soundParts(best))
  {
    best = soundCutInstead(std::move(best), proposedNormal);
  }
  if (!best.ok)
  {
    // every split failed (with a reason), or none gave a finite volume
    error = lastError.empty() ? "no cut of a part gave a finite volume" : lastError;
    return false;
  }
  c = std::move(best.complex);
  result.splitStats.splitTriangles += best.stats.splitTriangles;
  result.splitStats.snappedPoints += best.stats.snappedPoints;
  result.splitStats.chordPoints += best.stats.chordPoints;
  result.splitStats.crossingsWithin10Percent += best.stats.crossingsWithin10Percent;
  result.splitStats.crossingsWithin1Percent += best.stats.crossingsWithin1Percent;
  return true;
}

// Whether the cuts balance predicted cost (BalanceCriterion::PredictedCost):
// the size field's, or without one predictUniformCost's at the mesher's
// largest size (regular tetrahedra and the pieces of the input surface).
bool cutsByCost(const DecompositionOptions& options)
{
  return options.criterion == BalanceCriterion::PredictedCost;
}

// The mesher's largest size: costMaximumSize, or (0) its automatic size,
// the input's mean edge.
double largestMeshSize(const DecompositionOptions& options, const DecompositionResult& result)
{
  return options.costMaximumSize > 0 ? options.costMaximumSize : result.inputMeanEdgeLength;
}

// The field whose cost is balanced: no larger than the mesher's largest size.
SizeFunction costField(const DecompositionOptions& options, const DecompositionResult& result)
{
  return cappedSize(options.costSize, largestMeshSize(options, result));
}

// The complex of the whole checked surface, all of it part 0; false (with
// the input check's error in result) if the check refused the surface.
bool startComplex(PreparedSurface prepared, DecompositionResult& result, double& totalVolume)
{
  result.inputCheck = prepared.counts;
  result.warnings = prepared.warnings;
  if (!prepared.ok)
  {
    result.error = prepared.error;
    return false;
  }
  result.orientation = prepared.orientation;
  totalVolume = prepared.enclosedVolume;
  result.totalVolume = totalVolume;
  result.inputMeanEdgeLength = meanEdgeLength(prepared.surface);

  SurfaceComplex& c = result.complex;
  c.points = std::move(prepared.surface.points);
  c.triangles = std::move(prepared.surface.triangles);
  c.trianglePairs.assign(c.triangles.size(), SubdomainPair{ 0, -1 });
  c.sourceFaces = std::move(prepared.sourceOfTriangle);
  return true;
}

// Within 1e-13 of the diagonal: 1000 x the rounding of a computed crossing
// near the origin, 10 x under the 1e-12 that output points may lie off the
// input; far from it, 100 roundings of the coordinates (roundOffTolerance).
double flatTolerance(const SurfaceComplex& c)
{
  return roundOffTolerance(c.points, 1e-13);
}

/// @name The removal of flat crossings, checked
/// @{

// Whether the whole surface of subdomain `s` crosses itself, every region
// of it triangulated as partCrossesItself does near a cut (unsmoothed, at
// the default bounds), checked with CGAL's exact predicates. A region that
// cannot be triangulated counts as crossing.
bool subdomainCrossesItself(const SurfaceComplex& c, int s, InterfaceTriangulationCache& triangulations)
{
  CutZone everywhere; // reaches every box: every region is triangulated refined
  everywhere.normal = Vec3{ 1, 0, 0 };
  const double infinity = std::numeric_limits<double>::infinity();
  everywhere.box.lo = Vec3{ -infinity, -infinity, -infinity };
  everywhere.box.hi = Vec3{ infinity, infinity, infinity };
  everywhere.low = -infinity;
  everywhere.high = infinity;
  PartRegions r = regionsOfPart(c, s, everywhere, s, s, 0);
  r.hasCut = true;
  r.cut = everywhere;
  TriangleSurface part;
  std::vector<Index> near;
  if (!partSurface(c, s, r, true, triangulations, part, near))
  {
    return true;
  }
  const SelfIntersectionReport report = checkSelfIntersection(part);
  return !report.checked || report.intersects;
}

// Whether a point of the region is off its plane by more than `roundOff`.
bool isBent(const SurfaceComplex& c, const InterfaceRegion& region, double roundOff)
{
  const CuttingPlane& plane = c.planes[region.planeId];
  return std::any_of(region.edges.begin(), region.edges.end(), [&](const DirectedEdge& e) {
    return std::fabs(dot(plane.normal, c.points[e[0]] - plane.origin)) > roundOff;
  });
}

// The subdomains on either side of a region of `after` that lost a point
// to the removal (fewer loop edges than in `before`, region by region;
// every region if the regions differ) and is bent (a point of it off its
// plane by more than 1e-10 of the bounding-box diagonal). The removal keeps
// every planar star and flat region the same point set up to the flatness
// tolerance, so only a bent region, triangulated anew, can make a subdomain
// cross itself.
std::set<int> sidesOfBentShrunkRegions(const SurfaceComplex& before, const SurfaceComplex& after)
{
  std::set<int> sides;
  const bool sameRegions = before.interfaces.size() == after.interfaces.size();
  const double roundOff = 1e-10 * boundingBoxDiagonal(after.points);
  for (std::size_t k = 0; k < after.interfaces.size(); ++k)
  {
    const InterfaceRegion& region = after.interfaces[k];
    if (sameRegions && region.edges.size() == before.interfaces[k].edges.size())
    {
      continue;
    }
    const bool bent = isBent(after, region, roundOff);
    for (int side : region.pair)
    {
      if (side >= 0 && (bent || !sameRegions))
      {
        sides.insert(side);
      }
    }
  }
  return sides;
}

// The subdomains on either side of a bent region (as above) of one of
// `planes`: those a removal after each of these planes' cuts may have bent
// (Cutting::cut). A removal after plane i takes out only plane i's points,
// so only plane i's regions lose points.
std::set<int> sidesOfBentRegionsOn(const SurfaceComplex& c, const std::set<int>& planes)
{
  std::set<int> sides;
  const double roundOff = 1e-10 * boundingBoxDiagonal(c.points);
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (planes.count(region.planeId) && isBent(c, region, roundOff))
    {
      for (int side : region.pair)
      {
        if (side >= 0)
        {
          sides.insert(side);
        }
      }
    }
  }
  return sides;
}

// Of the subdomains `sides`, those that cross themselves
// (subdomainCrossesItself), the checks shared among processes as the cuts'
// are (options.checksPart; one maxOverProcesses per subdomain checked, the
// same number on every process).
std::set<int> crossingOf(const SurfaceComplex& c, const std::set<int>& sides, const DecompositionOptions& options,
  InterfaceTriangulationCache& triangulations)
{
  std::set<int> crossing;
  for (int s : sides)
  {
    int found = 0;
    std::string why;
    try
    {
      found = (!options.checksPart || options.checksPart(s)) && subdomainCrossesItself(c, s, triangulations);
    }
    catch (const std::exception& e)
    {
      if (!options.maxOverProcesses)
      {
        throw;
      }
      found = kCheckFailed; // still joins the collective, which then throws on every process
      why = e.what();
    }
    if (agreeOnCheck(options, found, why, "the check that taking out flat crossings made no subdomain cross itself "
                                          "failed") == 1)
    {
      crossing.insert(s);
    }
  }
  return crossing;
}

// Recursive bisection takes the flat crossings out once, after the last
// cut, and the cuts' own checks do not see that. On OCCT's Top and Bottom at
// K = 64 (volume balance, the cutter's defaults) it left subdomains 19, and
// 18 and 19, crossing themselves: the Top then failed in the mesher ("the
// surface of subdomain 19 is not closed"), in the GUI and pvbatch
// pipelines, which do not cut again. So the subdomains beside the bent
// regions the removal changed are checked whole (crossingOf), and
// where one crosses itself the removal is made again from the complex
// before it, keeping every point of the crossing subdomains; after
// kRemovalRounds rounds nothing is taken out. Returns the number of points
// taken out. Cost, the cutter alone on the 45 corpus surfaces at K = 16,
// 32, 64 (cases over 1 s, one process): 1.16 x by bisection; every
// subdomain the removal touched checked whole, 1.25 x; each one checked
// only where a plane's zone reaches (partCrossesItself), 1.28 x, as it
// checks a subdomain once per plane. Parallel planes' last removal is
// checked the same way: unchecked, it left subdomain 7 of OCCT's Bottom at
// K = 16 (by volume) crossing itself, and tetmesh.py failed on it in the
// mesher after 67 s of attempts, then recut keeping every flat crossing
// (2.57 M tetrahedra, 0.00 degrees). Their removals after each cut are
// checked once after the last cut (planesOfCrossingSlabs).
constexpr int kRemovalRounds = 4;

std::size_t removeCheckedFlatCrossings(SurfaceComplex& c, Index firstCutPoint, const DecompositionOptions& options,
  InterfaceTriangulationCache& triangulations, std::vector<char> keep, DecompositionResult& result)
{
  keep.resize(c.points.size(), 0);
  for (int round = 0; round < kRemovalRounds; ++round)
  {
    SurfaceComplex trial = c;
    const std::size_t count = removeFlatCrossings(trial, firstCutPoint, flatTolerance(c), options.faceGroups, &keep);
    const std::set<int> crossing = crossingOf(trial, sidesOfBentShrunkRegions(c, trial), options, triangulations);
    if (crossing.empty())
    {
      c = std::move(trial);
      return count;
    }
    std::ostringstream msg;
    msg << "taking out the flat crossings made " << crossing.size()
        << " subdomain(s) cross themselves (first: " << *crossing.begin() << "); their points were kept";
    result.warnings.push_back(msg.str());
    for (std::size_t i = 0; i < c.triangles.size(); ++i)
    {
      const auto& pair = c.trianglePairs[i];
      if (crossing.count(pair[0]) || crossing.count(pair[1]))
      {
        for (Index v : c.triangles[i])
        {
          keep[v] = 1;
        }
      }
    }
  }
  return 0;
}
/// @}

// The cuts of the decomposition. Parts are numbered as they are made (the
// whole object is part 0, every cut makes two new ones); leaves lists the
// final parts in subdomain order.
struct Cutting
{
  SurfaceComplex& c;
  const DecompositionOptions& options;
  DecompositionResult& result;
  const double solveTolerance;
  const Index inputPoints; // the points before the first cut
  InterfaceTriangulationCache& triangulations; // the trials' interface triangulations, kept across cuts
  const std::set<int>& keptPlanes; // parallel planes: the planes whose flat crossings stay (decomposeVolumeBalanced)
  bool keepPrevious = false;       // ... and the previous plane may be added to them (removalsBlockedCut)
  std::set<int> removedOnPlanes{}; // parallel planes: the planes whose removal after their cut took points out
  std::vector<char> keptPoints{};  // per point: made by the cut of a kept plane (1), or not (0, or past the end)
  std::set<int> planesToKeep{};    // parallel planes: the planes whose removal left a part crossing itself,
                                   // found when a later plane could not cut as asked (removalsBlockedCut)
  int nextCell = 1;
  std::vector<int> leaves{}; // cell ids in subdomain order
  std::string error{};

  CostSamples costSamples{}; // cutting by cost: the samples, following the cuts

  bool cut(int cell, const Vec3& proposedNormal, double fraction, int parts, int& below, int& above);
  bool removalsBlockedCut(bool ran, const Vec3& proposedNormal);
  bool parallelPlanes(int K);
  void warnOfTurnedPlanes(const std::vector<int>& turned, int K);
  bool bisect(int cell, int k);
};

// Parallel planes take the flat crossings out after every cut (Cutting::cut)
// unchecked, as checking the two parts of every cut made the planes' cuts
// 1.47 x slower. So after the last cut the subdomains beside the bent
// regions of the planes whose removals took points out are checked whole,
// once (and on the parts so far where a plane could not cut as asked,
// Cutting::removalsBlockedCut). Returns the planes beside those that cross themselves, with an
// error naming them in `result`; none if none does. `label` names what the
// complex's labels are: subdomains after the last cut, parts before.
std::set<int> planesOfCrossingSlabs(const Cutting& cutting, DecompositionResult& result, const char* label)
{
  const SurfaceComplex& c = cutting.c;
  const std::set<int> crossing =
    crossingOf(c, sidesOfBentRegionsOn(c, cutting.removedOnPlanes), cutting.options, cutting.triangulations);
  std::set<int> planes;
  for (const InterfaceRegion& region : c.interfaces)
  {
    if (cutting.removedOnPlanes.count(region.planeId) &&
      (crossing.count(region.pair[0]) || crossing.count(region.pair[1])))
    {
      planes.insert(region.planeId);
    }
  }
  if (!crossing.empty())
  {
    std::ostringstream msg;
    msg << "taking out the flat crossings after the cuts of " << planes.size() << " plane(s) (first: plane "
        << *planes.begin() << ") made " << crossing.size() << " " << label << "(s) cross themselves (first: "
        << *crossing.begin() << ")";
    result.error = msg.str();
    result.failedInCuts = true;
  }
  return planes;
}

// Cutting by cost: each part is cut by volume at the volume fraction that
// splits its cost samples as wanted, with the balance tolerance (of cost)
// made smaller in volume where the cost is denser than the part's mean;
// the samples follow the cuts.
bool Cutting::cut(int cell, const Vec3& proposedNormal, double fraction, int parts, int& below, int& above)
{
  below = nextCell++;
  above = nextCell++;
  DecompositionOptions partOptions = options;
  if (options.strategy == CutStrategy::ParallelPlanes)
  {
    partOptions.tiltDegrees = 0; // tilted, the planes would meet inside the object
  }
  if (cutsByCost(options))
  {
    const double costFraction = fraction;
    fraction = volumeFractionForCost(costSamples, c, cell, proposedNormal, fraction);
    partOptions.balanceTolerance *=
      std::min({ 1.0, fraction / costFraction, (1.0 - fraction) / (1.0 - costFraction) });
  }
  const Index firstNewPoint = static_cast<Index>(c.points.size());
  PartCut part(c, partOptions, result, cell, fraction, parts, below, above, solveTolerance, triangulations);
  const bool ran = part.run(proposedNormal, error);
  if (removalsBlockedCut(ran, proposedNormal) || !ran)
  {
    return false;
  }
  const CuttingPlane& plane = c.planes.back();
  moveSamples(costSamples, cell, plane.normal, dot(plane.normal, plane.origin), below, above);
  if (options.removeFlatCrossings && options.strategy == CutStrategy::ParallelPlanes)
  {
    // Parallel planes take the flat crossings out after every cut, not only
    // at the end: each plane cuts the rest, whose quad pieces' diagonals
    // the next plane crosses again, one more point per long triangle and
    // plane (FlatCrossingRemoval.h). On CGAL's pinion_small at K = 64 (1
    // rank) plane 62's interface had 15,085 contour points 2.4e-9 to 0.03
    // apart (plane 0's: 455), and the cutter's checks triangulated it into
    // 1.3 M triangles: the cut took 74 s, the mesh 1.0 M tetrahedra. Taken
    // out after every cut, the regions the checks triangulated had 5,894
    // boundary points in all (48,615 before), the cut took 4.6 s and the
    // mesh has 524 k tetrahedra. The price: a pass over the whole complex per cut,
    // 5-10 % of the cut (perf) on CGAL's refined_elephant (89 k triangles,
    // K = 64), which has no planar face and so nothing to take out.
    // Only the points this cut made are candidates. With every cut point a
    // candidate, a removal also took out earlier planes' points and could
    // leave the rest crossing itself: on OCCT's Top at K = 64 no try of
    // plane 45 was sound after plane 44's removal, and the whole
    // decomposition was cut again keeping every flat crossing (59,496
    // points instead of 27,461; 31.2 s instead of 11.3 s). Checking the
    // whole finished slab after each removal found nothing more on the
    // corpus (K = 16, 32, 64, by volume) and cost 7 %. Session 48 checked
    // the two parts of each cut beside the bent regions the removal shrank
    // (as bisection's last removal is, removeCheckedFlatCrossings): it
    // found OCCT's Bottom at K = 16 by predicted cost with part 10 crossing
    // itself and cut the Bottom at K = 64 by volume at once instead of
    // again keeping the flat crossings, but made the planes' cuts 1.47 x
    // slower on the corpus (cases over 1 s); not kept. Since session 49
    // the subdomains these removals bent are checked once, after the last
    // cut, and the planes beside one crossing itself are cut again keeping
    // their points (planesOfCrossingSlabs, keptPlanes).
    const int planeId = static_cast<int>(c.planes.size()) - 1;
    if (keptPlanes.count(planeId))
    {
      keptPoints.resize(c.points.size(), 0);
      std::fill(keptPoints.begin() + firstNewPoint, keptPoints.end(), 1);
    }
    else
    {
      const std::size_t count = removeFlatCrossings(c, firstNewPoint, flatTolerance(c), options.faceGroups);
      result.flatCrossingsRemoved += count;
      if (count > 0)
      {
        removedOnPlanes.insert(planeId);
      }
    }
  }
  return true;
}

/// @name Slabs thinner than the size
/// @{
// Parallel planes make K slabs whatever the object's extent along their
// normal. At K = 64 on the corpus at its sizes (serial TetGen making 50,000
// to 100,000 tetrahedra) the thinnest slab is 0.08 to 0.50 x the size on
// all 32 surfaces measured (0.32 to 1.0 x at K = 32). Such a slab is meshed much
// finer than asked between two interfaces crossing the same input
// triangles: CGAL's oblong at K = 64 (0.22 x) made 17 x serial TetGen's
// tetrahedra, and CGAL's pinion at K = 48 (0.30 x; 1.03 M interface
// triangles) failed after 332 s on a slab TetGen could not mesh in any input
// order. Thickness alone does not decide whether TetGen fails (OpenSCAD
// example005 at 0.08 x meshes), but the mesh grows and worsens as slabs thin
// (kMinimumSlabThickness), so before any cut it warns of slabs under the size
// and refuses slabs under options.minimumSlabThickness x the size, each with
// the largest K whose slabs are thick enough.

// The thinnest of the K equal-measure slabs of the whole object along
// `normal`: the offsets that split its measure in K.
double thinnestSlab(const SurfaceComplex& c, const Vec3& normal, BalanceCriterion criterion, int K)
{
  const HalfSpaceMeasure measure(c, 0, normal, criterion);
  double previous = measure.minimumOffset(), thinnest = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= K; ++i)
  {
    const double offset =
      i < K ? measure.offsetForFraction(static_cast<double>(i) / K, 1e-6) : measure.maximumOffset();
    thinnest = std::min(thinnest, offset - previous);
    previous = offset;
  }
  return thinnest;
}

// Whether a slab `slab` thick is at least `thickness`: the offsets are found
// to a tolerance.
bool atLeast(double slab, double thickness)
{
  return slab >= (1 - 1e-9) * thickness;
}

// The largest number of slabs, at most K - 1, whose thinnest is at least
// `thickness` (1 if none is): slabs thin about as 1 / K, so from that
// estimate down, one or two steps.
int largestSlabCount(const SurfaceComplex& c, const Vec3& normal, BalanceCriterion criterion, int K,
  double thinnest, double thickness)
{
  int largest = std::min(K - 1, static_cast<int>(std::ceil(K * thinnest / thickness)));
  while (largest > 1 && !atLeast(thinnestSlab(c, normal, criterion, largest), thickness))
  {
    --largest;
  }
  return std::max(largest, 1);
}

// Before any cut: a warning for slabs thinner than the size, a refusal (false
// with `error`) for slabs under options.minimumSlabThickness x the size.
bool checkSlabThickness(const SurfaceComplex& c, const Vec3& normal, const DecompositionOptions& options,
  DecompositionResult& result, std::string& error)
{
  const int K = options.numberOfSubdomains;
  const double size = largestMeshSize(options, result);
  const BalanceCriterion criterion = options.criterion; // HalfSpaceMeasure takes PredictedCost as Volume
  const double thinnest = thinnestSlab(c, normal, criterion, K);
  if (!(size > 0) || atLeast(thinnest, size))
  {
    return true;
  }
  const int thickEnough = largestSlabCount(c, normal, criterion, K, thinnest, size);
  std::ostringstream msg;
  msg.precision(3);
  msg << "ParallelPlanes with " << K << " subdomains cuts slabs as thin as " << thinnest << ", " << thinnest / size
      << " x the mesh size " << size;
  if (!(options.costMaximumSize > 0))
  {
    msg << " (the input's mean edge: MaximumSize, tetmesh.py --size, is 0; set it to the size you mesh at)";
  }
  // a size field may ask for much less than its cap `size` in the slabs, so
  // with one the slabs are only warned of
  const double floor = options.minimumSlabThickness * size;
  if (options.minimumSlabThickness > 0 && !options.costSize && !atLeast(thinnest, floor))
  {
    const int largest = largestSlabCount(c, normal, criterion, K, thinnest, floor);
    msg << ", under MinimumSlabThickness " << options.minimumSlabThickness
        << " x the size: refused before cutting. Such slabs are meshed far finer than the size asks, with poor "
           "tetrahedra between their two interfaces, and TetGen may fail on them. At most "
        << largest << " parallel slabs are " << options.minimumSlabThickness << " x the size thick (" << thickEnough
        << " as thick as the size). Use at most " << largest
        << " subdomains, RecursiveBisection (thicker parts), a smaller size, or MinimumSlabThickness 0 "
           "(tetmesh.py --minimum-slab-thickness 0) to cut them anyway";
    error = msg.str();
    result.refusedBeforeCutting = true;
    return false;
  }
  msg << ": they are meshed finer than the size asks, with poorer tetrahedra next to the interfaces, and TetGen "
         "may fail on them; at most "
      << thickEnough << " parallel slabs are as thick as the size (RecursiveBisection makes thicker parts)";
  result.warnings.push_back(msg.str());
  return true;
}
/// @}

// A parallel plane that could not cut as asked (it failed, or its cut
// turned off the planes' normal: soundCutInstead's other normals) may have
// been blocked by a part an earlier plane's removal of flat crossings left
// crossing itself, which the cut's checks count against every try. On
// OCCT's Bottom at K = 64 by volume, plane 13's removal left part 27
// crossing itself; every try of plane 14 at the planes' normal was refused
// for it, planes 14 to 17 were cut along x, no try of plane 18 was sound,
// and the whole decomposition was cut again keeping every flat crossing
// (still crossing itself). So the parts beside bent regions of planes with
// removals are checked whole then (planesOfCrossingSlabs, only on such a
// cut), and if one crosses itself the cut fails naming those planes, which
// decomposeKeepingCrossingPlanes keeps in its next round.
// Where no part crosses itself yet, the plane's own cut of the rest did: the
// rest is bounded by the previous plane's interface, which that plane's
// removal bent. With planes 12 and 13 kept, planes 16 to 20 of the Bottom
// were still turned (each slab below them crossed itself at the planes'
// normal); keeping plane 15's flat crossings too, the next round cut every
// plane at the normal (5 rounds, 9,482 points taken out instead of 8,132).
// So the previous plane is kept then too, where keepPrevious allows it
// (decomposeKeepingCrossingPlanes).
bool Cutting::removalsBlockedCut(bool ran, const Vec3& proposedNormal)
{
  if (options.strategy != CutStrategy::ParallelPlanes || !options.removeFlatCrossings || removedOnPlanes.empty())
  {
    return false;
  }
  if (ran && dot(c.planes.back().normal, proposedNormal) > 1.0 - 1e-12)
  {
    return false;
  }
  const std::string cutError = ran ? "" : error;
  planesToKeep = planesOfCrossingSlabs(*this, result, "part");
  const int previous = static_cast<int>(c.planes.size()) - (ran ? 2 : 1);
  if (planesToKeep.empty() && keepPrevious && removedOnPlanes.count(previous))
  {
    planesToKeep = { previous };
    result.error = "its cut of the rest crossed itself beside plane " + std::to_string(previous) +
      ", whose flat crossings were taken out";
    result.failedInCuts = true;
  }
  if (planesToKeep.empty())
  {
    return false;
  }
  error = "plane " + std::to_string(static_cast<int>(c.planes.size()) - (ran ? 1 : 0)) +
    " could not cut at the parallel planes' normal" + (cutError.empty() ? "" : " (" + cutError + ")") + ": " +
    result.error;
  return true;
}

// One direction for all planes; each plane cuts the rest of the object so
// that the slab below gets 1/(number of subdomains still to make) of it.
bool Cutting::parallelPlanes(int K)
{
  const Vec3 normal = cutNormal(c.points, cellPoints(c, 0), options.direction);
  if (!checkSlabThickness(c, normal, options, result, error))
  {
    return false;
  }
  int rest = 0;
  std::vector<int> turned;
  for (int i = 0; i < K - 1; ++i)
  {
    int below = 0, above = 0;
    if (!cut(rest, normal, 1.0 / (K - i), K - i, below, above))
    {
      return false;
    }
    if (std::fabs(dot(c.planes.back().normal, normal)) < 1.0 - 1e-12)
    {
      turned.push_back(static_cast<int>(c.planes.size()) - 1);
    }
    leaves.push_back(below);
    rest = above;
  }
  leaves.push_back(rest);
  warnOfTurnedPlanes(turned, K);
  return true;
}

// Parallel planes are parallel only where every cut at the planes' normal
// kept both halves free of self-intersections; where none did, the plane
// was cut along another normal (soundCutInstead: the proposed one, then x, y
// and z), and the slabs beside it are not parallel. Said, not silent: a
// user who asked for slabs (say, to stack them along a pipe) sees which.
void Cutting::warnOfTurnedPlanes(const std::vector<int>& turned, int K)
{
  if (turned.empty())
  {
    return;
  }
  std::ostringstream msg;
  msg << turned.size() << " of the " << K - 1
      << " parallel planes could not cut at the planes' normal without a part crossing itself and were cut along "
         "another normal (plane";
  for (std::size_t i = 0; i < turned.size() && i < 10; ++i)
  {
    msg << (i ? ", " : turned.size() > 1 ? "s " : " ") << turned[i];
  }
  msg << (turned.size() > 10 ? ", ..." : "")
      << "): the slabs beside them are not parallel. RecursiveBisection, or fewer subdomains, may avoid this";
  result.warnings.push_back(msg.str());
}

// Cuts part `cell` into k subdomains: its lower half k / 2, its upper half the rest.
bool Cutting::bisect(int cell, int k)
{
  if (k == 1)
  {
    leaves.push_back(cell);
    return true;
  }
  const Vec3 normal = cutNormal(c.points, cellPoints(c, cell), options.direction);
  const int lowerCount = k / 2;
  int below = 0, above = 0;
  if (!cut(cell, normal, static_cast<double>(lowerCount) / k, k, below, above))
  {
    return false;
  }
  return bisect(below, lowerCount) && bisect(above, k - lowerCount);
}

// Renumbers the parts to subdomains 0..K-1.
void renumberParts(SurfaceComplex& c, const std::vector<int>& leaves, int cellCount, int K)
{
  std::vector<int> subdomainOfCell(cellCount, -1);
  for (int s = 0; s < K; ++s)
  {
    subdomainOfCell[leaves[s]] = s;
  }
  auto relabel = [&](int cell) { return cell < 0 ? -1 : subdomainOfCell[cell]; };
  for (auto& pair : c.trianglePairs)
  {
    pair = { relabel(pair[0]), relabel(pair[1]) };
  }
  for (auto& region : c.interfaces)
  {
    region.pair = { relabel(region.pair[0]), relabel(region.pair[1]) };
    std::sort(region.edges.begin(), region.edges.end());
  }
  c.subdomainCount = K;
}

// The contract of the complex: every interface is bounded by closed loops
// (splitCell checks each piece; this guards the whole result).
std::string openInterfaceError(const SurfaceComplex& c)
{
  for (const InterfaceRegion& region : c.interfaces)
  {
    std::vector<std::vector<Index>> loops;
    if (!chainLoops(region.edges, loops))
    {
      std::ostringstream msg;
      msg << "internal: the interface between subdomains " << region.pair[0] << " and "
          << region.pair[1] << " on plane " << region.planeId << " is not bounded by closed loops";
      return msg.str();
    }
  }
  return {};
}

// The volume and measure of every subdomain and the worst imbalance; the
// error if the volumes do not add up to the input's or a subdomain
// encloses none.
std::string measureBalance(
  const SurfaceComplex& c, const DecompositionOptions& options, double totalVolume, DecompositionResult& result)
{
  const int K = options.numberOfSubdomains;
  result.subdomainVolume = subdomainVolumes(c);
  double enclosed = 0;
  for (double v : result.subdomainVolume)
  {
    enclosed += v;
  }
  if (!volumesAddUp(c, enclosed, totalVolume))
  {
    std::ostringstream msg;
    msg.precision(9);
    msg << "internal: the subdomains enclose " << enclosed << " in all, the input " << totalVolume
        << " (the cuts overlap); try another number of subdomains or strategy, or SnapFraction 0";
    return msg.str();
  }
  // by cost: the field's regular tetrahedra by quadrature on the final
  // subdomains, more exact than the samples (whose grid columns go whole
  // to one side of a plane)
  result.subdomainMeasure = !cutsByCost(options) ? measureSubdomains(c, options.criterion, result.subdomainVolume)
    : options.costSize ? predictCost(c, costField(options, result)).regularTetrahedra
                       : predictUniformCost(c, largestMeshSize(options, result), options.costThicknessCap).tetrahedra;
  double total = 0;
  for (double m : result.subdomainMeasure)
  {
    total += m;
  }
  for (int s = 0; s < K; ++s)
  {
    const double target = total / K;
    result.maximumImbalance =
      std::max(result.maximumImbalance, std::fabs(result.subdomainMeasure[s] / target - 1.0));
    if (!(result.subdomainVolume[s] > 0))
    {
      std::ostringstream msg;
      msg << "subdomain " << s << " encloses no volume";
      return msg.str();
    }
  }
  return {};
}
} // namespace

DecompositionResult decomposeVolumeBalanced(const TriangleSurface& input, const DecompositionOptions& options)
{
  return decomposeVolumeBalanced(prepareInputSurface(input, options.inputCheck), options);
}

namespace
{

// One decomposition with `options`, keeping the flat crossings of the
// parallel planes `keptPlanes`; result.failedInCuts says whether it failed
// in the cuts themselves (not on the options or the input), and
// `planesToKeep` the planes whose removal made a subdomain cross itself
// (planesOfCrossingSlabs), if that is why.
DecompositionResult decomposeOnce(PreparedSurface prepared, const DecompositionOptions& options,
  const std::set<int>& keptPlanes, std::set<int>& planesToKeep, bool keepPrevious = false)
{
  DecompositionResult result;
  const int K = options.numberOfSubdomains;
  result.error = optionError(options);
  if (!result.error.empty())
  {
    return result;
  }
  double totalVolume = 0;
  if (!startComplex(std::move(prepared), result, totalVolume))
  {
    return result;
  }
  SurfaceComplex& c = result.complex;
  const Index inputPoints = static_cast<Index>(c.points.size());
  InterfaceTriangulationCache triangulations;
  Cutting cutting{ c, options, result, std::min(1e-6, 0.01 * options.balanceTolerance), inputPoints, triangulations,
    keptPlanes };
  cutting.keepPrevious = keepPrevious;
  if (cutsByCost(options))
  {
    const TriangleSurface whole{ c.points, c.triangles };
    cutting.costSamples = options.costSize
      ? sampleCost(whole, costField(options, result), options.costSamples)
      : sampleUniformCost(whole, largestMeshSize(options, result), options.costSamples, options.costThicknessCap);
  }
  if (K > 1 && options.strategy == CutStrategy::ParallelPlanes)
  {
    if (!cutting.parallelPlanes(K))
    {
      result.error = cutting.error;
      result.failedInCuts = !result.refusedBeforeCutting;
      planesToKeep = cutting.planesToKeep;
      return result;
    }
  }
  else if (K > 1)
  {
    if (!cutting.bisect(0, K))
    {
      result.error = cutting.error;
      result.failedInCuts = !result.refusedBeforeCutting;
      return result;
    }
  }
  else
  {
    cutting.leaves.push_back(0);
  }
  renumberParts(c, cutting.leaves, cutting.nextCell, K);
  if (options.removeFlatCrossings && options.strategy == CutStrategy::ParallelPlanes)
  {
    planesToKeep = planesOfCrossingSlabs(cutting, result, "subdomain");
    if (!planesToKeep.empty())
    {
      return result;
    }
  }
  if (options.removeFlatCrossings)
  {
    result.flatCrossingsRemoved +=
      removeCheckedFlatCrossings(c, inputPoints, options, triangulations, cutting.keptPoints, result);
  }
  result.error = openInterfaceError(c);
  if (result.error.empty())
  {
    result.error = measureBalance(c, options, totalVolume, result);
  }
  if (!result.error.empty())
  {
    return result;
  }
  if (result.maximumImbalance > options.balanceTolerance)
  {
    std::ostringstream msg;
    msg << "balance tolerance " << options.balanceTolerance
        << " not reached: the worst subdomain deviates by " << result.maximumImbalance
        << " from its target "
        << (cutsByCost(options) ? "by predicted cost (the planes were placed by an estimate on a grid of samples; "
                     "more subdomains than ranks even the ranks out)"
                   : "(the surface is too coarse near a plane for this tolerance)");
    result.warnings.push_back(msg.str());
  }
  result.ok = true;
  return result;
}

// Decomposes keeping the flat crossings of the parallel planes whose
// removal made a subdomain cross itself (planesOfCrossingSlabs), adding
// such planes for up to `rounds` decompositions. On OCCT's Bottom at
// K = 16 by predicted cost the removals after planes 0, 9 and 10 left
// subdomain 10 crossing itself; a second decomposition keeping those
// planes' flat crossings (1,234 of 1,236 still taken out) cut it whole,
// the cut alone 16 s against 10.5 s unchecked (one process). With
// `keepPrevious` a plane turned beside a removal keeps that removal's plane
// too (Cutting::removalsBlockedCut), except in the last round, where a
// turned plane is better than no cut. Returns the first failure if every
// round fails.
DecompositionResult decomposeKeepingCrossingPlanes(
  const PreparedSurface& prepared, const DecompositionOptions& options, int rounds, bool keepPrevious)
{
  std::set<int> kept;
  std::vector<std::string> why;
  DecompositionResult first;
  for (int round = 0; round < rounds; ++round)
  {
    std::set<int> toKeep;
    DecompositionResult result =
      decomposeOnce(prepared, options, kept, toKeep, keepPrevious && round < rounds - 1);
    if (result.ok)
    {
      for (auto it = why.rbegin(); it != why.rend(); ++it)
      {
        result.warnings.insert(result.warnings.begin(), *it + "; cut again keeping those planes' flat crossings");
      }
      return result;
    }
    if (round == 0)
    {
      first = result;
    }
    if (!result.failedInCuts || toKeep.empty())
    {
      break;
    }
    why.push_back(result.error);
    kept.insert(toKeep.begin(), toKeep.end());
  }
  return first;
}

// Keeping the previous plane can push the turn one plane on: on OCCT's Top
// at K = 64 by cost planes 1, 2, 3, ... were kept one round each and all 8
// rounds failed, where rounds without it had cut with 6 planes turned. So
// those rounds come second, before every flat crossing is kept
// (decomposeVolumeBalanced). Measured on the corpus cuts in
// Testing/Corpus/results/turned-parallel-planes-session51.md.
constexpr int kKeepingRounds = 8;

DecompositionResult decomposeKeepingTurnedPlanes(const PreparedSurface& prepared, const DecompositionOptions& options)
{
  DecompositionResult first = decomposeKeepingCrossingPlanes(prepared, options, kKeepingRounds, true);
  if (first.ok || !first.failedInCuts || options.strategy != CutStrategy::ParallelPlanes)
  {
    return first;
  }
  DecompositionResult second = decomposeKeepingCrossingPlanes(prepared, options, kRemovalRounds, false);
  return second.ok ? second : first;
}
} // namespace

DecompositionResult decomposeVolumeBalanced(PreparedSurface prepared, const DecompositionOptions& options)
{
  std::set<int> none;
  if (!options.removeFlatCrossings)
  {
    return decomposeOnce(std::move(prepared), options, {}, none);
  }
  DecompositionResult first = decomposeKeepingTurnedPlanes(prepared, options);
  if (first.ok || !first.failedInCuts)
  {
    return first;
  }
  // Removing flat crossings leaves other contours, and so other parts to
  // cut: KiCad's SOD-70 by ParallelPlanes at K = 37 found no sound plane for
  // one part that way ("no balanced cut of a part kept both halves free of
  // self-intersections", on 1, 2 and 3 ranks), and meshed with the flat
  // crossings kept, as tetmesh.py's first recut does after a later stage
  // fails (session 32). Every rank runs the same cuts, so all retry alike.
  DecompositionOptions keeping = options;
  keeping.removeFlatCrossings = false;
  DecompositionResult second = decomposeOnce(std::move(prepared), keeping, {}, none);
  if (!second.ok)
  {
    return first;
  }
  second.warnings.insert(second.warnings.begin(),
    "the cut removing flat crossings failed (" + first.error + "); cut again keeping them (RemoveFlatCrossings off)");
  return second;
}
} // namespace ptm
