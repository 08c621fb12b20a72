#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace cscd {

// Disjoint sets over 0..n-1 with path halving; enough for the connectivity questions of mesh checks.
class UnionFind {
public:
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }

  uint32_t find(uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }

  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[a < b ? b : a] = a < b ? a : b;
  }

private:
  std::vector<uint32_t> parent;
};

} // namespace cscd
