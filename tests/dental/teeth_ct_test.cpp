// The CT of teeth on two box-shaped "teeth" facing each other (4 x 4 x 20 mm, 2 mm apart): enamel
// in each one's biting 8 mm, dentine in its root, bone around the root, soft tissue away from
// both, the fillings' metal brighter than anything else, and the same volume whatever the threads.
#include <gtest/gtest.h>

#include "sample/teeth_ct.h"
#include "support/test_shapes.h"

namespace maxillo {
namespace {

TriangleMesh box_tooth(double z0) {
  TriangleMesh tooth = testing::cube(1);
  tooth.vertices = tooth.vertices * Eigen::Vector3d(4, 4, 20).asDiagonal();
  tooth.vertices.col(2).array() += z0;
  return tooth;
}

double hu_at(const Volume& ct, const Eigen::Vector3d& p) {
  const Eigen::Vector3i ijk = ct.geometry.continuous_index(p).array().round().cast<int>();
  return ct.at(ijk.x(), ijk.y(), ijk.z());
}

TEST(TeethCt, EnamelDentineBoneAndMetalWhereTheyBelong) {
  const TriangleMesh upper = box_tooth(22), lower = box_tooth(0);  // upper bites down onto lower
  TeethCtOptions options;
  options.noise_hu = 0;
  options.fillings = 1;
  options.streak_hu = 0;
  const Volume ct = teeth_ct(upper, lower, options);
  EXPECT_NEAR(hu_at(ct, {2, 2, 25}), options.enamel_hu, 1);        // the upper tooth's crown
  EXPECT_NEAR(hu_at(ct, {2, 2, 36}), options.dentine_hu, 1);       // its root
  EXPECT_NEAR(hu_at(ct, {-1, 2, 36}), options.bone_hu, 1);         // 1 mm beside the root
  EXPECT_NEAR(hu_at(ct, {-1, 2, 25}), options.soft_tissue_hu, 1);  // beside the crown
  EXPECT_NEAR(hu_at(ct, {2, 2, 15}), options.enamel_hu, 1);        // the lower tooth's crown
  EXPECT_NEAR(hu_at(ct, {2, 2, 21}), options.soft_tissue_hu, 1);   // between the biting ends
  int metal = 0;
  for (int16_t value : ct.hu) metal += value >= 8000;
  EXPECT_GT(metal, 10);
}

TEST(TeethCt, TheSameVolumeWhateverTheThreads) {
  const TriangleMesh upper = box_tooth(22), lower = box_tooth(0);
  TeethCtOptions options;
  options.spacing_mm = 1;
  const Volume a = teeth_ct(upper, lower, options);
  options.max_threads = 1;
  EXPECT_EQ(teeth_ct(upper, lower, options).hu, a.hu);
  options.max_threads = 3;
  EXPECT_EQ(teeth_ct(upper, lower, options).hu, a.hu);
  options.seed = 2;
  EXPECT_NE(teeth_ct(upper, lower, options).hu, a.hu);  // the noise is the seed's
}

}  // namespace
}  // namespace maxillo
