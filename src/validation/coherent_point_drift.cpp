#include "validation/coherent_point_drift.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <tuple>
#include <unordered_map>

#include "core/error.h"
#include "core/parallel_slabs.h"
#include "geometry/aabb_tree.h"
#include "geometry/signed_distance.h"

namespace maxillo::validation {
namespace {

using Matrix = Eigen::MatrixXd;
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3>;

constexpr double kControlSpacingInBeta = 0.75;
// Mixture weights below exp(-kNegligibleExponent) are taken as zero (they would not change a sum).
constexpr double kNegligibleExponent = 40.0;
constexpr double kSmallestSigma2 = 1e-10;  // mm^2: a perfect fit stops shrinking here
// The mixture's sigma never falls below this fraction of the moving points' mean spacing. With a
// narrower mixture each centre would be pulled sideways towards the fixed points nearest to it, and
// since CPD's regularisation weakens with sigma^2 the field would follow: a sliding of the surface
// of the order of the spacing (measured: 0.76 mm mean on a sphere registered to itself with random
// subsets and no floor; 0.08 mm with even subsets and this floor).
constexpr double kSigmaFloorInSpacing = 0.5;

void check(const VertexMatrix& fixed, const VertexMatrix& moving, const CpdOptions& o) {
  if (fixed.rows() == 0 || moving.rows() == 0)
    throw Error(ErrorCode::kBadValue, "coherent point drift", "a point set is empty");
  if (!(o.beta_mm > 0) || !(o.lambda > 0) || !(o.outlier_weight >= 0 && o.outlier_weight < 1) || o.max_points < 1)
    throw Error(ErrorCode::kBadValue, "coherent point drift options",
                "need beta > 0, lambda > 0, 0 <= outlier weight < 1 and at least one point");
}

// The points accepted in a random order when each must lie at least `radius` from those accepted
// before it (Poisson-disk sampling, with a hash grid of cells `radius` wide).
std::vector<Eigen::Index> spaced_points(const VertexMatrix& points, const std::vector<Eigen::Index>& order,
                                        double radius) {
  std::unordered_map<uint64_t, std::vector<Eigen::Index>> grid;
  const auto cell = [radius](double v) { return long(std::floor(v / radius)); };
  const auto key = [](long x, long y, long z) {  // 21 bits per axis: ample for any mesh in mm
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  };
  std::vector<Eigen::Index> accepted;
  for (Eigen::Index i : order) {
    const long cx = cell(points(i, 0)), cy = cell(points(i, 1)), cz = cell(points(i, 2));
    bool free = true;
    for (long dx = -1; dx <= 1 && free; ++dx)
      for (long dy = -1; dy <= 1 && free; ++dy)
        for (long dz = -1; dz <= 1 && free; ++dz) {
          const auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (Eigen::Index j : it->second)
            if ((points.row(i) - points.row(j)).squaredNorm() < radius * radius) {
              free = false;
              break;
            }
        }
    if (!free) continue;
    grid[key(cx, cy, cz)].push_back(i);
    accepted.push_back(i);
  }
  return accepted;
}

// Up to `count` rows of `points`, evenly spread (Poisson-disk, the radius found by bisection so the
// count is as close to `count` as the bisection gets without exceeding it), in increasing order.
// Even spacing matters: a mixture centred on randomly clumped points pulls each one sideways
// towards the middle of its share of the other set (Lloyd's relaxation), which would read as a
// sliding of the surface.
std::vector<Eigen::Index> even_subset(const VertexMatrix& points, int count, uint32_t seed) {
  std::vector<Eigen::Index> order(static_cast<size_t>(points.rows()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  if (points.rows() <= count) return order;
  std::mt19937 random(seed);
  std::shuffle(order.begin(), order.end(), random);
  const double diagonal = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  double too_small = 0, large_enough = diagonal + 1;  // radius bounds: too many points / at most count
  std::vector<Eigen::Index> best = spaced_points(points, order, large_enough);
  for (int step = 0; step < 30 && large_enough - too_small > 1e-3 * large_enough; ++step) {
    const double radius = (too_small + large_enough) / 2;
    auto accepted = spaced_points(points, order, radius);
    if (Eigen::Index(accepted.size()) > count) {
      too_small = radius;
    } else {
      large_enough = radius;
      best = std::move(accepted);
    }
  }
  std::sort(best.begin(), best.end());
  return best;
}

Points rows_of(const VertexMatrix& all, const std::vector<Eigen::Index>& chosen) {
  Points points(Eigen::Index(chosen.size()), 3);
  for (size_t i = 0; i < chosen.size(); ++i) points.row(Eigen::Index(i)) = all.row(chosen[i]);
  return points;
}

// The first point in each cube of side `spacing` (in input order): an even spread of control points.
Points grid_subsample(const Points& points, double spacing) {
  std::map<std::tuple<long, long, long>, Eigen::Index> first_in_cell;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const auto cell =
        std::make_tuple(long(std::floor(points(i, 0) / spacing)), long(std::floor(points(i, 1) / spacing)),
                        long(std::floor(points(i, 2) / spacing)));
    if (first_in_cell.emplace(cell, i).second) kept.push_back(i);
  }
  Points controls(Eigen::Index(kept.size()), 3);
  for (size_t k = 0; k < kept.size(); ++k) controls.row(Eigen::Index(k)) = points.row(kept[k]);
  return controls;
}

// G(a_i, b_j) = exp(-|a_i - b_j|^2 / (2 beta^2)).
template <typename A, typename B>
Matrix gaussian_kernel(const A& a, const B& b, double beta) {
  Matrix g(a.rows(), b.rows());
  const double scale = -1.0 / (2 * beta * beta);
  for (Eigen::Index j = 0; j < b.rows(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) g(i, j) = std::exp(scale * (a.row(i) - b.row(j)).squaredNorm());
  return g;
}

// The E-step's sums over the posterior P (M x N: P(m, n) = probability that fixed point n came
// from mixture centre m), never stored whole.
struct Posterior {
  Eigen::VectorXd p1;   // P 1, per centre
  Eigen::VectorXd pt1;  // P^T 1, per fixed point
  Points px;            // P X
  double negative_log_likelihood = 0;
};

// The fixed points (E-step) and the moving points (M-step) are summed in this many fixed parts,
// each into its own partial sums, added in part order (core/parallel_slabs.h): the answer does not
// depend on the number of threads or on which finishes first.
constexpr int kParts = 8;

// The posterior's sums over the fixed points of `range`.
Posterior expectation_over(const Points& x, const PartRange& range, const Points& centres, double sigma2,
                           double outlier) {
  const Eigen::Index begin = range.begin, end = range.end;
  const Eigen::Index m = centres.rows();
  Posterior post{Eigen::VectorXd::Zero(m), Eigen::VectorXd::Zero(end - begin), Points::Zero(m, 3), 0};
  std::vector<std::pair<Eigen::Index, double>> near;  // centres of one fixed point with weight > 0
  near.reserve(size_t(m));
  const double scale = 1.0 / (2 * sigma2);
  for (Eigen::Index n = begin; n < end; ++n) {
    near.clear();
    double denominator = outlier;
    const double x0 = x(n, 0), x1 = x(n, 1), x2 = x(n, 2);
    for (Eigen::Index i = 0; i < m; ++i) {
      const double d0 = x0 - centres(i, 0), d1 = x1 - centres(i, 1), d2 = x2 - centres(i, 2);
      const double exponent = scale * (d0 * d0 + d1 * d1 + d2 * d2);
      if (exponent > kNegligibleExponent) continue;
      const double weight = std::exp(-exponent);
      near.emplace_back(i, weight);
      denominator += weight;
    }
    // When every centre is negligibly far and w = 0 the point carries no information.
    if (!(denominator > 0)) continue;
    double total = 0;
    for (const auto& [i, weight] : near) {
      const double p = weight / denominator;
      post.p1(i) += p;
      post.px.row(i) += p * x.row(n);
      total += p;
    }
    post.pt1(n - begin) = total;
    post.negative_log_likelihood -= std::log(denominator);
  }
  return post;
}

Posterior expectation(const Points& x, const Points& centres, double sigma2, double outlier_weight) {
  const Eigen::Index n_fixed = x.rows(), m = centres.rows();
  // The uniform outlier component's share of each denominator.
  const double outlier =
      std::pow(2 * M_PI * sigma2, 1.5) * outlier_weight / (1 - outlier_weight) * double(m) / double(n_fixed);
  std::vector<Posterior> parts(kParts);
  for_each_part(kParts, [&](int part) {
    parts[size_t(part)] = expectation_over(x, part_range(n_fixed, part, kParts), centres, sigma2, outlier);
  });
  Posterior post{Eigen::VectorXd::Zero(m), Eigen::VectorXd::Zero(n_fixed), Points::Zero(m, 3), 0};
  for (int p = 0; p < kParts; ++p) {
    const Posterior& part = parts[size_t(p)];
    post.p1 += part.p1;
    post.px += part.px;
    post.pt1.segment(part_range(n_fixed, p, kParts).begin, part.pt1.size()) = part.pt1;
    post.negative_log_likelihood += part.negative_log_likelihood;
  }
  post.negative_log_likelihood += 1.5 * double(n_fixed) * std::log(sigma2);
  return post;
}

// The M-step for the field's weights W (K x 3): minimises
//   1/(2 sigma2) sum_mn P(m, n) |x_n - y_m - (G_yc W)_m|^2 + lambda/2 tr(W^T G_cc W),
// i.e. solves (G_yc^T d(P1) G_yc + lambda sigma2 G_cc) W = G_yc^T (P X - d(P1) Y).
Points field_weights(const Matrix& g_yc, const Matrix& g_cc, const Points& y, const Posterior& post, double lambda,
                     double sigma2) {
  const Matrix weighted = g_yc.array().colwise() * post.p1.array().sqrt();
  // G_yc^T d(P1) G_yc, the M-step's largest cost (moving points x controls^2), by parts of the moving points.
  std::vector<Matrix> parts(kParts);
  for_each_part(kParts, [&](int part) {
    const PartRange rows = part_range(weighted.rows(), part, kParts);
    parts[size_t(part)] = Matrix::Zero(g_cc.rows(), g_cc.cols());
    parts[size_t(part)].selfadjointView<Eigen::Lower>().rankUpdate(
        weighted.middleRows(rows.begin, rows.end - rows.begin).transpose());
  });
  Matrix system = lambda * sigma2 * g_cc;
  for (const Matrix& part : parts) system.triangularView<Eigen::Lower>() += part;
  system.diagonal().array() += 1e-12 * (system.diagonal().sum() + 1.0);  // G_cc is only semi-definite numerically
  const Matrix rhs = g_yc.transpose() * (post.px - post.p1.asDiagonal() * y);
  return system.selfadjointView<Eigen::Lower>().ldlt().solve(rhs);
}

double updated_sigma2(const Points& x, const Points& moved, const Posterior& post) {
  const double np = post.p1.sum();
  if (!(np > 0)) return kSmallestSigma2;
  const double xx = (post.pt1.array() * x.rowwise().squaredNorm().array()).sum();
  const double xt = (post.px.array() * moved.array()).sum();
  const double tt = (post.p1.array() * moved.rowwise().squaredNorm().array()).sum();
  return std::max((xx - 2 * xt + tt) / (3 * np), kSmallestSigma2);
}

// Mean distance from each point to its nearest neighbour in the set.
double mean_spacing(const Points& x) {
  if (x.rows() < 2) return 0;
  double sum = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    double nearest = std::numeric_limits<double>::max();
    for (Eigen::Index j = 0; j < x.rows(); ++j)
      if (j != i) nearest = std::min(nearest, (x.row(i) - x.row(j)).squaredNorm());
    sum += std::sqrt(nearest);
  }
  return sum / double(x.rows());
}

double initial_sigma2(const Points& x, const Points& y) {
  const double m = double(y.rows()), n = double(x.rows());
  const double sum = m * x.squaredNorm() + n * y.squaredNorm() - 2 * x.colwise().sum().dot(y.colwise().sum());
  return std::max(sum / (3 * m * n), kSmallestSigma2);
}

}  // namespace

CpdResult nonrigid_cpd(const VertexMatrix& fixed, const VertexMatrix& moving, const CpdOptions& options) {
  check(fixed, moving, options);
  const Points x = rows_of(fixed, even_subset(fixed, options.max_points, options.seed));
  const Points y = rows_of(moving, even_subset(moving, options.max_points, options.seed + 1));
  const Points controls = grid_subsample(y, kControlSpacingInBeta * options.beta_mm);
  const Matrix g_yc = gaussian_kernel(y, controls, options.beta_mm);
  const Matrix g_cc = gaussian_kernel(controls, controls, options.beta_mm);

  CpdResult result;
  Points weights = Points::Zero(controls.rows(), 3);
  Points centres = y;
  double sigma2 = initial_sigma2(x, y);
  const double sigma2_floor = std::max(std::pow(kSigmaFloorInSpacing * mean_spacing(y), 2), kSmallestSigma2);
  double previous = 0;
  for (result.iterations = 0; result.iterations < options.max_iterations;) {
    const Posterior post = expectation(x, centres, sigma2, options.outlier_weight);
    const double objective =
        post.negative_log_likelihood + options.lambda / 2 * (weights.transpose() * g_cc * weights).trace();
    if (result.iterations > 0 && std::abs(objective - previous) <= options.tolerance * std::abs(objective)) break;
    previous = objective;

    weights = field_weights(g_yc, g_cc, y, post, options.lambda, sigma2);
    centres = y + g_yc * weights;
    sigma2 = std::max(updated_sigma2(x, centres, post), sigma2_floor);
    ++result.iterations;
  }
  result.sigma2 = sigma2;
  result.moved = moving + gaussian_kernel(moving, controls, options.beta_mm) * weights;
  return result;
}

namespace {

// The faces of `mesh` whose three vertices are included (all faces when `include` is empty).
TriangleMesh included_faces(const TriangleMesh& mesh, const std::vector<bool>& include) {
  if (include.empty()) return mesh;
  TriangleMesh part;
  part.vertices = mesh.vertices;
  part.faces.resize(mesh.face_count(), 3);
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < mesh.face_count(); ++f)
    if (include[size_t(mesh.faces(f, 0))] && include[size_t(mesh.faces(f, 1))] && include[size_t(mesh.faces(f, 2))])
      part.faces.row(kept++) = mesh.faces.row(f);
  part.faces.conservativeResize(kept, 3);
  return part;
}

// The vertices of `actual` within `reach` mm of `region` (all of them when the region has no faces).
VertexMatrix vertices_near(const TriangleMesh& actual, const TriangleMesh& region, double reach) {
  if (region.face_count() == 0) return actual.vertices;
  const AabbTree tree(region);
  std::vector<Eigen::Index> kept;
  for (Eigen::Index v = 0; v < actual.vertex_count(); ++v)
    if (tree.nearest(actual.vertices.row(v).transpose(), reach).face >= 0) kept.push_back(v);
  VertexMatrix near(Eigen::Index(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) near.row(Eigen::Index(i)) = actual.vertices.row(kept[i]);
  return near;
}

}  // namespace

std::vector<double> corresponding_point_distances(const TriangleMesh& predicted, const TriangleMesh& actual,
                                                  const std::vector<bool>& include, const CpdOptions& options) {
  if (!include.empty() && Eigen::Index(include.size()) != predicted.vertex_count())
    throw Error(ErrorCode::kBadValue, "corresponding point distances", "include has one flag per predicted vertex");
  if (actual.face_count() == 0)
    throw Error(ErrorCode::kBadValue, "corresponding point distances", "actual surface is empty");

  std::vector<Eigen::Index> chosen;
  for (Eigen::Index v = 0; v < predicted.vertex_count(); ++v)
    if (include.empty() || include[size_t(v)]) chosen.push_back(v);
  if (chosen.empty()) return {};
  VertexMatrix moving(Eigen::Index(chosen.size()), 3);
  for (size_t i = 0; i < chosen.size(); ++i) moving.row(Eigen::Index(i)) = predicted.vertices.row(chosen[i]);

  const VertexMatrix fixed =
      vertices_near(actual, included_faces(predicted, include), std::max(20.0, 2 * options.beta_mm));
  if (fixed.rows() == 0)
    throw Error(ErrorCode::kEmptyResult, "corresponding point distances",
                "no actual surface near the predicted region");
  const CpdResult registration = nonrigid_cpd(fixed, moving, options);

  // Each correspondence projected onto the actual surface; the sign from its outward normal there.
  const DistanceField field(actual);
  std::vector<double> distances;
  distances.reserve(chosen.size());
  for (Eigen::Index i = 0; i < moving.rows(); ++i) {
    const Eigen::Vector3d p = moving.row(i).transpose();
    const auto on_actual = field.signed_distance(registration.moved.row(i).transpose(), 1e9);
    const Eigen::Vector3d offset = p - on_actual.point;
    distances.push_back(offset.dot(on_actual.normal) < 0 ? -offset.norm() : offset.norm());
  }
  return distances;
}

}  // namespace maxillo::validation
