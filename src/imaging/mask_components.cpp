#include "imaging/mask_components.h"

#include <algorithm>
#include <numeric>

namespace maxillo {
namespace {

struct Run {
  uint32_t begin, end;  // [begin, end) along x
};

// The runs of value `value` in every row (j, k) of the grid; row r = j + ny * k.
struct Runs {
  std::vector<Run> runs;
  std::vector<size_t> row_start;  // runs of row r: [row_start[r], row_start[r + 1])
};

Runs runs_of(const Mask& mask, const MaskGrid& grid, uint8_t value) {
  Runs out;
  const size_t nx = grid.size[0], rows = grid.size[1] * grid.size[2];
  out.row_start.reserve(rows + 1);
  for (size_t row = 0; row < rows; ++row) {
    out.row_start.push_back(out.runs.size());
    const uint8_t* line = mask.data() + row * nx;
    for (size_t i = 0; i < nx;) {
      if ((line[i] != 0) != (value != 0)) {
        ++i;
        continue;
      }
      const size_t begin = i;
      while (i < nx && (line[i] != 0) == (value != 0)) ++i;
      out.runs.push_back({uint32_t(begin), uint32_t(i)});
    }
  }
  out.row_start.push_back(out.runs.size());
  return out;
}

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), size_t(0)); }
  size_t find(size_t a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];  // path halving
    return a;
  }
  // The smaller root wins, so a component's root is its first run whatever the merge order.
  void unite(size_t a, size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<size_t> parent_;
};

// Unites every run with the overlapping runs of an earlier row (the row above, or the same row
// of the previous slice).
void unite_with_row(const Runs& r, size_t row, size_t earlier, UnionFind& sets) {
  size_t e = r.row_start[earlier];
  const size_t e_end = r.row_start[earlier + 1];
  for (size_t a = r.row_start[row]; a < r.row_start[row + 1]; ++a) {
    while (e < e_end && r.runs[e].end <= r.runs[a].begin) ++e;
    for (size_t b = e; b < e_end && r.runs[b].begin < r.runs[a].end; ++b) sets.unite(a, b);
  }
}

// Component root of every run, and voxels per root.
struct Components {
  std::vector<size_t> root;
  std::vector<int64_t> voxels;  // indexed by root run
};

Components components_of(const Runs& r, const MaskGrid& grid) {
  const size_t ny = grid.size[1], nz = grid.size[2];
  UnionFind sets(r.runs.size());
  for (size_t k = 0; k < nz; ++k)
    for (size_t j = 0; j < ny; ++j) {
      const size_t row = j + ny * k;
      if (j > 0) unite_with_row(r, row, row - 1, sets);
      if (k > 0) unite_with_row(r, row, row - ny, sets);
    }
  Components c{std::vector<size_t>(r.runs.size()), std::vector<int64_t>(r.runs.size(), 0)};
  for (size_t a = 0; a < r.runs.size(); ++a) {
    c.root[a] = sets.find(a);
    c.voxels[c.root[a]] += r.runs[a].end - r.runs[a].begin;
  }
  return c;
}

// A mask of the runs whose component `keep` accepts.
template <typename Keep>
Mask paint(const Runs& r, const Components& c, const MaskGrid& grid, Keep&& keep) {
  Mask out(grid.voxel_count(), 0);
  const size_t nx = grid.size[0];
  for (size_t row = 0; row + 1 < r.row_start.size(); ++row)
    for (size_t a = r.row_start[row]; a < r.row_start[row + 1]; ++a)
      if (keep(c.root[a]))
        std::fill(out.begin() + long(row * nx + r.runs[a].begin), out.begin() + long(row * nx + r.runs[a].end), 1);
  return out;
}

bool touches_border(const Run& run, size_t row, const MaskGrid& grid) {
  const size_t j = row % grid.size[1], k = row / grid.size[1];
  return run.begin == 0 || run.end == grid.size[0] || j == 0 || j + 1 == grid.size[1] || k == 0 ||
         k + 1 == grid.size[2];
}

}  // namespace

Mask largest_component(const Mask& mask, const MaskGrid& grid) {
  const Runs r = runs_of(mask, grid, 1);
  const Components c = components_of(r, grid);
  size_t best = 0;
  for (size_t a = 0; a < c.voxels.size(); ++a)
    if (c.voxels[a] > c.voxels[best]) best = a;
  if (r.runs.empty()) return Mask(grid.voxel_count(), 0);
  return paint(r, c, grid, [&](size_t root) { return root == best; });
}

Mask components_of_at_least(const Mask& mask, const MaskGrid& grid, int64_t min_voxels) {
  const Runs r = runs_of(mask, grid, 1);
  const Components c = components_of(r, grid);
  return paint(r, c, grid, [&](size_t root) { return c.voxels[root] >= min_voxels; });
}

ComponentLabels label_components(const Mask& mask, const MaskGrid& grid) {
  const Runs r = runs_of(mask, grid, 1);
  const Components c = components_of(r, grid);
  ComponentLabels out{std::vector<int32_t>(grid.voxel_count(), 0), {0}};
  std::vector<int32_t> number(r.runs.size(), 0);  // by root run, 1-based
  const size_t nx = grid.size[0];
  for (size_t row = 0; row + 1 < r.row_start.size(); ++row)
    for (size_t a = r.row_start[row]; a < r.row_start[row + 1]; ++a) {
      int32_t& n = number[c.root[a]];
      if (!n) {
        out.voxels.push_back(c.voxels[c.root[a]]);
        n = out.count();
      }
      std::fill(out.label.begin() + long(row * nx + r.runs[a].begin),
                out.label.begin() + long(row * nx + r.runs[a].end), n);
    }
  return out;
}

Mask holes_filled(const Mask& mask, const MaskGrid& grid) {
  const Runs background = runs_of(mask, grid, 0);
  const Components c = components_of(background, grid);
  std::vector<uint8_t> outside(background.runs.size(), 0);  // by root: reaches the border
  for (size_t row = 0; row + 1 < background.row_start.size(); ++row)
    for (size_t a = background.row_start[row]; a < background.row_start[row + 1]; ++a)
      if (touches_border(background.runs[a], row, grid)) outside[c.root[a]] = 1;
  const Mask holes = paint(background, c, grid, [&](size_t root) { return !outside[root]; });
  Mask out = mask;
  for (size_t n = 0; n < out.size(); ++n) out[n] |= holes[n];
  return out;
}

}  // namespace maxillo
