#pragma once
// Repairs of a scanned dental arch before collision queries: the signed distance needs every
// closed shell (tooth) oriented with outward normals, and zero-area triangles carry no surface.
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::occlusion {

struct ArchRepairReport {
  int shells = 0;          // connected components (teeth when the arch is per tooth)
  int shells_flipped = 0;  // inward-oriented shells whose faces were reversed
  int degenerate_faces_removed = 0;
  int open_edges = 0;              // edges used by one face only (a shell that is not closed)
  std::vector<std::string> notes;  // one human-readable line per repair or warning
};

// Orients each shell outward (positive enclosed volume) and removes zero-area faces.
ArchRepairReport repair_arch(TriangleMesh& mesh);

}  // namespace maxillo::occlusion
