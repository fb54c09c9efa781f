// Issue 28, section 3: a header whose axis was flipped is undone (imaging/axis_flip.h): the
// reflection that the orientation check asks for, applied about the volume's centre, gives the
// anatomy its right way round again; a face turned sideways is not an axis flip.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "imaging/axis_flip.h"
#include "sample/phantom.h"

// Its own namespace: the orientation tests built in the same unity file name their flips alike.
namespace maxillo::axis_flip_testing {
namespace {

const Eigen::Matrix3d kFlipY = Eigen::Vector3d(1, -1, 1).asDiagonal();
const Eigen::Matrix3d kFlipZ = Eigen::Vector3d(1, 1, -1).asDiagonal();
const Eigen::Matrix3d kTurnedAboutX = Eigen::Vector3d(1, -1, -1).asDiagonal();
const Eigen::Matrix3d kQuarterAboutZ = (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished();

const Volume& phantom_ct() {
  static const Volume ct = make_phantom({.spacing_mm = 2.0}).ct;
  return ct;
}

Volume with_geometry(const Volume& volume, const VolumeGeometry& geometry) {
  Volume changed = volume;
  changed.geometry = geometry;
  return changed;
}

TEST(AxisFlip, EachVoxelIsReflectedAboutTheGridsCentre) {
  VolumeGeometry g;
  g.size = {40, 50, 30};
  g.spacing = {0.5, 0.7, 1.2};
  g.origin = {-12, 30, 80};
  g.direction = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d centre = grid_centre(g);
  for (const auto& flip : {kFlipY, kFlipZ, kTurnedAboutX}) {
    const VolumeGeometry flipped = flipped_about_centre(g, flip);
    EXPECT_LT((grid_centre(flipped) - centre).norm(), 1e-9) << "the volume stays where it was";
    for (const Eigen::Vector3d& ijk : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(39, 0, 29), Eigen::Vector3d(7, 31, 4)})
      EXPECT_LT((flipped.world(ijk) - (centre + flip * (g.world(ijk) - centre))).norm(), 1e-9);
    const VolumeGeometry back = flipped_about_centre(flipped, flip);  // a reflection undoes itself
    EXPECT_LT((back.origin - g.origin).norm(), 1e-9);
    EXPECT_LT((back.direction - g.direction).norm(), 1e-12);
    EXPECT_EQ(flipped.size, g.size);
    EXPECT_EQ(flipped.spacing, g.spacing);
  }
}

TEST(AxisFlip, TheCorrectionUndoesEachFlippedHeaderOfThePhantom) {
  for (const auto& fault : {kFlipY, kFlipZ, kTurnedAboutX}) {
    const Volume faulty = with_geometry(phantom_ct(), flipped_about_centre(phantom_ct().geometry, fault));
    const HeadOrientation found = check_head_orientation(faulty);
    ASSERT_TRUE(found.contradicts_header()) << found.finding();
    const auto correction = axis_flip_correction(found);
    ASSERT_TRUE(correction) << found.finding();
    EXPECT_EQ(*correction, fault) << "the reflection asked for is the one that was done";
    const Volume corrected = with_geometry(faulty, flipped_about_centre(faulty.geometry, *correction));
    EXPECT_FALSE(check_head_orientation(corrected).contradicts_header());
    // Exactly the original frame: the same voxel at the same place.
    EXPECT_LT((corrected.geometry.origin - phantom_ct().geometry.origin).norm(), 1e-9);
    EXPECT_LT((corrected.geometry.direction - phantom_ct().geometry.direction).norm(), 1e-12);
  }
}

TEST(AxisFlip, NothingToUndoWhenTheHeaderAgreesOrTheFaceIsSideways) {
  EXPECT_FALSE(axis_flip_correction(check_head_orientation(phantom_ct())));
  const Volume sideways = with_geometry(phantom_ct(), flipped_about_centre(phantom_ct().geometry, kQuarterAboutZ));
  const HeadOrientation found = check_head_orientation(sideways);
  ASSERT_TRUE(found.sideways) << found.finding();
  EXPECT_FALSE(axis_flip_correction(found)) << "a quarter turn is no axis flip";
  EXPECT_FALSE(axis_flip_correction(HeadOrientation{})) << "undetermined";
}

}  // namespace
}  // namespace maxillo::axis_flip_testing
