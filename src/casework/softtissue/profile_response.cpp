#include "casework/softtissue/profile_response.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "planning/osteotomy.h"
#include "validation/skin_cavities.h"

namespace maxillo::casework {
namespace {

constexpr double kMovedMm = 0.1;           // edges whose ends both moved less are not in the gradient figures
constexpr double kProfileHalfWidthMm = 2;  // how far off the midsagittal plane a profile vertex may lie
constexpr double kProfileHalfHeightMm = 1;

Eigen::Index nearest_vertex(const TriangleMesh& skin, const Eigen::Vector3d& p) {
  Eigen::Index best = 0;
  (skin.vertices.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return best;
}

// The skin's edges, each once, as (smaller, larger) vertex index pairs.
std::vector<std::pair<int, int>> unique_edges(const TriangleMesh& skin) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(size_t(skin.faces.rows()) * 3);
  for (Eigen::Index f = 0; f < skin.faces.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = skin.faces(f, e), b = skin.faces(f, (e + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// The P99.9 and the largest of |u_a - u_b| / |x_a - x_b| over the outer face's edges with an end
// that moved. Skin lining a cavity is left out: a CT's skin follows the air through the nostrils
// into the nasal cavity and the sinuses, whose linings ride on the bone they line and tear where
// a moved bone meets an unmoved one (on the phantom, 6 mm over one edge in the maxillary sinus).
void add_gradient(const TriangleMesh& skin, const Eigen::MatrixX3d& u, const std::vector<uint8_t>& on_bone,
                  const std::vector<int8_t>& lip_side, ProfileResponse& response) {
  std::vector<bool> moved(size_t(skin.vertices.rows()));
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) moved[size_t(v)] = u.row(v).norm() >= kMovedMm;
  const std::vector<bool> lining = validation::cavity_vertices(skin, moved);
  std::vector<double> gradient;
  for (const auto& [a, b] : unique_edges(skin)) {
    if (!moved[size_t(a)] && !moved[size_t(b)]) continue;
    if (lining[size_t(a)] || lining[size_t(b)]) continue;
    if (!on_bone.empty() && (on_bone[size_t(a)] || on_bone[size_t(b)])) continue;
    if (!lip_side.empty() && lip_side[size_t(a)] * lip_side[size_t(b)] < 0) continue;
    const double length = (skin.vertices.row(a) - skin.vertices.row(b)).norm();
    if (length <= 0) continue;
    gradient.push_back((u.row(a) - u.row(b)).norm() / length);
    if (gradient.back() > response.gradient_max) {
      response.gradient_max = gradient.back();
      response.steepest_at = 0.5 * (skin.vertices.row(a) + skin.vertices.row(b)).transpose();
    }
  }
  response.moved_edges = int(gradient.size());
  if (gradient.empty()) return;
  const size_t p999 = size_t(std::floor(0.999 * double(gradient.size() - 1)));
  std::nth_element(gradient.begin(), gradient.begin() + std::ptrdiff_t(p999), gradient.end());
  response.gradient_p999 = gradient[p999];
}

// A rigid move that moves no point of a head by a tenth of a millimetre (within 100 mm of the
// origin): an identity stored for a segment the plan left in place.
bool moves_anything(const Eigen::Isometry3d& move) {
  constexpr double kReachMm = 100, kMovedMm = 0.1;
  const double rotation = Eigen::AngleAxisd(move.linear()).angle();
  return move.translation().norm() + rotation * kReachMm > kMovedMm;
}

}  // namespace

std::optional<MaxillaryAdvancement> maxillary_advancement(const SegmentMoves& moves, const LandmarkSet& landmarks,
                                                          const AnatomicalFrame& frame) {
  const auto maxilla = moves.find(uint8_t(planning::Segment::kMaxilla));
  if (maxilla == moves.end()) return std::nullopt;
  for (const char* reference : {"A", "ANS", "U1"}) {
    const auto point = find_landmark(landmarks, reference);
    if (!point) continue;
    MaxillaryAdvancement advancement{(maxilla->second * *point - *point).dot(frame.anterior), reference};
    if (advancement.forward_mm < kSmallestAdvancementMm) return std::nullopt;
    for (const auto& [segment, move] : moves)
      if (segment != uint8_t(planning::Segment::kMaxilla) && segment != uint8_t(planning::Segment::kCranium) &&
          moves_anything(move))
        advancement.other_segments_moved = true;
    return advancement;
  }
  return std::nullopt;
}

const std::vector<PublishedResponse>& published_le_fort_advancement_response() {
  static const std::vector<PublishedResponse> published{
      {"Prn", "0.17; 1.1 mm for 4.15 mm at the lip",
       "3D scans of 32 patients (Maxillofac Plast Reconstr Surg 2018, PMC6173856); Vasudavan 2012 (JOMS 70:e270)", 0.0,
       0.40},
      {kDorsumLabel, "about 0 (nasal bones not cut)", "Le Fort I leaves the nasal bones in place", 0.0, 0.25},
      {"Sn", "0.51 +/- 0.13", "Rosen 1988, 41 patients (Plast Reconstr Surg 81:171)", 0.40, 0.95},
      {"Ls", "0.82 +/- 0.13", "Rosen 1988, 41 patients (Plast Reconstr Surg 81:171)", 0.50, 1.00},
      {"Li", "not measured in these series", "", std::nullopt, std::nullopt},
      {"PogS", "about 0 (mandible not moved)", "", std::nullopt, std::nullopt},
  };
  return published;
}

std::optional<std::pair<std::string, double>> nearest_landmark(const LandmarkSet& landmarks,
                                                               const Eigen::Vector3d& point) {
  std::optional<std::pair<std::string, double>> nearest;
  for (const auto& landmark : landmarks)
    if (const double d = (landmark.position - point).norm(); !nearest || d < nearest->second)
      nearest = std::pair{landmark.label, d};
  return nearest;
}

bool plausible(const PublishedResponse& published, double ratio) {
  if (published.plausible_low && ratio < *published.plausible_low) return false;
  return !published.plausible_high || ratio <= *published.plausible_high;
}

std::optional<Eigen::Index> profile_vertex_above(const TriangleMesh& skin, const AnatomicalFrame& frame,
                                                 const Eigen::Vector3d& tip, double above_mm) {
  std::optional<Eigen::Index> best;
  double most_anterior = -INFINITY;
  for (Eigen::Index v = 0; v < skin.vertices.rows(); ++v) {
    const Eigen::Vector3d offset = skin.vertices.row(v).transpose() - tip;
    if (std::abs(offset.dot(frame.left)) > kProfileHalfWidthMm) continue;
    if (std::abs(offset.dot(frame.superior) - above_mm) > kProfileHalfHeightMm) continue;
    if (offset.dot(frame.anterior) > most_anterior) {
      most_anterior = offset.dot(frame.anterior);
      best = v;
    }
  }
  return best;
}

ProfileResponse profile_response(const TriangleMesh& skin_before, const Eigen::MatrixX3d& displacement,
                                 const AnatomicalFrame& frame, const LandmarkSet& landmarks, double advancement_mm,
                                 const std::vector<uint8_t>& on_bone, const std::vector<int8_t>& lip_side) {
  ProfileResponse response;
  const auto tip = find_landmark(landmarks, "Prn");
  for (const auto& published : published_le_fort_advancement_response()) {
    ProfilePointResponse point{published.label};
    std::optional<Eigen::Index> vertex;
    if (published.label == kDorsumLabel) {
      if (tip) vertex = profile_vertex_above(skin_before, frame, *tip, kDorsumAboveTipMm);
    } else if (auto p = find_landmark(landmarks, published.label)) {
      vertex = nearest_vertex(skin_before, *p);
    }
    if (vertex && skin_before.vertices.rows() > 0) {
      point.present = true;
      point.forward_mm = displacement.row(*vertex).dot(frame.anterior.transpose());
      point.ratio = advancement_mm != 0 ? point.forward_mm / advancement_mm : 0;
    }
    response.points.push_back(point);
  }
  add_gradient(skin_before, displacement, on_bone, lip_side, response);
  if (auto nearest = nearest_landmark(landmarks, response.steepest_at))
    std::tie(response.steepest_near, response.steepest_near_mm) = *nearest;
  return response;
}

}  // namespace maxillo::casework
