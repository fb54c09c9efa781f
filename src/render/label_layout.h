#pragma once
// Where to put the text labels of marked points on an image so that no label hides another
// label or a marker: a greedy placement, pure geometry (no VTK), in pixels.
//
// Each label is tried at eight directions around its point (right, left, the four diagonals,
// above, below), first next to the marker, then one and more label heights further out; the
// first position that overlaps nothing placed so far, no marker and stays inside the image
// wins. When none is free the least overlapping one is taken (a dense cluster of points still
// gets every label). Labels are placed in the order given, so the caller decides who gets the
// nearest place. Deterministic: the same input gives the same layout.
#include <Eigen/Core>
#include <vector>

namespace maxillo::render {

struct PixelBox {
  Eigen::Vector2d min = Eigen::Vector2d::Zero();   // lower corner (x, y)
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  // width, height
  Eigen::Vector2d max() const { return min + size; }
  Eigen::Vector2d centre() const { return min + 0.5 * size; }
};

// Area shared by two boxes (0 when they are apart or only touch).
double overlap_area(const PixelBox& a, const PixelBox& b);

struct LabelRequest {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // the marked point, pixels
  Eigen::Vector2d size = Eigen::Vector2d::Zero();   // the label's text extent, pixels
};

struct PlacedLabel {
  PixelBox box;
  bool needs_leader = false;  // placed away from its marker: draw a line from the marker to it
};

// `marker_radius`: the markers' radius in pixels (each point's marker is an obstacle too);
// `image_size`: width, height. One PlacedLabel per request, in order.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels, double marker_radius,
                                      const Eigen::Vector2d& image_size);

}  // namespace maxillo::render
