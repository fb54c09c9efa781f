#pragma once
// Writes a tet mesh as a VTK XML unstructured grid (.vtu, ASCII), with the point vector array
// "displacement" (mm) and the point integer array "bc" (0 free, 1 fixed, 2 prescribed), for
// ParaView or VTK readers. Plain text: no VTK needed in this module.
#include <filesystem>

#include "softtissue/boundary_conditions.h"
#include "softtissue/tet_mesh.h"

namespace maxillo::softtissue {

// Throws maxillo::Error(kWriteFailed, path, reason) when the file cannot be written.
void write_vtu(const std::filesystem::path& path, const TetMesh& mesh, const Eigen::MatrixX3d& displacement,
               const BoundaryConditions& bc);

}  // namespace maxillo::softtissue
