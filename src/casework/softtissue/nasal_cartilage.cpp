#include "casework/softtissue/nasal_cartilage.h"

#include "ceph/landmark_frame.h"

namespace maxillo::casework {
namespace {

constexpr double kHalfAlarWidthMm = 17;

bool centroid_inside(const softtissue::TetMesh& mesh, int t, const softtissue::RegionShape& region) {
  return region.contains(softtissue::tet_corners(mesh, t).colwise().mean().transpose());
}

}  // namespace

std::optional<softtissue::RegionShape> nasal_cartilage_region(const LandmarkSet& landmarks) {
  const auto nasion = find_landmark(landmarks, "N"), spine = find_landmark(landmarks, "ANS");
  const auto subnasale = find_landmark(landmarks, "Sn"), tip = find_landmark(landmarks, "Prn");
  if (!nasion || !spine || !subnasale || !tip) return std::nullopt;
  const auto frame = anatomical_frame(landmarks);
  // The N-ANS line's normal in the midsagittal plane, pointing forward.
  Eigen::Vector3d forward = frame.left.cross(*nasion - *spine).normalized();
  if (forward.dot(frame.anterior) < 0) forward = -forward;
  const softtissue::RegionPlane in_front{*spine, forward};
  if (in_front.side(*tip) <= 0) return std::nullopt;
  return softtissue::RegionShape(std::vector<softtissue::RegionPlane>{
      in_front,
      {*subnasale, frame.superior},                           // above subnasale
      {*tip - kHalfAlarWidthMm * frame.left, frame.left},     // left of the right alar base
      {*tip + kHalfAlarWidthMm * frame.left, -frame.left}});  // right of the left one
}

int stiffen_region(softtissue::TetMesh& mesh, const softtissue::RegionShape& region, double factor) {
  if (mesh.stiffness.empty()) mesh.stiffness.assign(size_t(mesh.tet_count()), 1.0);
  int inside = 0;
  for (int t = 0; t < mesh.tet_count(); ++t) {
    if (!centroid_inside(mesh, t, region)) continue;
    mesh.stiffness[size_t(t)] = factor;
    ++inside;
  }
  return inside;
}

std::vector<uint8_t> region_tet_nodes(const softtissue::TetMesh& mesh, const softtissue::RegionShape& region) {
  std::vector<uint8_t> nodes(size_t(mesh.node_count()), 0);
  for (int t = 0; t < mesh.tet_count(); ++t)
    if (centroid_inside(mesh, t, region))
      for (int corner = 0; corner < 4; ++corner) nodes[size_t(mesh.tets(t, corner))] = 1;
  return nodes;
}

}  // namespace maxillo::casework
