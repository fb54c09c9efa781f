#pragma once
// Where the face model's lips part (issue 34): a CT of closed lips shows one block of soft tissue,
// and a model meshed from it ties the upper lip to the lower one, so that a maxilla brought
// forward drags the lower lip along or tears the skin between them. The lips meet in a cleft and
// slide on each other; the model is parted there (softtissue/mesh_parting.h):
//   the cleft: every 2.5 mm across the mouth, between the heights of labrale inferius and
//     superius, the height where the soft tissue's front lies furthest back (the middle of the
//     heights where no tissue stands in front of the teeth, where the lips are apart), read on the
//     tissue labels; the midline's is the stomion;
//   the lips: within 25 mm of the midline (an adult's corners of the mouth lie about 25 mm out),
//     in front of the dental arch (the upper incisor's tip, less 1 mm, falling back as x^2 / 50 mm
//     to the side: 6 mm at the canines, 12.5 mm at the corners), within 10 mm of the cleft;
//     above the cleft the upper lip, below it the lower. Behind the arch the tongue stays whole.
// The lips are parted, not held apart: no contact keeps one from passing into the other.
#include <Eigen/Core>
#include <optional>
#include <utility>
#include <vector>

#include "ceph/landmark.h"
#include "core/volume.h"
#include "softtissue/mesh_parting.h"

namespace maxillo::casework {

struct LipParting {
  Eigen::Vector3d stomion = Eigen::Vector3d::Zero();  // the cleft on the midline
  std::vector<std::pair<double, double>> cleft;       // (to the left, up) from the stomion, mm, left to right
  softtissue::PartingSide side;                       // +1 upper lip, -1 lower lip, 0 elsewhere
};

// nullopt when Ls, Li or both U1 and L1 are missing, or no soft tissue stands in front of the
// teeth between the heights of Li and Ls.
std::optional<LipParting> lip_parting(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels,
                                      const LandmarkSet& landmarks);

}  // namespace maxillo::casework
