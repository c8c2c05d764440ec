// The cutter alone (ptm::decomposeVolumeBalanced with the VolumeBalancedCutter
// filter's defaults: inertia direction, volume balance, flat crossings taken
// out) on one surface, for comparing two builds of the cut on the corpus:
// Testing/Corpus/compare_cuts.sh runs this of both and reports where the
// cuts differ and how the times compare.
//
//   cut_digest SURFACE.off K RecursiveBisection|ParallelPlanes [H]
//
// With H, the cuts balance the tetrahedra predicted for the size H
// (BalanceCriterion PredictedCost, tetmesh.py's default, without the
// thickness cap) instead of the volume.
//
// Prints one JSON object: ok (or the error), seconds of the decomposition,
// counts of planes, points, triangles and interface edges, the cutter's
// statistics, and digest, an FNV-1a hash of every plane, point coordinate,
// triangle and its pair and interface edge: equal digests mean the same cut,
// bit for bit. The cutter's warnings go to standard error.
#include "Fnv1a.h"
#include "OffFormat.h"
#include "VolumeBalancedDecomposition.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace
{
// Continues `hash` over the bytes of `value`.
template <typename T>
void add(std::uint64_t& hash, const T& value)
{
  hash = ptm::fnv1a(hash, &value, sizeof(T));
}

std::uint64_t digest(const ptm::SurfaceComplex& c, std::size_t& interfaceEdges)
{
  std::uint64_t f = ptm::kFnv1aOffset;
  for (const auto& plane : c.planes)
  {
    add(f, plane.origin);
    add(f, plane.normal);
  }
  for (const auto& p : c.points)
  {
    add(f, p);
  }
  for (std::size_t i = 0; i < c.triangles.size(); ++i)
  {
    add(f, c.triangles[i]);
    add(f, c.trianglePairs[i]);
  }
  interfaceEdges = 0;
  for (const auto& region : c.interfaces)
  {
    add(f, region.pair);
    add(f, region.planeId);
    for (const auto& e : region.edges)
    {
      add(f, e);
      ++interfaceEdges;
    }
  }
  return f;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 4 && argc != 5)
  {
    std::fprintf(stderr, "usage: cut_digest SURFACE.off K RecursiveBisection|ParallelPlanes [H]\n");
    return 2;
  }
  const ptm::OffReadResult file = ptm::readOffFile(argv[1]);
  if (!file.ok)
  {
    std::printf("{\"ok\": false, \"error\": \"%s\"}\n", file.error.c_str());
    return 1;
  }
  ptm::DecompositionOptions options;
  options.numberOfSubdomains = std::atoi(argv[2]);
  options.strategy = std::strcmp(argv[3], "ParallelPlanes") == 0 ? ptm::CutStrategy::ParallelPlanes
                                                                   : ptm::CutStrategy::RecursiveBisection;
  options.direction = ptm::CutDirection::Inertia; // as the cutter's default
  if (argc == 5)
  {
    options.criterion = ptm::BalanceCriterion::PredictedCost;
    options.costMaximumSize = std::atof(argv[4]);
  }
  const auto start = std::chrono::steady_clock::now();
  const ptm::DecompositionResult r = ptm::decomposeVolumeBalanced(file.data.surface, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const std::string& w : r.warnings)
  {
    std::fprintf(stderr, "warning: %s\n", w.c_str());
  }
  std::size_t edges = 0;
  const std::uint64_t hash = r.ok ? digest(r.complex, edges) : 0;
  std::printf("{\"ok\": %s, \"seconds\": %.4f, \"planes\": %zu, \"points\": %zu, \"triangles\": %zu, "
              "\"interface_edges\": %zu, \"tilted\": %d, \"aligned\": %d, \"rejected\": %d, "
              "\"flat_crossings_removed\": %zu, \"digest\": \"%016llx\"}\n",
    r.ok ? "true" : "false", seconds, r.complex.planes.size(), r.complex.points.size(),
    r.complex.triangles.size(), edges, r.tiltedCuts, r.alignedNormals, r.rejectedCuts,
    r.flatCrossingsRemoved, static_cast<unsigned long long>(hash));
  return r.ok ? 0 : 1;
}
