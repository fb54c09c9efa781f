#include "sample/simulated_dental_scan.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "geometry/mesh_transform.h"

namespace maxillo {
namespace {

// The tooth's long axis, pointing to its biting end.
Eigen::Vector3d biting_direction(const TriangleMesh& tooth, const Eigen::Vector3d& occlusal_side) {
  const Eigen::Vector3d centroid = tooth.vertices.colwise().mean().transpose();
  const Eigen::MatrixX3d centred = tooth.vertices.rowwise() - centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
  Eigen::Vector3d axis = solver.eigenvectors().col(2);  // the widest spread: crown to root apex
  if (axis.dot(occlusal_side - centroid) < 0) axis = -axis;
  return axis;
}

// The faces whose three corners lie within the crown, their vertices renumbered; `neck` receives
// the crown's open border edges (a -> b with the crown's faces on their left).
TriangleMesh crown_of(const TriangleMesh& tooth, const Eigen::Vector3d& axis, double height,
                      std::vector<std::pair<int, int>>& neck) {
  const Eigen::VectorXd along = tooth.vertices * axis;
  const double top = along.maxCoeff();
  std::vector<int> index(size_t(tooth.vertex_count()), -1);
  TriangleMesh crown;
  std::vector<Eigen::Vector3i> faces;
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index f = 0; f < tooth.face_count(); ++f) {
    const Eigen::Vector3i face = tooth.faces.row(f).transpose();
    if (top - along(face(0)) > height || top - along(face(1)) > height || top - along(face(2)) > height) continue;
    Eigen::Vector3i renumbered;
    for (int k = 0; k < 3; ++k) {
      int& i = index[size_t(face(k))];
      if (i < 0) {
        i = int(vertices.size());
        vertices.push_back(tooth.vertices.row(face(k)).transpose());
      }
      renumbered(k) = i;
    }
    faces.push_back(renumbered);
  }
  crown.vertices.resize(Eigen::Index(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i) crown.vertices.row(Eigen::Index(i)) = vertices[i].transpose();
  crown.faces.resize(Eigen::Index(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f) crown.faces.row(Eigen::Index(f)) = faces[f].transpose();
  // Directed edges without their reverse are the open border.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& face : faces)
    for (int k = 0; k < 3; ++k) ++edges[{face(k), face((k + 1) % 3)}];
  for (const auto& [edge, count] : edges)
    if (!edges.count({edge.second, edge.first})) neck.push_back(edge);
  return crown;
}

// A band of gingiva around the crown's neck: each border vertex copied `width` mm out from the
// tooth's axis and half that towards the root, and a quad between each border edge and its copy,
// oriented as the crown.
void add_collar(TriangleMesh& crown, const std::vector<std::pair<int, int>>& neck, const Eigen::Vector3d& axis,
                double width) {
  const Eigen::Vector3d centre = crown.vertices.colwise().mean().transpose();
  std::map<int, int> copy;
  std::vector<Eigen::Vector3d> added;
  const int base = int(crown.vertex_count());
  for (const auto& [a, b] : neck)
    for (int v : {a, b})
      if (!copy.count(v)) {
        const Eigen::Vector3d p = crown.vertices.row(v).transpose();
        Eigen::Vector3d out = (p - centre) - (p - centre).dot(axis) * axis;
        out = out.norm() > 1e-9 ? Eigen::Vector3d(out.normalized()) : Eigen::Vector3d::Zero();
        copy[v] = base + int(added.size());
        added.push_back(p + width * out - 0.5 * width * axis);
      }
  const Eigen::Index old_faces = crown.face_count();
  crown.vertices.conservativeResize(base + Eigen::Index(added.size()), 3);
  for (size_t i = 0; i < added.size(); ++i) crown.vertices.row(base + Eigen::Index(i)) = added[i].transpose();
  crown.faces.conservativeResize(old_faces + 2 * Eigen::Index(neck.size()), 3);
  Eigen::Index f = old_faces;
  for (const auto& [a, b] : neck) {  // the crown lies left of a -> b: the collar lies right, b -> a
    crown.faces.row(f++) << b, a, copy[a];
    crown.faces.row(f++) << b, copy[a], copy[b];
  }
}

}  // namespace

TriangleMesh split_triangles(const TriangleMesh& mesh) {
  TriangleMesh out;
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) vertices.push_back(mesh.vertices.row(v).transpose());
  std::map<std::pair<int, int>, int> midpoint;
  auto middle = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, added] = midpoint.try_emplace({key.first, key.second}, int(vertices.size()));
    if (added) vertices.push_back(0.5 * (vertices[size_t(a)] + vertices[size_t(b)]));
    return it->second;
  };
  out.faces.resize(4 * mesh.face_count(), 3);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const int a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    out.faces.row(4 * f) << a, ab, ca;
    out.faces.row(4 * f + 1) << ab, b, bc;
    out.faces.row(4 * f + 2) << ca, bc, c;
    out.faces.row(4 * f + 3) << ab, bc, ca;
  }
  out.vertices.resize(Eigen::Index(vertices.size()), 3);
  for (size_t i = 0; i < vertices.size(); ++i) out.vertices.row(Eigen::Index(i)) = vertices[i].transpose();
  return out;
}

TriangleMesh simulated_dental_scan(const std::vector<TriangleMesh>& teeth, const Eigen::Vector3d& occlusal_side,
                                   const DentalScanOptions& options) {
  std::vector<TriangleMesh> crowns;
  for (const auto& tooth : teeth) {
    const Eigen::Vector3d axis = biting_direction(tooth, occlusal_side);
    std::vector<std::pair<int, int>> neck;
    TriangleMesh crown = crown_of(tooth, axis, options.crown_height_mm, neck);
    if (crown.face_count() == 0) continue;
    add_collar(crown, neck, axis, options.collar_width_mm);
    crowns.push_back(std::move(crown));
  }
  std::vector<const TriangleMesh*> parts;
  for (const auto& crown : crowns) parts.push_back(&crown);
  TriangleMesh scan = split_triangles(merged(parts));
  std::mt19937 random(options.seed);
  std::normal_distribution<double> noise(0, options.noise_mm);
  for (Eigen::Index v = 0; v < scan.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) scan.vertices(v, k) += noise(random);
  return scan;
}

}  // namespace maxillo
