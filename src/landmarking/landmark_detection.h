#pragma once
// Automatic cephalometric landmarks on a head CT or cone-beam CT, without hands: the 29 points
// the program uses (landmark_template.h), each with the evidence its rule saw and the checks it
// passed or failed (landmark_checks.h). Classical and deterministic: no trained model, the
// same bits whatever the threads.
//
// The method (docs/ARCHITECTURE.md, "Automatic landmarks"):
//   1. grey values read as HU from the scan's own histogram (cone-beam scans are not HU);
//   2. the midsagittal plane from the symmetry of the bone surface (symmetry_plane.h);
//   3. sella (the pituitary fossa) and nasion in the midsagittal section, which set the head's
//      pitch provisionally (S-N rises 7 degrees over Frankfort) and its size (S-N / 70 mm);
//   4. porion and orbitale on both sides, which set the Frankfort horizontal;
//   5. the CT resampled at 0.5 mm in that head frame, and every landmark read there by its
//      anatomical definition (midline_landmarks.h, lateral_landmarks.h);
//   6. the checks, and a confidence per landmark from its evidence and its checks.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "ceph/landmark.h"
#include "core/volume.h"
#include "imaging/hounsfield_reading.h"
#include "landmarking/landmark_checks.h"
#include "landmarking/symmetry_plane.h"

namespace maxillo::landmarking {

// The method's version, stored with every automatic set: 2 reads cone-beam scans (their cupping
// undone, a frame from the ears and orbits, nothing taken at the field's edge).
inline constexpr const char* kMethodVersion = "maxillo-landmarks 2";

struct DetectedLandmark {
  std::string label;
  std::optional<Eigen::Vector3d> position;  // LPS mm; nullopt: absent (see note)
  double confidence = 0;                    // 0..1
  std::vector<CheckOutcome> checks;         // the checks that concern this landmark
  std::string note;                         // why absent, or what weakened it

  bool flagged() const;  // present but failed a check or of low confidence: not for planning
};

struct LandmarkDetection {
  std::vector<DetectedLandmark> landmarks;                       // in detected_labels() order
  Plane midsagittal;                                             // LPS
  double asymmetry_mm = 0;                                       // mean distance of the mirrored bone surface
  Eigen::Isometry3d head_frame = Eigen::Isometry3d::Identity();  // head frame -> LPS
  std::string frame_source;                                      // "Frankfort (porion, orbitale)" or "S-N + 7 degrees"
  GreyReading reading;  // how the scan's grey values were read as HU (a cone-beam scan's cupping undone first)
  double scale = 1;     // S-N / 70 mm

  // The landmarks present, as a set for the cephalometry (absent ones left out).
  LandmarkSet present() const;
  const DetectedLandmark* find(const std::string& label) const;
};

struct DetectionOptions {
  double fine_spacing_mm = 0.5;  // the head volume the landmarks are read in
};

// Throws Error(kBadValue, subject) for a volume too small to hold a head, no bone, or no skull
// (no sella and nasion found): `subject` names the scan in the message.
LandmarkDetection detect_landmarks(const Volume& ct, const std::string& subject, const DetectionOptions& options = {});

}  // namespace maxillo::landmarking
