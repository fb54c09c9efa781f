// The varied phantoms (sample/phantom_variation.h) and their two scanners: another patient per
// Patient ID, always the same one for the same ID; the head voxelised in its pose with its
// landmarks moved the same way; a cone-beam scan whose grey values are not HU but linear in them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <set>

#include "core/angles.h"
#include "imaging/grey_calibration.h"
#include "phantom_probe.h"
#include "sample/phantom_variation.h"

namespace maxillo::test {
namespace {

PhantomSpec quiet(PhantomSpec spec) {
  spec.noise_sigma_hu = 0;
  spec.partial_volume = PartialVolume::Sharp;
  return spec;
}

uint8_t label_at(const LabelVolume& labels, const Eigen::Vector3d& lps) {
  const Eigen::Vector3i v = nearest_voxel(labels.geometry, lps);
  if (!labels.geometry.contains(v.x(), v.y(), v.z())) return 255;
  return labels.labels[labels.geometry.index(v.x(), v.y(), v.z())];
}

TEST(PhantomVariation, ThePatientIdDecidesThePatient) {
  const PhantomSpec a = varied_phantom_spec("P-17", ScannerKind::kCt, 1.0);
  const PhantomSpec again = varied_phantom_spec("P-17", ScannerKind::kCt, 1.0);
  const PhantomSpec b = varied_phantom_spec("P-18", ScannerKind::kCt, 1.0);
  EXPECT_EQ(describe_variation(a), describe_variation(again));
  EXPECT_EQ(a.placement.rotation, again.placement.rotation);
  EXPECT_NE(describe_variation(a), describe_variation(b));
  // Over many IDs the draws cover their ranges.
  double smallest = 2, largest = 0, most_turned = 0, least_anb = 99, most_anb = -99;
  for (int id = 0; id < 200; ++id) {
    const PhantomSpec s = varied_phantom_spec("ID" + std::to_string(id), ScannerKind::kCt, 1.0);
    smallest = std::min(smallest, s.placement.scale), largest = std::max(largest, s.placement.scale);
    most_turned = std::max(most_turned, Eigen::AngleAxisd(s.placement.rotation).angle() / kDeg);
    const double jaws = s.maxillary_advancement_mm - s.mandibular_protrusion_mm;
    least_anb = std::min(least_anb, jaws), most_anb = std::max(most_anb, jaws);
    EXPECT_NEAR(s.placement.rotation.determinant(), 1.0, 1e-12);
    EXPECT_LE(s.placement.shift.cwiseAbs().maxCoeff(), 15.0);
  }
  EXPECT_LT(smallest, 0.93);
  EXPECT_GT(largest, 1.07);
  EXPECT_GT(most_turned, 15.0);
  EXPECT_LT(least_anb, -6.0);  // maxilla back, mandible forward: Class III
  EXPECT_GT(most_anb, 6.0);    // Class II
}

// A chin to one side: the mandibular body and chin move by the deviation, the rami, the cranium
// and the upper jaw stay; some patients' chins lie to the left, some to the right.
TEST(PhantomVariation, AChinToOneSideMovesTheMandibularBodyAlone) {
  PhantomSpec deviated;
  deviated.mandibular_deviation_mm = 2.5;
  const LandmarkSet moved = make_phantom_landmarks(deviated), straight = make_phantom_landmarks({});
  for (const char* label : {"B", "Pog", "Me", "Gn", "L1"})
    EXPECT_LT((*find_landmark(moved, label) - *find_landmark(straight, label) - Eigen::Vector3d(2.5, 0, 0)).norm(),
              1e-9)
        << label;
  for (const char* label : {"S", "N", "A", "ANS", "U1", "U6R", "GoR", "GoL", "ArR", "ArL", "PoR", "OrL"})
    EXPECT_LT((*find_landmark(moved, label) - *find_landmark(straight, label)).norm(), 1e-9) << label;
  // The bone is there: the chin's bone moved with its landmark.
  const Phantom phantom = make_phantom(quiet(deviated));
  const Eigen::Vector3d pog = *find_landmark(phantom.landmarks, "Pog");
  EXPECT_EQ(label_at(phantom.labels, pog + Eigen::Vector3d(0, 2, 0)), uint8_t(Tissue::kMandible));
  double leftmost = 0, rightmost = 0;
  for (int id = 0; id < 200; ++id) {
    const double d = varied_phantom_spec("ID" + std::to_string(id), ScannerKind::kCt, 1.0).mandibular_deviation_mm;
    EXPECT_LE(std::abs(d), 3.0);
    leftmost = std::max(leftmost, d), rightmost = std::min(rightmost, d);
  }
  EXPECT_GT(leftmost, 2.5);
  EXPECT_LT(rightmost, -2.5);
}

// The placed head is the designed head moved: a voxel of the placed scan holds what the designed
// head holds where the placement sends it back, and the landmarks moved the same way.
TEST(PhantomVariation, ThePlacedHeadAndItsLandmarksMoveTogether) {
  PhantomSpec placed = quiet({});
  placed.placement.scale = 1.06;
  placed.placement.rotation =
      (Eigen::AngleAxisd(13 * kDeg, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-9 * kDeg, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  placed.placement.shift = Eigen::Vector3d(7, -11, 4);
  const Phantom designed = make_phantom(quiet({})), moved = make_phantom(placed);

  for (const Landmark& l : designed.landmarks)
    EXPECT_LT((*find_landmark(moved.landmarks, l.label) - placed.placement.to_scanner(l.position)).norm(), 1e-9)
        << l.label;
  const VolumeGeometry& g = moved.labels.geometry;
  int agree = 0, compared = 0;
  std::set<int> tissues_seen;
  for (int k = 0; k < g.size.z(); k += 7)
    for (int j = 0; j < g.size.y(); j += 7)
      for (int i = 0; i < g.size.x(); i += 7) {
        const uint8_t there = label_at(designed.labels, placed.placement.to_anatomy(g.world(Eigen::Vector3d(i, j, k))));
        if (there == 255) continue;
        ++compared;
        agree += there == moved.labels.labels[g.index(i, j, k)];
        tissues_seen.insert(there);
      }
  // Voxel centres differ by up to half a voxel: only voxels at a tissue boundary may disagree.
  EXPECT_GT(double(agree) / compared, 0.95) << agree << " of " << compared;
  EXPECT_GE(tissues_seen.size(), 7u);
  // The chin's soft tissue, between Pog and its skin point, is in the scan: the grid covers the placed head.
  const Eigen::Vector3d chin = (landmark(designed, "PogS") + landmark(designed, "Pog")) / 2;
  EXPECT_EQ(label_at(moved.labels, placed.placement.to_scanner(chin)), uint8_t(Tissue::kSoftTissue));
}

TEST(PhantomVariation, AConeBeamScanIsLinearInHuAndCutToItsField) {
  PhantomSpec spec = quiet({});
  ConeBeamFlavour flavour;
  flavour.grey_per_hu = 0.7, flavour.grey_of_air = 300, flavour.padding_grey = 100;
  flavour.cupping = 0, flavour.metal_fillings = false;
  flavour.field_top_mm = 10;  // below sella and nasion, above orbitale
  spec.cone_beam = flavour;
  const Phantom scan = make_phantom(spec), ct = make_phantom(quiet({}));
  const VolumeGeometry& g = scan.ct.geometry;
  EXPECT_LE(g.world(g.size.cast<double>()).z(), 10 + 1.0);
  for (int k = 0; k < g.size.z(); k += 5)
    for (int j = 0; j < g.size.y(); j += 5)
      for (int i = 0; i < g.size.x(); i += 5) {
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const Eigen::Vector3i v = nearest_voxel(ct.ct.geometry, p);
        const double grey = scan.ct.hu[g.index(i, j, k)];
        if (!flavour.reconstructs(p))
          ASSERT_EQ(grey, 100) << "padding at " << p.transpose();
        else
          ASSERT_NEAR(grey, 300 + 0.7 * (ct.ct.at(v.x(), v.y(), v.z()) + 1000), 0.51) << p.transpose();
      }
  EXPECT_FALSE(find_landmark(scan.landmarks, "S"));
  EXPECT_FALSE(find_landmark(scan.landmarks, "N"));
  EXPECT_TRUE(find_landmark(scan.landmarks, "OrL"));
  EXPECT_TRUE(find_landmark(scan.landmarks, "Me"));
}

TEST(PhantomVariation, TheConeBeamFlavourNeedsItsOwnGreyScaleAndHasStreaks) {
  const PhantomSpec spec = varied_phantom_spec("CBCT-1", ScannerKind::kConeBeam, 1.0);
  const Phantom scan = make_phantom(spec);
  const GreyCalibration grey = estimate_grey_calibration(scan.ct);
  ASSERT_TRUE(grey.from_histogram);
  EXPECT_FALSE(grey.is_hounsfield());
  const ConeBeamFlavour& cb = *spec.cone_beam;
  EXPECT_NEAR(grey.air, cb.grey_of_air, 60 * cb.grey_per_hu);
  // Soft tissue reads lower than 40 HU would: the cupping darkens the head's middle.
  EXPECT_NEAR(grey.soft_tissue, cb.grey_of_air + 1040 * cb.grey_per_hu, 200 * cb.grey_per_hu);
  // Metal: the fillings hold the scanner's top grey value.
  int metal = 0;
  for (int16_t v : scan.ct.hu) metal += v >= int16_t(std::lround(cb.grey_of_air + 4071 * cb.grey_per_hu)) - 1;
  EXPECT_GT(metal, 20);
  // The same patient, the same bits.
  EXPECT_EQ(make_phantom(spec).ct.hu, scan.ct.hu);
}

}  // namespace
}  // namespace maxillo::test
