#include "VolumeBalancedDecomposition.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

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
  }
  return "?";
}

namespace
{
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
} // namespace

DecompositionResult decomposeVolumeBalanced(
  const TriangleSurface& input, const DecompositionOptions& options)
{
  DecompositionResult result;
  const int K = options.numberOfSubdomains;
  if (K < 1)
  {
    result.error = "the number of subdomains must be at least 1";
    return result;
  }
  if (!(options.balanceTolerance > 0 && options.balanceTolerance < 1))
  {
    result.error = "the balance tolerance must lie strictly between 0 and 1";
    return result;
  }
  if (!(options.snapFraction >= 0 && options.snapFraction < 0.5))
  {
    result.error = "the snap fraction must lie in [0, 0.5)";
    return result;
  }
  PreparedSurface prepared = prepareInputSurface(input, options.inputCheck);
  result.inputCheck = prepared.counts;
  result.warnings = prepared.warnings;
  if (!prepared.ok)
  {
    result.error = prepared.error;
    return result;
  }
  result.orientation = prepared.orientation;
  const TriangleSurface& surface = prepared.surface;
  const std::vector<Index>& source = prepared.sourceOfTriangle;
  const double totalVolume = prepared.enclosedVolume;
  result.totalVolume = totalVolume;
  double edgeSum = 0;
  for (const auto& t : surface.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edgeSum += norm(surface.points[t[(k + 1) % 3]] - surface.points[t[k]]);
    }
  }
  result.inputMeanEdgeLength = edgeSum / (3.0 * static_cast<double>(surface.triangles.size()));

  SurfaceComplex& c = result.complex;
  c.points = surface.points;
  c.triangles = surface.triangles;
  c.trianglePairs.assign(c.triangles.size(), SubdomainPair{ 0, -1 });
  c.sourceFaces = source;

  const double solveTolerance = std::min(1e-6, 0.01 * options.balanceTolerance);
  int nextCell = 1;
  std::vector<int> leaves; // cell ids in subdomain order
  std::string error;

  // Cuts `cell` so that the part below holds `fraction` of its measure. The
  // offset from the measure function is only a start: snapping vertices onto
  // the plane moves volume, so the split is tried on a copy, measured, and the
  // offset corrected (Newton with the cross-section area) until the part
  // below is within a quarter of the tolerance of one subdomain; if snapping
  // makes that impossible, it is halved step by step down to 0.001 (never 0:
  // a vertex a hair's breadth from the plane would leave a degenerate sliver).
  auto cut = [&](int cell, const Vec3& normal, double fraction, int parts, int& below,
               int& above) -> bool {
    const HalfSpaceMeasure measure(c, cell, normal, options.criterion);
    double offset = measure.offsetForFraction(fraction, solveTolerance);
    if (!(offset > measure.minimumOffset() && offset < measure.maximumOffset()))
    {
      error = "the subdomains are too many for this surface: a part cannot be cut further";
      return false;
    }
    const int planeId = static_cast<int>(c.planes.size());
    const std::vector<Index> points = cellPoints(c, cell);
    Vec3 centroid{ 0, 0, 0 };
    for (Index p : points)
    {
      centroid = centroid + c.points[p];
    }
    centroid = (1.0 / std::max<double>(1.0, static_cast<double>(points.size()))) * centroid;
    below = nextCell++;
    above = nextCell++;
    const bool volumeCriterion = options.criterion == BalanceCriterion::Volume;
    const double cellVolume = volumeCriterion ? labelVolume(c, cell) : 0.0;
    const double target = fraction * cellVolume;
    const double allowed = 0.25 * options.balanceTolerance * cellVolume / parts;

    SurfaceComplex best;
    PlaneSplitStats bestStats;
    double bestError = std::numeric_limits<double>::infinity();
    std::string lastError;
    // Splits a copy of the complex at `at`; keeps it if it is the best so far.
    // Returns false if the split failed; `missing` and `area` describe it.
    auto tryCut = [&](double at, double snap, double& missing, double& area) {
      SurfaceComplex trial = c;
      CuttingPlane plane;
      plane.normal = normal;
      plane.origin = centroid - (dot(normal, centroid) - at) * normal;
      plane.cutSubdomainCount = parts;
      trial.planes.push_back(plane);
      PlaneSplitOptions splitOptions;
      splitOptions.snapFraction = snap;
      PlaneSplitStats stats;
      if (!splitCell(trial, cell, normal, at, planeId, below, above, splitOptions, stats, lastError))
      {
        return false;
      }
      missing = volumeCriterion ? labelVolume(trial, below) - target : 0.0;
      // the volume changes with the offset at the rate of the cross-section area
      area = stats.interfaceEdges == 0
        ? 0.0
        : std::fabs(dot(normal, vectorArea(trial.points, trial.interfaces.back().edges)));
      if (std::fabs(missing) < bestError)
      {
        bestError = std::fabs(missing);
        best = std::move(trial);
        bestStats = stats;
      }
      return true;
    };
    const double smallestSnap = std::min(options.snapFraction, 0.001);
    for (double snap = options.snapFraction;; snap = std::max(0.5 * snap, smallestSnap))
    {
      for (int attempt = 0; attempt < 4; ++attempt)
      {
        double missing = 0, area = 0;
        if (!tryCut(offset, snap, missing, area) || bestError <= allowed || !(area > 0))
        {
          break;
        }
        offset -= missing / area;
      }
      if (bestError <= allowed || snap <= smallestSnap)
      {
        break;
      }
    }
    // Safety net: if the measure function's start led nowhere (seen with a
    // part of two bodies bounded by two nearly parallel interfaces, where the
    // start fell in the gap between them), bisect on the real split volume.
    if (volumeCriterion && bestError > allowed)
    {
      double lo = measure.minimumOffset(), hi = measure.maximumOffset();
      for (int step = 0; step < 60 && bestError > allowed; ++step)
      {
        const double middle = 0.5 * (lo + hi);
        double missing = 0, area = 0;
        if (!tryCut(middle, options.snapFraction, missing, area))
        {
          break;
        }
        (missing < 0 ? lo : hi) = middle;
      }
    }
    if (!std::isfinite(bestError))
    {
      // every split failed (with a reason), or none gave a finite volume
      error = lastError.empty() ? "no cut of a part gave a finite volume" : lastError;
      return false;
    }
    c = std::move(best);
    result.splitStats.splitTriangles += bestStats.splitTriangles;
    result.splitStats.snappedPoints += bestStats.snappedPoints;
    result.splitStats.chordPoints += bestStats.chordPoints;
    return true;
  };

  if (K > 1 && options.strategy == CutStrategy::ParallelPlanes)
  {
    // one direction for all planes; each plane cuts the rest of the object so
    // that the slab below gets 1/(number of subdomains still to make) of it
    const Vec3 normal = cutNormal(c.points, cellPoints(c, 0), options.direction);
    int rest = 0;
    for (int i = 0; i < K - 1; ++i)
    {
      int below = 0, above = 0;
      if (!cut(rest, normal, 1.0 / (K - i), K - i, below, above))
      {
        result.error = error;
        return result;
      }
      leaves.push_back(below);
      rest = above;
    }
    leaves.push_back(rest);
  }
  else if (K > 1)
  {
    std::function<bool(int, int)> bisect = [&](int cell, int k) -> bool {
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
    };
    if (!bisect(0, K))
    {
      result.error = error;
      return result;
    }
  }
  else
  {
    leaves.push_back(0);
  }

  // Renumber parts to subdomains 0..K-1.
  std::vector<int> subdomainOfCell(nextCell, -1);
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

  result.subdomainVolume = subdomainVolumes(c);
  result.subdomainMeasure =
    measureSubdomains(c, options.criterion, result.subdomainVolume);
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
      result.error = msg.str();
      return result;
    }
  }
  if (result.maximumImbalance > options.balanceTolerance)
  {
    std::ostringstream msg;
    msg << "balance tolerance " << options.balanceTolerance
        << " not reached: the worst subdomain deviates by " << result.maximumImbalance
        << " from its target (the surface is too coarse near a plane for this tolerance)";
    result.warnings.push_back(msg.str());
  }
  result.ok = true;
  return result;
}
} // namespace ptm
