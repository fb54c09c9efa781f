#pragma once
// The virtual occlusion workflow of `maxillo occlude` and the demo (issue 6): repair both arches,
// place the upper one by the start transform, guided alignment with the point pairs as springs,
// occlusionogram (image + per-vertex data), surgical splint, all written into one folder:
//   occlusion.json          final 4x4 upper_transform (upper file -> lower file coordinates),
//                           residual springs, contacts per tooth, repairs, splint figures
//   occlusionogram.png      both arches from the occlusal side, colour-coded distance
//   {upper,lower}_distances.csv  the occlusionogram data
//   splint.stl              the splint (lower file coordinates), unless disabled
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"
#include "occlusion/arch_repair.h"
#include "occlusion/guided_alignment.h"
#include "occlusion/occlusionogram.h"
#include "casework/occlusion/surgical_splint.h"
#include "records/occlusion_record.h"

namespace maxillo::casework {

struct OcclusionRunOptions {
  double contact_threshold_mm = 1.0;  // occlusionogram contact regions
  double tolerance_mm = 0.05;         // extra penetration allowed beyond the start pose's
  bool splint = true;
  occlusion::SplintOptions splint_options;
  std::string upper_label = "upper", lower_label = "lower";  // file names recorded in occlusion.json
};

struct OcclusionRun {
  TriangleMesh upper, lower;                                // as repaired, in their files' coordinates
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();  // the upper arch's start pose
  occlusion::ArchRepairReport upper_repair, lower_repair;
  occlusion::AlignmentResult aligned;
  double allowed_penetration_mm = 0;
  double contact_threshold_mm = 0;  // of the occlusionogram's contact regions
  size_t intersecting_triangle_pairs = 0;
  occlusion::Occlusionogram gram;
  std::optional<Splint> splint;
  std::string splint_error;  // why there is no splint when one was asked for
  std::filesystem::path folder;
  std::vector<std::string> files;   // written into folder
  records::OcclusionRecord record;  // the content of occlusion.json
};

// The occlusion computed: both arches repaired, the guided alignment, the occlusionogram and the
// splint. Nothing is written or rendered, so it needs no OpenGL context and may run beside other
// work. A splint that cannot be made is reported in splint_error rather than failing the run.
OcclusionRun compute_occlusion(TriangleMesh upper, TriangleMesh lower, const std::vector<occlusion::SpringPair>& pairs,
                               const Eigen::Isometry3d& start, const OcclusionRunOptions& options = {});

// A computed run's files into `folder` (the occlusionogram rendered), occlusion.json last; sets
// run.folder, run.files and run.record. Throws Error for an unwritable folder.
void write_occlusion_outputs(OcclusionRun& run, const std::filesystem::path& folder,
                             const OcclusionRunOptions& options = {});

// Both of the above. Throws Error for unwritable output folders (before computing); a splint that
// cannot be made is reported in splint_error (and occlusion.json) rather than failing the occlusion.
OcclusionRun run_occlusion(TriangleMesh upper, TriangleMesh lower, const std::vector<occlusion::SpringPair>& pairs,
                           const Eigen::Isometry3d& start, const std::filesystem::path& folder,
                           const OcclusionRunOptions& options = {});

}  // namespace maxillo::casework
