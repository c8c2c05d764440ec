// Fuzz target for the cutting core: the input check and the volume-balanced
// decomposition (SurfaceInputCheck.h, VolumeBalancedDecomposition.h) on small
// surfaces made from the fuzz bytes (FuzzedSurface.h), with 2 to 4 subdomains
// and any strategy, direction, criterion, tolerance and snap fraction.
//
// Contract: no crash, hang, sanitizer report or exception; the result is an
// error message or a labeled surface complex. A complex returned without an
// error must be usable by the later stages, so it is checked cheaply here:
// indices in range, finite points, labels in 0..K-1, every subdomain closed
// (each directed edge of its faces matched by its reverse), positive volumes
// that add up to the input's volume.
//
// PTM_FUZZ_DUMP_OFF=file.off writes the surface of the input being run (for
// turning a finding into a unit test) and prints the options.
#include "FuzzCheck.h"
#include "FuzzedSurface.h"

#include "OffFormat.h"
#include "VolumeBalancedDecomposition.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>

using namespace ptm;

namespace
{
DecompositionOptions fuzzedOptions(FuzzedDataProvider& in)
{
  DecompositionOptions o;
  o.numberOfSubdomains = in.ConsumeIntegralInRange<int>(2, 4);
  o.strategy = in.ConsumeBool() ? CutStrategy::ParallelPlanes : CutStrategy::RecursiveBisection;
  o.direction = in.PickValueInArray({ CutDirection::LongestExtent, CutDirection::Inertia,
    CutDirection::X, CutDirection::Y, CutDirection::Z });
  // mostly the volume balance the filter is named after
  o.criterion = in.PickValueInArray({ BalanceCriterion::Volume, BalanceCriterion::Volume,
    BalanceCriterion::Volume, BalanceCriterion::BoundaryFacets, BalanceCriterion::Nodes });
  o.balanceTolerance = in.PickValueInArray({ 0.01, 0.05, 0.2, 0.001, 0.9 });
  o.snapFraction = in.PickValueInArray({ 0.05, 0.0, 0.001, 0.25, 0.49 });
  // the filter lets the user switch the self-intersection check off
  o.inputCheck.checkSelfIntersections = in.ConsumeIntegralInRange<int>(0, 7) != 7;
  return o;
}

void checkComplex(const TriangleSurface& input, const DecompositionOptions& options,
  const DecompositionResult& r)
{
  const SurfaceComplex& c = r.complex;
  const int K = options.numberOfSubdomains;
  const Index pointCount = static_cast<Index>(c.points.size());
  auto validPoint = [&](Index v) { return v >= 0 && v < pointCount; };

  PTM_FUZZ_CHECK(c.subdomainCount == K, "subdomainCount " << c.subdomainCount << ", K " << K);
  PTM_FUZZ_CHECK(r.subdomainVolume.size() == static_cast<std::size_t>(K),
    r.subdomainVolume.size() << " volumes");
  PTM_FUZZ_CHECK(std::isfinite(r.totalVolume) && r.totalVolume > 0, "total volume " << r.totalVolume);
  for (const Vec3& p : c.points)
  {
    PTM_FUZZ_CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
      "point (" << p[0] << ", " << p[1] << ", " << p[2] << ")");
  }
  PTM_FUZZ_CHECK(c.trianglePairs.size() == c.triangles.size() && c.sourceFaces.size() == c.triangles.size(),
    c.triangles.size() << " triangles, " << c.trianglePairs.size() << " pairs, "
                       << c.sourceFaces.size() << " sources");
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    const Triangle& t = c.triangles[i];
    PTM_FUZZ_CHECK(validPoint(t[0]) && validPoint(t[1]) && validPoint(t[2]), "triangle " << i);
    PTM_FUZZ_CHECK(t[0] != t[1] && t[1] != t[2] && t[2] != t[0], "triangle " << i << " repeats a corner");
    const SubdomainPair& pair = c.trianglePairs[i];
    PTM_FUZZ_CHECK(pair[0] >= 0 && pair[0] < K && pair[1] == -1,
      "triangle " << i << " pair {" << pair[0] << ", " << pair[1] << "}");
    PTM_FUZZ_CHECK(c.sourceFaces[i] >= 0 && c.sourceFaces[i] < static_cast<Index>(input.triangles.size()),
      "triangle " << i << " source " << c.sourceFaces[i]);
  }
  for (std::size_t k = 0; k < c.interfaces.size(); ++k)
  {
    const InterfaceRegion& region = c.interfaces[k];
    PTM_FUZZ_CHECK(region.pair[0] >= 0 && region.pair[0] < K && region.pair[1] >= 0 &&
        region.pair[1] < K && region.pair[0] != region.pair[1],
      "interface " << k << " pair {" << region.pair[0] << ", " << region.pair[1] << "}");
    PTM_FUZZ_CHECK(region.planeId >= 0 && region.planeId < static_cast<int>(c.planes.size()),
      "interface " << k << " plane " << region.planeId);
    for (const DirectedEdge& e : region.edges)
    {
      PTM_FUZZ_CHECK(validPoint(e[0]) && validPoint(e[1]) && e[0] != e[1], "interface " << k << " edge");
    }
  }

  // every subdomain is closed: its directed edges cancel pairwise
  for (int s = 0; s < K; ++s)
  {
    std::map<DirectedEdge, int> open;
    auto add = [&](Index a, Index b) {
      auto reverse = open.find({ b, a });
      if (reverse != open.end() && --reverse->second == 0)
      {
        open.erase(reverse);
      }
      else if (reverse == open.end())
      {
        ++open[{ a, b }];
      }
    };
    for (const Triangle& t : subdomainTriangles(c, s))
    {
      add(t[0], t[1]);
      add(t[1], t[2]);
      add(t[2], t[0]);
    }
    for (const InterfaceRegion& region : c.interfaces)
    {
      for (const DirectedEdge& e : region.edges)
      {
        if (region.pair[0] == s)
        {
          add(e[0], e[1]);
        }
        else if (region.pair[1] == s)
        {
          add(e[1], e[0]);
        }
      }
    }
    PTM_FUZZ_CHECK(open.empty(), "subdomain " << s << " is open at " << open.size() << " edges, e.g. "
                                             << open.begin()->first[0] << "-" << open.begin()->first[1]);
  }

  // volumes: positive, and the pieces add up to the whole up to the round-off
  // of the divergence sums: relative to each term (bounded by |p|^3), and
  // absolute in the subnormal range, where a surface of size 1e-106 has its
  // volume (a check without that term failed wrongly on
  // corpus/decomposition/regression-subnormal-volume)
  double sum = 0, largest = 0;
  for (int s = 0; s < K; ++s)
  {
    PTM_FUZZ_CHECK(r.subdomainVolume[s] > 0, "subdomain " << s << " volume " << r.subdomainVolume[s]);
    sum += r.subdomainVolume[s];
  }
  for (const Vec3& p : c.points)
  {
    largest = std::max({ largest, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) });
  }
  std::size_t terms = c.triangles.size();
  for (const InterfaceRegion& region : c.interfaces)
  {
    terms += region.edges.size();
  }
  const double tolerance = 1e-9 * r.totalVolume +
    1e-13 * static_cast<double>(terms) * largest * largest * largest +
    64.0 * static_cast<double>(terms) * std::numeric_limits<double>::denorm_min();
  PTM_FUZZ_CHECK(std::fabs(sum - r.totalVolume) <= tolerance,
    "subdomain volumes add up to " << sum << ", the input encloses " << r.totalVolume
                                   << " (tolerance " << tolerance << ")");
  PTM_FUZZ_CHECK(std::isfinite(r.maximumImbalance), "imbalance " << r.maximumImbalance);
}

void dumpCase(const char* path, const TriangleSurface& surface, const DecompositionOptions& o)
{
  std::ofstream out(path);
  writeOff(out, surface, "fuzz case");
  std::cerr << "wrote " << path << ": " << surface.points.size() << " points, "
            << surface.triangles.size() << " triangles; K " << o.numberOfSubdomains << ", "
            << toString(o.strategy) << ", " << toString(o.direction) << ", "
            << toString(o.criterion) << ", balance tolerance " << o.balanceTolerance
            << ", snap fraction " << o.snapFraction << ", self-intersection check "
            << (o.inputCheck.checkSelfIntersections ? "on" : "off") << "\n";
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const DecompositionOptions options = fuzzedOptions(in);
  const TriangleSurface surface = fuzz::fuzzedSurface(in);
  if (const char* path = std::getenv("PTM_FUZZ_DUMP_OFF"))
  {
    dumpCase(path, surface, options);
  }

  const DecompositionResult r = decomposeVolumeBalanced(surface, options);
  if (!r.ok)
  {
    PTM_FUZZ_CHECK(!r.error.empty(), "refused without a message");
    return 0;
  }
  PTM_FUZZ_CHECK(r.error.empty(), "ok with the error '" << r.error << "'");
  checkComplex(surface, options, r);
  return 0;
}
