#ifndef PTM_INTERFACE_TRIANGULATION_CACHE_H
#define PTM_INTERFACE_TRIANGULATION_CACHE_H
// Results of triangulateInterface kept for the same region asked again.
//
// The cutter checks every trial cut by triangulating the interfaces of the
// parts it changed (VolumeBalancedDecomposition, partSurface); most of these
// regions are the same from trial to trial and from part to part (the new
// interface for the part on each side; the regions of earlier cuts that
// reach the new one's zone, in every trial and every later cut that comes
// near them). Triangulating them took half of the cutter's time (OCCT's
// Bottom at K = 64 by bisection: 50 % of 5.1 s). triangulateInterface is a
// function of its region and options alone, so a result found again for
// equal input (compared whole, not by hash alone) is the one it would
// compute: cuts stay the same bit for bit.
//
// Options with a size field (sizeAt) are not compared and never kept. The
// kept results are dropped all at once when their estimated size passes
// byteLimit, which bounds the memory and changes nothing but the time.
#include "InterfaceTriangulation.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace ptm
{
class InterfaceTriangulationCache
{
public:
  explicit InterfaceTriangulationCache(std::size_t byteLimit = std::size_t(256) << 20);

  // triangulateInterface(region, options), from the cache when the same
  // region and options were asked before.
  std::shared_ptr<const InterfaceTriangulationResult> triangulate(
    const PlanarRegion& region, const InterfaceTriangulationOptions& options);

  std::size_t hits() const { return this->Hits; }
  std::size_t misses() const { return this->Misses; }

private:
  struct Entry
  {
    PlanarRegion region;
    InterfaceTriangulationOptions options; // without sizeAt
    std::shared_ptr<const InterfaceTriangulationResult> result;
  };
  std::unordered_map<std::uint64_t, std::vector<Entry>> Entries;
  std::size_t ByteLimit;
  std::size_t Bytes = 0;
  std::size_t Hits = 0;
  std::size_t Misses = 0;
};
} // namespace ptm
#endif
