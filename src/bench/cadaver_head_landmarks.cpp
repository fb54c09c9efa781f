#include "bench/cadaver_head_landmarks.h"

namespace maxillo::bench {

LandmarkSet cadaver_head_landmarks_by_hand() {
  return {{"S", {-21.5, -20.5, 124}},  {"N", {-21.5, -77.5, 141}},  {"ANS", {-21.5, -94.5, 94}},
          {"PNS", {-21.5, -39.5, 97}}, {"U1", {-21.5, -100.5, 69}}, {"L1", {-21.5, -92.5, 65}},
          {"B", {-21.5, -91.5, 51}},   {"Pog", {-21.5, -90.5, 37}}, {"Me", {-21.5, -82.5, 24}},
          {"U6R", {-46.5, -75, 70}},   {"U6L", {3.5, -75, 70}},     {"L6R", {-46.5, -75, 66}},
          {"L6L", {3.5, -75, 66}},     {"OrR", {-54.5, -70, 116}},  {"OrL", {11.5, -70, 116}},
          {"PoR", {-83.5, 20, 110}},   {"PoL", {40.5, 20, 110}}};
}

LandmarkSet completed_by_hand(const LandmarkSet& detected, std::vector<std::string>& added) {
  LandmarkSet completed = detected;
  for (const auto& landmark : cadaver_head_landmarks_by_hand())
    if (!find_landmark(detected, landmark.label)) {
      completed.push_back(landmark);
      added.push_back(landmark.label);
    }
  return completed;
}

}  // namespace maxillo::bench
