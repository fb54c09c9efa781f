#pragma once
// A tetrahedral volume mesh: node positions in mm (any right-handed frame, patient LPS for
// patient meshes) and tetrahedra as 4 node indices. Positive orientation: the corners
// (a, b, c, d) satisfy det[b-a, c-a, d-a] > 0, so signed volumes are positive.
#include <Eigen/Core>

#include <vector>

namespace maxillo::softtissue {

struct TetMesh {
  Eigen::MatrixX3d nodes;  // n x 3, mm
  Eigen::MatrixX4i tets;   // m x 4, node indices, positively oriented
  // Per tet, its tissue's Young's modulus as a multiple of the model's material (Poisson's ratio
  // is the material's everywhere). Empty: homogeneous tissue, every factor 1.
  std::vector<double> stiffness;
  int node_count() const { return int(nodes.rows()); }
  int tet_count() const { return int(tets.rows()); }
  double stiffness_of(int t) const { return stiffness.empty() ? 1.0 : stiffness[size_t(t)]; }
};

// Corners of tet t as rows (4 x 3, mm).
Eigen::Matrix<double, 4, 3> tet_corners(const TetMesh& mesh, int t);
// Signed volume of tet t in mm^3 (positive when positively oriented).
double signed_volume(const TetMesh& mesh, int t);
// Swaps two corners of every negatively oriented tet. Returns how many were flipped.
int orient_positively(TetMesh& mesh);
// Number of tets whose signed volume is <= 0.
int count_non_positive_tets(const TetMesh& mesh);

// Node adjacency in compressed rows: the neighbours of node i (itself included, sorted
// ascending) are neighbours[offsets[i] .. offsets[i+1]). Two nodes are neighbours when they
// share a tet (for linear tets: share an edge).
struct NodeGraph {
  std::vector<int> offsets;     // n + 1
  std::vector<int> neighbours;  // sum of row lengths
  int row_begin(int i) const { return offsets[size_t(i)]; }
  int row_end(int i) const { return offsets[size_t(i) + 1]; }
  // Position of node j in row i (asserts that j is a neighbour of i).
  int find(int i, int j) const;
};
NodeGraph build_node_graph(const TetMesh& mesh);

}  // namespace maxillo::softtissue
