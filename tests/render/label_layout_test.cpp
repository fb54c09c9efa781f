// The labels of marked points (render/label_layout.h): beside their point when there is room,
// never over another label or a marker while a free place exists, inside the image, and the
// same layout for the same input.
#include "render/label_layout.h"

#include <gtest/gtest.h>

namespace maxillo::render {
namespace {

const Eigen::Vector2d kImage(1024, 1024);
const Eigen::Vector2d kLabelSize(40, 16);
constexpr double kRadius = 6;

double total_overlap(const std::vector<PlacedLabel>& placed, const std::vector<LabelRequest>& requests) {
  double sum = 0;
  for (size_t i = 0; i < placed.size(); ++i) {
    for (size_t j = i + 1; j < placed.size(); ++j) sum += overlap_area(placed[i].box, placed[j].box);
    for (const auto& r : requests)
      sum += overlap_area(placed[i].box,
                          {r.point - Eigen::Vector2d::Constant(kRadius), Eigen::Vector2d::Constant(2 * kRadius)});
  }
  return sum;
}

TEST(OverlapArea, OfBoxesApartTouchingAndCrossing) {
  const PixelBox a{{0, 0}, {10, 10}};
  EXPECT_EQ(overlap_area(a, {{20, 0}, {5, 5}}), 0);
  EXPECT_EQ(overlap_area(a, {{10, 0}, {5, 5}}), 0);  // touching edges share no area
  EXPECT_DOUBLE_EQ(overlap_area(a, {{5, 6}, {10, 10}}), 5 * 4);
  EXPECT_DOUBLE_EQ(overlap_area(a, {{2, 2}, {3, 3}}), 9);  // one inside the other
}

TEST(PlaceLabels, ALoneLabelSitsRightBesideItsPoint) {
  const std::vector<LabelRequest> one{{{500, 500}, kLabelSize}};
  const auto placed = place_labels(one, kRadius, kImage);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_FALSE(placed[0].needs_leader);
  EXPECT_GT(placed[0].box.min.x(), 500 + kRadius);       // right of the marker's rim
  EXPECT_LT(placed[0].box.min.x(), 500 + kRadius + 10);  // and close to it
  EXPECT_EQ(placed[0].box.size, kLabelSize);
}

TEST(PlaceLabels, APointAtTheImagesRightEdgeGetsItsLabelOnTheLeft) {
  const std::vector<LabelRequest> one{{{1020, 500}, kLabelSize}};
  const auto placed = place_labels(one, kRadius, kImage);
  EXPECT_LE(placed[0].box.max().x(), 1020 - kRadius);
  EXPECT_GE(placed[0].box.min.x(), 0);
}

TEST(PlaceLabels, AClusterOfPointsGetsLabelsThatHideNothing) {
  // Twelve points within 12 pixels (the incisors, lips and chin of a lateral view).
  std::vector<LabelRequest> cluster;
  for (int i = 0; i < 12; ++i) cluster.push_back({{500 + (i % 4) * 4.0, 500 + (i / 4) * 4.0}, kLabelSize});
  const auto placed = place_labels(cluster, kRadius, kImage);
  ASSERT_EQ(placed.size(), cluster.size());
  EXPECT_EQ(total_overlap(placed, cluster), 0);
  int moved_away = 0;
  for (const auto& p : placed) {
    moved_away += p.needs_leader;
    EXPECT_TRUE((p.box.min.array() >= 0).all() && (p.box.max().array() <= kImage.array()).all());
  }
  EXPECT_GT(moved_away, 0) << "twelve labels cannot all touch a 12-pixel cluster";
  // Deterministic: the same input, the same boxes.
  const auto again = place_labels(cluster, kRadius, kImage);
  for (size_t i = 0; i < placed.size(); ++i) EXPECT_EQ(again[i].box.min, placed[i].box.min);
}

TEST(PlaceLabels, WithNoFreePlaceEveryLabelIsStillPlaced) {
  // A 60 x 40 image cannot hold ten 40 x 16 labels apart: the least overlapping places are taken.
  std::vector<LabelRequest> crowded(10, LabelRequest{{30, 20}, kLabelSize});
  const auto placed = place_labels(crowded, kRadius, Eigen::Vector2d(60, 40));
  ASSERT_EQ(placed.size(), crowded.size());
  for (const auto& p : placed) EXPECT_EQ(p.box.size, kLabelSize);
}

}  // namespace
}  // namespace maxillo::render
