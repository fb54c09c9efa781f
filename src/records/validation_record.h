#pragma once
// A stored validation (the "validation" artefact, validation.json): one struct, read back
// strictly. The writer is validation_json (validation_json.h), which adds "format_version".
// What the consultation report and the nightly summary show is required: a missing or mistyped
// field is Error(kArchiveCorrupt) naming the artefact and the key path. Documents stored before
// "format_version" existed have this layout (version 1); a newer version is refused.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"
#include "validation/distance_statistics.h"

namespace maxillo::records {

struct ValidationRecord {
  static constexpr int kFormatVersion = 1;

  struct Registration {  // the post-operative CT onto the pre-operative one
    Eigen::Isometry3d moving_to_fixed = Eigen::Isometry3d::Identity();
    double metric = 0;  // Mattes mutual information at the end
    int iterations = 0;
    double seconds = 0;
    double cranium_icp_rms_mm = 0;
  };
  struct Segment {  // one moved bone segment: planned against performed
    std::string segment;
    Eigen::Isometry3d planned = Eigen::Isometry3d::Identity(), actual = Eigen::Isometry3d::Identity();
    double icp_rms_mm = 0, mean_difference_mm = 0, max_difference_mm = 0, rotation_difference_deg = 0;
  };
  struct Region {  // distances of the predicted to the post-operative skin in one face region
    std::string region;
    validation::DistanceStatistics closest;
    std::optional<validation::DistanceStatistics> corresponding;  // none when not computed
  };

  int format_version = kFormatVersion;
  int64_t case_id = 0;
  std::string case_label;
  int64_t preop_series = 0, postop_series = 0;
  std::string preop_date, postop_date;  // DICOM dates, "" when the study has none
  std::string inputs_hash;
  Registration registration;
  std::vector<Segment> segments;
  std::vector<Region> regions;  // "face" first
  double seconds = 0;
};

// `source` names the document in errors ("artefact 31 (validation)").
ValidationRecord read_validation_record(const Json& json, const std::string& source);

}  // namespace maxillo::records
