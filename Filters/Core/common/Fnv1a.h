#ifndef PTM_FNV1A_H
#define PTM_FNV1A_H
// FNV-1a, the 64-bit hash of bytes the stages use to compare what ranks hold
// (RankCollectives), to name a machine (TetGenSubdomainMesher) and to compare
// two builds' cuts (Testing/Benchmarks/cut_digest): not cryptographic, but
// the same bytes give the same hash on every platform.
#include <cstddef>
#include <cstdint>

namespace ptm
{
constexpr std::uint64_t kFnv1aOffset = 1469598103934665603ull;

// The hash of `bytes` bytes at `data`, continuing from `hash` (start with
// kFnv1aOffset).
inline std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t bytes)
{
  const unsigned char* b = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i)
  {
    hash = (hash ^ b[i]) * 1099511628211ull;
  }
  return hash;
}
} // namespace ptm
#endif
