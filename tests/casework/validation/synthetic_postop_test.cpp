// The synthetic post-operative CT filled in cubes of voxels (one skin distance query settles a cube far from the
// skin) is the CT filled voxel by voxel: the shortcut only skips queries whose answer it already knows. (Where the
// moved skin passes through itself the two may differ: not on this 2 mm phantom, which therefore must match exactly.)
#include <gtest/gtest.h>

#include "casework/phantom_case.h"
#include "casework/validation/synthetic_postop.h"

namespace maxillo::casework {
namespace {

using testing::TemporaryFolder;

TEST(SyntheticPostop, CubesOfVoxelsGiveTheCtOfOneQueryPerVoxel) {
  TemporaryFolder folder;
  const PlannedCase planned = testing_support::planned_phantom(folder.path(), 2.0, 6);

  SyntheticPostopOptions per_voxel;
  per_voxel.skin_block_voxels = 1;
  const SyntheticPostop reference = make_synthetic_postop(planned, per_voxel);
  ASSERT_EQ(reference.ct.hu.size(), size_t(planned.preop_ct.geometry.voxel_count()));
  // The face moved: the CT differs from the pre-operative one, or the comparison below would prove nothing.
  EXPECT_NE(reference.ct.hu, planned.preop_ct.hu);

  for (int n : {4, 7}) {  // the default, and cubes cut by the volume's edges
    SyntheticPostopOptions cubes;
    cubes.skin_block_voxels = n;
    const SyntheticPostop fast = make_synthetic_postop(planned, cubes);
    size_t different = 0;
    for (size_t v = 0; v < fast.ct.hu.size(); ++v) different += fast.ct.hu[v] != reference.ct.hu[v];
    EXPECT_EQ(different, 0u) << "cubes of " << n << " voxels";
  }
}

TEST(SyntheticPostop, CubesOfNoVoxelsAreRefused) {
  SyntheticPostopOptions options;
  options.skin_block_voxels = 0;
  EXPECT_THROW(make_synthetic_postop(PlannedCase{}, options), Error);
}

}  // namespace
}  // namespace maxillo::casework
