#include "geometry/signed_distance.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace maxillo {
namespace {

using Eigen::Vector3d;

double angle_between(const Vector3d& u, const Vector3d& v) {
  const double nu = u.norm(), nv = v.norm();
  if (nu == 0 || nv == 0) return 0;
  return std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0));
}

}  // namespace

DistanceField::DistanceField(const TriangleMesh& mesh) : tree_(mesh) {
  const int faces = int(mesh.face_count());
  face_normals_.resize(size_t(faces));
  edge_normals_.assign(size_t(3 * faces), Vector3d::Zero());
  vertex_normals_.assign(size_t(mesh.vertex_count()), Vector3d::Zero());
  std::map<std::pair<int, int>, Vector3d> edge_sums;
  for (int f = 0; f < faces; ++f) {
    const Triangle t = tree_.triangle(f);
    const Vector3d n = (t.b - t.a).cross(t.c - t.a);
    face_normals_[size_t(f)] = n.norm() > 0 ? Vector3d(n.normalized()) : Vector3d::Zero();
    const Vector3d corners[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      const int v0 = mesh.faces(f, k), v1 = mesh.faces(f, (k + 1) % 3);
      // Eigen vectors are not zeroed by default construction: insert zero explicitly.
      auto entry = edge_sums.try_emplace({std::min(v0, v1), std::max(v0, v1)}, Vector3d::Zero()).first;
      entry->second += face_normals_[size_t(f)];
      const double angle = angle_between(corners[(k + 1) % 3] - corners[k], corners[(k + 2) % 3] - corners[k]);
      vertex_normals_[size_t(mesh.faces(f, k))] += angle * face_normals_[size_t(f)];
    }
  }
  for (int f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const int v0 = mesh.faces(f, k), v1 = mesh.faces(f, (k + 1) % 3);
      edge_normals_[size_t(3 * f + k)] = edge_sums.at({std::min(v0, v1), std::max(v0, v1)});
    }
}

Vector3d DistanceField::pseudo_normal(int face, TriangleFeature feature) const {
  const auto& f = tree_.mesh().faces;
  switch (feature) {
    case TriangleFeature::Face: return face_normals_[size_t(face)];
    case TriangleFeature::EdgeAB: return edge_normals_[size_t(3 * face)];
    case TriangleFeature::EdgeBC: return edge_normals_[size_t(3 * face + 1)];
    case TriangleFeature::EdgeCA: return edge_normals_[size_t(3 * face + 2)];
    case TriangleFeature::VertexA: return vertex_normals_[size_t(f(face, 0))];
    case TriangleFeature::VertexB: return vertex_normals_[size_t(f(face, 1))];
    case TriangleFeature::VertexC: return vertex_normals_[size_t(f(face, 2))];
  }
  return face_normals_[size_t(face)];
}

SignedDistance DistanceField::signed_distance(const Vector3d& p, double max_distance) const {
  const NearestPoint nearest = tree_.nearest(p, max_distance);
  if (nearest.face < 0) return {};
  Vector3d normal = pseudo_normal(nearest.face, nearest.feature);
  normal = normal.norm() > 0 ? Vector3d(normal.normalized()) : face_normals_[size_t(nearest.face)];
  const double sign = (p - nearest.point).dot(normal) < 0 ? -1.0 : 1.0;
  return {true, sign * nearest.distance, nearest.point, normal, nearest.face};
}

}  // namespace maxillo
