#pragma once
// The surgery as performed (thesis ch. 8): each planned bone segment is registered rigidly onto
// the post-operative bone surface by the iterative closest point method, starting from the
// planned move, which gives the move the surgeon actually made.
//
// Point-to-plane ICP (Chen & Medioni 1992): each iteration pairs sampled vertices of the moving
// surface with their closest points on the target and solves the linearised least-squares
// problem sum(((R p + t - q) . n_q)^2) for a small rotation and a translation. Pairs are trimmed:
// farther than max_pair_distance_mm, closest point on the target's open border (a segment's cut
// faces have no counterpart there), or normals more than 60 degrees apart are left out.
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>

#include "core/triangle_mesh.h"

namespace maxillo::validation {

struct IcpOptions {
  int max_iterations = 60;
  double max_pair_distance_mm = 4.0;  // pairs farther apart are not used
  double tolerance_mm = 1e-4;         // stop when an iteration moves no sample farther than this
  int max_samples = 20000;            // moving vertices used (a deterministic random subset)
  uint32_t seed = 1;
};

struct IcpResult {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // moving frame -> target frame
  double rms_mm = 0;  // root mean square closest-point distance of the final pairs
  int iterations = 0;
  int pairs = 0;  // pairs used in the last iteration
};

// What ICP needs of its target, built once (its closest-point tree, open border and face
// normals): for registering surfaces onto one target from many starts (dental/arch_registration.h).
// Keeps a reference to `target`, which must outlive it unchanged.
class IcpTarget {
 public:
  explicit IcpTarget(const TriangleMesh& target);
  ~IcpTarget();
  IcpTarget(const IcpTarget&) = delete;
  IcpTarget& operator=(const IcpTarget&) = delete;
  struct Parts;
  const Parts& parts() const { return *parts_; }

 private:
  std::unique_ptr<Parts> parts_;
};

// Moves `moving` (e.g. a planned bone segment's surface in pre-operative coordinates) onto
// `target` (the post-operative bone surface in the same frame), starting from `initial` (e.g.
// the planned move). Both meshes consistently oriented (normals out). Throws Error(BadValue)
// for an empty mesh and Error(Processing) when fewer than 6 pairs lie within reach.
IcpResult rigid_icp(const TriangleMesh& moving, const TriangleMesh& target, const Eigen::Isometry3d& initial,
                    const IcpOptions& options = {});
IcpResult rigid_icp(const TriangleMesh& moving, const IcpTarget& target, const Eigen::Isometry3d& initial,
                    const IcpOptions& options = {});

}  // namespace maxillo::validation
