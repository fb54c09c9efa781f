#pragma once
// Small pieces shared by mesh_measures.cpp, mesh_repair.cpp and softtissue/bone_attachment.cpp.
#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace maxillo::topology {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(Eigen::Index n) : parent(size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[size_t(x)] != x) x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void unite(int a, int b) { parent[size_t(find(a))] = find(b); }
};

// The undirected edge {a, b} as one integer.
inline uint64_t edge_key(int a, int b) { return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b)); }

}  // namespace maxillo::topology
