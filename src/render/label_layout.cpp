#include "render/label_layout.h"

#include <algorithm>
#include <array>
#include <limits>

namespace maxillo::render {
namespace {

// Unit directions tried around a point, in order of preference: beside it reads best.
const std::array<Eigen::Vector2d, 8> kDirections = {
    Eigen::Vector2d(1, 0),  Eigen::Vector2d(-1, 0),  Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1),
    Eigen::Vector2d(1, -1), Eigen::Vector2d(-1, -1), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)};

constexpr int kRings = 8;         // how far out a label may go, in label heights
constexpr double kGapPixels = 3;  // between a marker's rim and its label

// The label's box when its nearest side or corner lies `distance` from the point along `direction`.
PixelBox box_towards(const LabelRequest& label, const Eigen::Vector2d& direction, double distance) {
  const Eigen::Vector2d anchor = label.point + distance * direction;
  // direction.x = 1: the box starts at the anchor; -1: it ends there; 0: it is centred on it.
  const Eigen::Vector2d offset((direction.x() - 1) * 0.5 * label.size.x(), (direction.y() - 1) * 0.5 * label.size.y());
  return {anchor + offset, label.size};
}

PixelBox marker_box(const Eigen::Vector2d& point, double radius) {
  return {point - Eigen::Vector2d::Constant(radius), Eigen::Vector2d::Constant(2 * radius)};
}

double outside_area(const PixelBox& box, const Eigen::Vector2d& image_size) {
  const double inside = overlap_area(box, {Eigen::Vector2d::Zero(), image_size});
  return box.size.prod() - inside;
}

}  // namespace

double overlap_area(const PixelBox& a, const PixelBox& b) {
  const Eigen::Vector2d low = a.min.cwiseMax(b.min), high = a.max().cwiseMin(b.max());
  const Eigen::Vector2d extent = (high - low).cwiseMax(0.0);
  return extent.prod();
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels, double marker_radius,
                                      const Eigen::Vector2d& image_size) {
  std::vector<PixelBox> obstacles;
  for (const auto& l : labels) obstacles.push_back(marker_box(l.point, marker_radius));

  std::vector<PlacedLabel> placed;
  for (const auto& label : labels) {
    PlacedLabel best;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring < kRings && best_cost > 0; ++ring) {
      const double distance = marker_radius + kGapPixels + ring * label.size.y();
      for (const auto& direction : kDirections) {
        const PixelBox box = box_towards(label, direction, distance);
        // Leaving the image is worse than covering another label.
        double cost = 4 * outside_area(box, image_size);
        for (const auto& o : obstacles) cost += overlap_area(box, o);
        if (cost < best_cost) best_cost = cost, best = {box, ring > 0};
        if (cost == 0) break;
      }
    }
    obstacles.push_back(best.box);
    placed.push_back(best);
  }
  return placed;
}

}  // namespace maxillo::render
