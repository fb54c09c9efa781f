// The profile response (casework/softtissue/profile_response.h) on a synthetic face whose answers are known:
// a rigid move gives every point the whole advancement and no gradient; a move that grows
// linearly with height gives each point its height's share and the slope as the largest gradient.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "casework/softtissue/profile_response.h"
#include "planning/osteotomy.h"
#include "support/test_meshes.h"

namespace maxillo::casework {
namespace {

// A frontal grid (x left, z up, 0.5 mm apart) whose front is a ridge along the midline x = 0:
// y = -50 + |x| / 2, so the most anterior vertex of a row lies on the midline (LPS: anterior is -y).
TriangleMesh ridge_face() {
  constexpr int kColumns = 81, kRows = 161;  // x in [-20, 20], z in [0, 80]
  TriangleMesh mesh;
  mesh.vertices.resize(kColumns * kRows, 3);
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kColumns; ++c) {
      const double x = -20 + 0.5 * c, z = 0.5 * r;
      mesh.vertices.row(r * kColumns + c) << x, -50 + std::abs(x) / 2, z;
    }
  mesh.faces.resize(2 * (kColumns - 1) * (kRows - 1), 3);
  int f = 0;
  for (int r = 0; r + 1 < kRows; ++r)
    for (int c = 0; c + 1 < kColumns; ++c) {
      const int v = r * kColumns + c;
      mesh.faces.row(f++) << v, v + 1, v + kColumns + 1;
      mesh.faces.row(f++) << v, v + kColumns + 1, v + kColumns;
    }
  return mesh;
}

AnatomicalFrame patient_axes() { return {}; }  // anterior -y, superior +z, left +x

LandmarkSet profile_landmarks() {
  return {
      {"Prn", {0, -50, 50}}, {"Sn", {0, -50, 42}}, {"Ls", {0, -50, 34}}, {"Li", {0, -50, 26}}, {"PogS", {0, -50, 10}}};
}

TEST(ProfileResponse, RigidAdvancementMovesEveryPointByTheWholeAdvancement) {
  const auto skin = ridge_face();
  const Eigen::MatrixX3d u = Eigen::RowVector3d(0, -6, 0).replicate(skin.vertices.rows(), 1);
  const auto response = profile_response(skin, u, patient_axes(), profile_landmarks(), 6);
  ASSERT_EQ(response.points.size(), published_le_fort_advancement_response().size());
  for (const auto& point : response.points) {
    EXPECT_TRUE(point.present) << point.label;
    EXPECT_NEAR(point.ratio, 1.0, 1e-12) << point.label;
  }
  EXPECT_EQ(response.gradient_max, 0);
  EXPECT_GT(response.moved_edges, 0);
}

TEST(ProfileResponse, MoveGrowingWithHeightGivesEachPointItsShareAndTheSlope) {
  const auto skin = ridge_face();
  const double slope = 0.05;  // mm of forward move per mm of height
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(skin.vertices.rows(), 3);
  u.col(1) = -slope * skin.vertices.col(2);
  const auto response = profile_response(skin, u, patient_axes(), profile_landmarks(), 5);
  const auto dorsum = profile_vertex_above(skin, patient_axes(), {0, -50, 50}, kDorsumAboveTipMm);
  ASSERT_TRUE(dorsum);
  for (const auto& point : response.points) {
    const double height =
        point.label == kDorsumLabel ? skin.vertices(*dorsum, 2) : find_landmark(profile_landmarks(), point.label)->z();
    EXPECT_NEAR(point.ratio, slope * height / 5, 1e-12) << point.label;
  }
  // Along a vertical edge |du| / |dx| is the slope; along any other, less.
  EXPECT_NEAR(response.gradient_max, slope, 1e-12);
  EXPECT_LE(response.gradient_p999, slope + 1e-12);
}

// A face that tears along a line (the skin above z = 33 moves 5 mm forward, below it stays): the
// steepest edges cross the tear (0.5 mm long, 5 mm apart in move), and the landmark nearest to
// the steepest is the upper lip's, 0.75 mm above the tear.
TEST(ProfileResponse, TheSteepestEdgeIsFoundAtATear) {
  const auto skin = ridge_face();
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(skin.vertices.rows(), 3);
  for (Eigen::Index v = 0; v < u.rows(); ++v)
    if (skin.vertices(v, 2) > 33) u(v, 1) = -5;
  const auto response = profile_response(skin, u, patient_axes(), profile_landmarks(), 5);
  EXPECT_NEAR(response.gradient_max, 5 / 0.5, 1e-9);  // across a vertical edge 0.5 mm long
  EXPECT_NEAR(response.steepest_at.z(), 33.25, 1e-9);
  const auto nearest = nearest_landmark(profile_landmarks(), response.steepest_at);
  ASSERT_TRUE(nearest);
  EXPECT_EQ(nearest->first, "Ls");
  EXPECT_FALSE(nearest_landmark({}, response.steepest_at));
}

// Skin that lines a cavity (a CT's skin follows the air into the nose and the sinuses) rides on
// the bone it lines and may tear where moved bone meets unmoved bone; the gradient figures are
// the outer face's. A head as a box with a box-shaped cavity inside (its walls facing inwards):
// a corner of the cavity moved is no gradient; a corner of the outer face moved is.
TEST(ProfileResponse, CavityLiningsAreNotInTheGradient) {
  TriangleMesh cavity = testing::make_box({-10, -10, -10}, {10, 10, 10});
  cavity.faces.col(1).swap(cavity.faces.col(2));  // normals into the cavity, away from the tissue
  const TriangleMesh head = testing::append(testing::make_box({-50, -50, -50}, {50, 50, 50}), cavity);
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(head.vertices.rows(), 3);
  u(8, 1) = -5;  // a corner of the cavity
  auto response = profile_response(head, u, patient_axes(), profile_landmarks(), 5);
  EXPECT_EQ(response.moved_edges, 0);
  EXPECT_EQ(response.gradient_max, 0);
  u(0, 1) = -5;  // a corner of the outer face, at (-50, -50, -50)
  response = profile_response(head, u, patient_axes(), profile_landmarks(), 5);
  EXPECT_GT(response.moved_edges, 0);
  EXPECT_NEAR(response.gradient_max, 5 / 100.0, 1e-12);                // along the box's 100 mm edges
  EXPECT_NEAR(response.steepest_at.cwiseAbs().maxCoeff(), 50, 1e-12);  // on the outer face
}

TEST(ProfileResponse, DorsumIsTheMostAnteriorMidlineVertexAboveTheTip) {
  const auto skin = ridge_face();
  const Eigen::Vector3d tip(0.3, -50, 40);
  const auto v = profile_vertex_above(skin, patient_axes(), tip, 8);
  ASSERT_TRUE(v);
  EXPECT_EQ(skin.vertices(*v, 0), 0);  // on the ridge
  EXPECT_NEAR(skin.vertices(*v, 2), 48, 1.0);
  EXPECT_FALSE(profile_vertex_above(skin, patient_axes(), tip, 60));  // above the face
}

TEST(ProfileResponse, AbsentLandmarksAreReportedAbsent) {
  const auto skin = ridge_face();
  const Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(skin.vertices.rows(), 3);
  const auto response = profile_response(skin, u, patient_axes(), {{"Ls", {0, -50, 34}}}, 6);
  for (const auto& point : response.points) EXPECT_EQ(point.present, point.label == "Ls") << point.label;
  EXPECT_EQ(response.moved_edges, 0);
}

TEST(ProfileResponse, PlausibleBandsFollowThePublishedFigures) {
  for (const auto& published : published_le_fort_advancement_response()) {
    if (published.label == "Prn") {
      EXPECT_TRUE(plausible(published, 0.17));
      EXPECT_FALSE(plausible(published, 0.82));
    }
    if (published.label == "Ls") {
      EXPECT_TRUE(plausible(published, 0.82));
      EXPECT_FALSE(plausible(published, 0.3));
    }
    if (published.label == "Li") {
      EXPECT_TRUE(plausible(published, 0.3));  // no band
    }
  }
}

// The maxilla's advancement is its move read at A: a translation gives its forward part, a turn
// about a transverse axis 40 mm above A gives 40 mm times the angle's sine.
TEST(MaxillaryAdvancement, IsTheMaxillasForwardMoveAtA) {
  const LandmarkSet landmarks{{"A", {0, -60, 20}}, {"ANS", {0, -62, 25}}};
  const auto maxilla = uint8_t(planning::Segment::kMaxilla);
  SegmentMoves moves{{maxilla, Eigen::Isometry3d(Eigen::Translation3d(1, -6, 2))}};
  auto advancement = maxillary_advancement(moves, landmarks, patient_axes());
  ASSERT_TRUE(advancement);
  EXPECT_NEAR(advancement->forward_mm, 6, 1e-12);
  EXPECT_EQ(advancement->reference, "A");
  EXPECT_FALSE(advancement->other_segments_moved);

  // Turned by 0.1 rad about the transverse axis 40 mm above A: A swings forward by 40 sin 0.1.
  const Eigen::Vector3d pivot(0, -60, 60);
  moves[maxilla] =
      Eigen::Translation3d(pivot) * Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitX()) * Eigen::Translation3d(-pivot);
  advancement = maxillary_advancement(moves, landmarks, patient_axes());
  ASSERT_TRUE(advancement);
  EXPECT_NEAR(advancement->forward_mm, 40 * std::sin(0.1), 1e-12);

  // Without A the move is read at ANS; a moved mandible is named; an identity stored for it is not.
  moves[maxilla] = Eigen::Translation3d(0, -4, 0) * Eigen::Isometry3d::Identity();
  moves[uint8_t(planning::Segment::kMandible)] = Eigen::Isometry3d::Identity();
  advancement = maxillary_advancement(moves, {{"ANS", {0, -62, 25}}}, patient_axes());
  ASSERT_TRUE(advancement);
  EXPECT_EQ(advancement->reference, "ANS");
  EXPECT_FALSE(advancement->other_segments_moved);
  moves[uint8_t(planning::Segment::kMandible)] = Eigen::Translation3d(0, -3, 0) * Eigen::Isometry3d::Identity();
  EXPECT_TRUE(maxillary_advancement(moves, landmarks, patient_axes())->other_segments_moved);
}

TEST(MaxillaryAdvancement, NoneWhenTheMaxillaDoesNotComeForward) {
  const LandmarkSet landmarks{{"A", {0, -60, 20}}};
  const auto maxilla = uint8_t(planning::Segment::kMaxilla);
  EXPECT_FALSE(maxillary_advancement({}, landmarks, patient_axes()));  // the maxilla not moved
  const SegmentMoves setback{{maxilla, Eigen::Isometry3d(Eigen::Translation3d(0, 3, 0))}};
  EXPECT_FALSE(maxillary_advancement(setback, landmarks, patient_axes()));
  const SegmentMoves small{{maxilla, Eigen::Isometry3d(Eigen::Translation3d(0, -0.5, 0))}};
  EXPECT_FALSE(maxillary_advancement(small, landmarks, patient_axes()));
  const SegmentMoves forward{{maxilla, Eigen::Isometry3d(Eigen::Translation3d(0, -5, 0))}};
  EXPECT_FALSE(maxillary_advancement(forward, {{"Me", {0, -60, -40}}}, patient_axes()));  // no A, ANS, U1
}

}  // namespace
}  // namespace maxillo::casework
