#include "occlusion/occlusionogram.h"

#include <algorithm>
#include <numeric>

namespace maxillo::occlusion {
namespace {

int find_root(std::vector<int>& parent, int v) {
  while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
  return v;
}

// Distances of `mesh`'s vertices (placed by `to_other`) to `other`.
ArchDistances arch_distances(const TriangleMesh& mesh, const DistanceField& other, const Eigen::Isometry3d& to_other,
                             const OcclusionogramOptions& options) {
  ArchDistances arch;
  int count = 0;
  arch.tooth_of_vertex = vertex_components(mesh, &count);
  arch.teeth.resize(size_t(count));
  for (int c = 0; c < count; ++c)
    arch.teeth[size_t(c)].component = c, arch.teeth[size_t(c)].min_distance_mm = options.max_distance_mm;
  arch.distance_mm.resize(size_t(mesh.vertex_count()), options.max_distance_mm);
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const SignedDistance d =
        other.signed_distance(to_other * Eigen::Vector3d(mesh.vertices.row(v).transpose()), options.max_distance_mm);
    if (d.found) arch.distance_mm[size_t(v)] = d.distance;
    const int tooth = arch.tooth_of_vertex[size_t(v)];
    if (tooth < 0) continue;
    ToothContacts& t = arch.teeth[size_t(tooth)];
    ++t.vertices;
    t.min_distance_mm = std::min(t.min_distance_mm, arch.distance_mm[size_t(v)]);
    if (arch.distance_mm[size_t(v)] < options.contact_threshold_mm) ++t.contact_vertices, ++arch.contact_vertices;
  }
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                          c = mesh.vertices.row(mesh.faces(f, 2));
    const double third = 0.5 * (b - a).cross(c - a).norm() / 3.0;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces(f, k);
      if (arch.distance_mm[size_t(v)] < options.contact_threshold_mm) {
        arch.teeth[size_t(arch.tooth_of_vertex[size_t(v)])].contact_area_mm2 += third;
        arch.contact_area_mm2 += third;
      }
    }
  }
  return arch;
}

}  // namespace

std::vector<int> vertex_components(const TriangleMesh& mesh, int* component_count) {
  std::vector<int> parent(static_cast<size_t>(mesh.vertex_count()));
  std::iota(parent.begin(), parent.end(), 0);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int k = 1; k < 3; ++k) {
      const int a = find_root(parent, mesh.faces(f, 0)), b = find_root(parent, mesh.faces(f, k));
      if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
    }
  std::vector<char> used(parent.size(), 0);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(mesh.faces(f, k))] = 1;
  std::vector<int> label(parent.size(), -1), root_label(parent.size(), -1);
  int count = 0;
  for (size_t v = 0; v < parent.size(); ++v) {
    if (!used[v]) continue;
    const int root = find_root(parent, int(v));
    if (root_label[size_t(root)] < 0) root_label[size_t(root)] = count++;
    label[v] = root_label[size_t(root)];
  }
  *component_count = count;
  return label;
}

Occlusionogram compute_occlusionogram(const DistanceField& upper, const DistanceField& lower,
                                      const Eigen::Isometry3d& upper_pose, const OcclusionogramOptions& options) {
  return {arch_distances(upper.mesh(), lower, upper_pose, options),
          arch_distances(lower.mesh(), upper, upper_pose.inverse(), options)};
}

}  // namespace maxillo::occlusion
