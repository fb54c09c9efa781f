#pragma once
// Rigid moves of a surface, and simple closed shapes to draw axes and markers with.
#include <Eigen/Geometry>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo {

// The mesh with every vertex mapped by `transform` (faces unchanged; a rigid move keeps the
// orientation, so outward normals stay outward).
TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& transform);

// A closed cylinder (capped at both ends, outward normals) from `a` to `b`, `sides` facets around.
TriangleMesh cylinder_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, int sides = 24);

// Concatenation of meshes (faces re-indexed); no vertex welding.
TriangleMesh merged(const std::vector<const TriangleMesh*>& meshes);

}  // namespace maxillo
