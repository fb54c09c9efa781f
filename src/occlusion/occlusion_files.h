#pragma once
// Input files of `maxillo occlude`.
//   PAIRS.csv : one pair per row, "ux,uy,uz,lx,ly,lz" in mm: the upper point in the UPPER file's
//               coordinates (it moves with the arch), the lower point in the LOWER file's. An
//               optional header row (non-numeric) and blank lines are skipped.
//   START.json: {"upper_transform": [[r00,r01,r02,tx],[..],[..],[0,0,0,1]]}, a rigid 4x4 (mm)
//               applied to the upper arch first (upper file -> lower file coordinates).
#include <Eigen/Geometry>
#include <filesystem>
#include <vector>

#include "core/json.h"
#include "occlusion/guided_alignment.h"

namespace maxillo::occlusion {

// Throws Error(kFileNotFound | kBadValue, path, reason naming the row).
std::vector<SpringPair> read_spring_pairs(const std::filesystem::path& path);

// Throws Error(kBadValue, path, reason) unless the matrix is rigid (orthonormal, det +1,
// last row 0 0 0 1, within 1e-6).
Eigen::Isometry3d read_upper_transform(const std::filesystem::path& path);

// Row-major 4x4 as nested JSON arrays, and back (throws Error(kBadValue, subject, ...)).
Json transform_to_json(const Eigen::Isometry3d& transform);
Eigen::Isometry3d transform_from_json(const Json& value, const std::string& subject);

}  // namespace maxillo::occlusion
