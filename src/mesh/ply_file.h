#pragma once
// PLY, read by our own parser rather than VTK's: vtkPLYReader dereferences a null element and
// crashes the process on a malformed header (found by fuzzing, tests/fuzz/regressions/mesh_file).
//
// Accepted: format ascii 1.0, binary_little_endian 1.0 or binary_big_endian 1.0; an element
// "vertex" with float/double (or integer) properties x, y, z among any others; an element "face"
// with a list property "vertex_indices" (or "vertex_index") of polygons, fan-triangulated; other
// elements and properties are skipped. Every count is checked against the bytes that remain
// before anything is allocated. Throws Error(kBadValue, source, reason).
#include <cstddef>
#include <span>
#include <string>

#include "core/triangle_mesh.h"

namespace maxillo {

TriangleMesh parse_ply(std::span<const std::byte> bytes, const std::string& source);

}  // namespace maxillo
