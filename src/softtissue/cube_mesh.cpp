#include "softtissue/cube_mesh.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>

namespace maxillo::softtissue {
namespace {

// Hex corners are numbered by bits: corner c lies at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1).
using HexTets = std::vector<std::array<int, 4>>;

HexTets kuhn_tets() {
  // One tet per monotone path 000 -> 111 through the axes in order (a, b, c).
  const std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  HexTets tets;
  for (const auto& order : orders) {
    int first = 1 << order[0], second = first | (1 << order[1]);
    tets.push_back({0, first, second, 7});
  }
  return tets;
}

HexTets five_tets(bool even) {
  if (even) return {{0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}, {1, 2, 4, 7}};
  return {{1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}, {0, 3, 5, 6}};
}

}  // namespace

int tets_per_hex(HexSplit split) { return split == HexSplit::kFiveTets ? 5 : 6; }

int cube_divisions_for_tets(int target_tets, HexSplit split) {
  assert(target_tets > 0 && "cube_divisions_for_tets: target must be positive");
  int k = std::max(1, int(std::lround(std::cbrt(double(target_tets) / tets_per_hex(split)))));
  auto miss = [&](int d) { return std::abs(double(d) * d * d * tets_per_hex(split) - target_tets); };
  if (miss(k + 1) < miss(k)) ++k;
  if (k > 1 && miss(k - 1) < miss(k)) --k;
  return k;
}

TetMesh make_cube_mesh(const CubeSpec& spec) {
  assert(spec.divisions >= 1 && spec.side_mm > 0 && "make_cube_mesh: need k >= 1 and a positive side");
  const int k = spec.divisions, n = k + 1;
  const double h = spec.side_mm / k;
  TetMesh mesh;
  mesh.nodes.resize(n * n * n, 3);
  for (int l = 0; l < n; ++l)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) mesh.nodes.row(i + n * (j + n * l)) << h * i, h * j, h * l;
  const HexTets kuhn = kuhn_tets(), even = five_tets(true), odd = five_tets(false);
  mesh.tets.resize(k * k * k * tets_per_hex(spec.split), 4);
  int row = 0;
  for (int l = 0; l < k; ++l)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        const HexTets& pattern = spec.split == HexSplit::kSixTets ? kuhn : ((i + j + l) % 2 == 0 ? even : odd);
        for (const auto& tet : pattern) {
          for (int a = 0; a < 4; ++a) {
            int c = tet[size_t(a)];
            mesh.tets(row, a) = (i + (c & 1)) + n * ((j + ((c >> 1) & 1)) + n * (l + ((c >> 2) & 1)));
          }
          ++row;
        }
      }
  orient_positively(mesh);
  return mesh;
}

}  // namespace maxillo::softtissue
