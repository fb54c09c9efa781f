#include "casework/validation/synthetic_postop.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "core/parallel_slabs.h"
#include "imaging/segmentation.h"
#include "core/volume_resample.h"
#include "mesh/surface_extraction.h"
#include "geometry/vertex_normals.h"
#include "geometry/signed_distance.h"

namespace maxillo::casework {
namespace {

constexpr double kSoftTissueHu = 40;          // what fills space the face grew into
constexpr double kSoftTissueCeilingHu = 150;  // soft tissue sampled next to bone that left keeps below bone
constexpr double kAirHu = -1000;
constexpr double kMovedSkinMm = 0.02;  // skin that moves less than this keeps its pre-operative voxels

// Whether the voxel nearest `lps` or one of its six face neighbours has `label`: the rim of partial
// volume around a structure, whose HU belongs to it.
bool touches_label(const LabelVolume& labels, const Eigen::Vector3d& lps, uint8_t label) {
  const Eigen::Vector3i ijk = labels.geometry.continuous_index(lps).array().round().cast<int>();
  static const std::array<Eigen::Vector3i, 7> offsets{
      Eigen::Vector3i(0, 0, 0),  Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(-1, 0, 0), Eigen::Vector3i(0, 1, 0),
      Eigen::Vector3i(0, -1, 0), Eigen::Vector3i(0, 0, 1), Eigen::Vector3i(0, 0, -1)};
  for (const auto& o : offsets) {
    const Eigen::Vector3i n = ijk + o;
    if (labels.geometry.contains(n.x(), n.y(), n.z()) &&
        labels.labels[size_t(labels.geometry.index(n.x(), n.y(), n.z()))] == label)
      return true;
  }
  return false;
}

// The skin's HU across the surface: a linear ramp through the skin threshold, so that the threshold's iso-surface
// lies where the signed distance is zero.
struct SkinRamp {
  double threshold_hu;
  double hu_per_mm;
  double hu(double signed_mm) const { return std::clamp(threshold_hu - signed_mm * hu_per_mm, kAirHu, kSoftTissueHu); }
  double inner_width_mm() const { return (kSoftTissueHu - threshold_hu) / hu_per_mm; }
  double outer_width_mm() const { return (threshold_hu - kAirHu) / hu_per_mm; }  // air from here out
};

// Where the post-operative skin lies, seen from a cube of voxels. A distance changes by at most the distance moved,
// so one signed distance query at the cube's centre bounds it for every voxel of the cube, and across a closed surface
// that does not pass through itself the sign cannot change without the distance passing through zero. Only cubes
// that the skin's ramp (or the search's reach) may cross then need a query per voxel: a thin shell, where the whole
// face region needed one each. Where the moved skin does fold through itself (the known error pushes the unsmoothed
// iso-surface along its vertex normals) inside and outside are not defined, and a cube takes its centre's side where
// a voxel's own query may say the other: 417 of the 1 mm demo's 12.8 million voxels, around the lips.
enum class SkinSide { kUnknown, kBeyondReach, kOutside, kInside, kEachVoxel };

struct VoxelCube {
  Eigen::Vector3d centre;              // pre-operative frame
  double radius_mm = 0;                // from the centre to the cube's farthest voxel
  SkinSide side = SkinSide::kUnknown;  // settled when a voxel first needs it
};

// The cube of voxels lo..hi (inclusive) of `g`, placed in the pre-operative frame by `to_preop`.
VoxelCube voxel_cube(const VolumeGeometry& g, const Eigen::Isometry3d& to_preop, const Eigen::Vector3i& lo,
                     const Eigen::Vector3i& hi) {
  VoxelCube cube;
  cube.centre = to_preop * g.world(0.5 * (lo + hi).cast<double>());
  for (int corner = 0; corner < 8; ++corner) {  // the farthest voxel of a box is one of its corners
    const Eigen::Vector3i c((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    cube.radius_mm = std::max(cube.radius_mm, (to_preop * g.world(c.cast<double>()) - cube.centre).norm());
  }
  return cube;
}

// A skin pushed out along its normals by the known bump.
TriangleMesh bumped_skin(const TriangleMesh& predicted, const std::vector<double>& bump) {
  const VertexMatrix normals = vertex_normals(predicted);
  TriangleMesh actual = predicted;
  for (Eigen::Index v = 0; v < actual.vertex_count(); ++v) actual.vertices.row(v) += bump[size_t(v)] * normals.row(v);
  return actual;
}

std::vector<double> error_bump(const TriangleMesh& skin, const Eigen::Vector3d& centre,
                               const SyntheticPostopOptions& options) {
  std::vector<double> bump(size_t(skin.vertex_count()));
  const double two_sigma2 = 2 * options.error_sigma_mm * options.error_sigma_mm;
  for (Eigen::Index v = 0; v < skin.vertex_count(); ++v)
    bump[size_t(v)] =
        options.error_mm * std::exp(-(skin.vertices.row(v).transpose() - centre).squaredNorm() / two_sigma2);
  return bump;
}

// Axis-aligned box around the skin vertices that moved (prediction or bump), grown by `margin`;
// empty (containing nothing) when none moved.
Eigen::AlignedBox3d moved_skin_box(const TriangleMesh& before, const TriangleMesh& after, double margin) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index v = 0; v < before.vertex_count(); ++v) {
    if ((after.vertices.row(v) - before.vertices.row(v)).norm() < kMovedSkinMm) continue;
    box.extend(before.vertices.row(v).transpose());
    box.extend(after.vertices.row(v).transpose());
  }
  if (box.isEmpty()) return box;
  box.min().array() -= margin;
  box.max().array() += margin;
  return box;
}

class PostopVoxels {
 public:
  PostopVoxels(const PlannedCase& planned, const SegmentMoves& moves, const TriangleMesh& skin_before,
               const TriangleMesh& skin_after, double reach_mm)
      : planned_(planned),
        skin_field_(skin_after),
        reach_mm_(reach_mm),
        ramp_{SegmentationOptions{}.skin_hu, 600.0 / planned.preop_ct.geometry.spacing.minCoeff()},
        box_(moved_skin_box(skin_before, skin_after, reach_mm)) {
    for (const auto& [segment, move] : moves) inverse_moves_.emplace_back(segment, move.inverse());
  }

  // HU at a point of the pre-operative frame after surgery; `cube` holds the point's voxel.
  double hu(const Eigen::Vector3d& y, VoxelCube& cube) const {
    if (auto bone = moved_bone(y)) return *bone;
    const uint8_t segment = sample_nearest(planned_.cut.segments, y);
    if (segment != 0 && !is_moved(segment)) return sample_trilinear(planned_.preop_ct, y);
    return soft_tissue_or_air(y, cube);
  }

 private:
  // A moved segment's bone at y, sampled where it came from. (Taking the partial-volume rim just
  // outside the segment along made the fitted move worse, 0.25 against 0.19 mm on the 1.5 mm
  // phantom: the rim also holds its neighbours' partial volume.)
  std::optional<double> moved_bone(const Eigen::Vector3d& y) const {
    for (const auto& [segment, inverse] : inverse_moves_) {
      const Eigen::Vector3d source = inverse * y;
      if (sample_nearest(planned_.cut.segments, source) == segment) return sample_trilinear(planned_.preop_ct, source);
    }
    return std::nullopt;
  }

  bool is_moved(uint8_t segment) const {
    return std::any_of(inverse_moves_.begin(), inverse_moves_.end(), [&](const auto& m) { return m.first == segment; });
  }

  // Next to where a moved segment was: its partial volume must not stay behind as bone.
  bool beside_moved_bone(const Eigen::Vector3d& y) const {
    return std::any_of(inverse_moves_.begin(), inverse_moves_.end(),
                       [&](const auto& m) { return touches_label(planned_.cut.segments, y, m.first); });
  }

  double soft_value(const Eigen::Vector3d& y) const {
    const double value = sample_trilinear(planned_.preop_ct, y);
    return beside_moved_bone(y) ? std::min(value, kSoftTissueCeilingHu) : value;
  }

  // Within reach of the new skin: the ramp across it, air outside, the pre-operative interior inside. Elsewhere
  // what the pre-operative CT had, without the bone that moved away.
  double soft_tissue_or_air(const Eigen::Vector3d& y, VoxelCube& cube) const {
    if (box_.contains(y)) {
      if (cube.side == SkinSide::kUnknown) cube.side = side_of(cube);
      switch (cube.side) {
        case SkinSide::kOutside: return kAirHu;
        case SkinSide::kInside: return interior_hu(y);
        case SkinSide::kEachVoxel: {
          const auto d = skin_field_.signed_distance(y, reach_mm_);
          if (d.found && d.distance > -ramp_.inner_width_mm()) return ramp_.hu(d.distance);
          if (d.found) return interior_hu(y);
          break;
        }
        default: break;  // beyond reach
      }
    }
    const uint8_t tissue = sample_nearest(planned_.tissues.segmentation, y);
    if (tissue == kBone || tissue == kTeeth) return kSoftTissueHu;  // bone that moved away
    return soft_value(y);
  }

  // What every voxel of the cube has in common, if the query at its centre settles it. For a cube of one voxel this
  // decides exactly as the voxel's own query would.
  SkinSide side_of(const VoxelCube& cube) const {
    const double r = cube.radius_mm;
    const auto d = skin_field_.signed_distance(cube.centre, reach_mm_ + r);
    if (!d.found) return SkinSide::kBeyondReach;
    if (std::abs(d.distance) + r >= reach_mm_) return SkinSide::kEachVoxel;  // some may lie beyond reach
    if (d.distance - r >= ramp_.outer_width_mm()) return SkinSide::kOutside;
    if (d.distance + r <= -ramp_.inner_width_mm()) return SkinSide::kInside;
    return SkinSide::kEachVoxel;
  }

  double interior_hu(const Eigen::Vector3d& y) const {
    const uint8_t tissue = sample_nearest(planned_.tissues.segmentation, y);
    if (tissue == kSoftTissue || tissue == kEnclosedAir) return std::min(soft_value(y), kSoftTissueCeilingHu);
    return kSoftTissueHu;  // where air or bone was before
  }

  const PlannedCase& planned_;
  DistanceField skin_field_;
  double reach_mm_;
  SkinRamp ramp_;
  Eigen::AlignedBox3d box_;
  std::vector<std::pair<uint8_t, Eigen::Isometry3d>> inverse_moves_;
};

// The skin iso-surface of the pre-operative CT as marching cubes gives it: no smoothing, no decimation, inside the
// segmented body.
TriangleMesh raw_skin(const PlannedCase& planned) {
  const double skin_hu = SegmentationOptions{}.skin_hu;
  const SurfaceOptions unsmoothed{.keep_largest_components = 1, .smoothing_iterations = 0, .target_triangles = 0};
  return extract_region_surface(planned.preop_ct, planned.tissues.segmentation, LabelRange{}, skin_hu, unsmoothed);
}

}  // namespace

Eigen::Isometry3d synthetic_reposition(const VolumeGeometry& g, const SyntheticPostopOptions& options) {
  const Eigen::Vector3d centre = g.world(0.5 * (g.size.cast<double>() - Eigen::Vector3d::Ones()));
  const double angle = options.reposition_deg * M_PI / 180;
  Eigen::Isometry3d postop_to_preop = Eigen::Isometry3d::Identity();
  postop_to_preop.translate(centre + Eigen::Vector3d::Constant(options.reposition_mm));
  postop_to_preop.rotate(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
  postop_to_preop.translate(-centre);
  return postop_to_preop;
}

SyntheticPostop make_synthetic_postop(const PlannedCase& planned, const SyntheticPostopOptions& options) {
  if (options.skin_block_voxels < 1)
    throw Error(ErrorCode::kBadValue, "synthetic post-op", "skin_block_voxels must be at least 1");
  SyntheticPostop result;
  result.moves = planned.planned_moves;
  result.postop_to_preop = synthetic_reposition(planned.preop_ct.geometry, options);

  log::info("synthetic post-operative CT: predicting the face for the planned moves");
  SoftTissueInput input{&planned.tissues.jaws, &planned.cut.segments, &planned.skin, planned.landmarks, result.moves};
  const SoftTissuePrediction prediction =
      predict_soft_tissue(input, options.soft_tissue, planned.face_model(options.soft_tissue).get());
  result.predicted_skin = prediction.skin_after;

  const Eigen::Vector3d centre_before = require_landmark(planned.landmarks, options.error_centre, "synthetic post-op");
  VertexMatrix centre(1, 3);
  centre.row(0) = centre_before.transpose();
  const Eigen::Vector3d centre_after = centre_before + displacement_at(prediction, centre, 10.0).row(0).transpose();
  const std::vector<double> bump = error_bump(result.predicted_skin, centre_after, options);
  result.actual_skin = bumped_skin(result.predicted_skin, bump);
  result.known_error_mm.resize(bump.size());
  std::transform(bump.begin(), bump.end(), result.known_error_mm.begin(), [](double e) { return -e; });

  log::info("synthetic post-operative CT: building the volume");
  // The CT encodes the pre-operative CT's own skin iso-surface (not smoothed) moved like the prediction, so that
  // extracting the skin from it repeats exactly what extracting it from the pre-operative CT did: the smoothing's
  // slight outward drift on convex skin (~0.06 mm on a 30 mm sphere) then cancels, as it does between two real scans.
  const TriangleMesh raw_before = raw_skin(planned);
  const Eigen::MatrixX3d raw_move =
      displacement_at(prediction, raw_before.vertices, options.soft_tissue.skin_binding_mm);
  TriangleMesh raw_after = raw_before;
  raw_after.vertices += raw_move;
  raw_after = bumped_skin(raw_after, error_bump(raw_after, centre_after, options));
  const double max_skin_move = raw_move.rowwise().norm().maxCoeff() + options.error_mm;
  const PostopVoxels voxels(planned, result.moves, raw_before, raw_after, max_skin_move + 3.0);
  result.ct.geometry = planned.preop_ct.geometry;
  result.ct.hu.resize(size_t(result.ct.geometry.voxel_count()));
  const auto& g = result.ct.geometry;
  // Every voxel is computed on its own from read-only inputs, in cubes of n voxels a side: slabs of cube layers run
  // in parallel.
  const int n = options.skin_block_voxels;
  const Eigen::Vector3i last = g.size - Eigen::Vector3i::Ones();
  for_each_slab(0, (g.size.z() + n - 1) / n,
                [&](int layer0, int layer1) {
                  for (int layer = layer0; layer < layer1; ++layer)
                    for (int j0 = 0; j0 < g.size.y(); j0 += n)
                      for (int i0 = 0; i0 < g.size.x(); i0 += n) {
                        const Eigen::Vector3i lo(i0, j0, layer * n);
                        const Eigen::Vector3i hi = (lo + Eigen::Vector3i::Constant(n - 1)).cwiseMin(last);
                        VoxelCube cube = voxel_cube(g, result.postop_to_preop, lo, hi);
                        for (int k = lo.z(); k <= hi.z(); ++k)
                          for (int j = lo.y(); j <= hi.y(); ++j)
                            for (int i = lo.x(); i <= hi.x(); ++i) {
                              const Eigen::Vector3d y = result.postop_to_preop * g.world(Eigen::Vector3d(i, j, k));
                              result.ct.at(i, j, k) =
                                  int16_t(std::lround(std::clamp(voxels.hu(y, cube), -1024.0, 3071.0)));
                            }
                      }
                },
                {.min_slab_size = 1});
  return result;
}

}  // namespace maxillo::casework
