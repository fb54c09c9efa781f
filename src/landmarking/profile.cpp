#include "landmarking/profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace maxillo::landmarking {
namespace {

template <typename Inside>
std::optional<Eigen::Vector3d> march(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double length,
                                     double step, Inside inside) {
  double t = 0;
  if (inside(from)) return from;
  while (t < length) {
    const double next = std::min(length, t + step);
    if (inside(from + next * direction)) {
      double lo = t, hi = next;
      while (hi - lo > 0.02) {
        const double mid = (lo + hi) / 2;
        (inside(from + mid * direction) ? hi : lo) = mid;
      }
      return from + hi * direction;
    }
    t = next;
  }
  return std::nullopt;
}

// The lower convex hull of the points (y as height over z), as indices in the input order.
std::vector<size_t> anterior_hull(const Profile& p) {
  std::vector<size_t> order(p.size());
  for (size_t i = 0; i < p.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a].z < p[b].z; });
  std::vector<size_t> hull;
  auto cross = [&](size_t o, size_t a, size_t b) {
    return (p[a].z - p[o].z) * (p[b].y - p[o].y) - (p[a].y - p[o].y) * (p[b].z - p[o].z);
  };
  for (size_t i : order) {
    while (hull.size() >= 2 && cross(hull[hull.size() - 2], hull.back(), i) <= 0) hull.pop_back();
    hull.push_back(i);
  }
  return hull;
}

}  // namespace

std::optional<Eigen::Vector3d> first_crossing(const HeadVolume& v, const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& direction, double length, double threshold,
                                              double step) {
  return march(from, direction, length, step, [&](const Eigen::Vector3d& p) { return v.hu(p) >= threshold; });
}

std::optional<Eigen::Vector3d> first_drop(const HeadVolume& v, const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& direction, double length, double threshold,
                                          double step) {
  return march(from, direction, length, step, [&](const Eigen::Vector3d& p) { return v.hu(p) < threshold; });
}

std::optional<Eigen::Vector3d> first_edge(const HeadVolume& v, const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& direction, double length, double threshold) {
  const auto crossing = first_crossing(v, from, direction, length, threshold);
  if (!crossing) return std::nullopt;
  const double t0 = (*crossing - from).dot(direction);
  double peak = v.hu(*crossing), t_peak = t0;
  for (double t = t0; t <= t0 + 2.5; t += 0.1)
    if (const double hu = v.hu(from + t * direction); hu > peak) peak = hu, t_peak = t;
  const double before = std::max(0.0, t0 - 1.5);
  const double level = (v.hu(from + before * direction) + peak) / 2;
  double lo = before, hi = t_peak;
  if (v.hu(from + lo * direction) >= level) return crossing;  // no clean ramp: keep the threshold's
  while (hi - lo > 0.01) {
    const double mid = (lo + hi) / 2;
    (v.hu(from + mid * direction) >= level ? hi : lo) = mid;
  }
  return from + hi * direction;
}

namespace {

// The tissue's edge seen from the front on each column of one row (x from centre_x - half_width
// to centre_x + half_width in 0.5 mm steps, one column when half_width is 0); nullopt where a
// column meets no tissue.
std::vector<std::optional<ProfilePoint>> row_edges(const HeadVolume& v, double z, double y_from, double y_to,
                                                   double threshold, double centre_x, double half_width) {
  const int columns = half_width > 0 ? int(std::ceil(half_width / 0.5)) : 0;
  std::vector<std::optional<ProfilePoint>> edges;
  for (int c = -columns; c <= columns; ++c) {
    const double x = centre_x + (columns ? half_width * c / columns : 0);
    const auto hit = first_edge(v, {x, y_from, z}, {0, 1, 0}, y_to - y_from, threshold);
    edges.push_back(hit ? std::optional<ProfilePoint>(ProfilePoint{z, hit->y(), x}) : std::nullopt);
  }
  return edges;
}

// The most anterior of the edges whose column lies within `reach` of x (all when reach is infinite).
std::optional<ProfilePoint> most_anterior_edge(const std::vector<std::optional<ProfilePoint>>& edges, double x,
                                               double reach) {
  std::optional<ProfilePoint> best;
  for (const auto& edge : edges)
    if (edge && std::abs(edge->x - x) <= reach && (!best || edge->y < best->y)) best = edge;
  return best;
}

}  // namespace

Profile anterior_profile(const HeadVolume& v, double z_top, double z_bottom, double y_from, double y_to,
                         double threshold, double centre_x, double half_width, double z_step) {
  Profile profile;
  const int rows = int(std::floor((z_top - z_bottom) / z_step)) + 1;
  for (int r = 0; r < rows; ++r) {
    const auto edges = row_edges(v, z_top - r * z_step, y_from, y_to, threshold, centre_x, half_width);
    if (const auto best = most_anterior_edge(edges, centre_x, std::numeric_limits<double>::infinity()))
      profile.push_back(*best);
  }
  return profile;
}

std::vector<Profile> column_profiles(const HeadVolume& v, double z_top, double z_bottom, double y_from, double y_to,
                                     double threshold, double centre_x, double half_width, double z_step) {
  std::vector<Profile> columns;
  const int rows = int(std::floor((z_top - z_bottom) / z_step)) + 1;
  for (int r = 0; r < rows; ++r) {
    const auto edges = row_edges(v, z_top - r * z_step, y_from, y_to, threshold, centre_x, half_width);
    columns.resize(edges.size());
    for (size_t c = 0; c < edges.size(); ++c)
      if (edges[c]) columns[c].push_back(*edges[c]);
  }
  return columns;
}

std::vector<double> depth_behind_hull(const Profile& profile) {
  std::vector<double> depth(profile.size(), 0);
  if (profile.size() < 3) return depth;
  const auto hull = anterior_hull(profile);
  for (size_t i = 0; i < profile.size(); ++i) {
    for (size_t h = 0; h + 1 < hull.size(); ++h) {
      const auto& a = profile[hull[h]];
      const auto& b = profile[hull[h + 1]];
      if (profile[i].z < a.z || profile[i].z > b.z || b.z == a.z) continue;
      // Distance from the point to the hull edge, along the edge's normal.
      const Eigen::Vector2d edge(b.y - a.y, b.z - a.z), to(profile[i].y - a.y, profile[i].z - a.z);
      const Eigen::Vector2d normal(edge.y(), -edge.x());
      depth[i] = std::abs(normal.dot(to)) / normal.norm();
      break;
    }
  }
  return depth;
}

Profile until_jump(const Profile& profile, double max_jump_mm) {
  Profile kept;
  for (const auto& point : profile) {
    if (!kept.empty() && std::abs(point.y - kept.back().y) > max_jump_mm) break;
    kept.push_back(point);
  }
  return kept;
}

int most_anterior(const Profile& profile) {
  int best = -1;
  for (size_t i = 0; i < profile.size(); ++i)
    if (best < 0 || profile[i].y < profile[size_t(best)].y) best = int(i);
  return best;
}

int most_posterior(const Profile& profile) {
  int best = -1;
  for (size_t i = 0; i < profile.size(); ++i)
    if (best < 0 || profile[i].y > profile[size_t(best)].y) best = int(i);
  return best;
}

Profile between_heights(const Profile& profile, double z_low, double z_high) {
  Profile kept;
  for (const auto& point : profile)
    if (point.z >= z_low && point.z <= z_high) kept.push_back(point);
  return kept;
}

namespace {

// Vertex height of the parabola fitted to (z, value) near profile[index]; nullopt when the fit
// has no vertex inside the window.
std::optional<double> parabola_vertex(const Profile& profile, const std::vector<double>& value, int index,
                                      double half_window_mm) {
  const double z0 = profile[size_t(index)].z;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  int count = 0;
  for (size_t i = 0; i < profile.size(); ++i) {
    const double dz = profile[i].z - z0;
    if (std::abs(dz) > half_window_mm) continue;
    const Eigen::Vector3d row(dz * dz, dz, 1);
    normal += row * row.transpose();
    rhs += row * value[i];
    ++count;
  }
  if (count < 5) return std::nullopt;
  const Eigen::Vector3d c = normal.ldlt().solve(rhs);
  if (std::abs(c[0]) < 1e-9) return std::nullopt;
  const double vertex = -c[1] / (2 * c[0]);
  if (std::abs(vertex) > half_window_mm) return std::nullopt;
  return z0 + vertex;
}

// The profile's y (and x) at height z, linear between the two samples around it.
ProfilePoint at_height(const Profile& profile, int index, double z) {
  ProfilePoint best = profile[size_t(index)];
  for (size_t i = 0; i + 1 < profile.size(); ++i) {
    const auto& a = profile[i];
    const auto& b = profile[i + 1];
    if ((z - a.z) * (z - b.z) > 0 || a.z == b.z) continue;
    const double t = (z - a.z) / (b.z - a.z);
    return {z, a.y + t * (b.y - a.y), a.x + t * (b.x - a.x)};
  }
  return best;
}

}  // namespace

ProfilePoint refined_extremum(const Profile& profile, int index, double half_window_mm) {
  std::vector<double> y(profile.size());
  for (size_t i = 0; i < profile.size(); ++i) y[i] = profile[i].y;
  const auto vertex = parabola_vertex(profile, y, index, half_window_mm);
  return vertex ? at_height(profile, index, *vertex) : profile[size_t(index)];
}

ProfilePoint refined_peak(const Profile& profile, const std::vector<double>& value, int index, double half_window_mm) {
  const auto vertex = parabola_vertex(profile, value, index, half_window_mm);
  return vertex ? at_height(profile, index, *vertex) : profile[size_t(index)];
}

}  // namespace maxillo::landmarking
