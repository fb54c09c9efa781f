#pragma once
// A synthetic post-operative CT with a known answer, to check the validation end to end (issue: "a synthetic
// post-operative case made from a known displacement field yields its known error distribution").
//
// The surgery is performed exactly as planned: every bone segment the plan moves is moved by its planned rigid
// transform. The face after surgery is the model's prediction for those moves plus a known error: a smooth bump e(p)
// = A exp(-|p - c|^2 / 2 sigma^2) along the skin's outward normal, centred on a soft tissue landmark (the lower lip
// by default). A validation that works must therefore find, at each predicted skin vertex, the signed error -e(p)
// (the prediction lies behind the real face by e). Finally the head lies differently in the post-operative scanner (a
// known rigid repositioning), which the registration must undo.
//
// The CT is built voxel by voxel in the post-operative scanner frame: moved bone is sampled from the pre-operative CT
// through its segment's inverse move; unmoved bone and the interior of the soft tissue come from the pre-operative
// CT; the skin is a linear HU ramp through the skin threshold across the signed distance to the post-operative skin
// surface, so an iso-surface at that threshold recovers the surface to a fraction of a voxel.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/volume.h"
#include "casework/plan/planned_case.h"
#include "casework/softtissue/soft_tissue_prediction.h"

namespace maxillo::casework {

struct SyntheticPostopOptions {
  double error_mm = 2.0;            // A: the real face lies this far in front of the
                                    // prediction at the bump's centre
  double error_sigma_mm = 12.0;     // sigma of the bump
  std::string error_centre = "Li";  // soft tissue landmark at the bump's centre
                                    // (pre-operative position)
  double reposition_deg = 2.0;      // the head turned about the scanner's vertical axis ...
  double reposition_mm = 3.0;       // ... and shifted along each axis, in the post-operative scan
  SoftTissueOptions soft_tissue;    // the model whose prediction the "real" face starts from
  int skin_block_voxels = 4;        // the CT is filled in cubes of this many voxels a side; one distance query
                                    // at a cube's centre settles every voxel of it that is far from the skin
                                    // (1: a query per voxel; the same CT wherever the moved skin does not
                                    // pass through itself)
};

struct SyntheticPostop {
  Volume ct;                           // post-operative CT, in the post-operative scanner frame
  Eigen::Isometry3d postop_to_preop;   // what registration must find
  SegmentMoves moves;                  // the bone moves performed (= planned)
  TriangleMesh predicted_skin;         // the prediction for those moves (pre-operative frame)
  TriangleMesh actual_skin;            // the post-operative skin (pre-operative frame)
  std::vector<double> known_error_mm;  // per predicted skin vertex: -e(p)
};

// The known repositioning for the options (a rotation about the superior axis through the CT's centre, then the
// shift), as the map from post-operative to pre-operative scanner coordinates.
Eigen::Isometry3d synthetic_reposition(const VolumeGeometry& geometry, const SyntheticPostopOptions& options);

SyntheticPostop make_synthetic_postop(const PlannedCase& planned, const SyntheticPostopOptions& options = {});

}  // namespace maxillo::casework
