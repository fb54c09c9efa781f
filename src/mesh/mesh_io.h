#pragma once
// Mesh files, format chosen by extension (case-insensitive):
//   .stl  binary STL written; binary or ASCII read (stl_file.h: vertices merged)
//   .ply  binary little-endian PLY written; ASCII or binary read (ply_file.h)
//   .obj  Wavefront OBJ (text; v and f records)
//   .vtp  VTK XML PolyData (binary, compressed)
// Coordinates are written as they are (patient LPS mm for maxillo surfaces); no unit or frame
// is stored in STL/PLY/OBJ, so readers must know the convention.
#include <filesystem>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo {

enum class MeshFormat { Stl, Ply, Obj, Vtp };

// The format for a path's extension; throws Error(kUsage, path, ...) listing the known ones.
MeshFormat mesh_format_for(const std::filesystem::path& path);

// Writes atomically (temporary file + rename). Throws Error(kWriteFailed, path, reason).
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path);

// A per-vertex array (one row per vertex, 1 or 3 columns), e.g. "displacement" in mm.
struct PointArray {
  std::string name;
  Eigen::MatrixXd values;
};
// As above, with point arrays; only .vtp stores them (the other formats have no place for them).
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path, const std::vector<PointArray>& arrays);

// Throws Error(kFileNotFound | kBadValue, path, reason); polygons are triangulated.
TriangleMesh read_mesh(const std::filesystem::path& path);

// Every mesh file (a known extension) directly in `folder`, in the order of their names (a
// folder's own order is the file system's, which differs between machines), e.g. one tooth per
// file. Throws as read_mesh, and Error(kFileNotFound) for a folder that is not there.
std::vector<TriangleMesh> read_meshes_in(const std::filesystem::path& folder);

}  // namespace maxillo
