#pragma once
// What `maxillo bench register` (register_benchmark.h) and the cadaver registration test share:
// the real head CT, a known rigid move of it, the skin points the error is measured on, and
// elastix as the anchor.
//
// Error measure: the fixed CT's skin vertices p; the moving CT shows p at known(p); a registration
// result M (moving_to_fixed) sends that back to M(known(p)); the error is the RMS over the skin
// of |M(known(p)) - p| in mm.
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>

#include "core/volume.h"
#include "imaging/rigid_registration.h"

namespace maxillo::bench {

// The Stanford/UNC cadaver head (see scripts/cthead-to-dicom) in patient LPS, as the DICOM series
// reads back: identity direction, origin (-127.5, -127.5, 0), 1 x 1 x 2 mm, HU = stored - 1024.
// `slices` is the folder with CThead.1 ... CThead.113; Error(kFileNotFound) when they are absent.
Volume read_cadaver_head(const std::filesystem::path& slices);

// The known move, fixed -> moving: a rotation by rotation_deg about the oblique axis (1, 2, 3)
// through the centre of the volume, then a translation of translation_mm along (2, -3, 6)
// (7 mm gives (2, -3, 6) mm).
Eigen::Isometry3d known_rigid_move(const VolumeGeometry& geometry, double rotation_deg, double translation_mm);

// Vertices (rows) of the skin surface of the CT (segmentation, -400 HU, ~50,000 triangles).
Eigen::MatrixX3d skin_vertices(const Volume& ct);

// RMS over the points of |moving_to_fixed(fixed_to_moving(p)) - p|, mm.
double rms_error_mm(const Eigen::MatrixX3d& points, const Eigen::Isometry3d& moving_to_fixed,
                    const Eigen::Isometry3d& fixed_to_moving);

// elastix 5 (rigid EulerTransform + AdvancedMattesMutualInformation, 3 levels of a recursive
// pyramid 4/2/1, adaptive stochastic gradient descent, 250 iterations and 2048 random samples
// per level, the same box as a fixed mask): the images and the parameter file are written to
// `workdir`, elastix runs as a child process. nullopt when `elastix` is not on PATH.
struct ElastixRun {
  Eigen::Isometry3d moving_to_fixed = Eigen::Isometry3d::Identity();
  double seconds = 0;  // wall time of the elastix process (reading the images included)
};
bool elastix_available();
std::optional<ElastixRun> run_elastix(const Volume& fixed, const Volume& moving, const RegistrationBox& box,
                                      const std::filesystem::path& workdir);

// Reads TransformParameters.0.txt of an EulerTransform: elastix maps FIXED to MOVING points,
// p_m = R (p_f - c) + c + t with R = Rz Rx Ry (ComputeZYX false, ITK's Euler3DTransform) or
// Rz Ry Rx (true); returns the inverse, moving_to_fixed. Error(kBadValue, file) when it is not one.
Eigen::Isometry3d read_elastix_euler(const std::filesystem::path& transform_parameters);

}  // namespace maxillo::bench
