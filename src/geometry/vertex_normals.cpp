#include "geometry/vertex_normals.h"

#include <Eigen/Geometry>

namespace maxillo {

VertexMatrix vertex_normals(const TriangleMesh& mesh) {
  VertexMatrix normals = VertexMatrix::Zero(mesh.vertex_count(), 3);
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::RowVector3d twice_area_normal = (b - a).cross(c - a).transpose();  // length = 2 x area
    for (int k = 0; k < 3; ++k) normals.row(mesh.faces(f, k)) += twice_area_normal;
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0) normals.row(v) /= length;
  }
  return normals;
}

}  // namespace maxillo
