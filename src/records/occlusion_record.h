#pragma once
// The result of a virtual occlusion (`maxillo occlude`, the demo; the "occlusion" artefact,
// DIR/occlusion.json): one struct with one writer and one strict reader. The reader fails with
// Error(kArchiveCorrupt) naming the document and the key path on a missing or mistyped field.
// Results written before "format_version" existed have version 1's layout; a newer version is
// refused.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/json.h"
#include "occlusion/arch_repair.h"
#include "occlusion/occlusionogram.h"

namespace maxillo::records {

struct OcclusionRecord {
  // 2: upper_centroid added (required from this version on), where the report reads the motion.
  static constexpr int kFormatVersion = 2;

  struct Arch {  // the occlusionogram's contacts on one arch
    int contact_vertices = 0;
    double contact_area_mm2 = 0;
    std::vector<occlusion::ToothContacts> teeth;
  };
  struct Splint {      // the splint asked for and what was made (casework/occlusion/surgical_splint.h)
    std::string file;  // "splint.stl", in the result's folder
    double minimum_thickness_mm = 0, imprint_depth_mm = 0, clearance_mm = 0, voxel_mm = 0;
    double thickness_mm = 0;  // thinnest sampled column of the wafer
    int thickness_columns = 0;
    double volume_mm3 = 0;
    int64_t triangles = 0;
    bool watertight = false;
    int components = 0;
    double min_distance_upper_mm = 0, min_distance_lower_mm = 0;
    int64_t intersecting_pairs_upper = 0, intersecting_pairs_lower = 0;
    double seconds = 0;
  };

  int format_version = kFormatVersion;
  std::string upper_file, lower_file;                                 // the arches' labels (their file names)
  std::string frame;                                                  // what the coordinates are, in words
  Eigen::Isometry3d upper_transform = Eigen::Isometry3d::Identity();  // upper file -> lower file coordinates
  Eigen::Isometry3d start_transform = Eigen::Isometry3d::Identity();
  std::optional<Eigen::Vector3d> upper_centroid;  // of the upper arch, its file's coordinates; none in version 1
  bool converged = false;                         // the guided alignment's status ("converged" or "iteration_limit")
  int iterations = 0;
  std::vector<double> residual_spring_mm;
  double penetration_mm = 0, allowed_penetration_mm = 0;
  int64_t intersecting_triangle_pairs = 0;
  double contact_threshold_mm = 0;
  Arch upper, lower;
  occlusion::ArchRepairReport upper_repair, lower_repair;
  std::optional<Splint> splint;  // none when no splint was asked for, or it could not be made
  std::string splint_error;      // why it could not be made
  std::vector<std::string> files;
};

Json to_json(const OcclusionRecord& record);
// `source` names the document in errors (its file, or "artefact N (occlusion)").
OcclusionRecord read_occlusion_record(const Json& json, const std::string& source);

}  // namespace maxillo::records
