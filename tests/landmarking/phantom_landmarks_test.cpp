// The detector against the phantom's truth (the landmarks its generator places by
// construction), as it is and in other poses and spacings: the same anatomy must give the same
// points, moved with the head.
#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/Geometry>
#include <atomic>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <numbers>
#include <thread>

#include "core/angles.h"
#include "support/posed_volume.h"
#include "core/error.h"
#include "landmarking/landmark_detection.h"
#include "sample/phantom.h"
#include "sample/phantom_variation.h"

namespace maxillo::landmarking {
namespace {

// Distances of the detected landmarks that are not flagged from their truth.
std::map<std::string, double> errors_against(const LandmarkDetection& found, const LandmarkSet& truth,
                                             const Eigen::Isometry3d& truth_to_scan = Eigen::Isometry3d::Identity()) {
  std::map<std::string, double> errors;
  for (const auto& l : found.landmarks)
    if (l.position && !l.flagged())
      if (auto t = find_landmark(truth, l.label)) errors[l.label] = (*l.position - truth_to_scan * *t).norm();
  return errors;
}

double mean_of(const std::map<std::string, double>& errors) {
  double sum = 0;
  for (const auto& [label, e] : errors) sum += e;
  return errors.empty() ? 1e9 : sum / double(errors.size());
}

// One varied bench patient's CT at `spacing_mm`: `label` found, not flagged, within `limit_mm`.
void expect_found_near_truth(const char* patient, double spacing_mm, const char* label, double limit_mm) {
  const Phantom phantom = make_phantom(varied_phantom_spec(patient, ScannerKind::kCt, spacing_mm));
  const auto errors = errors_against(detect_landmarks(phantom.ct, patient), phantom.landmarks);
  ASSERT_TRUE(errors.count(label)) << label << " missed or flagged on " << patient;
  EXPECT_LT(errors.at(label), limit_mm) << label << " on " << patient;
}

// The same voxels with a header that places them turned and shifted: the head in another pose.
const Phantom& default_phantom() {
  static const Phantom phantom = make_phantom({});
  return phantom;
}

TEST(PhantomLandmarks, TheDefaultPhantomsLandmarksAreFoundNearTheirTruth) {
  const LandmarkDetection found = detect_landmarks(default_phantom().ct, "phantom");
  const auto errors = errors_against(found, default_phantom().landmarks);
  for (const auto& l : found.landmarks) {
    ASSERT_TRUE(l.position) << l.label << ": " << l.note;
    EXPECT_FALSE(l.flagged()) << l.label;
    // Every landmark was found again from a second start (landmark_checks.h), and passed; sella,
    // whose window is the same from both starts, is not checked so.
    const auto again =
        std::find_if(l.checks.begin(), l.checks.end(), [](const CheckOutcome& c) { return c.name == "second start"; });
    if (l.label == "S") {
      EXPECT_EQ(again, l.checks.end());
      continue;
    }
    ASSERT_NE(again, l.checks.end()) << l.label;
    EXPECT_TRUE(again->passed) << l.label << ": " << again->detail;
  }
  // Measured 2026-11-28 (1 mm phantom): mean 0.70 mm over the 27 confident landmarks; L1 (1.8)
  // the weakest. (Or was 2.6-2.8 mm until the phantom's orbital margin had its lowest point where
  // its truth said: docs/ARCHITECTURE.md, "Varied phantoms".)
  EXPECT_LT(mean_of(errors), 1.0);
  for (const auto& [label, e] : errors) std::cout << label << " " << e << " mm\n";
  for (const auto& [label, e] : errors) EXPECT_LT(e, label == "L1" ? 2.2 : 1.6) << label;
  EXPECT_EQ(found.frame_source, "Frankfort horizontal (porion and orbitale)");
  EXPECT_NEAR(found.scale, 1.0, 0.02);  // S-N 70 mm
}

TEST(PhantomLandmarks, TheLandmarksMoveWithTheHeadInEveryPose) {
  const LandmarkDetection reference = detect_landmarks(default_phantom().ct, "phantom");
  const std::vector<Eigen::Isometry3d> poses = {
      Eigen::Translation3d(12, -8, 5) * Eigen::AngleAxisd(12 * kDeg, Eigen::Vector3d::UnitZ()),
      Eigen::Translation3d(-5, 4, -20) * Eigen::AngleAxisd(-14 * kDeg, Eigen::Vector3d::UnitX()),
      Eigen::Translation3d(0, 0, 7) * Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d(1, 1, 1).normalized()),
  };
  for (const auto& pose : poses) {
    const LandmarkDetection found = detect_landmarks(testing::posed(default_phantom().ct, pose), "posed phantom");
    double sum = 0, worst = 0;
    int count = 0;
    for (const auto& l : found.landmarks) {
      const DetectedLandmark* before = reference.find(l.label);
      ASSERT_EQ(l.position.has_value(), before->position.has_value()) << l.label;
      if (!l.position || l.flagged() || before->flagged()) continue;
      const double moved = (*l.position - pose * *before->position).norm();
      sum += moved;
      worst = std::max(worst, moved);
      ++count;
      EXPECT_LT(moved, 2.0) << l.label;
    }
    std::cout << "phantom pose: " << count << " landmarks moved with the head to within mean " << sum / count
              << " mm, worst " << worst << " mm\n";
    EXPECT_LT(sum / count, 0.6) << "mean displacement from the pose's image";
    // And against the truth, moved with the head.
    EXPECT_LT(mean_of(errors_against(found, default_phantom().landmarks, pose)), 1.6);
  }
}

TEST(PhantomLandmarks, AFinerAndACoarserScanOfTheSameHeadAgree) {
  for (double spacing : {0.75, 1.4}) {
    const Phantom phantom = make_phantom({.spacing_mm = spacing});
    const LandmarkDetection found = detect_landmarks(phantom.ct, "phantom");
    const auto errors = errors_against(found, phantom.landmarks);
    EXPECT_LT(mean_of(errors), 1.6) << spacing << " mm";
    for (const auto& [label, e] : errors) std::cout << spacing << " mm voxels: " << label << " " << e << " mm\n";
    std::string left_out;
    for (const auto& l : found.landmarks)
      if (!errors.count(l.label)) {
        left_out += " " + l.label + " (" + l.note;
        for (const auto& c : l.checks)
          if (!c.passed) left_out += "; " + c.name + ": " + c.detail;
        left_out += ")";
      }
    EXPECT_EQ(left_out, "") << spacing << " mm: absent or flagged";
  }
}

// Other patients (size, jaws, noise drawn from their IDs) voxelised turned and shifted in the
// scanner: not the head the rules were written on. Two of `maxillo bench landmarks`' patients:
// one small (0.96) with its mandible 1.8 mm forward, turned 18.5 degrees; one large (1.06) with
// both jaws back, turned 19.4 degrees. Measured 2026-11-28 (1 mm): every landmark but Ar within
// 2 mm, means 0.58 and 0.60 mm over 27.
TEST(PhantomLandmarks, OtherPatientsInOtherPosesAreFoundNearTheirTruth) {
  for (const char* patient : {"BENCH-003", "BENCH-006"}) {
    const Phantom phantom = make_phantom(varied_phantom_spec(patient, ScannerKind::kCt, 1.0));
    const LandmarkDetection found = detect_landmarks(phantom.ct, patient);
    const auto errors = errors_against(found, phantom.landmarks);
    for (const auto& [label, e] : errors) std::cout << patient << ": " << label << " " << e << " mm\n";
    EXPECT_LT(mean_of(errors), 1.0) << patient;
    EXPECT_GE(errors.size(), 26u) << patient;  // at most three absent or flagged
    for (const auto& [label, e] : errors) EXPECT_LT(e, label == "L1" ? 3.0 : 2.0) << patient << " " << label;
  }
}

// A chin 3 mm to one side (an asymmetric mandible, the rami in place): its midsagittal points lie
// off the skull's midline, and are read in the chin's own middle, in a head turned 8 degrees.
TEST(PhantomLandmarks, AChinToOneSideIsReadInItsOwnMiddle) {
  for (double deviation : {3.0, -3.0}) {
    PhantomSpec spec;
    spec.mandibular_deviation_mm = deviation;
    spec.placement.rotation = Eigen::AngleAxisd(8 * kDeg, Eigen::Vector3d(1, 2, 1).normalized()).toRotationMatrix();
    const Phantom phantom = make_phantom(spec);
    const LandmarkSet straight_chin = make_phantom_landmarks([&] {
      PhantomSpec s = spec;
      s.mandibular_deviation_mm = 0;
      return s;
    }());
    const LandmarkDetection found = detect_landmarks(phantom.ct, "chin to one side");
    const auto errors = errors_against(found, phantom.landmarks);
    // Not L1: its window follows the chin, but on this phantom it is still found 2-3 mm off (one
    // side flagged, the other not); bench landmarks measures it over the varied patients.
    for (const char* label : {"B", "Pog", "Me", "Gn"}) {
      // The truth moved as far as the chin: read in the skull's midline it would be that far off.
      EXPECT_GT((*find_landmark(phantom.landmarks, label) - *find_landmark(straight_chin, label)).norm(),
                0.95 * std::abs(deviation))
          << label;
      ASSERT_TRUE(errors.count(label)) << label << " missed or flagged, deviation " << deviation;
      EXPECT_LT(errors.at(label), 1.0) << label << ", deviation " << deviation;
    }
  }
}

// BENCH-017's alveolar crest curls back 2.7 mm behind the front just below the crowns: its top
// passed for B (6.5 mm above the truth, weakly evident) until the search for B ended at
// infradentale, the front's most anterior point near its top. The chin's concavity is 2.6 mm deep.
TEST(PhantomLandmarks, TheAlveolarCrestCurlingBackIsNotTakenForB) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-017", ScannerKind::kCt, 0.7));
  const LandmarkDetection found = detect_landmarks(phantom.ct, "crest");
  const auto errors = errors_against(found, phantom.landmarks);
  for (const char* label : {"B", "Pog"}) {
    ASSERT_TRUE(errors.count(label)) << label << " missed or flagged";
    EXPECT_LT(errors.at(label), 1.5) << label;
    EXPECT_EQ(found.find(label)->note.find("flat chin"), std::string::npos) << label;
  }
}

// The lower central incisors touch their neighbours with no gap a scan resolves: the crown's
// distal end was read at the lateral incisor's, 2-3.4 mm to the right on these patients. Now a
// crown narrower or wider than the mean width by a fifth is not the crown, and L1 lies half that
// width from the arch's midline. Measured across the midsagittal plane.
TEST(PhantomLandmarks, TheLowerIncisorIsReadInItsOwnCrownNotItsNeighbours) {
  for (const auto& [patient, spacing] : {std::pair{"BENCH-014", 0.8}, {"BENCH-017", 0.7}, {"BENCH-022", 0.9}}) {
    const Phantom phantom = make_phantom(varied_phantom_spec(patient, ScannerKind::kCt, spacing));
    const LandmarkDetection found = detect_landmarks(phantom.ct, patient);
    const DetectedLandmark* l1 = found.find("L1");
    ASSERT_TRUE(l1 && l1->position) << patient;
    const double across = found.midsagittal.signed_distance(*l1->position) -
                          found.midsagittal.signed_distance(*find_landmark(phantom.landmarks, "L1"));
    EXPECT_LT(std::abs(across), 1.0) << patient;
  }
}

// With a tight overjet the upper incisor stands against the lower crown: the lower edge's labial
// face, read forward from its lingual tip, ran on through both crowns (6.3-6.4 mm) and put L1
// 2.6 mm too far forward on these two bench patients (2.9 and 3.0 mm off). BENCH-022's second
// start also took a lone hit on the alveolar bone, after a gap, for the lingual face below an
// overjet jump, and was flagged 13.6 mm away. Both now found, unflagged, within 1.5 mm.
TEST(PhantomLandmarks, AnUpperIncisorAgainstTheLowerOneIsNotReadAsItsLabialFace) {
  expect_found_near_truth("BENCH-020", 0.6, "L1", 1.5);
  expect_found_near_truth("BENCH-022", 0.9, "L1", 1.5);
}

// At 1.4 mm voxels the spine is a bump of 0.2 mm on a bone front whose top, under the aperture's
// rim, stands 0.3 mm further forward: the rim had been taken for ANS, 5.1 mm above it.
TEST(PhantomLandmarks, TheNasalSpineIsFoundAtCoarseVoxels) { expect_found_near_truth("BENCH-007", 1.4, "ANS", 1.5); }

// At 1.5 mm voxels BENCH-026's skin between forehead and nose has two bottoms 6.5 mm apart and
// 0.03 mm apart in depth: the upper one had been taken, 6 mm above the truth. Of bottoms as deep,
// the one nearest nasion's height is the soft-tissue nasion.
TEST(PhantomLandmarks, TheSoftTissueNasionLiesOverNasion) { expect_found_near_truth("BENCH-026", 1.5, "NS", 1.5); }

// A small overjet: below the upper incisor's edge the lower incisor's labial face stands only
// 1.19 mm behind it (this patient, at 1 mm voxels), under the 1.2 mm step the rule took for the
// end of the crown; the point seen first moves 5 mm sideways at once (another tooth), which now
// ends it too. Before, U1 was absent here.
TEST(PhantomLandmarks, AnUpperIncisorBarelyInFrontOfTheLowerOneIsFound) {
  PhantomSpec spec = varied_phantom_spec("BENCH-002", ScannerKind::kCt, 1.0);
  // Its chin straight: drawn 3 mm to the left, the lower incisors leave the upper one's slab and
  // its edge is missed for that reason (bench landmarks counts such misses), not the overjet's.
  spec.mandibular_deviation_mm = 0;
  const Phantom phantom = make_phantom(spec);
  const LandmarkDetection found = detect_landmarks(phantom.ct, "small overjet");
  const DetectedLandmark* u1 = found.find("U1");
  ASSERT_TRUE(u1 && u1->position) << (u1 ? u1->note : "");
  EXPECT_FALSE(u1->flagged());
  EXPECT_LT((*u1->position - *find_landmark(phantom.landmarks, "U1")).norm(), 1.0);
}

// In the phantom's Class III bites only the lower central incisors are tipped back behind the
// upper ones: the lower laterals stand 3 mm in front of the upper central's distal half, their
// edges above its edge. The slab's profile ran from the upper central's face onto them with no
// jump back, and U1 was absent (6 of bench landmarks' 30 patients). Read column by column, the
// upper central's face ends in a slope onto the lower central behind it. Found within 1 mm as
// `maxillo sample --class III` draws it, in a turned pose, and on two bench patients.
void expect_upper_incisor_near_truth(const Volume& ct, const LandmarkSet& truth, const std::string& name,
                                     const Eigen::Isometry3d& truth_to_scan = Eigen::Isometry3d::Identity()) {
  const LandmarkDetection found = detect_landmarks(ct, name);
  const DetectedLandmark* u1 = found.find("U1");
  ASSERT_TRUE(u1 && u1->position) << name << ": " << (u1 ? u1->note : "");
  EXPECT_FALSE(u1->flagged()) << name;
  EXPECT_LT((*u1->position - truth_to_scan * *find_landmark(truth, "U1")).norm(), 1.0) << name;
}

TEST(PhantomLandmarks, AClassIIIUpperIncisorIsReadBetweenTheLowerLateralsInFrontOfIt) {
  const Phantom class_iii = make_phantom(phantom_spec_for_class(SkeletalClass::III));
  expect_upper_incisor_near_truth(class_iii.ct, class_iii.landmarks, "class III");
  const Eigen::Isometry3d pose =
      Eigen::Translation3d(6, -4, 3) * Eigen::AngleAxisd(11 * kDeg, Eigen::Vector3d(1, -1, 2).normalized());
  expect_upper_incisor_near_truth(testing::posed(class_iii.ct, pose), class_iii.landmarks, "class III, posed", pose);
  for (const auto& [patient, spacing] : {std::pair{"BENCH-005", 1.1}, {"BENCH-017", 0.7}}) {
    const Phantom phantom = make_phantom(varied_phantom_spec(patient, ScannerKind::kCt, spacing));
    expect_upper_incisor_near_truth(phantom.ct, phantom.landmarks, patient);
  }
}

// The detection of `label` exists and lies within `mm` of the phantom's truth.
void expect_found_within(const LandmarkDetection& found, const Phantom& phantom, const char* label, double mm) {
  const DetectedLandmark* landmark = found.find(label);
  ASSERT_TRUE(landmark && landmark->position) << label << ": " << (landmark ? landmark->note : "");
  EXPECT_LT((*landmark->position - *find_landmark(phantom.landmarks, label)).norm(), mm) << label;
}

// BENCH-019 at 1 mm voxels (turned 9 degrees in the scanner): its upper right first molar was
// refused as narrower than the canine in front of it, where the arch turns across the search box
// (now a molar is compared with the crowns behind it only), and its lower left one merged with
// both premolars into one 21.5 mm crown (a run longer than any tooth is now split at its most
// marked narrowing). Both found within 1.5 mm; the lower one may be flagged, its arch being drawn
// asymmetric (the mirror check).
TEST(PhantomLandmarks, AFirstMolarIsToldFromTheCanineAndFromPremolarsMergedWithIt) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-019", ScannerKind::kCt, 1.0));
  const LandmarkDetection found = detect_landmarks(phantom.ct, "BENCH-019");
  for (const char* label : {"U6R", "L6L"}) expect_found_within(found, phantom, label, 1.5);
  EXPECT_FALSE(found.find("U6R")->flagged());
}

// BENCH-024, a cone-beam scan at 0.44 mm: its upper first molars' cusps lie 8.5 mm in front of
// the template's and the second molars' 3 mm behind it. The first molar is the front one of the
// molars in a row with the crown nearest the template, not that crown (which was the second
// molar, 11.6 mm off).
TEST(PhantomLandmarks, AFirstMolarIsTheFrontOfTheMolarsInARowWhereTheTemplateIsAToothOff) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-024", ScannerKind::kConeBeam, 0.44));
  const LandmarkDetection found = detect_landmarks(phantom.ct, "BENCH-024");
  for (const char* label : {"U6R", "U6L"}) {
    expect_found_within(found, phantom, label, 1.5);
    EXPECT_FALSE(found.find(label)->flagged()) << label;
  }
}

// A cone-beam field cut between the orbitale and the sella: no sella, no nasion, on which the
// first frame rests, and grey values that are not HU. The frame comes from the ear canals and
// the orbits (ear_orbit_frame.h); what lies above the field is absent with its reason.
TEST(PhantomLandmarks, AConeBeamFieldCutBelowTheSellaGetsItsFrameFromTheEarsAndOrbits) {
  PhantomSpec spec = varied_phantom_spec("CBCT-CUT", ScannerKind::kConeBeam, 1.0);
  spec.cone_beam->field_top_mm = 12;  // scanner z: above the orbitale (0), below sella (20) and nasion (28)
  // Padded below air: padding at air's own value is not told from air (grey_calibration.cpp), and
  // a porion just beyond the cylinder's wall is then found rather than reported absent.
  spec.cone_beam->padding_grey = spec.cone_beam->grey_of_air - 200 * spec.cone_beam->grey_per_hu;
  spec.placement.rotation = Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();  // chin down
  spec.placement.shift.setZero();
  const Phantom phantom = make_phantom(spec);
  ASSERT_FALSE(find_landmark(phantom.landmarks, "S"));
  ASSERT_FALSE(find_landmark(phantom.landmarks, "N"));
  const LandmarkDetection found = detect_landmarks(phantom.ct, "cbct");
  EXPECT_NE(found.frame_source.find("found without sella and nasion"), std::string::npos) << found.frame_source;
  EXPECT_FALSE(found.reading.grey.is_hounsfield());
  for (const char* label : {"S", "N"}) {
    ASSERT_FALSE(found.find(label)->position) << label;
    EXPECT_NE(found.find(label)->note.find("outside the scanned field"), std::string::npos) << found.find(label)->note;
  }
  // Nothing invented: the chin below the field's floor, a porion beyond its wall, the soft-tissue
  // nasion without its nasion are absent, each with its reason.
  for (const auto& l : found.landmarks) {
    if (!find_landmark(phantom.landmarks, l.label)) {
      EXPECT_FALSE(l.position) << l.label << " invented";
    }
  }
  // The frame: its origin where the designed sella lies, its size the head's.
  const Eigen::Vector3d sella = spec.placement.to_scanner({0, 0, 20});
  EXPECT_LT((found.head_frame.inverse() * sella).norm(), 2.5);
  EXPECT_NEAR(found.scale, spec.placement.scale, 0.03);
  // Every confident landmark below the field's edge near its truth: the midline of the maxilla
  // too, once the cupping is undone (before, the lifted soft tissue of the nose passed for the
  // nasal spine, 26 mm off). Measured 2026-11-28 (1 mm): mean 0.77 mm over 18, Ls (1.6) the farthest.
  EXPECT_GT(found.reading.cupping_depth, 0.5 * spec.cone_beam->cupping);
  const auto errors = errors_against(found, phantom.landmarks);
  for (const auto& [label, e] : errors) std::cout << "cut cone-beam: " << label << " " << e << " mm\n";
  EXPECT_LT(mean_of(errors), 1.0);
  for (const char* label :
       {"OrR", "OrL", "PoR", "ANS", "A", "PNS", "GoR", "GoL", "U1", "L1", "U6R", "U6L", "L6R", "L6L"})
    EXPECT_TRUE(errors.count(label)) << label;
  for (const auto& [label, e] : errors) EXPECT_LT(e, 2.0) << label;
}

// Towards its lateral end an orbit's lower rim may dip into a notch 2-3 mm wide, a few tenths of
// a millimetre deeper than the rim's broad bottom, beyond a low bump (where the lateral rim rises
// to the zygoma). On these turned cone-beam heads of the bench the notch was read as the bottom,
// or the bump moved the bottom's middle from one start to the other: OrL 14.3 mm off on BENCH-006
// (the notch at the search's end), 11.7 mm on BENCH-030 (the bump). Both orbitales are found,
// unflagged, at the broad bottom.
TEST(PhantomLandmarks, AnOrbitaleIsTheRimsBroadBottomNotANotchBesideIt) {
  for (const auto& [patient, spacing] : {std::pair{"BENCH-006", 0.34}, {"BENCH-030", 0.4}}) {
    const Phantom phantom = make_phantom(varied_phantom_spec(patient, ScannerKind::kConeBeam, spacing));
    const LandmarkDetection found = detect_landmarks(phantom.ct, patient);
    const auto errors = errors_against(found, phantom.landmarks);
    ASSERT_TRUE(errors.count("OrL")) << patient << ": " << found.find("OrL")->note;
    EXPECT_LT(errors.at("OrL"), 1.0) << patient;
    if (find_landmark(phantom.landmarks, "OrR") && errors.count("OrR")) {
      EXPECT_LT(errors.at("OrR"), 1.5) << patient;
    }
  }
}

// A cone-beam field whose top passes 2 mm above the right orbitale and whose cylinder cuts the
// left ear, padded at air's own value (BENCH-006 of the bench). The orbitale is the rim's lowest
// point only where the rim is seen rising on both sides: with the rim cut just above it, the
// right one is absent with that reason (it had been read 33 mm off, deep in the orbit), the
// left, lower in this turned head, is found; the left porion, beyond the cylinder's wall, is not
// invented at the wall (the padding at air's value is recognised as not scanned).
TEST(PhantomLandmarks, AnOrbitaleTheFieldsTopCutsJustAboveIsAbsentNotMisread) {
  const PhantomSpec spec = varied_phantom_spec("BENCH-006", ScannerKind::kConeBeam, 0.6);
  ASSERT_TRUE(spec.cone_beam);
  ASSERT_EQ(spec.cone_beam->padding_grey, spec.cone_beam->grey_of_air) << "the premise: padding at air's value";
  const Phantom phantom = make_phantom(spec);
  ASSERT_TRUE(find_landmark(phantom.landmarks, "OrR"));
  ASSERT_FALSE(find_landmark(phantom.landmarks, "PoL")) << "the premise: the left ear canal outside the field";
  const LandmarkDetection found = detect_landmarks(phantom.ct, "BENCH-006");
  const DetectedLandmark* right = found.find("OrR");
  ASSERT_TRUE(right);
  EXPECT_FALSE(right->position);
  EXPECT_NE(right->note.find("orbital rim above it was not scanned"), std::string::npos) << right->note;
  const auto errors = errors_against(found, phantom.landmarks);
  ASSERT_TRUE(errors.count("OrL")) << found.find("OrL")->note;
  EXPECT_LT(errors.at("OrL"), 2.0);
  for (const auto& l : found.landmarks) {
    if (!find_landmark(phantom.landmarks, l.label)) {
      EXPECT_FALSE(l.position) << l.label << " invented";
    }
  }
}

// A cone-beam scan cut a little above the sella (no forehead above the nasion, no vertex) and
// short behind (its cylinder cuts the skull's back and the right ear canal): BENCH-024 of the
// bench, refused before ("no head frame"). Its sella lies 93 mm behind the skull's front, beyond
// 0.7 of the cut skull's length where it was sought; its size comes from where its orbits lie in
// front of the one canal (mirrored for the other), and its orbits' rims, read across a wider
// width, are found where they are. (At 0.6 mm: at 1 mm its left canal's roof is lost too, as
// both are on BENCH-027, which stays refused.)
TEST(PhantomLandmarks, AConeBeamFieldCutAboveTheSellaAndThroughAnEarIsRead) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-024", ScannerKind::kConeBeam, 0.6));
  ASSERT_FALSE(find_landmark(phantom.landmarks, "PoR")) << "the premise: the right ear canal outside the field";
  ASSERT_TRUE(find_landmark(phantom.landmarks, "S"));
  const LandmarkDetection found = detect_landmarks(phantom.ct, "BENCH-024");
  const auto errors = errors_against(found, phantom.landmarks);
  for (const char* label : {"S", "OrR", "OrL", "ANS", "PNS", "Me"}) {
    ASSERT_TRUE(errors.count(label)) << label << " missed or flagged: " << found.find(label)->note;
    EXPECT_LT(errors.at(label), 2.0) << label;
  }
  EXPECT_LT(mean_of(errors), 1.0);
  for (const auto& l : found.landmarks) {
    if (!find_landmark(phantom.landmarks, l.label)) {
      EXPECT_FALSE(l.position) << l.label << " invented";
    }
  }
}

// A cone-beam field whose floor cuts through the symphysis above the chin (BENCH-015 of the
// bench, at its 0.5 mm; its floor lies above B too): the lowest forward extremum left on the
// bone's front, 11.6 mm below L1, was reported as Pog (so were BENCH-012's and BENCH-030's,
// 7.6-7.8 mm above their B). Without the chin's lower border it cannot be told from the chin:
// Pog, Me and Gn are absent, naming the field.
TEST(PhantomLandmarks, AChinCutByTheConeBeamFieldsFloorIsNotInvented) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-015", ScannerKind::kConeBeam, 0.5));
  ASSERT_FALSE(find_landmark(phantom.landmarks, "Pog")) << "the premise: the chin below the field";
  const LandmarkDetection found = detect_landmarks(phantom.ct, "BENCH-015");
  for (const char* label : {"Pog", "Me", "Gn"}) {
    const auto& l = *found.find(label);
    EXPECT_FALSE(l.position) << label << " invented";
    EXPECT_NE(l.note.find("outside the scanned field"), std::string::npos) << label << ": " << l.note;
  }
  for (const auto& l : found.landmarks) {
    if (!find_landmark(phantom.landmarks, l.label)) {
      EXPECT_FALSE(l.position) << l.label << " invented";
    }
  }
}

// A cone-beam field whose top ends a few millimetres above the sella turcica (BENCH-009 of the
// bench: 8 mm above S, 2.5-3.5 mm above the pocket's top). The fossa is scanned whole and S is
// found, at two spacings; it was missed, the field's edge being closer than the 6 mm of brain the
// rule then asked for. Where the top cuts the fossa's walls (BENCH-006: 1.3 mm above S), S is
// absent, naming the field, and not placed at a truncated pocket's centre.
TEST(PhantomLandmarks, ASellaJustBelowAConeBeamFieldsTopIsFoundAndOneTheTopCutsIsNot) {
  for (double spacing : {0.5, 0.8}) {
    const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-009", ScannerKind::kConeBeam, spacing));
    const auto truth = find_landmark(phantom.landmarks, "S");
    ASSERT_TRUE(truth) << "the premise: the sella inside the field";
    const auto& s = *detect_landmarks(phantom.ct, "BENCH-009").find("S");
    ASSERT_TRUE(s.position) << spacing << " mm: " << s.note;
    EXPECT_LT((*s.position - *truth).norm(), 1.0) << spacing << " mm";
  }
  const Phantom cut = make_phantom(varied_phantom_spec("BENCH-006", ScannerKind::kConeBeam, 0.5));
  const auto& s = *detect_landmarks(cut.ct, "BENCH-006").find("S");
  EXPECT_FALSE(s.position) << "placed in a fossa the field cuts";
  EXPECT_NE(s.note.find("top edge cuts the sella turcica"), std::string::npos) << s.note;
}

// At 1.2 mm voxels BENCH-002's anterior nasal spine is a bump 0.3 mm ahead of the bone's front
// where it slopes back below the aperture's rim, and no extremum over 1.5 mm: the rim was taken
// for the spine, 3.3 mm above it. A bump ahead of the slope now counts (1.7 mm off; 0.6-0.8 mm at
// 1.1 and 1.3 mm, checked with `maxillo sample --vary`; at 1.5 mm it is still missed).
TEST(PhantomLandmarks, TheNasalSpineIsABumpOnTheSlopeBelowTheAperturesRimAtCoarseVoxels) {
  const Phantom phantom = make_phantom(varied_phantom_spec("BENCH-002", ScannerKind::kCt, 1.2));
  const auto& ans = *detect_landmarks(phantom.ct, "BENCH-002").find("ANS");
  ASSERT_TRUE(ans.position) << ans.note;
  EXPECT_LT((*ans.position - *find_landmark(phantom.landmarks, "ANS")).norm(), 2.0);
}

// The same scan gives the same bits run after run, whatever else the machine is doing (a busy
// thread competes for the cores): every sum is split into fixed parts joined in order.
TEST(PhantomLandmarks, TheSameBitsWhateverTheLoad) {
  const Volume ct = make_phantom({.spacing_mm = 1.5}).ct;
  const LandmarkDetection reference = detect_landmarks(ct, "phantom");
  std::atomic<bool> stop{false};
  std::thread busy([&] {
    volatile double x = 0;
    while (!stop) x = x + 1;
  });
  const LandmarkDetection loaded = detect_landmarks(ct, "phantom");
  stop = true;
  busy.join();
  ASSERT_EQ(loaded.landmarks.size(), reference.landmarks.size());
  for (size_t i = 0; i < loaded.landmarks.size(); ++i) {
    EXPECT_EQ(loaded.landmarks[i].position.has_value(), reference.landmarks[i].position.has_value());
    if (loaded.landmarks[i].position) {
      EXPECT_EQ(*loaded.landmarks[i].position, *reference.landmarks[i].position) << loaded.landmarks[i].label;
    }
  }
  EXPECT_EQ(loaded.midsagittal.normal, reference.midsagittal.normal);
}

TEST(PhantomLandmarks, ABoxOfAirIsNotAHead) {
  Volume air;
  air.geometry.size = {80, 80, 80};
  air.geometry.spacing.setConstant(1.0);
  air.hu.assign(size_t(air.geometry.voxel_count()), -1000);
  try {
    detect_landmarks(air, "air.mhd");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("air.mhd"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no bone found"), std::string::npos) << e.what();
  }
  Volume small = air;
  small.geometry.size = {30, 30, 30};
  small.hu.resize(27000);
  EXPECT_THROW(detect_landmarks(small, "small.mhd"), Error);
}

}  // namespace
}  // namespace maxillo::landmarking
