// Skin over exposed bone (casework/softtissue/exposed_bone.h): a block of bone under a sphere of skin whose
// tissue is 1 mm thick on one side and 10 mm on the other. The thin side lies on the bone and
// moves with it; the thick side is tissue and keeps the model's move.
#include "casework/softtissue/exposed_bone.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "planning/osteotomy.h"
#include "support/test_shapes.h"

namespace maxillo::casework {
namespace {

// 0.5 mm voxels over [-20, 20]^3; bone of the maxilla where x > 9 (a sphere of radius 10 about
// the origin has 1 mm of tissue over it at x = 10, and 19 mm at x = -10).
LabelVolume bone_at_the_right() {
  LabelVolume segments;
  segments.geometry.size = Eigen::Vector3i(81, 81, 81);
  segments.geometry.spacing = Eigen::Vector3d::Constant(0.5);
  segments.geometry.origin = Eigen::Vector3d::Constant(-20);
  segments.labels.assign(81 * 81 * 81, 0);
  for (int k = 0; k < 81; ++k)
    for (int j = 0; j < 81; ++j)
      for (int i = 0; i < 81; ++i)
        if (segments.geometry.world(Eigen::Vector3d(i, j, k)).x() > 9)
          segments.labels[size_t(segments.geometry.index(i, j, k))] = uint8_t(planning::Segment::kMaxilla);
  return segments;
}

TEST(ExposedBone, ThinTissueMovesWithItsBoneAndThickTissueDoesNot) {
  const TriangleMesh skin = testing::uv_sphere(Eigen::Vector3d::Zero(), 10);
  const auto segment_of = exposed_bone_segments(skin, bone_at_the_right());
  int on_bone = 0;
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) {
    const double x = skin.vertices(v, 0);
    if (x > 9.5) {
      EXPECT_EQ(segment_of[size_t(v)], uint8_t(planning::Segment::kMaxilla)) << "x = " << x;
    }
    if (x < 7) {
      EXPECT_EQ(segment_of[size_t(v)], 0) << "x = " << x;  // bone more than 2 mm under it, or none
    }
    on_bone += segment_of[size_t(v)] != 0;
  }
  EXPECT_GT(on_bone, 0);

  // The maxilla advanced 6 mm: its vertices move 6 mm, the others keep the model's move.
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Constant(skin.vertices.rows(), 3, 0.5);
  const SegmentMoves moves{{uint8_t(planning::Segment::kMaxilla), Eigen::Isometry3d(Eigen::Translation3d(0, -6, 0))}};
  move_exposed_bone(skin, segment_of, moves, u);
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) {
    const Eigen::RowVector3d expected =
        segment_of[size_t(v)] ? Eigen::RowVector3d(0, -6, 0) : Eigen::RowVector3d::Constant(0.5);
    EXPECT_EQ(u.row(v), expected);
  }
  // A segment the plan leaves in place holds its skin still.
  move_exposed_bone(skin, segment_of, {}, u);
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v)
    if (segment_of[size_t(v)]) {
      EXPECT_EQ(u.row(v).norm(), 0);
    }
}

}  // namespace
}  // namespace maxillo::casework
