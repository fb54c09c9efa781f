#include "occlusion/occlusion_files.h"

#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "support/temporary_folder.h"

namespace maxillo::occlusion {
namespace {

TEST(ReadSpringPairs, ReadsRowsAfterAHeader) {
  TemporaryFolder folder;
  write_file_atomically(folder / "pairs.csv", "ux,uy,uz,lx,ly,lz\n1,2,3,4,5,6\n\n0.5, 0, 0,1,1,1\n7,8,9,-1,-2,-3\n");
  const auto pairs = read_spring_pairs(folder / "pairs.csv");
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].upper, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(pairs[0].lower, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(pairs[2].lower, Eigen::Vector3d(-1, -2, -3));
}

TEST(ReadSpringPairs, RefusesBadRowsAndTooFewPairs) {
  TemporaryFolder folder;
  write_file_atomically(folder / "short.csv", "1,2,3,4,5,6\n1,2,3,4,5,6\n");
  EXPECT_THROW(read_spring_pairs(folder / "short.csv"), Error);
  write_file_atomically(folder / "bad.csv", "1,2,3,4,5,6\n1,2,3,4,5\n1,2,3,4,5,6\n");
  EXPECT_THROW(read_spring_pairs(folder / "bad.csv"), Error);
  write_file_atomically(folder / "text.csv", "1,2,3,4,5,6\n1,2,x,4,5,6\n1,2,3,4,5,6\n");
  EXPECT_THROW(read_spring_pairs(folder / "text.csv"), Error);
  EXPECT_THROW(read_spring_pairs(folder / "absent.csv"), Error);
}

TEST(UpperTransform, RoundTripsAndRefusesNonRigidMatrices) {
  TemporaryFolder folder;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(1, -2, 3)).rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  write_file_atomically(folder / "start.json", Json{{"upper_transform", transform_to_json(t)}}.dump());
  EXPECT_TRUE(read_upper_transform(folder / "start.json").isApprox(t, 1e-12));
  Json scaled = transform_to_json(t);
  scaled[0][0] = 2.0;
  write_file_atomically(folder / "scaled.json", Json{{"upper_transform", scaled}}.dump());
  EXPECT_THROW(read_upper_transform(folder / "scaled.json"), Error);
  write_file_atomically(folder / "nokey.json", "{}");
  EXPECT_THROW(read_upper_transform(folder / "nokey.json"), Error);
  write_file_atomically(folder / "broken.json", "{");
  EXPECT_THROW(read_upper_transform(folder / "broken.json"), Error);
}

}  // namespace
}  // namespace maxillo::occlusion
