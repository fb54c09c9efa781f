#include "occlusion/arch_contacts.h"

#include <algorithm>

namespace maxillo::occlusion {
namespace {

std::vector<int> vertices_of_flagged_faces(const TriangleMesh& mesh, const std::vector<char>& flags) {
  std::vector<char> used(size_t(mesh.vertex_count()), 0);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    if (flags[size_t(f)])
      for (int k = 0; k < 3; ++k) used[size_t(mesh.faces(f, k))] = 1;
  std::vector<int> vertices;
  for (size_t v = 0; v < used.size(); ++v)
    if (used[v]) vertices.push_back(int(v));
  return vertices;
}

}  // namespace

ContactState assess_contacts(const DistanceField& upper, const DistanceField& lower,
                             const Eigen::Isometry3d& upper_pose, double band_mm) {
  const Eigen::Isometry3d lower_to_upper = upper_pose.inverse();
  const auto [upper_faces, lower_faces] = upper.tree().faces_near(lower.tree(), lower_to_upper, band_mm);
  ContactState state;
  // Upper vertices against the fixed lower surface: the gap grows as the vertex moves along
  // the lower surface's outward normal.
  for (int v : vertices_of_flagged_faces(upper.mesh(), upper_faces)) {
    const Eigen::Vector3d x = upper_pose * Eigen::Vector3d(upper.mesh().vertices.row(v).transpose());
    const SignedDistance d = lower.signed_distance(x, band_mm);
    if (d.found) state.contacts.push_back({ContactSide::UpperVertex, v, d.distance, x, d.normal});
  }
  // Lower vertices against the moving upper surface: the gap shrinks as the nearest upper
  // point moves along the upper surface's outward normal.
  for (int v : vertices_of_flagged_faces(lower.mesh(), lower_faces)) {
    const Eigen::Vector3d w = lower.mesh().vertices.row(v).transpose();
    const SignedDistance d = upper.signed_distance(lower_to_upper * w, band_mm);
    if (d.found)
      state.contacts.push_back(
          {ContactSide::LowerVertex, v, d.distance, upper_pose * d.point, -(upper_pose.linear() * d.normal)});
  }
  for (const ArchContact& c : state.contacts) state.max_penetration_mm = std::max(state.max_penetration_mm, -c.gap_mm);
  return state;
}

}  // namespace maxillo::occlusion
