#pragma once
// The region of the face where a prediction is judged, and its subregions (thesis ch. 6 and 8 report errors for the
// whole face and per region). The region is the face without the eyes and the neck: below the orbital rims, in front
// of the ears, not under the chin. Subregions follow the soft tissue profile landmarks: the nose above subnasale, the
// upper lip between subnasale and the lips' meeting line, the lower lip down to halfway to soft pogonion, the chin
// below that, the cheeks lateral to the lips and the nose.
//
// Positions are classified in an anatomical frame (anterior, superior, left unit vectors), so a head tilted in the
// scanner is cut the same way.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo::validation {

enum class FaceRegion : uint8_t { kOutside = 0, kNose, kUpperLip, kLowerLip, kChin, kCheeks };
inline constexpr std::array kFaceSubregions{FaceRegion::kNose, FaceRegion::kUpperLip, FaceRegion::kLowerLip,
                                            FaceRegion::kChin, FaceRegion::kCheeks};
std::string_view region_name(FaceRegion region);  // "nose", "upper lip", ... ("outside")

struct FaceAxes {
  Eigen::Vector3d anterior = -Eigen::Vector3d::UnitY();  // LPS unit vectors
  Eigen::Vector3d superior = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d left = Eigen::Vector3d::UnitX();
};

// The landmarks the cuts are made from (LPS mm): soft tissue subnasale, labrale superius and inferius, soft pogonion;
// bony orbitale, porion (each the mean of both sides) and menton.
struct FaceLandmarks {
  Eigen::Vector3d subnasale, labrale_superius, labrale_inferius, soft_pogonion;
  Eigen::Vector3d orbitale, porion, menton;
};

struct FaceRegionOptions {
  double lip_half_width_mm = 25;  // lips and chin reach this far either side of the midline
  double nose_half_width_mm = 20;
  double nose_depth_mm = 15;   // the nose: at most this far behind subnasale
  double ear_margin_mm = 25;   // the region starts this far in front of the porions
  double neck_depth_mm = 20;   // behind menton by more than this and below it: neck
  double chin_margin_mm = 15;  // the region reaches this far below menton
};

// One region per point.
std::vector<FaceRegion> classify_face_regions(const VertexMatrix& points, const FaceLandmarks& landmarks,
                                              const FaceAxes& axes, const FaceRegionOptions& options = {});

// include[i] = (regions[i] == region), or != kOutside for the whole face (region kOutside).
std::vector<bool> region_mask(const std::vector<FaceRegion>& regions, FaceRegion region);

}  // namespace maxillo::validation
