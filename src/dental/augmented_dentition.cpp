#include "dental/augmented_dentition.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "core/error.h"
#include "core/parallel_slabs.h"
#include "core/volume_resample.h"
#include "geometry/aabb_tree.h"
#include "geometry/signed_distance.h"

namespace maxillo::dental {
namespace {

constexpr double kNoLevel = std::numeric_limits<double>::infinity();
constexpr double kCellMm = 0.5;      // of the gingival level's map over the occlusal plane
constexpr double kOwnCrownMm = 1.0;  // a crown's own scan points set the level this close

// Heights along the occlusal direction and positions in the occlusal plane.
struct OcclusalFrame {
  Eigen::Vector3d up, u, v;
  explicit OcclusalFrame(const Eigen::Vector3d& towards_occlusal) : up(towards_occlusal.normalized()) {
    u = up.unitOrthogonal();
    v = up.cross(u);
  }
  double height(const Eigen::Vector3d& p) const { return p.dot(up); }
  Eigen::Vector2d plane(const Eigen::Vector3d& p) const { return {p.dot(u), p.dot(v)}; }
};

// The gingival level over the occlusal plane (step 2): a map of cells, each holding the lowest
// on-teeth scan height within the search radius, or kNoLevel.
class GingivalLevel {
 public:
  GingivalLevel(const OcclusalFrame& frame, const std::vector<Eigen::Vector3d>& on_teeth, const Eigen::Vector2d& low,
                const Eigen::Vector2d& high, double radius)
      : frame_(frame), low_(low) {
    size_ = ((high - low) / kCellMm).array().ceil().cast<int>() + 1;
    std::vector<double> lowest(size_t(size_.x()) * size_t(size_.y()), kNoLevel);
    for (const Eigen::Vector3d& p : on_teeth) {
      double& cell = lowest[index(cell_of(p))];
      cell = std::min(cell, frame.height(p));
    }
    // Over a crown, its own scan sets the level (the nearest cells): a neighbour whose neck lies
    // lower must not cut the CT below this crown's neck, which would open a gap under its shell.
    // Beside the crowns, where the scan has no point on the teeth, the lowest level around reaches
    // out to the radius and cuts what the CT shows there (a streak, a crown's partial volume).
    const std::vector<double> own = lowest_within(lowest, kOwnCrownMm);
    neck_ = lowest_within(lowest, radius);
    cut_.resize(lowest.size());
    for (size_t c = 0; c < lowest.size(); ++c) cut_[c] = own[c] != kNoLevel ? own[c] : neck_[c];
  }

  // Each cell's lowest height within `radius` (kNoLevel: none).
  std::vector<double> lowest_within(const std::vector<double>& lowest, double radius) const {
    std::vector<double> out(lowest.size(), kNoLevel);
    const int reach = int(std::ceil(radius / kCellMm));
    for (int j = 0; j < size_.y(); ++j)
      for (int i = 0; i < size_.x(); ++i) {
        double level = kNoLevel;
        for (int dj = -reach; dj <= reach; ++dj)
          for (int di = -reach; di <= reach; ++di) {
            const int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= size_.x() || jj >= size_.y() || di * di + dj * dj > reach * reach) continue;
            level = std::min(level, lowest[index({ii, jj})]);
          }
        out[index({i, j})] = level;
      }
    return out;
  }

  // The lowest neck around p: a scan point above it is on a crown (kNoLevel outside the map or
  // where no crown is near).
  double neck(const Eigen::Vector3d& p) const { return read(neck_, p); }
  // Where the CT is cut over p: its own crown's lowest point on the teeth, else the neck around.
  double cut(const Eigen::Vector3d& p) const { return read(cut_, p); }

 private:
  double read(const std::vector<double>& map, const Eigen::Vector3d& p) const {
    const Eigen::Vector2i c = cell_of(p);
    if (c.x() < 0 || c.y() < 0 || c.x() >= size_.x() || c.y() >= size_.y()) return kNoLevel;
    return map[index(c)];
  }
  Eigen::Vector2i cell_of(const Eigen::Vector3d& p) const {
    return ((frame_.plane(p) - low_) / kCellMm).array().floor().cast<int>();
  }
  size_t index(const Eigen::Vector2i& c) const { return size_t(c.x()) + size_t(size_.x()) * size_t(c.y()); }

  OcclusalFrame frame_;
  Eigen::Vector2d low_;
  Eigen::Vector2i size_;
  std::vector<double> neck_, cut_;
};

// An axis-aligned grid around the points, with a margin.
LabelVolume grid_around(const std::vector<const TriangleMesh*>& meshes, double voxel, double margin) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(kNoLevel), high = -low;
  for (const TriangleMesh* mesh : meshes) {
    low = low.cwiseMin(mesh->vertices.colwise().minCoeff().transpose());
    high = high.cwiseMax(mesh->vertices.colwise().maxCoeff().transpose());
  }
  LabelVolume grid;
  grid.geometry.spacing = Eigen::Vector3d::Constant(voxel);
  grid.geometry.origin = low - Eigen::Vector3d::Constant(margin);
  grid.geometry.size = ((high - low + Eigen::Vector3d::Constant(2 * margin)) / voxel).array().ceil().cast<int>() + 1;
  grid.labels.assign(size_t(grid.geometry.voxel_count()), 0);
  return grid;
}

// Whether one of the CT voxels around p carries the label.
bool near_label(const LabelVolume& labels, const Eigen::Vector3d& p, uint8_t label) {
  const Eigen::Vector3i base = labels.geometry.continuous_index(p).array().floor().cast<int>();
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3i c = base + Eigen::Vector3i(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    if (labels.geometry.contains(c.x(), c.y(), c.z()) &&
        labels.labels[size_t(labels.geometry.index(c.x(), c.y(), c.z()))] == label)
      return true;
  }
  return false;
}

constexpr uint8_t kShell = 1, kKeptCt = 2, kOutside = 3;

// Step 3: the crowns' triangles drawn into the grid, sampled at a third of a voxel and each
// sample's voxel marked, down to `inward` mm behind each triangle (against its normal: into the
// tooth). A slab that deep (over two voxels) leaves no 6-connected path through it, and it
// closes the neck: a CT's tooth at its threshold lies a few tenths of a millimetre inside the
// true surface, which the scan is, and the gap would let the outside in. The slab grows only
// inwards, so narrow gaps between neighbouring crowns and the fissures stay open.
int64_t draw_shell(LabelVolume& grid, const TriangleMesh& scan, const std::vector<uint8_t>& crown, double inward) {
  const VolumeGeometry& g = grid.geometry;
  std::vector<uint8_t> sampled(grid.labels.size(), 0);
  const double step = g.spacing.x() / 3;
  const int depths = int(std::ceil(inward / step));
  for (Eigen::Index f = 0; f < scan.face_count(); ++f) {
    const Eigen::Vector3i face = scan.faces.row(f).transpose();
    if (!crown[size_t(face(0))] || !crown[size_t(face(1))] || !crown[size_t(face(2))]) continue;
    const Eigen::Vector3d a = scan.vertices.row(face(0)).transpose(), b = scan.vertices.row(face(1)).transpose(),
                          c = scan.vertices.row(face(2)).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    const int n = std::max(1, int(std::ceil(std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / step)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        for (int d = 0; d <= depths; ++d) {
          const Eigen::Vector3d p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n) - normal * (d * step);
          const Eigen::Vector3i v = g.continuous_index(p).array().round().cast<int>();
          if (g.contains(v.x(), v.y(), v.z())) sampled[size_t(g.index(v.x(), v.y(), v.z()))] = 1;
        }
  }
  int64_t voxels = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        bool hit = false;
        for (const Eigen::Vector3i& d :
             {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(-1, 0, 0), Eigen::Vector3i(0, 1, 0),
              Eigen::Vector3i(0, -1, 0), Eigen::Vector3i(0, 0, 1), Eigen::Vector3i(0, 0, -1)}) {
          const Eigen::Vector3i q(i + d.x(), j + d.y(), k + d.z());
          if (g.contains(q.x(), q.y(), q.z()) && sampled[size_t(g.index(q.x(), q.y(), q.z()))]) hit = true;
        }
        if (hit) {
          grid.labels[size_t(g.index(i, j, k))] = kShell;
          ++voxels;
        }
      }
  return voxels;
}

// Step 5: a 6-connected flood fill from every border voxel through the unmarked ones.
void flood_outside(LabelVolume& grid) {
  const VolumeGeometry& g = grid.geometry;
  std::deque<Eigen::Vector3i> queue;
  auto visit = [&](int i, int j, int k) {
    if (!g.contains(i, j, k)) return;
    uint8_t& l = grid.labels[size_t(g.index(i, j, k))];
    if (l != 0) return;
    l = kOutside;
    queue.emplace_back(i, j, k);
  };
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        if (i == 0 || j == 0 || k == 0 || i == g.size.x() - 1 || j == g.size.y() - 1 || k == g.size.z() - 1)
          visit(i, j, k);
  while (!queue.empty()) {
    const Eigen::Vector3i v = queue.front();
    queue.pop_front();
    visit(v.x() + 1, v.y(), v.z());
    visit(v.x() - 1, v.y(), v.z());
    visit(v.x(), v.y() + 1, v.z());
    visit(v.x(), v.y() - 1, v.z());
    visit(v.x(), v.y(), v.z() + 1);
    visit(v.x(), v.y(), v.z() - 1);
  }
}

// The voxels within `steps` 6-connected steps of a marked one (a breadth-first search).
std::vector<uint8_t> within_steps(const std::vector<uint8_t>& marked, const VolumeGeometry& g, int steps) {
  std::vector<uint8_t> near = marked;
  std::vector<Eigen::Vector3i> front;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        if (marked[size_t(g.index(i, j, k))]) front.emplace_back(i, j, k);
  for (int step = 0; step < steps; ++step) {
    std::vector<Eigen::Vector3i> next;
    for (const Eigen::Vector3i& v : front)
      for (const Eigen::Vector3i& d :
           {Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(-1, 0, 0), Eigen::Vector3i(0, 1, 0), Eigen::Vector3i(0, -1, 0),
            Eigen::Vector3i(0, 0, 1), Eigen::Vector3i(0, 0, -1)}) {
        const Eigen::Vector3i q = v + d;
        if (!g.contains(q.x(), q.y(), q.z())) continue;
        uint8_t& n = near[size_t(g.index(q.x(), q.y(), q.z()))];
        if (n) continue;
        n = 1;
        next.push_back(q);
      }
    front = std::move(next);
  }
  return near;
}

// The scan's triangles whose three corners lie on a crown.
TriangleMesh crown_triangles(const TriangleMesh& scan, const std::vector<uint8_t>& crown) {
  TriangleMesh crowns;
  crowns.vertices = scan.vertices;
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < scan.face_count(); ++f) {
    const Eigen::Vector3i face = scan.faces.row(f).transpose();
    if (crown[size_t(face(0))] && crown[size_t(face(1))] && crown[size_t(face(2))]) faces.push_back(face);
  }
  crowns.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) crowns.faces.row(Eigen::Index(f)) = faces[f].transpose();
  return crowns;
}

// Step 6: the solid as a field (saturated), and near the crowns the scan's signed distance: on the
// shell's voxels (drawn a voxel beyond the scan, so the solid alone lies too far out), and
// elsewhere where its side agrees with the solid's (by the crowns' open neck the pseudo-normal's
// side is not to be trusted, and the solid's is).
Volume crown_field(const LabelVolume& solid, const std::vector<uint8_t>& shell, const TriangleMesh& scan,
                   const std::vector<uint8_t>& crown, double band_mm) {
  Volume field{solid.geometry, std::vector<int16_t>(solid.labels.size())};
  for (size_t v = 0; v < solid.labels.size(); ++v) field.hu[v] = solid.labels[v] ? kFieldSaturation : -kFieldSaturation;
  const TriangleMesh crowns = crown_triangles(scan, crown);
  if (crowns.face_count() == 0) return field;
  const DistanceField distance(crowns);
  const VolumeGeometry& g = solid.geometry;
  const std::vector<uint8_t> near = within_steps(shell, g, int(std::ceil(band_mm / g.spacing.x())) + 1);
  for_each_slab(0, g.size.z(), [&](int first, int last) {
    for (int k = first; k < last; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          const size_t v = size_t(g.index(i, j, k));
          if (!near[v]) continue;  // farther from the crowns than the band: the solid's value stands
          const auto d = distance.signed_distance(g.world(Eigen::Vector3d(i, j, k)), band_mm);
          if (!d.found) continue;
          if (!shell[v] && (d.distance < 0) != (solid.labels[v] != 0)) continue;
          field.hu[v] = int16_t(std::clamp(-1000.0 * d.distance, -double(kFieldSaturation), double(kFieldSaturation)));
        }
  });
  return field;
}

}  // namespace

AugmentedDentition augmented_dentition(const Volume& ct, const LabelVolume& jaw_labels, uint8_t jaw_label,
                                       const TriangleMesh& ct_teeth, const TriangleMesh& placed_scan,
                                       const Eigen::Vector3d& towards_occlusal,
                                       const AugmentedDentitionOptions& options) {
  const OcclusalFrame frame(towards_occlusal);
  // Step 2: the scan's points on the CT's teeth, and the level their lowest ones set.
  const AabbTree teeth(ct_teeth);
  std::vector<Eigen::Vector3d> on_teeth;
  Eigen::Vector2d low = Eigen::Vector2d::Constant(kNoLevel), high = -low;
  for (Eigen::Index i = 0; i < placed_scan.vertex_count(); ++i) {
    const Eigen::Vector3d p = placed_scan.vertices.row(i).transpose();
    if (teeth.nearest(p, options.on_teeth_mm).face >= 0) on_teeth.push_back(p);
  }
  // The map covers the CT's teeth too: a streak beside the scan's outline must find its level.
  for (const TriangleMesh* mesh : {&placed_scan, &ct_teeth})
    for (Eigen::Index i = 0; i < mesh->vertex_count(); ++i) {
      const Eigen::Vector2d q = frame.plane(mesh->vertices.row(i).transpose());
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
    }
  if (on_teeth.empty())
    throw Error(ErrorCode::kProcessing, "dental scan",
                "no point of it lies on the CT's teeth: it is not placed on them");
  const GingivalLevel level(frame, on_teeth, low, high, options.neck_search_mm);

  AugmentedDentition out;
  // Step 3: the crowns, above the level.
  out.crown_vertex.assign(size_t(placed_scan.vertex_count()), 0);
  for (Eigen::Index i = 0; i < placed_scan.vertex_count(); ++i) {
    const Eigen::Vector3d p = placed_scan.vertices.row(i).transpose();
    out.crown_vertex[size_t(i)] = frame.height(p) >= level.neck(p) - 1e-9;
  }
  out.solid = grid_around({&ct_teeth, &placed_scan}, options.voxel_mm, options.margin_mm);
  out.crown_voxels = draw_shell(out.solid, placed_scan, out.crown_vertex, options.shell_inward_mm);
  // Step 4: the CT's teeth of this jaw, below the level and the seal.
  const VolumeGeometry& g = out.solid.geometry;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        uint8_t& l = out.solid.labels[size_t(g.index(i, j, k))];
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (!near_label(jaw_labels, p, jaw_label) || sample_trilinear(ct, p) < options.teeth_hu) continue;
        if (frame.height(p) > level.cut(p) + options.seal_mm) {
          ++out.ct_voxels_cut;
          continue;
        }
        ++out.ct_voxels_kept;
        if (l == 0) l = kKeptCt;
      }
  // Step 5: what the outside does not reach is the dentition.
  flood_outside(out.solid);
  std::vector<uint8_t> shell(out.solid.labels.size());
  for (size_t v = 0; v < shell.size(); ++v) shell[v] = out.solid.labels[v] == kShell;
  for (uint8_t& l : out.solid.labels) l = l == kOutside ? 0 : 1;
  out.field = crown_field(out.solid, shell, placed_scan, out.crown_vertex, options.crown_band_mm);
  return out;
}

}  // namespace maxillo::dental
