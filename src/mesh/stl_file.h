#pragma once
// STL, read by our own parser rather than VTK's: vtkSTLReader reads any bytes as a binary STL of
// garbage triangles, and a file from outside (a scanned dental arch) must be refused, not
// guessed at. Both encodings:
//   binary  80-byte header, uint32 triangle count n, then n records of 50 bytes (normal,
//           three corners as float32 little endian, 2 attribute bytes): exactly 84 + 50 n bytes;
//   ASCII   "solid", then per triangle "facet normal ... outer loop vertex x y z (x3) endloop
//           endfacet", then "endsolid".
// Corners with equal coordinates are merged into one vertex (STL stores every triangle's corners
// apart). Throws Error(kBadValue, source, reason) for anything else, or non-finite coordinates.
#include <cstddef>
#include <span>
#include <string>

#include "core/triangle_mesh.h"

namespace maxillo {

TriangleMesh parse_stl(std::span<const std::byte> bytes, const std::string& source);

}  // namespace maxillo
