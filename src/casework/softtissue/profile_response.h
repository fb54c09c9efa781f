#pragma once
// How a predicted face's midline profile follows a Le Fort I advancement, beside what published
// series measured (issue 34): the forward move of the soft-tissue profile points (pronasale,
// subnasale, labrale superius and inferius, soft-tissue pogonion, and the nasal dorsum 8 mm above
// the tip) as a fraction of the advancement; and how sharply the displacement changes over the
// outer face (cavity linings left out), where a shear at the model's edge shows as a large gradient.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "casework/plan/planned_case.h"
#include "ceph/landmark.h"
#include "core/triangle_mesh.h"
#include "geometry/anatomical_frame.h"

namespace maxillo::casework {

inline constexpr const char* kDorsumLabel = "dorsum";  // the nasal dorsum's profile point, not a landmark
inline constexpr double kDorsumAboveTipMm = 8;

// What studies of Le Fort I advancement measured at a profile point, and the band this program
// calls plausible for a prediction (docs/ARCHITECTURE.md, "Soft tissue realism", cites them).
struct PublishedResponse {
  std::string label;                                    // Prn, Sn, Ls, Li, PogS, dorsum
  std::string published;                                // as the source gives it, e.g. "0.51 +/- 0.13"
  std::string source;                                   // short citation
  std::optional<double> plausible_low, plausible_high;  // fraction of the advancement; none: no band
};
const std::vector<PublishedResponse>& published_le_fort_advancement_response();

struct ProfilePointResponse {
  std::string label;
  bool present = false;   // the landmark (or, for the dorsum, the profile) was there
  double forward_mm = 0;  // the predicted skin's move along the frame's anterior axis
  double ratio = 0;       // forward_mm / the advancement
};

struct ProfileResponse {
  std::vector<ProfilePointResponse> points;  // in published_le_fort_advancement_response()'s order
  double gradient_p999 = 0;                  // |du| / |dx| over the outer face's edges that moved, mm per mm
  double gradient_max = 0;
  Eigen::Vector3d steepest_at = Eigen::Vector3d::Zero();  // the midpoint of the edge with gradient_max
  std::string steepest_near;                              // the landmark nearest to it ("" without landmarks)
  double steepest_near_mm = 0;                            // and its distance
  int moved_edges = 0;  // outer-face edges with an end that moved >= 0.1 mm: what the gradient figures are over
};

// The point on the skin's midline profile `above_mm` above `tip` (along the frame's superior
// axis): the most anterior skin vertex within 2 mm of the midsagittal plane through the tip and
// 1 mm of that height; nullopt when the skin has none there.
std::optional<Eigen::Index> profile_vertex_above(const TriangleMesh& skin, const AnatomicalFrame& frame,
                                                 const Eigen::Vector3d& tip, double above_mm);

// `displacement`: per vertex of `skin_before`. `landmarks`: the case's (the soft-tissue profile
// points among them are read; each is taken at its nearest skin vertex). `on_bone`: per vertex,
// non-zero where the surface runs over exposed teeth or bone (casework/softtissue/exposed_bone.h); their edges
// are no skin and stay out of the gradient (upper and lower crowns in contact slide apart), as do
// the edges from a vertex of the upper lip to one of the lower (`lip_side` +1 and -1, as the model
// parted between the lips carries them: they slide on each other there, a slip, not a shear).
ProfileResponse profile_response(const TriangleMesh& skin_before, const Eigen::MatrixX3d& displacement,
                                 const AnatomicalFrame& frame, const LandmarkSet& landmarks, double advancement_mm,
                                 const std::vector<uint8_t>& on_bone = {}, const std::vector<int8_t>& lip_side = {});

// The landmark nearest to `point` and its distance; nullopt for an empty set.
std::optional<std::pair<std::string, double>> nearest_landmark(const LandmarkSet& landmarks,
                                                               const Eigen::Vector3d& point);

// Whether `ratio` lies in the plausible band of `published` (true where it has no band).
bool plausible(const PublishedResponse& published, double ratio);

// How far a plan brings the maxilla forward: its segment's move at the A point (the published
// ratios are soft tissue over the bone's move under it), or at ANS, then U1, when A is absent.
struct MaxillaryAdvancement {
  double forward_mm = 0;
  std::string reference;              // the landmark it was read at
  bool other_segments_moved = false;  // the mandible, a ramus or the chin moved as well
};
inline constexpr double kSmallestAdvancementMm = 1;  // below it the ratios are noise over a small move
// nullopt when the maxilla moves forward by less than kSmallestAdvancementMm (or not at all), or
// none of A, ANS and U1 is known.
std::optional<MaxillaryAdvancement> maxillary_advancement(const SegmentMoves& moves, const LandmarkSet& landmarks,
                                                          const AnatomicalFrame& frame);

}  // namespace maxillo::casework
