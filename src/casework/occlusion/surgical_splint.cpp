#include "casework/occlusion/surgical_splint.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "geometry/mesh_measures.h"
#include "mesh/surface_extraction.h"

namespace maxillo::casework {
namespace {

using namespace maxillo::occlusion;

// Parameter t of the line point + t * direction where it crosses the triangle, if it does
// (Moeller-Trumbore).
bool line_crosses_triangle(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b, const Eigen::Vector3d& c, double& t) {
  const Eigen::Vector3d ab = b - a, ac = c - a, p = direction.cross(ac);
  const double det = ab.dot(p);
  if (std::abs(det) < 1e-14) return false;
  const Eigen::Vector3d s = point - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Eigen::Vector3d q = s.cross(ab);
  const double v = direction.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  t = ac.dot(q) / det;
  return true;
}

double min_vertex_distance(const TriangleMesh& splint, const DistanceField& arch, const Eigen::Isometry3d& to_arch) {
  double nearest = 1e300;
  for (Eigen::Index v = 0; v < splint.vertex_count(); ++v) {
    const NearestPoint p = arch.tree().nearest(to_arch * Eigen::Vector3d(splint.vertices.row(v).transpose()), 5.0);
    if (p.face >= 0) nearest = std::min(nearest, p.distance);
  }
  return nearest;
}

double sampled_thickness(const TriangleMesh& splint, const SplintField& field, int* columns) {
  constexpr int kColumns = 64;
  const auto& all = field.tooth_free_columns;
  const VolumeGeometry& g = field.field.geometry;
  double thinnest = 1e300;
  *columns = 0;
  for (int s = 0; s < kColumns && !all.empty(); ++s) {
    const int column = all[size_t(s) * all.size() / kColumns];
    if (s > 0 && column == all[size_t(s - 1) * all.size() / kColumns]) continue;
    // Off the grid lines, so the line never passes exactly through a vertex of the surface.
    const Eigen::Vector3d point =
        g.world(Eigen::Vector3d(column % g.size.x() + 0.37, column / g.size.x() + 0.21, 0.5 * (g.size.z() - 1)));
    thinnest = std::min(thinnest, thickness_along(splint, point, field.plane.normal));
    ++*columns;
  }
  return *columns > 0 ? thinnest : 0;
}

}  // namespace

double thickness_along(const TriangleMesh& mesh, const Eigen::Vector3d& point, const Eigen::Vector3d& direction) {
  std::vector<double> crossings;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    double t = 0;
    if (line_crosses_triangle(point, direction, mesh.vertices.row(mesh.faces(f, 0)).transpose(),
                              mesh.vertices.row(mesh.faces(f, 1)).transpose(),
                              mesh.vertices.row(mesh.faces(f, 2)).transpose(), t))
      crossings.push_back(t);
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end(), [](double a, double b) { return b - a < 1e-9; }),
                  crossings.end());  // a crossing on a shared edge counts once
  double inside = 0;
  for (size_t k = 0; k + 1 < crossings.size(); k += 2) inside += crossings[k + 1] - crossings[k];
  return inside;
}

Splint make_splint(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& upper_pose,
                   const SplintOptions& options) {
  const auto clock = std::chrono::steady_clock::now();
  const SplintField field = splint_field(upper, lower, upper_pose, options);
  SurfaceOptions surface;
  surface.keep_largest_components = 1;
  surface.smoothing_iterations = 0;
  surface.target_triangles = 0;
  Splint splint;
  splint.plane = field.plane;
  splint.mesh = extract_surface(field.field, 0.0, surface);
  if (splint.mesh.face_count() == 0) throw Error(ErrorCode::kProcessing, "splint", "the splint solid is empty");

  SplintReport& r = splint.report;
  r.triangles = splint.mesh.face_count();
  r.watertight = is_watertight(splint.mesh);
  r.components = int(connected_components(splint.mesh).face_counts.size());
  r.volume_mm3 = signed_volume(splint.mesh);
  r.thickness_mm = sampled_thickness(splint.mesh, field, &r.thickness_columns);
  const AabbTree splint_tree(splint.mesh);
  const Eigen::Isometry3d lower_to_upper = upper_pose.inverse();
  r.min_distance_upper_mm = min_vertex_distance(splint.mesh, upper, lower_to_upper);
  r.min_distance_lower_mm = min_vertex_distance(splint.mesh, lower, Eigen::Isometry3d::Identity());
  r.intersecting_pairs_upper = int64_t(splint_tree.intersecting_faces(upper.tree(), upper_pose).size());
  r.intersecting_pairs_lower =
      int64_t(splint_tree.intersecting_faces(lower.tree(), Eigen::Isometry3d::Identity()).size());
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return splint;
}

}  // namespace maxillo::casework
