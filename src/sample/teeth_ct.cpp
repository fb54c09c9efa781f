#include "sample/teeth_ct.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/parallel_slabs.h"
#include "geometry/signed_distance.h"

namespace maxillo {
namespace {

// One arch's biting direction (towards the other arch) and how far its biting end reaches along it.
struct Arch {
  const DistanceField& field;
  Eigen::Vector3d biting;  // unit
  double end = 0;          // max of v . biting over its vertices
  bool in_crown(const Eigen::Vector3d& p, double height) const { return end - p.dot(biting) <= height; }
};

Arch arch_of(const DistanceField& field, const Eigen::Vector3d& towards) {
  Arch arch{field, towards.normalized(), 0};
  arch.end = (field.mesh().vertices * arch.biting).maxCoeff();
  return arch;
}

VolumeGeometry grid_around(const TriangleMesh& upper, const TriangleMesh& lower, const TeethCtOptions& options) {
  const Eigen::Vector3d low =
      upper.vertices.colwise().minCoeff().transpose().cwiseMin(lower.vertices.colwise().minCoeff().transpose()) -
      Eigen::Vector3d::Constant(options.margin_mm);
  const Eigen::Vector3d high =
      upper.vertices.colwise().maxCoeff().transpose().cwiseMax(lower.vertices.colwise().maxCoeff().transpose()) +
      Eigen::Vector3d::Constant(options.margin_mm);
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(options.spacing_mm);
  g.origin = low;
  g.size = ((high - low) / options.spacing_mm).array().ceil().cast<int>().matrix() + Eigen::Vector3i::Ones();
  return g;
}

// The value of a voxel at p from the teeth and the bone around their roots (no metal, no noise).
double anatomy_hu(const Eigen::Vector3d& p, const Arch& upper, const Arch& lower, const TeethCtOptions& o) {
  // Far enough to see the surface from the middle of the widest tooth (a molar, about 11 mm).
  constexpr double kReachMm = 6;
  double value = o.soft_tissue_hu;
  for (const Arch* arch : {&upper, &lower}) {
    const SignedDistance d = arch->field.signed_distance(p, kReachMm);
    if (!d.found) continue;
    const bool crown = arch->in_crown(p, o.crown_height_mm);
    const double outside = crown ? o.soft_tissue_hu : (d.distance < o.bone_shell_mm ? o.bone_hu : o.soft_tissue_hu);
    const double inside_share = std::clamp(0.5 - d.distance / o.spacing_mm, 0.0, 1.0);  // partial volume
    const double tooth = crown ? o.enamel_hu : o.dentine_hu;
    value = std::max(value, inside_share * tooth + (1 - inside_share) * outside);
  }
  return value;
}

struct Filling {
  Eigen::Vector3d centre;
};

// Fillings at the biting end of the back teeth: the upper arch's two ends along its width and
// the lower arch's first, each sunk 1 mm into its tooth.
std::vector<Filling> fillings_of(const Arch& upper, const Arch& lower, int count) {
  std::vector<Filling> fillings;
  for (const Arch* arch : {&upper, &lower}) {
    const auto& v = arch->field.mesh().vertices;
    const Eigen::Vector3d centroid = v.colwise().mean().transpose();
    const Eigen::MatrixX3d centred = v.rowwise() - centroid.transpose();
    const Eigen::Vector3d width =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred.transpose() * centred).eigenvectors().col(2);
    for (double side : {1.0, -1.0}) {
      Eigen::Index best = -1;
      double extreme = -1e300;
      for (Eigen::Index i = 0; i < v.rows(); ++i) {
        const Eigen::Vector3d p = v.row(i).transpose();
        if (!arch->in_crown(p, 2.0)) continue;  // the biting surface
        if (side * (p - centroid).dot(width) > extreme) extreme = side * (p - centroid).dot(width), best = i;
      }
      if (best >= 0 && int(fillings.size()) < count)
        fillings.push_back({Eigen::Vector3d(v.row(best).transpose()) - 1.0 * arch->biting});
    }
  }
  return fillings;
}

// A filling's streaks in the axial slices through it: six lines through its centre, bright and
// dark in turn, each a Gaussian ridge 0.5 mm wide whose contrast falls off with distance.
double streaks_hu(const Eigen::Vector3d& p, const Filling& f, const TeethCtOptions& o) {
  const Eigen::Vector3d r = p - f.centre;
  if (std::abs(r.z()) > 3 || r.head<2>().norm() < o.filling_radius_mm) return 0;
  const double distance = r.head<2>().norm();
  double value = 0;
  for (int m = 0; m < 6; ++m) {
    const double angle = m * M_PI / 6;
    const Eigen::Vector2d along(std::cos(angle), std::sin(angle));
    const double off_line = std::abs(r.x() * along.y() - r.y() * along.x());
    const double sign = m % 2 ? -1 : 1;
    value += sign * o.streak_hu * std::exp(-std::pow(off_line / 0.5, 2)) * 10 / (distance + 5);
  }
  return value * std::exp(-std::pow(r.z() / 1.5, 2));
}

}  // namespace

Volume teeth_ct(const TriangleMesh& upper_teeth, const TriangleMesh& lower_teeth, const TeethCtOptions& options) {
  const DistanceField upper_field(upper_teeth), lower_field(lower_teeth);
  const Eigen::Vector3d upper_centre = upper_teeth.vertices.colwise().mean().transpose(),
                        lower_centre = lower_teeth.vertices.colwise().mean().transpose();
  const Arch upper = arch_of(upper_field, lower_centre - upper_centre),
             lower = arch_of(lower_field, upper_centre - lower_centre);
  const std::vector<Filling> fillings = fillings_of(upper, lower, options.fillings);
  Volume ct;
  ct.geometry = grid_around(upper_teeth, lower_teeth, options);
  ct.hu.assign(size_t(ct.geometry.voxel_count()), 0);
  const auto& g = ct.geometry;
  for_each_slab(
      0, g.size.z(),
      [&](int first, int last) {
        for (int k = first; k < last; ++k) {
          std::mt19937 random(options.seed * 100003u + uint32_t(k));  // per slice: the same whatever the threads
          std::normal_distribution<double> noise(0, options.noise_hu);
          for (int j = 0; j < g.size.y(); ++j)
            for (int i = 0; i < g.size.x(); ++i) {
              const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
              double value = anatomy_hu(p, upper, lower, options);
              for (const Filling& f : fillings) {
                if ((p - f.centre).norm() <= options.filling_radius_mm) value = 8000;  // amalgam
                value += streaks_hu(p, f, options);
              }
              value += noise(random);
              ct.at(i, j, k) = int16_t(std::clamp(std::lround(value), -1024L, 16000L));
            }
        }
      },
      SlabOptions{options.max_threads, 1});
  return ct;
}

}  // namespace maxillo
