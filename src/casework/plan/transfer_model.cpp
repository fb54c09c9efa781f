#include "casework/plan/transfer_model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geometry/mesh_measures.h"
#include "mesh/surface_extraction.h"
#include "planning/osteotomy.h"

namespace maxillo::casework {
namespace {

// Box (in the segment volume's index-aligned frame, i.e. continuous indices scaled by spacing)
// of the maxilla and the screws, plus the margin.
Eigen::AlignedBox3d model_box(const LabelVolume& segments, const std::vector<ScrewAxis>& screws,
                              const TransferModelOptions& o) {
  const auto& g = segments.geometry;
  Eigen::AlignedBox3d box;
  const int64_t nx = g.size.x(), ny = g.size.y();
  for (int64_t v = 0; v < int64_t(segments.labels.size()); ++v)
    if (segments.labels[size_t(v)] == uint8_t(planning::Segment::kMaxilla))
      box.extend(Eigen::Vector3d(double(v % nx), double((v / nx) % ny), double(v / (nx * ny))).cwiseProduct(g.spacing));
  if (box.isEmpty())
    throw Error(ErrorCode::kEmptyResult, "transfer model", "the plan has no Le Fort I maxilla segment");
  for (const auto& s : screws) {
    for (const Eigen::Vector3d& end :
         {Eigen::Vector3d(s.entry - o.outside_mm * s.direction), Eigen::Vector3d(s.entry + s.length_mm * s.direction)})
      box.extend(g.continuous_index(end).cwiseProduct(g.spacing));
  }
  box.min().array() -= o.margin_mm;
  box.max().array() += o.margin_mm;
  // Never beyond the scanned volume.
  box.min() = box.min().cwiseMax(Eigen::Vector3d::Zero());
  box.max() = box.max().cwiseMin((g.size.cast<double>() - Eigen::Vector3d::Ones()).cwiseProduct(g.spacing));
  return box;
}

// Distance of p from the segment [a, a + length * d] and the position t along it.
struct AxisDistance {
  double radial;
  double t;
};
AxisDistance axis_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& d) {
  const double t = d.dot(p - a);
  return {(p - a - t * d).norm(), t};
}

enum class TubePart { None, Wall, Bore };
TubePart tube_part(const Eigen::Vector3d& p, const std::vector<ScrewAxis>& screws, const TransferModelOptions& o) {
  TubePart part = TubePart::None;
  for (const auto& s : screws) {
    auto [radial, t] = axis_distance(p, s.entry, s.direction);
    if (t < -o.outside_mm || t > s.length_mm) continue;
    if (radial <= o.bore_radius_mm) return TubePart::Bore;  // the bore wins: the screw must pass
    if (radial <= o.bore_radius_mm + o.wall_mm) part = TubePart::Wall;
  }
  return part;
}

bool is_midface(uint8_t segment) {
  return segment == uint8_t(planning::Segment::kCranium) || segment == uint8_t(planning::Segment::kMaxilla);
}

}  // namespace

TransferModel make_transfer_model(const LabelVolume& segments, const std::vector<ScrewAxis>& screws,
                                  const TransferModelOptions& options) {
  const auto& g = segments.geometry;
  const Eigen::AlignedBox3d box = model_box(segments, screws, options);
  // The fine grid shares the CT's axes; only spacing and origin differ.
  LabelVolume model;
  model.geometry.direction = g.direction;
  model.geometry.spacing = Eigen::Vector3d::Constant(options.voxel_mm);
  model.geometry.origin = g.origin + g.direction * box.min();
  model.geometry.size = ((box.max() - box.min()) / options.voxel_mm).array().floor().cast<int>() + 1;
  model.labels.assign(size_t(model.geometry.voxel_count()), 0);
  const auto& f = model.geometry;
  for (int k = 0; k < f.size.z(); ++k)
    for (int j = 0; j < f.size.y(); ++j)
      for (int i = 0; i < f.size.x(); ++i) {
        const Eigen::Vector3d p = f.world(Eigen::Vector3d(i, j, k));
        const TubePart part = tube_part(p, screws, options);
        bool solid = part == TubePart::Wall;
        if (part == TubePart::None) {
          // Nearest CT voxel: the bone keeps the CT's resolution, only the tubes are finer.
          const Eigen::Vector3i c = g.continuous_index(p).array().round().cast<int>();
          solid = g.contains(c.x(), c.y(), c.z()) && is_midface(segments.labels[size_t(g.index(c.x(), c.y(), c.z()))]);
        }
        model.labels[size_t(f.index(i, j, k))] = solid ? 1 : 0;
      }
  SurfaceOptions surface;
  surface.keep_largest_components = 1;  // one printable piece: loose fragments would fall off
  surface.smoothing_iterations = 10;
  surface.target_triangles = options.target_triangles;
  TransferModel result;
  result.mesh = extract_surface(model, 1, surface);
  result.volume_ml = signed_volume(result.mesh) / 1000.0;
  result.watertight = is_watertight(result.mesh);
  return result;
}

}  // namespace maxillo::casework
