#include "occlusion/splint_field.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "core/error.h"

namespace maxillo::occlusion {
namespace {

Eigen::Vector3d vertex(const TriangleMesh& mesh, Eigen::Index v) { return mesh.vertices.row(v).transpose(); }

// d[q] = min_p (q - p)^2 + f[p] over one row (the lower envelope of parabolas).
void squared_distance_1d(const std::vector<double>& f, std::vector<double>& d) {
  const int n = int(f.size());
  std::vector<int> apex(static_cast<size_t>(n), 0);
  std::vector<double> boundary(static_cast<size_t>(n) + 1, 0);
  int k = 0;
  boundary[0] = -std::numeric_limits<double>::infinity();
  boundary[1] = std::numeric_limits<double>::infinity();
  const auto intersection = [&](int q, int p) {
    return ((f[size_t(q)] + double(q) * q) - (f[size_t(p)] + double(p) * p)) / (2.0 * q - 2.0 * p);
  };
  for (int q = 1; q < n; ++q) {
    double s = intersection(q, apex[size_t(k)]);
    while (k > 0 && s <= boundary[size_t(k)]) s = intersection(q, apex[size_t(--k)]);
    if (k == 0 && s <= boundary[0]) s = boundary[0];
    apex[size_t(++k)] = q;
    boundary[size_t(k)] = s;
    boundary[size_t(k) + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (boundary[size_t(k) + 1] < q) ++k;
    const double dq = q - apex[size_t(k)];
    d[size_t(q)] = dq * dq + f[size_t(apex[size_t(k)])];
  }
}

// Signed distances of one arch at the grid's voxels: exact within `radius` of the surface; the
// sign of farther voxels is carried over from their neighbours (two voxels a grid step apart,
// both farther than radius > step from the surface, cannot lie on its two sides), and voxels
// with no measured neighbour in reach are outside. Voxels with skip[n] are left at +radius.
std::vector<float> arch_distances(const DistanceField& arch, const Eigen::Isometry3d& grid_to_arch,
                                  const VolumeGeometry& g, const std::vector<char>& skip, double radius) {
  const int64_t count = g.voxel_count();
  std::vector<float> distance(static_cast<size_t>(count), static_cast<float>(radius));
  std::vector<signed char> sign(static_cast<size_t>(count), 0);  // 0: not yet known
  std::deque<int64_t> known;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const int64_t n = g.index(i, j, k);
        if (skip[size_t(n)]) continue;
        const SignedDistance d = arch.signed_distance(grid_to_arch * g.world(Eigen::Vector3d(i, j, k)), radius);
        if (!d.found) continue;
        distance[size_t(n)] = float(d.distance);
        sign[size_t(n)] = d.distance < 0 ? -1 : 1;
        known.push_back(n);
      }
  const int64_t steps[3] = {1, g.size.x(), int64_t(g.size.x()) * g.size.y()};
  while (!known.empty()) {
    const int64_t n = known.front();
    known.pop_front();
    const int64_t ijk[3] = {n % steps[1], (n / steps[1]) % g.size.y(), n / steps[2]};
    for (int axis = 0; axis < 3; ++axis)
      for (int side : {-1, 1}) {
        const int64_t c = ijk[axis] + side;
        if (c < 0 || c >= g.size[axis]) continue;
        const int64_t m = n + side * steps[axis];
        if (skip[size_t(m)] || sign[size_t(m)] != 0) continue;
        sign[size_t(m)] = sign[size_t(n)];
        distance[size_t(m)] = float(sign[size_t(n)] * radius);
        known.push_back(m);
      }
  }
  return distance;
}

}  // namespace

std::vector<double> distance_to_marked(const std::vector<char>& marked, int width, int height) {
  constexpr double kFar = 1e20;  // finite "infinity" keeps the parabola intersections defined
  std::vector<double> squared(marked.size());
  for (size_t n = 0; n < marked.size(); ++n) squared[n] = marked[n] ? 0.0 : kFar;
  std::vector<double> row(static_cast<size_t>(width)), row_out(row.size());
  std::vector<double> column(static_cast<size_t>(height)), column_out(column.size());
  for (int y = 0; y < height; ++y) {
    std::copy_n(&squared[size_t(y) * size_t(width)], width, row.begin());
    squared_distance_1d(row, row_out);
    std::copy_n(row_out.begin(), width, &squared[size_t(y) * size_t(width)]);
  }
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) column[size_t(y)] = squared[size_t(y) * size_t(width) + size_t(x)];
    squared_distance_1d(column, column_out);
    for (int y = 0; y < height; ++y) squared[size_t(y) * size_t(width) + size_t(x)] = column_out[size_t(y)];
  }
  std::vector<double> distance(squared.size());
  for (size_t n = 0; n < squared.size(); ++n)
    distance[n] = squared[n] >= kFar / 2 ? std::numeric_limits<double>::infinity() : std::sqrt(squared[n]);
  return distance;
}

OcclusalPlane fit_occlusal_plane(const DistanceField& upper, const DistanceField& lower,
                                 const Eigen::Isometry3d& upper_pose, double region_mm) {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d upper_centroid = Eigen::Vector3d::Zero();
  for (Eigen::Index v = 0; v < upper.mesh().vertex_count(); ++v) {
    const Eigen::Vector3d x = upper_pose * vertex(upper.mesh(), v);
    upper_centroid += x;
    if (lower.signed_distance(x, region_mm).found) points.push_back(x);
  }
  upper_centroid /= double(std::max<Eigen::Index>(1, upper.mesh().vertex_count()));
  const Eigen::Isometry3d lower_to_upper = upper_pose.inverse();
  for (Eigen::Index v = 0; v < lower.mesh().vertex_count(); ++v)
    if (upper.signed_distance(lower_to_upper * vertex(lower.mesh(), v), region_mm).found)
      points.push_back(vertex(lower.mesh(), v));
  if (points.size() < 3)
    throw Error(ErrorCode::kProcessing, "occlusal plane",
                "fewer than 3 vertices of the arches lie within " + std::to_string(region_mm) +
                    " mm of each other: the arches are not in occlusion");
  OcclusalPlane plane;
  for (const auto& p : points) plane.centre += p;
  plane.centre /= double(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - plane.centre) * (p - plane.centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(scatter);  // eigenvalues ascending
  plane.normal = axes.eigenvectors().col(0).normalized();
  if (plane.normal.dot(upper_centroid - plane.centre) < 0) plane.normal = -plane.normal;
  plane.u = axes.eigenvectors().col(2).normalized();  // along the arch's widest spread
  plane.u = (plane.u - plane.u.dot(plane.normal) * plane.normal).normalized();
  plane.v = plane.normal.cross(plane.u);  // (u, v, normal) right-handed
  return plane;
}

SplintField splint_field(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& upper_pose,
                         const SplintOptions& options) {
  SplintField out;
  out.plane = fit_occlusal_plane(upper, lower, upper_pose, options.plane_region_mm);
  const OcclusalPlane& plane = out.plane;
  const double h = options.voxel_mm, half = options.thickness_mm / 2 + options.imprint_depth_mm;
  out.slab_half_thickness_mm = half;

  // The teeth's outline in the plane: every vertex of either arch within the slab, projected.
  std::vector<Eigen::Vector2d> outline;
  const auto collect = [&](const TriangleMesh& mesh, const Eigen::Isometry3d& to_lower) {
    for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
      const Eigen::Vector3d x = to_lower * vertex(mesh, v) - plane.centre;
      if (std::abs(x.dot(plane.normal)) <= half + options.clearance_mm)
        outline.emplace_back(x.dot(plane.u), x.dot(plane.v));
    }
  };
  collect(upper.mesh(), upper_pose);
  collect(lower.mesh(), Eigen::Isometry3d::Identity());
  if (outline.empty()) throw Error(ErrorCode::kProcessing, "splint", "no tooth crosses the occlusal plane");
  Eigen::Vector2d lo = outline.front(), hi = outline.front();
  for (const auto& p : outline) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double pad = options.margin_mm + 2 * h;
  lo -= Eigen::Vector2d::Constant(pad), hi += Eigen::Vector2d::Constant(pad);

  VolumeGeometry& g = out.field.geometry;
  g.size = Eigen::Vector3i(int(std::ceil((hi.x() - lo.x()) / h)) + 1, int(std::ceil((hi.y() - lo.y()) / h)) + 1,
                           int(std::ceil((2 * half + 4 * h) / h)) + 1);
  g.spacing = Eigen::Vector3d::Constant(h);
  g.direction.col(0) = plane.u, g.direction.col(1) = plane.v, g.direction.col(2) = plane.normal;
  g.origin = plane.centre + lo.x() * plane.u + lo.y() * plane.v - (half + 2 * h) * plane.normal;

  // Band: margin minus the in-plane distance to the outline (positive inside).
  const int width = g.size.x(), height = g.size.y();
  std::vector<char> marked(size_t(width) * size_t(height), 0);
  for (const auto& p : outline) {
    const int i = int(std::lround((p.x() - lo.x()) / h)), j = int(std::lround((p.y() - lo.y()) / h));
    marked[size_t(j) * size_t(width) + size_t(i)] = 1;
  }
  const std::vector<double> outline_distance = distance_to_marked(marked, width, height);
  const auto band = [&](int i, int j) {
    return options.margin_mm - h * outline_distance[size_t(j) * size_t(width) + size_t(i)];
  };
  const auto slab = [&](int k) { return half - std::abs(-(half + 2 * h) + k * h); };

  // Arch distances only where the band and slab leave the voxel within two voxels of the splint.
  std::vector<char> skip(size_t(g.voxel_count()));
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) skip[size_t(g.index(i, j, k))] = std::min(band(i, j), slab(k)) < -2 * h;
  const double radius = std::max(2.0, 4 * h) + options.clearance_mm;
  const std::vector<float> to_upper = arch_distances(upper, upper_pose.inverse(), g, skip, radius);
  const std::vector<float> to_lower = arch_distances(lower, Eigen::Isometry3d::Identity(), g, skip, radius);

  out.field.hu.resize(size_t(g.voxel_count()));
  std::vector<char> column_touches(size_t(width) * size_t(height), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const size_t n = size_t(g.index(i, j, k));
        const double nearest_arch = std::min(to_upper[n], to_lower[n]);
        const double value = std::min({band(i, j), slab(k), nearest_arch - options.clearance_mm});
        out.field.hu[n] = int16_t(std::clamp(std::lround(value * 1000), -32000L, 32000L));
        if (slab(k) >= 0 && nearest_arch <= options.clearance_mm + h)
          column_touches[size_t(j) * size_t(width) + size_t(i)] = 1;
      }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      if (band(i, j) > h && !column_touches[size_t(j) * size_t(width) + size_t(i)])
        out.tooth_free_columns.push_back(i + width * j);
  return out;
}

}  // namespace maxillo::occlusion
