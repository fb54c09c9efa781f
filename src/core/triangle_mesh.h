#pragma once
// A triangle surface in the patient LPS frame, millimetres. Faces index rows of vertices and
// are ordered counter-clockwise seen from outside (normals point out of the tissue).
// This is the type modules exchange; VTK's vtkPolyData stays inside src/mesh and src/render.
#include <Eigen/Core>

namespace maxillo {

using VertexMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using FaceMatrix = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriangleMesh {
  VertexMatrix vertices;  // n x 3, LPS mm
  FaceMatrix faces;       // m x 3, zero-based vertex indices

  Eigen::Index vertex_count() const { return vertices.rows(); }
  Eigen::Index face_count() const { return faces.rows(); }
};

}  // namespace maxillo
