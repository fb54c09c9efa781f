// The synthetic post-operative CT filled in cubes of voxels (one skin distance query settles a cube far from the
// skin) is the CT filled voxel by voxel: the shortcut only skips queries whose answer it already knows. (Where the
// moved skin passes through itself the two may differ: not on this 2 mm phantom, which therefore must match exactly.)
#include <gtest/gtest.h>

#include "archive_fixture.h"
#include "pipeline/case_landmarks.h"
#include "pipeline/plan_archive.h"
#include "pipeline/planned_case.h"
#include "pipeline/sample_case.h"
#include "pipeline/synthetic_postop.h"

namespace maxillo::pipeline {
namespace {

using testing::TemporaryFolder;

TEST(SyntheticPostop, CubesOfVoxelsGiveTheCtOfOneQueryPerVoxel) {
  TemporaryFolder folder;
  const SampleCase sample = write_sample_case(SkeletalClass::I, 2.0, folder / "sample");
  Archive archive = Archive::open(folder / "archive", OpenMode::CreateIfMissing);
  ASSERT_TRUE(archive.import_paths({sample.ct_folder}, testing::quiet()).all_ok());
  const int64_t case_id = archive.resolve_case(kPhantomPatientId);
  attach_landmarks(archive, case_id, sample.landmarks, "phantom");
  store_plan(archive, case_id, planning::distraction_plan({.advancement_mm = 6, .widening_mm = 0}, "test"));
  const PlannedCase planned = load_planned_case(archive, case_id);

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
}  // namespace maxillo::pipeline
