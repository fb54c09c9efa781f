#include "softtissue/element_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace maxillo::softtissue {
namespace {

// Outward-independent face normals: face a is opposite corner a.
std::array<Eigen::Vector3d, 4> face_normals(const Eigen::Matrix<double, 4, 3>& p) {
  std::array<Eigen::Vector3d, 4> normals;
  for (int a = 0; a < 4; ++a) {
    Eigen::Vector3d q0 = p.row((a + 1) % 4), q1 = p.row((a + 2) % 4), q2 = p.row((a + 3) % 4);
    Eigen::Vector3d normal = (q1 - q0).cross(q2 - q0);
    // Point the normal away from the opposite corner.
    if (normal.dot(Eigen::Vector3d(p.row(a)) - q0) > 0) normal = -normal;
    normals[size_t(a)] = normal;
  }
  return normals;
}

}  // namespace

double min_dihedral_angle_deg(const TetMesh& mesh, int t) {
  auto normals = face_normals(tet_corners(mesh, t));
  double smallest = 180.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      const auto &na = normals[size_t(a)], &nb = normals[size_t(b)];
      double cosine = std::clamp(-na.dot(nb) / (na.norm() * nb.norm()), -1.0, 1.0);
      smallest = std::min(smallest, std::acos(cosine) * 180.0 / std::numbers::pi);
    }
  return smallest;
}

double aspect_ratio(const TetMesh& mesh, int t) {
  Eigen::Matrix<double, 4, 3> p = tet_corners(mesh, t);
  double longest = 0, area = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (p.row(a) - p.row(b)).norm());
  for (const auto& normal : face_normals(p)) area += 0.5 * normal.norm();
  double inradius = 3.0 * std::abs(signed_volume(mesh, t)) / area;
  return longest / (2.0 * inradius) / std::sqrt(6.0);
}

MeshQuality mesh_quality(const TetMesh& mesh) {
  MeshQuality quality;
  quality.min_dihedral_deg = 180.0;
  for (int t = 0; t < mesh.tet_count(); ++t) {
    double ratio = aspect_ratio(mesh, t);
    quality.min_dihedral_deg = std::min(quality.min_dihedral_deg, min_dihedral_angle_deg(mesh, t));
    quality.max_aspect_ratio = std::max(quality.max_aspect_ratio, ratio);
    quality.mean_aspect_ratio += ratio;
  }
  if (mesh.tet_count() > 0) quality.mean_aspect_ratio /= mesh.tet_count();
  return quality;
}

}  // namespace maxillo::softtissue
