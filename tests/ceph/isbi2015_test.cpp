// Real data: the 150 ISBI 2015 training cephalograms (../shared/data/isbi2015-ceph). Our SNA, SNB
// and ANB, computed from the pixel coordinates (0.1 mm, y down) with the challenge's thresholds,
// must give the organisers' class of every image.
#include "ceph/isbi2015.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "ceph/cephalometric_analysis.h"

namespace maxillo::ceph {
namespace {

const std::filesystem::path kTable =
    std::filesystem::path(MAXILLO_SHARED_DATA) / "isbi2015-ceph/isbi2015_train_landmarks.csv";

TEST(Isbi2015, OurSnaSnbAnbReproduceEveryOfficialClass) {
  if (!std::filesystem::exists(kTable)) GTEST_SKIP() << "ISBI 2015 landmark table absent: " << kTable;
  auto images = read_isbi_landmark_table(kTable);
  ASSERT_EQ(images.size(), 150u);
  auto agreement = isbi_class_agreement(images);
  EXPECT_EQ(agreement.images, 150);
  EXPECT_EQ(agreement.anb_equal, 150);
  EXPECT_EQ(agreement.snb_equal, 150);
  EXPECT_EQ(agreement.sna_equal, 150);
  for (const auto& d : agreement.disagreements) ADD_FAILURE() << d;
}

TEST(Isbi2015, FirstImageLandmarksAndPlausibleAngles) {
  if (!std::filesystem::exists(kTable)) GTEST_SKIP() << "ISBI 2015 landmark table absent: " << kTable;
  auto images = read_isbi_landmark_table(kTable);
  ASSERT_FALSE(images.empty());
  const auto& first = images.front();
  EXPECT_EQ(first.image_id, "001");
  EXPECT_EQ(first.landmarks.size(), 19u);
  EXPECT_EQ(*find_landmark(first.landmarks, "S"), Eigen::Vector3d(832, 994, 0));
  EXPECT_EQ(*find_landmark(first.landmarks, "U1"), Eigen::Vector3d(1449, 1864, 0));  // UIT
  auto analysis = analyse(cephalogram_to_sagittal(first.landmarks, isbi_axes()));
  // Image 001: ANB class 3 (< 3.2), SNB class 3 (> 78.7), SNA class 2 (> 83.2).
  EXPECT_LT(*analysis.value("ANB"), 3.2);
  EXPECT_GT(*analysis.value("SNB"), 78.7);
  EXPECT_GT(*analysis.value("SNA"), 83.2);
  // A and PNS/ANS in the nasion frame: anterior maxilla below and behind N, PNS behind ANS.
  EXPECT_GT(*analysis.value("ANS_Y"), 30);
  EXPECT_LT(*analysis.value("PNS_X"), *analysis.value("ANS_X"));
  EXPECT_FALSE(analysis.value("Wits").has_value());  // no molar points in the ISBI set
}

TEST(Isbi2015, ClassThresholdsAreInclusiveForClassOne) {
  EXPECT_EQ(isbi_anb_class(3.2), 1);
  EXPECT_EQ(isbi_anb_class(5.7), 1);
  EXPECT_EQ(isbi_anb_class(5.71), 2);
  EXPECT_EQ(isbi_anb_class(-1), 3);
  EXPECT_EQ(isbi_snb_class(74.59), 2);
  EXPECT_EQ(isbi_snb_class(78.8), 3);
  EXPECT_EQ(isbi_sna_class(83.3), 2);
  EXPECT_EQ(isbi_sna_class(79.3), 3);
  EXPECT_EQ(isbi_sna_class(80), 1);
}

}  // namespace
}  // namespace maxillo::ceph
