#include "geometry/aabb_tree.h"

#include <algorithm>
#include <cmath>

namespace maxillo {
namespace {

constexpr int kLeafSize = 4;

double squared_distance_to_box(const Eigen::Vector3d& p, const Aabb& box) {
  const Eigen::Vector3d outside = (box.min - p).cwiseMax(p - box.max).cwiseMax(0.0);
  return outside.squaredNorm();
}

// The axis-aligned box (this frame) enclosing `box` (other frame) after the rigid transform.
Aabb transformed(const Aabb& box, const Eigen::Isometry3d& transform) {
  const Eigen::Vector3d centre = transform * (0.5 * (box.min + box.max));
  const Eigen::Vector3d half = transform.linear().cwiseAbs() * (0.5 * (box.max - box.min));
  return {centre - half, centre + half};
}

bool boxes_within(const Aabb& a, const Aabb& b, double gap) {
  return ((a.min.array() - gap) <= b.max.array()).all() && ((b.min.array() - gap) <= a.max.array()).all();
}

}  // namespace

AabbTree::AabbTree(const TriangleMesh& mesh) : mesh_(&mesh) {
  const int faces = int(mesh.face_count());
  order_.resize(size_t(faces));
  std::vector<Eigen::Vector3d> centroids(static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) {
    order_[size_t(f)] = f;
    const Triangle t = triangle(f);
    centroids[size_t(f)] = (t.a + t.b + t.c) / 3.0;
  }
  nodes_.reserve(size_t(2 * faces / kLeafSize + 2));
  if (faces > 0) build(0, faces, centroids);
}

Triangle AabbTree::triangle(int face) const {
  const auto& v = mesh_->vertices;
  const auto f = mesh_->faces.row(face);
  return {v.row(f(0)).transpose(), v.row(f(1)).transpose(), v.row(f(2)).transpose()};
}

// Median split along the longest axis of the centroids' box; deterministic for a given mesh.
int AabbTree::build(int first, int count, const std::vector<Eigen::Vector3d>& centroids) {
  const int index = int(nodes_.size());
  nodes_.push_back({});
  Aabb box, centre_box;
  for (int i = first; i < first + count; ++i) {
    const int face = order_[size_t(i)];
    const Triangle t = triangle(face);
    box.extend(t.a), box.extend(t.b), box.extend(t.c);
    centre_box.extend(centroids[size_t(face)]);
  }
  nodes_[size_t(index)].box = box;
  if (count <= kLeafSize) {
    nodes_[size_t(index)].first = first;
    nodes_[size_t(index)].count = count;
    return index;
  }
  int axis = 0;
  (centre_box.max - centre_box.min).maxCoeff(&axis);
  const int half = count / 2;
  auto begin = order_.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&](int x, int y) {
    const double cx = centroids[size_t(x)][axis], cy = centroids[size_t(y)][axis];
    return cx < cy || (cx == cy && x < y);
  });
  const int left = build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[size_t(index)].left = left;
  nodes_[size_t(index)].right = right;
  return index;
}

template <typename Visit>
void AabbTree::traverse_pairs(const AabbTree& other, const Eigen::Isometry3d& other_to_this, double gap,
                              Visit&& visit) const {
  if (nodes_.empty() || other.nodes_.empty()) return;
  std::vector<std::pair<int, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const Node& a = nodes_[size_t(i)];
    const Node& b = other.nodes_[size_t(j)];
    if (!boxes_within(a.box, transformed(b.box, other_to_this), gap)) continue;
    const bool a_leaf = a.left < 0, b_leaf = b.left < 0;
    if (a_leaf && b_leaf) {
      visit(a, b);
    } else if (b_leaf || (!a_leaf && (a.box.max - a.box.min).squaredNorm() >= (b.box.max - b.box.min).squaredNorm())) {
      stack.push_back({a.right, j});
      stack.push_back({a.left, j});
    } else {
      stack.push_back({i, b.right});
      stack.push_back({i, b.left});
    }
  }
}

std::vector<FacePair> AabbTree::intersecting_faces(const AabbTree& other,
                                                   const Eigen::Isometry3d& other_to_this) const {
  std::vector<FacePair> pairs;
  std::vector<Triangle> placed;
  traverse_pairs(other, other_to_this, 0.0, [&](const Node& a, const Node& b) {
    placed.clear();
    for (int k = b.first; k < b.first + b.count; ++k) {
      Triangle t = other.triangle(other.order_[size_t(k)]);
      placed.push_back({other_to_this * t.a, other_to_this * t.b, other_to_this * t.c});
    }
    for (int m = a.first; m < a.first + a.count; ++m) {
      const Triangle mine = triangle(order_[size_t(m)]);
      for (int k = 0; k < b.count; ++k)
        if (triangles_intersect(mine, placed[size_t(k)]))
          pairs.emplace_back(order_[size_t(m)], other.order_[size_t(b.first + k)]);
    }
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::pair<std::vector<char>, std::vector<char>> AabbTree::faces_near(const AabbTree& other,
                                                                     const Eigen::Isometry3d& other_to_this,
                                                                     double gap) const {
  std::vector<char> mine(size_t(mesh_->face_count()), 0), theirs(size_t(other.mesh_->face_count()), 0);
  traverse_pairs(other, other_to_this, gap, [&](const Node& a, const Node& b) {
    for (int m = a.first; m < a.first + a.count; ++m) mine[size_t(order_[size_t(m)])] = 1;
    for (int k = b.first; k < b.first + b.count; ++k) theirs[size_t(other.order_[size_t(k)])] = 1;
  });
  return {std::move(mine), std::move(theirs)};
}

NearestPoint AabbTree::nearest(const Eigen::Vector3d& p, double max_distance) const {
  NearestPoint best;
  double best_squared = max_distance * max_distance;
  if (nodes_.empty()) return best;
  std::vector<int> stack{0};
  stack.reserve(64);
  while (!stack.empty()) {
    const Node& node = nodes_[size_t(stack.back())];
    stack.pop_back();
    if (squared_distance_to_box(p, node.box) > best_squared) continue;
    if (node.left < 0) {
      for (int m = node.first; m < node.first + node.count; ++m) {
        const int face = order_[size_t(m)];
        const ClosestPoint c = closest_point_on_triangle(p, triangle(face));
        const double squared = (c.point - p).squaredNorm();
        if (squared <= best_squared && (best.face < 0 || squared < best_squared || face < best.face)) {
          best = {face, c.point, c.feature, 0.0};
          best_squared = squared;
        }
      }
      continue;
    }
    // Visit the nearer child first (pushed last) so the radius shrinks early.
    const double dl = squared_distance_to_box(p, nodes_[size_t(node.left)].box);
    const double dr = squared_distance_to_box(p, nodes_[size_t(node.right)].box);
    if (dl <= dr)
      stack.push_back(node.right), stack.push_back(node.left);
    else
      stack.push_back(node.left), stack.push_back(node.right);
  }
  if (best.face >= 0) best.distance = std::sqrt(best_squared);
  return best;
}

}  // namespace maxillo
