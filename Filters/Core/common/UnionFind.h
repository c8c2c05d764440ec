#ifndef PTM_UNION_FIND_H
#define PTM_UNION_FIND_H
// Disjoint sets over 0..n-1 with path halving: groups the corners of a
// triangle surface into vertex fans (the input check's non-manifold
// vertices, the self-intersection check's fast manifold test).
#include <cstddef>
#include <numeric>
#include <vector>

namespace ptm
{
struct UnionFind
{
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n)
    : parent(n)
  {
    std::iota(parent.begin(), parent.end(), std::size_t{ 0 });
  }
  std::size_t find(std::size_t x)
  {
    while (parent[x] != x)
    {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};
} // namespace ptm
#endif
