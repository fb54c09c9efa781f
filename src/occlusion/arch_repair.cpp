#include "occlusion/arch_repair.h"

#include <map>

#include "occlusion/occlusionogram.h"

namespace maxillo::occlusion {
namespace {

int remove_degenerate_faces(TriangleMesh& mesh) {
  FaceMatrix kept(mesh.face_count(), 3);
  Eigen::Index count = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                          c = mesh.vertices.row(mesh.faces(f, 2));
    if ((b - a).cross(c - a).norm() > 0) kept.row(count++) = mesh.faces.row(f);
  }
  const int removed = int(mesh.face_count() - count);
  mesh.faces = kept.topRows(count);
  return removed;
}

int count_open_edges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(f, k), b = mesh.faces(f, (k + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  int open = 0;
  for (const auto& [edge, n] : uses) open += n == 1;
  return open;
}

}  // namespace

ArchRepairReport repair_arch(TriangleMesh& mesh) {
  ArchRepairReport report;
  report.degenerate_faces_removed = remove_degenerate_faces(mesh);
  if (report.degenerate_faces_removed > 0)
    report.notes.push_back("removed " + std::to_string(report.degenerate_faces_removed) + " zero-area triangles");
  std::vector<int> labels = vertex_components(mesh, &report.shells);
  // Enclosed volume per shell (divergence theorem); negative = faces point inward.
  std::vector<double> volume(size_t(report.shells), 0.0);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)), b = mesh.vertices.row(mesh.faces(f, 1)),
                          c = mesh.vertices.row(mesh.faces(f, 2));
    volume[size_t(labels[size_t(mesh.faces(f, 0))])] += a.dot(b.cross(c)) / 6.0;
  }
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    if (volume[size_t(labels[size_t(mesh.faces(f, 0))])] < 0) std::swap(mesh.faces(f, 1), mesh.faces(f, 2));
  for (double v : volume) report.shells_flipped += v < 0;
  if (report.shells_flipped > 0)
    report.notes.push_back("reversed " + std::to_string(report.shells_flipped) + " inward-oriented shells");
  report.open_edges = count_open_edges(mesh);
  if (report.open_edges > 0)
    report.notes.push_back(std::to_string(report.open_edges) +
                           " open edges: a shell is not closed, penetration signs near it are unreliable");
  return report;
}

}  // namespace maxillo::occlusion
