#include "mesh/quadric_decimation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace maxillo {
namespace {

// Sum of area-weighted squared distances to planes, as error(p) = p'Ap + 2b'p + c.
struct Quadric {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double c = 0;

  void add_plane(const Eigen::Vector3d& unit_normal, double offset, double weight) {
    a += weight * unit_normal * unit_normal.transpose();
    b += weight * offset * unit_normal;
    c += weight * offset * offset;
  }
  double error(const Eigen::Vector3d& p) const { return std::max(0.0, p.dot(a * p) + 2 * b.dot(p) + c); }
  Quadric operator+(const Quadric& other) const { return {a + other.a, b + other.b, c + other.c}; }
};

// On a flat patch (or along a straight crease) the planes do not fix a point: A is singular and
// the best place is chosen among the edge's ends and middle instead, which keeps flat faces flat
// and corners where they are.
constexpr double kMinConditioning = 1e-6;  // 1 / (Frobenius condition number of A)

double triangle_quality(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  const double edges = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
  if (edges <= 0) return 0;
  return 2 * std::sqrt(3.0) * (p1 - p0).cross(p2 - p0).norm() / edges;  // area = |cross| / 2
}

// Where the quadric's error is least, A p = -b, when A is far enough from singular to fix a
// point. The test is on the Frobenius condition number |A| |A^-1|, which for a 3 x 3 matrix lies
// between the 2-norm one (largest over smallest eigenvalue) and three times it: unlike an
// eigen-decomposition it needs no trigonometry, and it is computed a few million times per
// head-sized surface. A^-1 is the adjugate over the determinant.
std::optional<Eigen::Vector3d> well_conditioned_minimum(const Quadric& q) {
  const Eigen::Matrix3d& a = q.a;
  Eigen::Matrix3d adjugate;
  adjugate.col(0) = a.col(1).cross(a.col(2));
  adjugate.col(1) = a.col(2).cross(a.col(0));
  adjugate.col(2) = a.col(0).cross(a.col(1));
  adjugate.transposeInPlace();
  const double determinant = a.col(0).dot(adjugate.row(0).transpose());
  if (!(determinant > 0) || a.norm() * adjugate.norm() * kMinConditioning >= determinant) return std::nullopt;
  return Eigen::Vector3d(-(adjugate * q.b) / determinant);
}

// A queued collapse, kept small (the queue holds about a million): its place is computed again
// when it is taken, from the same quadrics, so it is the same place.
struct Candidate {
  double cost;
  int v0, v1;  // v0 < v1; v1 is merged into v0
  uint32_t stamp0, stamp1;
};

struct Placement {
  Eigen::Vector3d position;
  double cost;
};

// Least cost first; equal costs by vertex numbers, so the order never depends on anything else.
bool before(const Candidate& x, const Candidate& y) {
  if (x.cost != y.cost) return x.cost < y.cost;
  if (x.v0 != y.v0) return x.v0 < y.v0;
  return x.v1 < y.v1;
}

// Candidates by cost, in buckets of 1/8 octave (costs within 9 % of each other share one). A
// binary heap of a million candidates spent most of the decimation's time in cache misses, and
// most of what it held was stale; buckets are appended to and sorted a batch at a time. The
// lowest bucket is taken whole and sorted, so the order is exact within it and deterministic.
class CandidateBuckets {
 public:
  void push(const Candidate& c) {
    const size_t b = bucket(c.cost);
    buckets_[b].push_back(c);
    lowest_ = std::min(lowest_, b);
    ++size_;
  }
  bool empty() const { return size_ == 0; }
  // The lowest bucket's candidates in order (the bucket is emptied; pushes may refill it).
  std::vector<Candidate> take_lowest() {
    while (buckets_[lowest_].empty()) ++lowest_;
    std::vector<Candidate> batch;
    batch.swap(buckets_[lowest_]);
    size_ -= batch.size();
    std::sort(batch.begin(), batch.end(), before);
    return batch;
  }
  void clear() { *this = CandidateBuckets(); }

 private:
  static constexpr int kPerOctave = 8, kOctaves = 96, kLowestOctave = -64;  // 2^-64 .. 2^32 mm^4
  static size_t bucket(double cost) {
    if (!(cost > 0)) return 0;
    // Clamped as a double first: an infinite cost must not reach the conversion to int.
    const double b = std::floor(kPerOctave * (std::log2(cost) - kLowestOctave)) + 1;
    return size_t(std::clamp(b, 1.0, double(kPerOctave * kOctaves - 1)));
  }
  std::vector<std::vector<Candidate>> buckets_ = std::vector<std::vector<Candidate>>(kPerOctave * kOctaves);
  size_t lowest_ = buckets_.size();
  size_t size_ = 0;
};

class Decimator {
 public:
  Decimator(const TriangleMesh& mesh, const QuadricDecimationOptions& options)
      : options_(options),
        positions_(mesh.vertices),
        faces_(mesh.faces),
        face_alive_(size_t(mesh.face_count()), 1),
        vertex_faces_(size_t(mesh.vertex_count())),
        quadrics_(size_t(mesh.vertex_count())),
        stamp_(size_t(mesh.vertex_count()), 0),
        locked_(size_t(mesh.vertex_count()), 0),
        faces_left_(mesh.face_count()),
        min_turn_cos_(std::cos(options.max_normal_turn_deg * M_PI / 180)) {
    for (Eigen::Index f = 0; f < faces_.rows(); ++f)
      for (int k = 0; k < 3; ++k) vertex_faces_[size_t(faces_(f, k))].push_back(int(f));
    build_quadrics();
    lock_border_vertices();
  }

  QuadricDecimationResult run() {
    QuadricDecimationResult result;
    // A refused collapse may become possible after its neighbours changed: a few passes over
    // the remaining edges, until the target is met or a pass collapses nothing.
    for (int pass = 0; pass < 4 && faces_left_ > options_.target_triangles; ++pass) {
      const int64_t before = collapses_;
      push_all_edges();
      while (!queue_.empty() && faces_left_ > options_.target_triangles)
        for (const Candidate& next : queue_.take_lowest()) {
          if (faces_left_ <= options_.target_triangles) break;
          if (is_current(next) && try_collapse(next)) ++collapses_;
        }
      queue_.clear();
      if (collapses_ == before) break;
    }
    result.collapses = collapses_;
    result.reached_target = faces_left_ <= options_.target_triangles;
    result.mesh = compacted();
    return result;
  }

 private:
  Eigen::Vector3d position(int v) const { return positions_.row(v).transpose(); }

  void build_quadrics() {
    for (Eigen::Index f = 0; f < faces_.rows(); ++f) {
      const Eigen::Vector3d p0 = position(faces_(f, 0)), p1 = position(faces_(f, 1)), p2 = position(faces_(f, 2));
      const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0);
      const double area = 0.5 * cross.norm();
      if (area <= 0) continue;
      const Eigen::Vector3d normal = cross.normalized();
      for (int k = 0; k < 3; ++k) quadrics_[size_t(faces_(f, k))].add_plane(normal, -normal.dot(p0), area);
    }
  }

  // Vertices on an edge that does not have exactly two faces keep their place. Each edge is
  // counted from its first end's faces (a vertex has a handful), not by sorting every edge.
  void lock_border_vertices() {
    for (Eigen::Index f = 0; f < faces_.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = faces_(f, k), b = faces_(f, (k + 1) % 3);
        int faces_on_edge = 0;
        for (int g : vertex_faces_[size_t(a)]) faces_on_edge += contains(g, b);
        if (faces_on_edge != 2) locked_[size_t(a)] = locked_[size_t(b)] = 1;
      }
  }

  // The other vertices of the faces around v, sorted, each once, into `around` (a buffer kept
  // by the caller: this runs three times per collapse, and allocating was a tenth of the time).
  void neighbours(int v, std::vector<int>& around) const {
    around.clear();
    for (int f : vertex_faces_[size_t(v)])
      for (int k = 0; k < 3; ++k)
        if (faces_(f, k) != v) around.push_back(faces_(f, k));
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }

  Candidate candidate(int v0, int v1) const {
    return {placement(v0, v1).cost, v0, v1, stamp_[size_t(v0)], stamp_[size_t(v1)]};
  }

  Placement placement(int v0, int v1) const {
    const Quadric q = quadrics_[size_t(v0)] + quadrics_[size_t(v1)];
    const Eigen::Vector3d p0 = position(v0), p1 = position(v1), middle = 0.5 * (p0 + p1);
    Eigen::Vector3d best = middle;
    bool solved = false;
    if (const auto optimum = well_conditioned_minimum(q)) {
      best = *optimum;
      // An optimum far along a nearly flat patch is not trusted.
      solved = best.allFinite() && (best - middle).norm() <= (p1 - p0).norm();
    }
    if (!solved) {
      best = p0;
      for (const Eigen::Vector3d& p : {p1, middle})
        if (q.error(p) < q.error(best)) best = p;
    }
    return {best, q.error(best)};
  }

  void push_edges_of(int v) {
    if (locked_[size_t(v)]) return;
    neighbours(v, around_);
    for (int n : around_)
      if (!locked_[size_t(n)]) queue_.push(candidate(std::min(v, n), std::max(v, n)));
  }

  void push_all_edges() {
    for (Eigen::Index v = 0; v < positions_.rows(); ++v) {
      if (locked_[size_t(v)] || vertex_faces_[size_t(v)].empty()) continue;
      neighbours(int(v), around_);
      for (int n : around_)
        if (n > v && !locked_[size_t(n)]) queue_.push(candidate(int(v), n));
    }
  }

  bool is_current(const Candidate& c) const {
    return !vertex_faces_[size_t(c.v0)].empty() && !vertex_faces_[size_t(c.v1)].empty() &&
           stamp_[size_t(c.v0)] == c.stamp0 && stamp_[size_t(c.v1)] == c.stamp1;
  }

  bool contains(int f, int v) const { return faces_(f, 0) == v || faces_(f, 1) == v || faces_(f, 2) == v; }

  // The two faces on the edge, or false when the edge is not between exactly two faces.
  bool edge_faces(int v0, int v1, std::array<int, 2>& shared) const {
    int found = 0;
    for (int f : vertex_faces_[size_t(v0)])
      if (contains(f, v1)) {
        if (found == 2) return false;
        shared[size_t(found++)] = f;
      }
    return found == 2;
  }

  int opposite_vertex(int f, int v0, int v1) const {
    for (int k = 0; k < 3; ++k)
      if (faces_(f, k) != v0 && faces_(f, k) != v1) return faces_(f, k);
    return -1;
  }

  // Link condition: the ends' common neighbours are exactly the two vertices opposite the edge.
  bool keeps_topology(int v0, int v1, const std::array<int, 2>& shared) {
    const int a = opposite_vertex(shared[0], v0, v1), b = opposite_vertex(shared[1], v0, v1);
    if (a < 0 || b < 0 || a == b) return false;
    neighbours(v0, around_);
    neighbours(v1, around_other_);
    int common = 0;
    for (auto i = around_.begin(), j = around_other_.begin(); i != around_.end() && j != around_other_.end();) {
      if (*i < *j) {
        ++i;
      } else if (*j < *i) {
        ++j;
      } else {
        if (*i != a && *i != b) return false;
        ++common, ++i, ++j;
      }
    }
    return common == 2;
  }

  // No face that stays turns too far or becomes a needle.
  bool keeps_shape(int v0, int v1, const Eigen::Vector3d& p) const {
    for (int v : {v0, v1})
      for (int f : vertex_faces_[size_t(v)]) {
        if (contains(f, v0) && contains(f, v1)) continue;  // removed by the collapse
        Eigen::Vector3d before[3], after[3];
        for (int k = 0; k < 3; ++k) {
          before[k] = position(faces_(f, k));
          after[k] = faces_(f, k) == v ? p : before[k];
        }
        const Eigen::Vector3d n_before = (before[1] - before[0]).cross(before[2] - before[0]);
        const Eigen::Vector3d n_after = (after[1] - after[0]).cross(after[2] - after[0]);
        const double lengths = n_before.norm() * n_after.norm();
        if (lengths <= 0 || n_before.dot(n_after) < min_turn_cos_ * lengths) return false;
        const double quality = triangle_quality(after[0], after[1], after[2]);
        if (quality < options_.min_triangle_quality && quality < triangle_quality(before[0], before[1], before[2]))
          return false;
      }
    return true;
  }

  static void remove_face(std::vector<int>& list, int f) { list.erase(std::find(list.begin(), list.end(), f)); }

  bool try_collapse(const Candidate& c) {
    const int v0 = c.v0, v1 = c.v1;
    if (faces_left_ - 2 < 4) return false;  // a tetrahedron is as small as a closed surface gets
    std::array<int, 2> shared;
    if (!edge_faces(v0, v1, shared) || !keeps_topology(v0, v1, shared)) return false;
    const Eigen::Vector3d p = placement(v0, v1).position;
    if (!keeps_shape(v0, v1, p)) return false;
    for (int f : shared) {
      face_alive_[size_t(f)] = 0;
      for (int k = 0; k < 3; ++k)
        if (faces_(f, k) != v1) remove_face(vertex_faces_[size_t(faces_(f, k))], f);
    }
    for (int f : vertex_faces_[size_t(v1)]) {
      if (!face_alive_[size_t(f)]) continue;
      for (int k = 0; k < 3; ++k)
        if (faces_(f, k) == v1) faces_(f, k) = v0;
      vertex_faces_[size_t(v0)].push_back(f);
    }
    vertex_faces_[size_t(v1)].clear();
    positions_.row(v0) = p.transpose();
    quadrics_[size_t(v0)] = quadrics_[size_t(v0)] + quadrics_[size_t(v1)];
    ++stamp_[size_t(v0)];
    ++stamp_[size_t(v1)];
    faces_left_ -= 2;
    push_edges_of(v0);
    return true;
  }

  TriangleMesh compacted() const {
    std::vector<int> new_index(size_t(positions_.rows()), -1);
    TriangleMesh out;
    int vertices = 0;
    for (Eigen::Index v = 0; v < positions_.rows(); ++v)
      if (!vertex_faces_[size_t(v)].empty()) new_index[size_t(v)] = vertices++;
    out.vertices.resize(vertices, 3);
    for (Eigen::Index v = 0; v < positions_.rows(); ++v)
      if (new_index[size_t(v)] >= 0) out.vertices.row(new_index[size_t(v)]) = positions_.row(v);
    out.faces.resize(faces_left_, 3);
    Eigen::Index next = 0;
    for (Eigen::Index f = 0; f < faces_.rows(); ++f) {
      if (!face_alive_[size_t(f)]) continue;
      for (int k = 0; k < 3; ++k) out.faces(next, k) = new_index[size_t(faces_(f, k))];
      ++next;
    }
    return out;
  }

  QuadricDecimationOptions options_;
  VertexMatrix positions_;
  FaceMatrix faces_;
  std::vector<char> face_alive_;
  std::vector<std::vector<int>> vertex_faces_;  // empty once the vertex is merged away
  std::vector<Quadric> quadrics_;
  std::vector<uint32_t> stamp_;  // bumped when a vertex moves: its queued collapses are stale
  std::vector<char> locked_;
  int64_t faces_left_;
  int64_t collapses_ = 0;
  double min_turn_cos_;
  CandidateBuckets queue_;
  std::vector<int> around_, around_other_;  // neighbours' buffers
};

}  // namespace

QuadricDecimationResult decimate_quadric(const TriangleMesh& mesh, const QuadricDecimationOptions& options) {
  if (mesh.face_count() <= options.target_triangles) return {mesh, 0, true};
  return Decimator(mesh, options).run();
}

}  // namespace maxillo
