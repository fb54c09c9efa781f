#pragma once
// The phantom's dental scans (issue 30): what an intraoral scanner would give of the phantom's
// teeth, for `maxillo sample`, the demo and the tests of `maxillo dental`. Each tooth is traced
// at `spacing_mm` from its analytic shape (sample/phantom_dentition.h), not from the CT's
// voxels, so that the scan and the CT's teeth are two samplings of one anatomy, as a patient's
// are. The crowns are cut from the roots and given a gingival collar, noise and another
// triangulation (sample/simulated_dental_scan.h); each arch then lies in a scanner's frame of
// its own, far from the CT's, and the truth of its registration is the pose that frame had.
#include <Eigen/Geometry>
#include <filesystem>

#include "core/triangle_mesh.h"
#include "sample/phantom.h"

namespace maxillo::casework {

struct PhantomDentalScan {
  TriangleMesh scan;                                             // mm, in the scanner's frame
  Eigen::Isometry3d scan_to_ct = Eigen::Isometry3d::Identity();  // the truth: scanner frame -> CT (LPS)
};

struct PhantomDentalScans {
  PhantomDentalScan upper, lower;
};

struct PhantomDentalScanOptions {
  double spacing_mm = 0.25;  // of the grid each tooth is traced on
  double noise_mm = 0.02;
  uint32_t seed = 1;
};

// Deterministic: the same spec and options give the same meshes.
PhantomDentalScans make_phantom_dental_scans(const PhantomSpec& spec, const PhantomDentalScanOptions& options = {});

// upper.stl and lower.stl (binary STL, mm, the scanner's frame) and truth.json (each arch's
// scan_to_ct as a 4x4 row-major matrix) into `folder`, created.
void write_phantom_dental_scans(const PhantomDentalScans& scans, const std::filesystem::path& folder);

// The truth written by write_phantom_dental_scans, for tests and benchmarks.
PhantomDentalScans read_phantom_dental_truth(const std::filesystem::path& folder);

}  // namespace maxillo::casework
