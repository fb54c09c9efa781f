#include "ceph/landmark_frame.h"

namespace maxillo {

AnatomicalFrame anatomical_frame(const LandmarkSet& landmarks) {
  return frankfort_frame({.porion_right = find_landmark(landmarks, "PoR"),
                          .porion_left = find_landmark(landmarks, "PoL"),
                          .orbitale_right = find_landmark(landmarks, "OrR"),
                          .orbitale_left = find_landmark(landmarks, "OrL")});
}

}  // namespace maxillo
