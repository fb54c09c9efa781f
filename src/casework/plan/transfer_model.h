#pragma once
// The transfer model of a distraction plan (thesis ch. 4a): a printable stereolithographic model
// of the pre-operative midface with a tube in each maxillary sinus along the planned screw axis.
// The distraction screw fits the tube's bore, so the screw's position on the model is the
// planned vector; the surgeon bends the distractor plates on it and a template is made from it.
//
// Built in voxels, then one iso-surface: the model is watertight by construction, whatever the
// tubes cross. Model = (midface bone within a box around the maxilla) ∪ tube walls − bores, at a
// finer voxel size than the CT so the bore is round enough to take a screw.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo::casework {

// A distraction screw: it enters the anterior maxillary wall at `entry` and runs `length_mm`
// along the unit `direction` (the distraction vector, pointing backwards into the sinus).
struct ScrewAxis {
  std::string side;  // "right" or "left"
  Eigen::Vector3d entry = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();
  double length_mm = 30;
};

struct TransferModelOptions {
  double voxel_mm = 0.5;        // model resolution
  double bore_radius_mm = 1.1;  // screw (M2) + printing clearance
  double wall_mm = 1.5;         // tube wall thickness
  double outside_mm = 6;        // the tube stands this far in front of the entry point
  double margin_mm = 12;        // box around the maxilla and the tubes
  int64_t target_triangles = 400000;
};

struct TransferModel {
  TriangleMesh mesh;
  double volume_ml = 0;
  bool watertight = false;
};

// `segments` is an osteotomy result (osteotomy.h Segment labels): the cranium and maxilla
// segments in the box make the midface. Throws Error (kEmptyResult) when there is no maxilla.
TransferModel make_transfer_model(const LabelVolume& segments, const std::vector<ScrewAxis>& screws,
                                  const TransferModelOptions& options = {});

}  // namespace maxillo::casework
