#include "InterfaceTriangulationCache.h"

#include "Fnv1a.h"

namespace ptm
{
namespace
{
std::uint64_t hashOf(const PlanarRegion& region, const InterfaceTriangulationOptions& options)
{
  std::uint64_t h = kFnv1aOffset;
  h = fnv1a(h, &region.origin, sizeof(region.origin));
  h = fnv1a(h, &region.normal, sizeof(region.normal));
  h = fnv1a(h, region.points.data(), region.points.size() * sizeof(Vec3));
  h = fnv1a(h, region.edges.data(), region.edges.size() * sizeof(region.edges[0]));
  const double numbers[2] = { options.minimumAngleDegrees, options.maximumEdgeLength };
  const bool flags[3] = { options.refine, options.smooth, options.keepIsolatedPoints };
  h = fnv1a(h, numbers, sizeof(numbers));
  return fnv1a(h, flags, sizeof(flags));
}

// Equal as inputs of triangulateInterface: bit for bit (a -0.0 against a
// 0.0 counts as different, which only costs a triangulation).
bool sameBits(const Vec3& a, const Vec3& b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

bool sameInput(const PlanarRegion& a, const InterfaceTriangulationOptions& oa, const PlanarRegion& b,
  const InterfaceTriangulationOptions& ob)
{
  if (!(oa.minimumAngleDegrees == ob.minimumAngleDegrees && oa.maximumEdgeLength == ob.maximumEdgeLength &&
        oa.refine == ob.refine && oa.smooth == ob.smooth && oa.keepIsolatedPoints == ob.keepIsolatedPoints))
  {
    return false;
  }
  if (!sameBits(a.origin, b.origin) || !sameBits(a.normal, b.normal) || a.points.size() != b.points.size() ||
    a.edges != b.edges)
  {
    return false;
  }
  for (std::size_t i = 0; i < a.points.size(); ++i)
  {
    if (!sameBits(a.points[i], b.points[i]))
    {
      return false;
    }
  }
  return true;
}

std::size_t bytesOf(const PlanarRegion& region, const InterfaceTriangulationResult& result)
{
  return region.points.size() * sizeof(Vec3) + region.edges.size() * sizeof(region.edges[0]) +
    result.triangulation.newPoints.size() * sizeof(Vec3) +
    result.triangulation.triangles.size() * sizeof(Triangle) + result.error.size() + 256;
}
} // namespace

InterfaceTriangulationCache::InterfaceTriangulationCache(std::size_t byteLimit)
  : ByteLimit(byteLimit)
{
}

std::shared_ptr<const InterfaceTriangulationResult> InterfaceTriangulationCache::triangulate(
  const PlanarRegion& region, const InterfaceTriangulationOptions& options)
{
  if (options.sizeAt)
  {
    ++this->Misses;
    return std::make_shared<const InterfaceTriangulationResult>(triangulateInterface(region, options));
  }
  const std::uint64_t h = hashOf(region, options);
  auto found = this->Entries.find(h);
  if (found != this->Entries.end())
  {
    for (const Entry& e : found->second)
    {
      if (sameInput(e.region, e.options, region, options))
      {
        ++this->Hits;
        return e.result;
      }
    }
  }
  ++this->Misses;
  auto result = std::make_shared<const InterfaceTriangulationResult>(triangulateInterface(region, options));
  const std::size_t bytes = bytesOf(region, *result);
  if (this->Bytes + bytes > this->ByteLimit)
  {
    this->Entries.clear();
    this->Bytes = 0;
  }
  if (bytes <= this->ByteLimit)
  {
    this->Entries[h].push_back({ region, options, result });
    this->Bytes += bytes;
  }
  return result;
}
} // namespace ptm
