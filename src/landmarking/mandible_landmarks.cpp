#include "landmarking/mandible_landmarks.h"

#include <cmath>
#include <vector>

#include "landmarking/articulare.h"
#include "landmarking/landmark_template.h"
#include "landmarking/profile.h"

namespace maxillo::landmarking {
namespace {

constexpr double kStep = 0.5;  // the ramus grid (mm)
// Bone for the connectivity: above the partial volume of a thin gap (the coronoid process
// under the zygomatic arch, the condyle in its fossa), below any cortical plate's own value.
constexpr double kConnectedBoneHu = 700;

// The ramus region's bone connected to the seed, as a 3D grid and its side view.
class RamusView {
 public:
  RamusView(const HeadVolume& v, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) : lo_(grid_corner(lo, kStep)) {
    for (int a = 0; a < 3; ++a) n_[a] = int((hi[a] - lo_[a]) / kStep) + 1;
    bone_.resize(size_t(n_[0]) * n_[1] * n_[2]);
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i) bone_[index(i, j, k)] = v.hu(at(i, j, k)) >= kConnectedBoneHu;
  }

  // Keeps the bone connected (6-neighbours) to the bone voxel nearest `seed`; false if none near.
  bool keep_connected_to(const Eigen::Vector3d& seed, double reach_mm) {
    int start = -1;
    double best = reach_mm * reach_mm;
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i)
          if (bone_[index(i, j, k)] && (at(i, j, k) - seed).squaredNorm() < best) {
            best = (at(i, j, k) - seed).squaredNorm();
            start = int(index(i, j, k));
          }
    if (start < 0) return false;
    std::vector<uint8_t> kept(bone_.size(), 0);
    std::vector<int> queue{start};
    kept[size_t(start)] = 1;
    for (size_t next = 0; next < queue.size(); ++next) {
      const int i = queue[next] % n_[0], j = (queue[next] / n_[0]) % n_[1], k = queue[next] / (n_[0] * n_[1]);
      const int around[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
      for (const auto& m : around) {
        if (m[0] < 0 || m[1] < 0 || m[2] < 0 || m[0] >= n_[0] || m[1] >= n_[1] || m[2] >= n_[2]) continue;
        const size_t id = index(m[0], m[1], m[2]);
        if (bone_[id] && !kept[id]) {
          kept[id] = 1;
          queue.push_back(int(id));
        }
      }
    }
    bone_ = std::move(kept);
    return true;
  }

  // Side view: the posterior border y_max per height and the lower border z_min per column.
  std::vector<Eigen::Vector2d> posterior_border() const {
    std::vector<Eigen::Vector2d> border;  // (y, z)
    for (int k = 0; k < n_[2]; ++k) {
      int back = -1;
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i)
          if (bone_[index(i, j, k)]) back = std::max(back, j);
      if (back >= 0) border.emplace_back(lo_.y() + back * kStep, lo_.z() + k * kStep);
    }
    return border;
  }
  // The posterior border followed upwards from the row at `start_z`: in each row, the run of
  // bone that continues the previous row's (overlapping it or within 2 mm), and its posterior
  // end. Another bone behind the ramus (the styloid process, the mastoid) is not taken for it as
  // long as the side view shows a gap between them.
  std::vector<Eigen::Vector2d> traced_posterior_border(double start_z) const {
    std::vector<Eigen::Vector2d> border;
    const int k0 = std::max(0, int(std::lround((start_z - lo_.z()) / kStep)));
    int previous_front = -1, previous_back = -1;
    for (int k = k0; k < n_[2]; ++k) {
      std::vector<uint8_t> row(size_t(n_[1]), 0);
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0] && !row[size_t(j)]; ++i) row[size_t(j)] = bone_[index(i, j, k)];
      int chosen_front = -1, chosen_back = -1;
      for (int j = 0; j < n_[1];) {
        if (!row[size_t(j)]) {
          ++j;
          continue;
        }
        int end = j;
        while (end + 1 < n_[1] && row[size_t(end + 1)]) ++end;
        const int reach = int(2 / kStep);
        const bool continues = previous_back < 0 ? true : end >= previous_front - reach && j <= previous_back + reach;
        if (continues && (previous_back < 0 ? end > chosen_back
                                            : chosen_back < 0 || std::abs(end - previous_back) <
                                                                     std::abs(chosen_back - previous_back))) {
          chosen_front = j;
          chosen_back = end;
        }
        j = end + 1;
      }
      if (chosen_back < 0) break;
      border.emplace_back(lo_.y() + chosen_back * kStep, lo_.z() + k * kStep);
      previous_front = chosen_front;
      previous_back = chosen_back;
    }
    return border;
  }

  std::vector<Eigen::Vector2d> lower_border() const {
    std::vector<Eigen::Vector2d> border;
    for (int j = 0; j < n_[1]; ++j) {
      int low = n_[2];
      for (int k = 0; k < n_[2] && low == n_[2]; ++k)
        for (int i = 0; i < n_[0]; ++i)
          if (bone_[index(i, j, k)]) {
            low = k;
            break;
          }
      if (low < n_[2]) border.emplace_back(lo_.y() + j * kStep, lo_.z() + low * kStep);
    }
    return border;
  }
  // Whether the side view has bone at (y, z).
  bool seen(double y, double z) const {
    const int j = int(std::lround((y - lo_.y()) / kStep)), k = int(std::lround((z - lo_.z()) / kStep));
    if (j < 0 || k < 0 || j >= n_[1] || k >= n_[2]) return false;
    for (int i = 0; i < n_[0]; ++i)
      if (bone_[index(i, j, k)]) return true;
    return false;
  }
  // The middle of the bone's lateral extent at (y, z): where the landmark lies across the ramus.
  std::optional<double> middle_x(double y, double z) const {
    const int j = int(std::lround((y - lo_.y()) / kStep)), k = int(std::lround((z - lo_.z()) / kStep));
    if (j < 0 || k < 0 || j >= n_[1] || k >= n_[2]) return std::nullopt;
    int first = -1, last = -1;
    for (int i = 0; i < n_[0]; ++i)
      if (bone_[index(i, j, k)]) {
        if (first < 0) first = i;
        last = i;
      }
    if (first < 0) return std::nullopt;
    return lo_.x() + (first + last) * kStep / 2;
  }
  double top() const {
    for (int k = n_[2] - 1; k >= 0; --k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i)
          if (bone_[index(i, j, k)]) return lo_.z() + k * kStep;
    return lo_.z();
  }

 private:
  size_t index(int i, int j, int k) const { return size_t(i) + size_t(n_[0]) * (size_t(j) + size_t(n_[1]) * k); }
  Eigen::Vector3d at(int i, int j, int k) const { return lo_ + kStep * Eigen::Vector3d(i, j, k); }

  Eigen::Vector3d lo_;
  int n_[3];
  std::vector<uint8_t> bone_;
};

// The point of `points` on the tangent from `from`: the one whose direction from `from` leans
// farthest towards `lean` (a unit vector across the line's general direction).
Eigen::Vector2d tangent_point(const Eigen::Vector2d& from, const std::vector<Eigen::Vector2d>& points,
                              const Eigen::Vector2d& general, const Eigen::Vector2d& lean) {
  Eigen::Vector2d best = points.front();
  double best_angle = -1e9;
  for (const auto& p : points) {
    const Eigen::Vector2d d = p - from;
    if (d.dot(general) < 5) continue;  // too close to `from` to define a line
    const double angle = std::atan2(d.dot(lean), d.dot(general));
    if (angle > best_angle) {
      best_angle = angle;
      best = p;
    }
  }
  return best;
}

// Intersection of the lines a + s u and b + t w.
std::optional<Eigen::Vector2d> intersection(const Eigen::Vector2d& a, const Eigen::Vector2d& u,
                                            const Eigen::Vector2d& b, const Eigen::Vector2d& w) {
  const double det = u.x() * (-w.y()) - u.y() * (-w.x());
  if (std::abs(det) < 1e-9) return std::nullopt;
  const Eigen::Vector2d r = b - a;
  const double s = (r.x() * (-w.y()) - r.y() * (-w.x())) / det;
  return a + s * u;
}

}  // namespace

void find_ramus_landmarks(const HeadVolume& v, double scale, int side, Findings& found) {
  const std::string suffix = side > 0 ? "L" : "R";
  const Eigen::Vector3d go = expected_position("Go" + suffix, scale), ar = expected_position("Ar" + suffix, scale);
  const auto me_it = found.find("Me");
  const Eigen::Vector3d me =
      me_it != found.end() && me_it->second.position ? *me_it->second.position : expected_position("Me", scale);
  const double x_mid = std::abs(go.x());
  const Eigen::Vector3d lo(side > 0 ? x_mid - 16 : -x_mid - 16, go.y() - 32, go.z() - 16);
  const Eigen::Vector3d hi(side > 0 ? x_mid + 16 : -x_mid + 16, ar.y() + 10 * scale, ar.z() + 24.5);
  RamusView ramus(v, lo, hi);
  if (!ramus.keep_connected_to(go, 14)) {
    const std::string reason = v.scanned(go) ? "no mandibular angle near its expected place"
                                             : "the mandibular angle lies outside the scanned field";
    found["Go" + suffix] = found["Ar" + suffix] = RuleFinding::absent(reason);
    return;
  }
  // The posterior border read upwards from the angle, until it jumps to another bone.
  // The traced border (to the grid's half millimetre), then each point to a fraction of it: a
  // ray from just behind the border forwards, at the middle of the ramus's width.
  Profile border;
  for (const auto& p : ramus.traced_posterior_border(go.z())) {
    const double x = ramus.middle_x(p.x(), p.y()).value_or(go.x());
    const auto edge = first_edge(v, {x, p.x() + 1.5, p.y()}, {0, -1, 0}, 3, kBoneHu);
    border.push_back({p.y(), edge ? edge->y() : p.x(), x});
  }
  Profile neck_profile;
  // The ramus tangent's upper point (for Go): read upwards from 15 mm above the angle, the
  // border leans back up to the condylar neck, where it turns forward (by 0.7 mm or more) before
  // the condylar head; the most posterior point before that turn.
  double running_max = -1e9;
  for (const auto& p : until_jump(border, 3)) {
    if (p.z <= go.z() + 15 * scale) continue;
    if (p.y < running_max - 0.7) break;
    running_max = std::max(running_max, p.y);
    neck_profile.push_back(p);
  }
  if (neck_profile.size() < 5) {
    found["Ar" + suffix] = found["Go" + suffix] = RuleFinding::absent("no posterior border of the ramus");
    return;
  }
  const ProfilePoint neck_point = refined_extremum(neck_profile, most_posterior(neck_profile), 2);
  const Eigen::Vector2d neck2(neck_point.y, neck_point.z);
  // Articulare (articulare.h) on the border from 10 mm below the neck's point up (the angle
  // below turns too fast for its continuity rule).
  found["Ar" + suffix] = find_articulare(v, between_heights(until_jump(border, 3), neck_point.z - 10, 1e9), scale);
  // Go: the bisector of the ramus tangent and the mandibular plane, onto the angle's outline.
  std::vector<Eigen::Vector2d> lower_posterior;
  for (const auto& p : border)
    if (p.z < neck_point.z - 5) lower_posterior.emplace_back(p.y, p.z);
  const std::vector<Eigen::Vector2d> lower = ramus.lower_border();
  if (lower_posterior.empty() || lower.empty()) {
    found["Go" + suffix] = RuleFinding::absent("no outline of the mandibular angle");
    return;
  }
  const Eigen::Vector2d me2(me.y(), me.z());
  const Eigen::Vector2d ramus_touch = tangent_point(neck2, lower_posterior, {0, -1}, {1, 0});
  const Eigen::Vector2d border_touch = tangent_point(me2, lower, {1, 0}, {0, -1});
  const Eigen::Vector2d up = (neck2 - ramus_touch).normalized(), forward = (me2 - border_touch).normalized();
  const auto vertex = intersection(ramus_touch, up, border_touch, forward);
  if (!vertex) {
    found["Go" + suffix] = RuleFinding::absent("the ramus and the lower border are parallel");
    return;
  }
  // The angle's most prominent point along the bisector's outward direction: for a rounded
  // angle where the bisector meets it, for a sharp one its vertex.
  const Eigen::Vector2d outward = -(up + forward).normalized();
  std::vector<Eigen::Vector2d> outline = lower;
  outline.insert(outline.end(), lower_posterior.begin(), lower_posterior.end());
  std::optional<Eigen::Vector2d> go2;
  for (const auto& p : outline)
    if ((p - *vertex).norm() < 20 && (!go2 || p.dot(outward) > go2->dot(outward))) go2 = p;
  if (!go2) {
    found["Go" + suffix] = RuleFinding::absent("no outline near the angle's vertex");
    return;
  }
  // Across the ramus: the middle of the bone 2 mm inside the outline point, where the plate's
  // whole cross-section lies (at the outline a turned head's partial voxels put it up to 2.2 mm
  // to one side), or nearer the outline where no bone lies there.
  std::optional<double> go_x;
  for (double inside : {2.0, 1.0, 0.5, 0.0})
    if (!go_x) go_x = ramus.middle_x(go2->x() - inside * outward.x(), go2->y() - inside * outward.y());
  if (!go_x) {
    found["Go" + suffix] = RuleFinding::absent("no bone across the angle at its outline");
    return;
  }
  found["Go" + suffix] = RuleFinding::found({*go_x, go2->x(), go2->y()}, 1);
}

}  // namespace maxillo::landmarking
