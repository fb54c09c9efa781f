#include "sections/occlusion_section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/report_blocks.h"

namespace maxillo::sections {
namespace {

using testing::blocks_of;
using testing::notes_of;

// A Frankfort-like frame turned 90 degrees from the scanner axes, so a wrong axis shows.
AnatomicalFrame turned_frame() {
  AnatomicalFrame frame;
  frame.anterior = Eigen::Vector3d(1, 0, 0);
  frame.left = Eigen::Vector3d(0, 1, 0);
  frame.superior = frame.anterior.cross(frame.left);  // (0, 0, 1)
  return frame;
}

TEST(AnatomicalMotion, ReadsATranslationAlongTheFrameAxes) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.pretranslate(Eigen::Vector3d(2, -3, 0.5));
  const AnatomicalMotion m = anatomical_motion(motion, turned_frame(), Eigen::Vector3d(10, 20, 30));
  EXPECT_NEAR(m.anterior_mm, 2, 1e-12);
  EXPECT_NEAR(m.left_mm, -3, 1e-12);
  EXPECT_NEAR(m.superior_mm, 0.5, 1e-12);
  EXPECT_NEAR(m.pitch_deg, 0, 1e-12);
  EXPECT_NEAR(m.roll_deg, 0, 1e-12);
  EXPECT_NEAR(m.yaw_deg, 0, 1e-12);
}

TEST(AnatomicalMotion, ARotationAboutTheLeftAxisIsPitchWithTheFrontGoingUp) {
  const AnatomicalFrame frame = turned_frame();
  const Eigen::Vector3d reference(0, 0, 0);
  // anterior x left = superior, so turning the front up is a negative turn about `left`.
  Eigen::Isometry3d motion(Eigen::AngleAxisd(-4 * M_PI / 180, frame.left));
  const AnatomicalMotion m = anatomical_motion(motion, frame, reference);
  EXPECT_NEAR(m.pitch_deg, 4, 1e-9);
  EXPECT_NEAR(m.roll_deg, 0, 1e-9);
  EXPECT_NEAR(m.yaw_deg, 0, 1e-9);
  EXPECT_GT((motion * frame.anterior).dot(frame.superior), 0);  // the front goes up
  // About a point 10 mm anterior of the axis: the chord 2 r sin(a/2), mostly superior.
  const AnatomicalMotion at_front = anatomical_motion(motion, frame, 10 * frame.anterior);
  EXPECT_NEAR(std::hypot(at_front.anterior_mm, at_front.superior_mm), 20 * std::sin(2 * M_PI / 180), 1e-9);
  EXPECT_GT(at_front.superior_mm, 0);
}

TEST(AnatomicalMotion, YawAndRollFollowTheirAxes) {
  const AnatomicalFrame frame = turned_frame();
  const AnatomicalMotion yaw =
      anatomical_motion(Eigen::Isometry3d(Eigen::AngleAxisd(-3 * M_PI / 180, frame.superior)), frame, {0, 0, 0});
  EXPECT_NEAR(yaw.yaw_deg, -3, 1e-9);
  EXPECT_NEAR(yaw.pitch_deg, 0, 1e-9);
  const AnatomicalMotion roll =
      anatomical_motion(Eigen::Isometry3d(Eigen::AngleAxisd(1.5 * M_PI / 180, frame.anterior)), frame, {0, 0, 0});
  EXPECT_NEAR(roll.roll_deg, 1.5, 1e-9);
  EXPECT_NEAR(roll.yaw_deg, 0, 1e-9);
  EXPECT_GT((Eigen::AngleAxisd(1.5 * M_PI / 180, frame.anterior) * frame.left).dot(frame.superior), 0);  // left up
  EXPECT_GT((Eigen::AngleAxisd(3 * M_PI / 180, frame.superior) * frame.anterior).dot(frame.left), 0);    // front left
}

// The section from a stored occlusion: the pictures stored with it, the teeth in contact only,
// the upper arch's motion read at its centroid in the frame, the splint's figures.
records::StoredOcclusion stored_occlusion() {
  records::StoredOcclusion stored;
  stored.occlusionogram = "/objects/gram";
  stored.splint_render = "/objects/splint";
  records::OcclusionRecord& o = stored.record;
  o.converged = true;
  o.iterations = 17;
  o.residual_spring_mm = {0.25, 0.5};
  o.contact_threshold_mm = 1;
  o.upper = {12, 3.5, {{0, 400, 12, 3.5, -0.0625}, {1, 380, 0, 0, 1.5}}};
  o.lower = {9, 3.0, {{0, 410, 9, 3.0, 0.25}}};
  o.upper_transform = Eigen::Translation3d(2, 0, -1) * Eigen::Isometry3d::Identity();
  o.upper_centroid = Eigen::Vector3d(10, 20, 30);
  o.splint = records::OcclusionRecord::Splint{"splint.stl", 2,    1, 0.1,   0.25, 2.125, 96, 1234.5,
                                              20480,        true, 1, 0.125, 0.25, 0,     0,  3.5};
  return stored;
}

TEST(OcclusionSection, IsBuiltFromTheStoredOcclusion) {
  const report::Section section = occlusion_section(stored_occlusion(), turned_frame());
  const auto grids = blocks_of<report::ImageGrid>(section);
  ASSERT_EQ(grids.size(), 1u);
  ASSERT_EQ(grids[0]->figures.size(), 2u);
  EXPECT_EQ(grids[0]->figures[1].png, "/objects/splint");
  const auto tables = blocks_of<report::Table>(section);
  ASSERT_EQ(tables.size(), 2u);
  ASSERT_EQ(tables[0]->rows.size(), 2u);  // the upper tooth without contact is left out
  EXPECT_EQ(tables[0]->rows[0], (std::vector<std::string>{"upper", "1", "12", "3.5", "-0.06"}));
  // 2 mm forward and 1 mm down, no turn, in a frame whose anterior is +x and superior +z.
  EXPECT_EQ(tables[1]->rows[0][1], "2.00");
  EXPECT_EQ(tables[1]->rows[0][2], "-1.00");
  const auto facts = blocks_of<report::KeyValueBlock>(section);
  ASSERT_EQ(facts.size(), 2u);
  EXPECT_EQ(facts[0]->pairs[0].second, "converged after 17 iterations");
  EXPECT_EQ(facts[1]->pairs[1].second, "yes (one closed piece)");
}

TEST(OcclusionSection, AnOcclusionStoredWithoutItsCentroidSaysSoInsteadOfAMotion) {
  records::StoredOcclusion stored = stored_occlusion();
  stored.record.upper_centroid.reset();
  stored.splint_render.reset();
  const report::Section section = occlusion_section(stored, turned_frame());
  EXPECT_EQ(blocks_of<report::Table>(section).size(), 1u);  // contacts only
  EXPECT_EQ(blocks_of<report::ImageGrid>(section)[0]->figures.size(), 1u);
  EXPECT_NE(notes_of(section).find("format version 1"), std::string::npos) << notes_of(section);
}

}  // namespace
}  // namespace maxillo::sections
