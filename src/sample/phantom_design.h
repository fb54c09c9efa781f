#pragma once
// The phantom's cephalometric design: where the skeleton's key points are, from which every
// part is built, and the two displacement knobs (maxilla, mandible) of PhantomSpec.
//
// Reference anatomy = Class I, built in the mid-sagittal plane from:
//   S at (0, 0, 20) mm, S-N 70 mm rising 7 deg anteriorly above Frankfort horizontal (z = 0),
//   A at 58 mm from N with SNA 82 deg, B at 95 mm from N with SNB 80 deg.
// Displaced anatomy (the mandible also to one side, PhantomSpec::mandibular_deviation_mm): a query point is pulled back to the reference anatomy
// (to_maxilla_reference / to_mandible_reference) and a landmark is pushed forward
// (from_maxilla_reference / from_mandible_reference), so landmarks stay exactly on their parts.
#include "sample/implicit.h"
#include "sample/phantom.h"

namespace maxillo::sample {

// Cephalometric design values (mm, deg).
inline constexpr double kSellaHeight = 20;     // S above Frankfort horizontal
inline constexpr double kSellaNasion = 70;     // S-N length
inline constexpr double kSnToFrankfort = 7;    // SN rises anteriorly by this angle
inline constexpr double kSna = 82, kSnb = 80;  // reference (Class I) angles
inline constexpr double kNasionToA = 58;       // N-A distance
inline constexpr double kNasionToB = 95;       // N-B distance
inline constexpr double kOcclusalTilt = 8;     // occlusal plane descends anteriorly (to FH)
inline constexpr double kLeFortLevel = -14;    // z of the maxillary displacement's hinge band
inline constexpr double kChinDepth = 7.5;      // mental protuberance semi-axis, anterior (mm)
inline constexpr double kChinHeight = 13.5;    // mental protuberance semi-axis, vertical (mm)
inline constexpr double kChinHalfWidth = 14;   // mental protuberance semi-axis, lateral (mm)

struct PhantomDesign {
  double maxilla_shift = 0;       // mm anterior, below the Le Fort I level
  double mandible_shift = 0;      // mm anterior, mandibular body and chin
  double mandible_deviation = 0;  // mm to the patient's left (+x), mandibular body and chin

  // Reference (undisplaced) mid-sagittal skeleton, LPS mm.
  Vector3d S, N, A, B, ANS, PNS, Pog, Gn, Me;
  // Occlusal plane: passes through occlusal_origin with unit normal occlusal_normal (up).
  Vector3d occlusal_origin, occlusal_normal;

  // z of the occlusal plane above the mid-sagittal point at anterior coordinate a.
  double occlusal_z(double a) const;
  // z of the palatal plane (line ANS-PNS) at anterior coordinate a.
  double palatal_z(double a) const;
  // Upper alveolar front (mid-sagittal): deepest at A (subspinale).
  double upper_alveolar_front(double z) const;
  // Lower alveolar and symphysis front above the chin (mid-sagittal): deepest at B.
  double lower_alveolar_front(double z) const;

  // Weight (0..1) of the maxillary displacement at height z: 1 below the Le Fort I band.
  static double maxilla_weight(double z);
  // Weight (0..1) of the mandibular displacement at reference anterior coordinate a:
  // 0 at the rami, 1 from the premolars forward.
  static double mandible_weight(double a);

  Vector3d to_maxilla_reference(const Vector3d& p) const;
  Vector3d from_maxilla_reference(const Vector3d& p) const;
  Vector3d to_mandible_reference(const Vector3d& p) const;
  Vector3d from_mandible_reference(const Vector3d& p) const;
};

PhantomDesign make_design(const PhantomSpec& spec);

}  // namespace maxillo::sample
