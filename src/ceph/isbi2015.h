#pragma once
// The ISBI 2015 cephalometric challenge (Wang et al., MedIA 2016): its landmark table and the
// skeletal classes of its challenge 2, so that our SNA/SNB/ANB can be checked against the
// organisers' labels (see ../shared/data/isbi2015-ceph/PROVENANCE.md).
//
// Table: isbi2015_train_landmarks.csv, header
//   image_id,split,S_x,S_y,N_x,N_y,...,Ar_x,Ar_y,ANB_cls,SNB_cls,SNA_cls,...
// coordinates in image pixels (0.1 mm, y DOWN, face towards +x). Challenge labels are renamed to
// ours: LIT -> L1, UIT -> U1, SoftPog -> PogS; the others keep their names (S, N, Or, Po, A, B,
// Pog, Me, Gn, Go, UL, LL, Sn, PNS, ANS, Ar). Landmarks are returned with z = 0, in pixels.
#include <filesystem>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "ceph/sagittal_projection.h"

namespace maxillo::ceph {

inline constexpr double kIsbiPixelSpacingMm = 0.1;
// Image pixel axes of the challenge's radiographs.
inline CephalogramAxes isbi_axes() { return {kIsbiPixelSpacingMm, ImageVerticalAxis::kDown, FacingDirection::kPlusX}; }

struct IsbiImage {
  std::string image_id;                             // "001"
  LandmarkSet landmarks;                            // pixels, z = 0
  int anb_class = 0, snb_class = 0, sna_class = 0;  // the organisers' labels (1, 2, 3)
};

// Error(kFileNotFound / kBadValue, path, reason naming the line) on unreadable or malformed files.
std::vector<IsbiImage> read_isbi_landmark_table(const std::filesystem::path& path);

// The challenge's class rules (organisers' thresholds, degrees):
//   ANB: 1 if 3.2 <= ANB <= 5.7, 2 if > 5.7, 3 if < 3.2
//   SNB: 1 if 74.6 <= SNB <= 78.7, 2 if < 74.6, 3 if > 78.7
//   SNA: 1 if 79.4 <= SNA <= 83.2, 2 if > 83.2, 3 if < 79.4
int isbi_anb_class(double anb_deg);
int isbi_snb_class(double snb_deg);
int isbi_sna_class(double sna_deg);

struct IsbiAgreement {
  int images = 0;
  int anb_equal = 0, snb_equal = 0, sna_equal = 0;
  std::vector<std::string> disagreements;  // "017 ANB: ours 1 (3.25 deg), organisers 3"
};
// SNA/SNB/ANB of every image computed by analyse() in the image's sagittal frame, classified,
// and compared with the organisers' labels.
IsbiAgreement isbi_class_agreement(const std::vector<IsbiImage>& images);

}  // namespace maxillo::ceph
