#include "geometry/mesh_transform.h"

#include <cassert>
#include <cmath>

namespace maxillo {

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& transform) {
  TriangleMesh result = mesh;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v)
    result.vertices.row(v) = (transform * Eigen::Vector3d(mesh.vertices.row(v).transpose())).transpose();
  return result;
}

TriangleMesh cylinder_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, int sides) {
  assert(sides >= 3 && (b - a).norm() > 0);
  const Eigen::Vector3d axis = (b - a).normalized();
  // Any two unit vectors perpendicular to the axis and to each other span the rings.
  const Eigen::Vector3d u = axis.unitOrthogonal(), w = axis.cross(u);
  TriangleMesh mesh;
  mesh.vertices.resize(2 * sides + 2, 3);
  for (int s = 0; s < sides; ++s) {
    const double angle = 2 * M_PI * s / sides;
    const Eigen::Vector3d offset = radius * (std::cos(angle) * u + std::sin(angle) * w);
    mesh.vertices.row(s) = (a + offset).transpose();
    mesh.vertices.row(sides + s) = (b + offset).transpose();
  }
  const int cap_a = 2 * sides, cap_b = 2 * sides + 1;
  mesh.vertices.row(cap_a) = a.transpose();
  mesh.vertices.row(cap_b) = b.transpose();
  mesh.faces.resize(4 * sides, 3);
  for (int s = 0; s < sides; ++s) {
    const int next = (s + 1) % sides;
    // Counter-clockwise seen from outside: the ring runs u -> w, i.e. anticlockwise about the axis.
    mesh.faces.row(4 * s + 0) << s, next, sides + next;
    mesh.faces.row(4 * s + 1) << s, sides + next, sides + s;
    mesh.faces.row(4 * s + 2) << cap_a, next, s;                  // cap at a faces -axis
    mesh.faces.row(4 * s + 3) << cap_b, sides + s, sides + next;  // cap at b faces +axis
  }
  return mesh;
}

TriangleMesh merged(const std::vector<const TriangleMesh*>& meshes) {
  Eigen::Index vertices = 0, faces = 0;
  for (const auto* m : meshes) {
    vertices += m->vertex_count();
    faces += m->face_count();
  }
  TriangleMesh result;
  result.vertices.resize(vertices, 3);
  result.faces.resize(faces, 3);
  Eigen::Index v = 0, f = 0;
  for (const auto* m : meshes) {
    result.vertices.middleRows(v, m->vertex_count()) = m->vertices;
    result.faces.middleRows(f, m->face_count()) = m->faces.array() + int(v);
    v += m->vertex_count();
    f += m->face_count();
  }
  return result;
}

}  // namespace maxillo
