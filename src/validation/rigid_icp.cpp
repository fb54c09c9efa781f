#include "validation/rigid_icp.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/parallel_slabs.h"
#include "geometry/vertex_normals.h"
#include "geometry/aabb_tree.h"

namespace maxillo::validation {
namespace {

// Pairs whose normals differ by more than this are not the same piece of surface.
const double kMinNormalCosine = std::cos(60.0 * M_PI / 180.0);

Eigen::Vector3d row(const VertexMatrix& v, int i) { return v.row(i).transpose(); }

// The target's open border: edges used by one face, and their vertices. A closest point there is
// where the target simply ends, not a counterpart of the moving point. Kept per face (a bit per
// edge) and per vertex, so a pair is checked without a lookup.
class Border {
 public:
  explicit Border(const TriangleMesh& mesh)
      : open_edges_(size_t(mesh.face_count()), 0), vertex_(size_t(mesh.vertex_count()), 0) {
    // Every edge once per face using it, by its ends; equal neighbours after sorting are the same edge.
    struct Use {
      int low, high, face, edge;
      auto operator<=>(const Use&) const = default;
    };
    std::vector<Use> uses;
    uses.reserve(size_t(mesh.face_count()) * 3);
    for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.faces(f, k), b = mesh.faces(f, (k + 1) % 3);
        uses.push_back({std::min(a, b), std::max(a, b), int(f), k});
      }
    std::sort(uses.begin(), uses.end());
    for (size_t i = 0; i < uses.size();) {
      size_t j = i;
      while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
      if (j - i == 1) {
        open_edges_[size_t(uses[i].face)] |= char(1 << uses[i].edge);
        vertex_[size_t(uses[i].low)] = vertex_[size_t(uses[i].high)] = 1;
      }
      i = j;
    }
  }

  bool contains(const TriangleMesh& mesh, int face, TriangleFeature feature) const {
    const auto f = mesh.faces.row(face);
    const char open = open_edges_[size_t(face)];
    switch (feature) {
      case TriangleFeature::Face: return false;
      case TriangleFeature::EdgeAB: return open & 1;
      case TriangleFeature::EdgeBC: return open & 2;
      case TriangleFeature::EdgeCA: return open & 4;
      case TriangleFeature::VertexA: return vertex_[size_t(f(0))] != 0;
      case TriangleFeature::VertexB: return vertex_[size_t(f(1))] != 0;
      case TriangleFeature::VertexC: return vertex_[size_t(f(2))] != 0;
    }
    return false;
  }

 private:
  std::vector<char> open_edges_;  // per face: bit k set when edge k (k to k+1) has no other face
  std::vector<char> vertex_;      // on an open edge
};

// Up to `count` vertex indices, a deterministic random subset in increasing order.
std::vector<int> sample_vertices(Eigen::Index vertex_count, int count, uint32_t seed) {
  std::vector<int> all(static_cast<size_t>(vertex_count));
  std::iota(all.begin(), all.end(), 0);
  if (count > 0 && vertex_count > count) {
    std::mt19937 random(seed);
    std::shuffle(all.begin(), all.end(), random);
    all.resize(size_t(count));
    std::sort(all.begin(), all.end());
  }
  return all;
}

struct Pair {
  Eigen::Vector3d p;       // moving sample, placed by the current transform
  Eigen::Vector3d q;       // its closest point on the target
  Eigen::Vector3d normal;  // the target face's unit normal at q
};

}  // namespace

struct IcpTarget::Parts {
  explicit Parts(const TriangleMesh& mesh) : target(mesh), tree(mesh), border(mesh) {
    face_normals.reserve(size_t(mesh.face_count()));
    for (Eigen::Index f = 0; f < mesh.face_count(); ++f) {
      const auto t = tree.triangle(int(f));
      const Eigen::Vector3d n = (t.b - t.a).cross(t.c - t.a);
      face_normals.push_back(n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
    }
  }
  const TriangleMesh& target;
  AabbTree tree;
  Border border;
  std::vector<Eigen::Vector3d> face_normals;
};

IcpTarget::IcpTarget(const TriangleMesh& target) : parts_(std::make_unique<Parts>(target)) {}
IcpTarget::~IcpTarget() = default;

namespace {

class Matcher {
 public:
  Matcher(const TriangleMesh& moving, const IcpTarget::Parts& target, const IcpOptions& options)
      : moving_(moving),
        target_(target),
        options_(options),
        moving_normals_(vertex_normals(moving)),
        samples_(sample_vertices(moving.vertex_count(), options.max_samples, options.seed)) {}

  // The samples' pairs in the samples' order. The closest-point queries, most of ICP's time, run
  // in fixed parts of the samples, each into its own list; the lists are joined in order, so the
  // pairs do not depend on the threads.
  std::vector<Pair> pairs(const Eigen::Isometry3d& transform) const {
    constexpr int kParts = 16;
    std::vector<std::vector<Pair>> found(kParts);
    for_each_part(kParts, [&](int part) {
      const PartRange range = part_range(int64_t(samples_.size()), part, kParts);
      for (int64_t s = range.begin; s < range.end; ++s)
        if (auto pair = pair_of(samples_[size_t(s)], transform)) found[size_t(part)].push_back(*pair);
    });
    std::vector<Pair> joined;
    joined.reserve(samples_.size());
    for (const auto& part : found) joined.insert(joined.end(), part.begin(), part.end());
    return joined;
  }

 private:
  std::optional<Pair> pair_of(int i, const Eigen::Isometry3d& transform) const {
    const Eigen::Vector3d p = transform * row(moving_.vertices, i);
    const auto nearest = target_.tree.nearest(p, options_.max_pair_distance_mm);
    if (nearest.face < 0 || target_.border.contains(target_.target, nearest.face, nearest.feature)) return std::nullopt;
    const Eigen::Vector3d& n = target_.face_normals[size_t(nearest.face)];
    if ((transform.linear() * moving_normals_.row(i).transpose()).dot(n) < kMinNormalCosine) return std::nullopt;
    return Pair{p, nearest.point, n};
  }

  const TriangleMesh& moving_;
  const IcpTarget::Parts& target_;
  const IcpOptions& options_;
  VertexMatrix moving_normals_;  // unit, area-weighted (geometry/vertex_normals.h)
  std::vector<int> samples_;
};

// One point-to-plane step: the small rotation w (about the pairs' centroid c) and translation t
// minimising sum(((p + w x (p - c) + t - q) . n)^2), returned as an exact rigid increment. Also the
// largest distance the increment moves any paired point (for the stop criterion).
std::pair<Eigen::Isometry3d, double> point_to_plane_step(const std::vector<Pair>& pairs) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& pair : pairs) centroid += pair.p;
  centroid /= double(pairs.size());

  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  double radius = 0;
  for (const auto& pair : pairs) {
    const Eigen::Vector3d arm = pair.p - centroid;
    radius = std::max(radius, arm.norm());
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << arm.cross(pair.normal), pair.normal;  // d(residual)/d(w, t)
    const double residual = (pair.p - pair.q).dot(pair.normal);
    normal_matrix.selfadjointView<Eigen::Lower>().rankUpdate(jacobian);
    rhs -= jacobian * residual;
  }
  // A whisper of damping keeps a rotationally symmetric pair set (a sphere, a cylinder) solvable;
  // the free directions then simply do not move.
  normal_matrix.diagonal().array() += 1e-12 * (normal_matrix.trace() + 1.0);
  const Eigen::Matrix<double, 6, 1> x = normal_matrix.selfadjointView<Eigen::Lower>().ldlt().solve(rhs);
  const Eigen::Vector3d w = x.head<3>(), t = x.tail<3>();

  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  if (w.norm() > 0) step.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  step.translation() = centroid + t - step.linear() * centroid;  // rotate about the centroid
  return {step, t.norm() + w.norm() * radius};
}

double rms_distance(const std::vector<Pair>& pairs) {
  double sum = 0;
  for (const auto& pair : pairs) sum += (pair.p - pair.q).squaredNorm();
  return pairs.empty() ? 0.0 : std::sqrt(sum / double(pairs.size()));
}

}  // namespace

IcpResult rigid_icp(const TriangleMesh& moving, const TriangleMesh& target, const Eigen::Isometry3d& initial,
                    const IcpOptions& options) {
  if (target.vertex_count() == 0 || target.face_count() == 0)
    throw Error(ErrorCode::kBadValue, "ICP target surface", "the mesh is empty");
  return rigid_icp(moving, IcpTarget(target), initial, options);
}

IcpResult rigid_icp(const TriangleMesh& moving, const IcpTarget& target, const Eigen::Isometry3d& initial,
                    const IcpOptions& options) {
  if (moving.vertex_count() == 0 || moving.face_count() == 0)
    throw Error(ErrorCode::kBadValue, "ICP moving surface", "the mesh is empty");
  if (target.parts().target.vertex_count() == 0 || target.parts().target.face_count() == 0)
    throw Error(ErrorCode::kBadValue, "ICP target surface", "the mesh is empty");

  const Matcher matcher(moving, target.parts(), options);
  IcpResult result;
  result.transform = initial;
  std::vector<Pair> pairs;
  for (result.iterations = 0; result.iterations < options.max_iterations;) {
    pairs = matcher.pairs(result.transform);
    if (pairs.size() < 6)
      throw Error(ErrorCode::kProcessing, "ICP",
                  "only " + std::to_string(pairs.size()) + " surface pairs within " +
                      std::to_string(options.max_pair_distance_mm) + " mm: the start is too far from the target");
    const auto [step, largest_motion] = point_to_plane_step(pairs);
    result.transform = step * result.transform;
    ++result.iterations;
    if (largest_motion < options.tolerance_mm) break;
  }
  pairs = matcher.pairs(result.transform);
  result.pairs = int(pairs.size());
  result.rms_mm = rms_distance(pairs);
  return result;
}

}  // namespace maxillo::validation
