#include "planning/osteotomy.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <tuple>

#include "core/error.h"
#include "planning/voxel_components.h"
#include "ceph/landmark_frame.h"

namespace maxillo::planning {
namespace {

constexpr std::array<std::string_view, kSegmentCount> kSegmentNames = {
    "none", "cranium", "maxilla", "mandible", "ramus_right", "ramus_left", "chin"};

// Default cut heights and offsets (mm). A Le Fort I runs above the nasal floor and the apices of
// the upper teeth, from the piriform rim back to the pterygomaxillary junction; the "high"
// variant takes more of the anterior maxillary wall (more advancement of the paranasal region).
constexpr double kLeFortLowAboveAns = 5;
constexpr double kLeFortHighAboveAns = 10;
constexpr double kLeFortBelowOrbitale = 10;  // the cut must stay below the infraorbital foramen
constexpr double kPterygomaxillaryBehindPns = 3;
constexpr double kBssoBehindFirstMolar = 22;          // behind the second/third molar region
constexpr double kGenioplastyFractionAboveMe = 0.35;  // of the Me-B height, at the midline
constexpr double kGenioplastyTiltDeg = 15;            // the cut descends posteriorly

bool has_label(const std::vector<uint8_t>& set, uint8_t label) {
  return std::find(set.begin(), set.end(), label) != set.end();
}

enum class Tissue { kOther, kBone, kUpperTooth, kLowerTooth, kMandible };

// What each input label value is, as a lookup table.
std::array<Tissue, 256> tissue_table(const SkeletonLabels& labels) {
  std::array<Tissue, 256> table{};
  table.fill(Tissue::kOther);
  for (int v = 0; v < 256; ++v) {
    auto value = uint8_t(v);
    if (has_label(labels.bone, value)) table[v] = Tissue::kBone;
    if (has_label(labels.upper_teeth, value)) table[v] = Tissue::kUpperTooth;
    if (has_label(labels.lower_teeth, value)) table[v] = Tissue::kLowerTooth;
    if (has_label(labels.mandible, value)) table[v] = Tissue::kMandible;
  }
  return table;
}

// Voxel centres in LPS, computed once per voxel index.
class VoxelPositions {
 public:
  explicit VoxelPositions(const VolumeGeometry& g) : g_(g) {}
  Eigen::Vector3d at(int64_t index) const {
    const int64_t nx = g_.size.x(), ny = g_.size.y();
    return g_.world(Eigen::Vector3d(double(index % nx), double((index / nx) % ny), double(index / (nx * ny))));
  }

 private:
  const VolumeGeometry& g_;
};

// The components of `candidate` that hold at least one voxel where `seed` is true.
std::vector<uint8_t> components_touching(const std::vector<uint8_t>& candidate, const std::vector<uint8_t>& seed,
                                         const Eigen::Vector3i& size) {
  auto components = voxel_components(candidate, size);
  std::vector<uint8_t> keep(size_t(components.count) + 1, 0);
  for (size_t v = 0; v < seed.size(); ++v)
    if (seed[v] && components.id[v]) keep[size_t(components.id[v])] = 1;
  std::vector<uint8_t> result(candidate.size(), 0);
  for (size_t v = 0; v < candidate.size(); ++v) result[v] = keep[size_t(components.id[v])];
  return result;
}

void assign_maxilla(const std::vector<Tissue>& tissue, const Osteotomies& cuts, const VoxelPositions& position,
                    const Eigen::Vector3i& size, std::vector<uint8_t>& segment) {
  // Candidates: maxillary bone and upper teeth below the cut and in front of the junction.
  std::vector<uint8_t> candidate(tissue.size(), 0), teeth(tissue.size(), 0);
  for (size_t v = 0; v < tissue.size(); ++v) {
    if (tissue[v] != Tissue::kBone && tissue[v] != Tissue::kUpperTooth) continue;
    auto p = position.at(int64_t(v));
    if (cuts.le_fort_i->side(p) <= 0) continue;
    if (cuts.pterygomaxillary && cuts.pterygomaxillary->side(p) <= 0) continue;
    candidate[v] = 1;
    teeth[v] = tissue[v] == Tissue::kUpperTooth;
  }
  auto maxilla = components_touching(candidate, teeth, size);
  for (size_t v = 0; v < tissue.size(); ++v)
    if (maxilla[v]) segment[v] = uint8_t(Segment::kMaxilla);
}

// Distal mandible or one of the rami: a voxel belongs to the ramus of its side when it lies
// behind that side's cut plane. The side is decided by the midpoint between the two planes.
Segment mandible_part(const Osteotomies& cuts, const Eigen::Vector3d& p, const Eigen::Vector3d& left) {
  if (!cuts.bsso_right || !cuts.bsso_left) return Segment::kMandible;
  const Eigen::Vector3d middle = 0.5 * (cuts.bsso_right->point + cuts.bsso_left->point);
  const bool on_left = left.dot(p - middle) > 0;
  const CutPlane& cut = on_left ? *cuts.bsso_left : *cuts.bsso_right;
  if (cut.side(p) > 0) return Segment::kMandible;
  return on_left ? Segment::kRamusLeft : Segment::kRamusRight;
}

void assign_chin(const std::vector<Tissue>& tissue, const CutPlane& cut, const VoxelPositions& position,
                 const Eigen::Vector3i& size, std::vector<uint8_t>& segment) {
  std::vector<uint8_t> candidate(tissue.size(), 0);
  for (size_t v = 0; v < tissue.size(); ++v)
    if (segment[v] == uint8_t(Segment::kMandible) && cut.side(position.at(int64_t(v))) > 0) candidate[v] = 1;
  // Only the largest piece below the cut is the chin: a plane tilted through the symphysis may
  // also graze the lower border further back, and those slivers stay with the mandible.
  auto components = voxel_components(candidate, size);
  if (components.count == 0) return;
  auto largest = int32_t(std::max_element(components.sizes.begin(), components.sizes.end()) - components.sizes.begin());
  for (size_t v = 0; v < tissue.size(); ++v)
    if (components.id[v] == largest) segment[v] = uint8_t(Segment::kChin);
}

std::vector<SegmentStats> segment_stats(const LabelVolume& segments) {
  std::array<int64_t, kSegmentCount> counts{};
  for (auto value : segments.labels) ++counts[value];
  const double voxel_ml = segments.geometry.spacing.prod() / 1000.0;
  std::vector<SegmentStats> stats;
  for (int s = 1; s < kSegmentCount; ++s)
    if (counts[size_t(s)] > 0) stats.push_back({Segment(s), counts[size_t(s)], double(counts[size_t(s)]) * voxel_ml});
  return stats;
}

void require_segment(const std::vector<SegmentStats>& stats, Segment segment, std::string_view cut) {
  for (const auto& s : stats)
    if (s.segment == segment) return;
  throw Error(ErrorCode::kEmptyResult, std::string(cut),
              "the cut leaves no " + std::string(segment_name(segment)) + " segment; check the cut plane");
}

}  // namespace

std::string_view segment_name(Segment segment) { return kSegmentNames[size_t(segment)]; }

std::optional<Segment> parse_segment(std::string_view name) {
  for (int s = 0; s < kSegmentCount; ++s)
    if (kSegmentNames[size_t(s)] == name) return Segment(s);
  return std::nullopt;
}

CutPlane default_le_fort_i(const LandmarkSet& landmarks, LeFortVariant variant) {
  const auto ans = require_landmark(landmarks, "ANS", "Le Fort I"),
             pns = require_landmark(landmarks, "PNS", "Le Fort I");
  const auto frame = anatomical_frame(landmarks);
  // Parallel to the palatal plane: its anterior direction, tilted about the transverse axis only.
  Eigen::Vector3d palatal = ans - pns;
  palatal -= frame.left * frame.left.dot(palatal);
  palatal.normalize();
  CutPlane cut;
  cut.normal = frame.left.cross(palatal).normalized();  // points down, towards the palate
  const double above = variant == LeFortVariant::Low ? kLeFortLowAboveAns : kLeFortHighAboveAns;
  cut.point = ans - above * cut.normal;
  if (auto orbitale = bilateral_mean(landmarks, "Or"); orbitale && cut.side(*orbitale) > -kLeFortBelowOrbitale)
    throw Error(ErrorCode::kBadValue, "Le Fort I",
                "the cut would pass within " + std::to_string(int(kLeFortBelowOrbitale)) +
                    " mm of the orbitale (infraorbital nerve); check ANS and Or");
  return cut;
}

CutPlane default_pterygomaxillary(const LandmarkSet& landmarks) {
  const auto pns = require_landmark(landmarks, "PNS", "pterygomaxillary junction");
  const auto frame = anatomical_frame(landmarks);
  return {pns - kPterygomaxillaryBehindPns * frame.anterior, frame.anterior};
}

std::pair<CutPlane, CutPlane> default_bsso(const LandmarkSet& landmarks) {
  const auto frame = anatomical_frame(landmarks);
  auto side_cut = [&](const char* side) {
    const std::string molar = std::string("L6") + side;
    return CutPlane{require_landmark(landmarks, molar, "BSSO") - kBssoBehindFirstMolar * frame.anterior,
                    frame.anterior};
  };
  return {side_cut("R"), side_cut("L")};
}

Osteotomies default_osteotomies(const LandmarkSet& landmarks, const OsteotomyChoice& choice) {
  Osteotomies cuts;
  if (choice.le_fort_i) {
    cuts.le_fort_i = default_le_fort_i(landmarks, choice.le_fort_variant);
    cuts.pterygomaxillary = default_pterygomaxillary(landmarks);
  }
  if (choice.bsso) std::tie(cuts.bsso_right, cuts.bsso_left) = default_bsso(landmarks);
  if (choice.genioplasty) cuts.genioplasty = default_genioplasty(landmarks);
  return cuts;
}

CutPlane default_genioplasty(const LandmarkSet& landmarks) {
  const auto b = require_landmark(landmarks, "B", "genioplasty"), me = require_landmark(landmarks, "Me", "genioplasty");
  const auto pog = require_landmark(landmarks, "Pog", "genioplasty");
  const auto frame = anatomical_frame(landmarks);
  const double height = frame.superior.dot(b - me);
  // On the chin's front at the cut height, descending posteriorly by the tilt.
  Eigen::Vector3d point = pog + frame.superior * (frame.superior.dot(me - pog) + kGenioplastyFractionAboveMe * height);
  const double tilt = kGenioplastyTiltDeg * M_PI / 180;
  Eigen::Vector3d normal = -std::cos(tilt) * frame.superior + std::sin(tilt) * frame.anterior;
  return {point, normal.normalized()};
}

OsteotomyResult cut_skeleton(const LabelVolume& tissues, const Osteotomies& cuts, const SkeletonLabels& labels) {
  const auto table = tissue_table(labels);
  const auto& g = tissues.geometry;
  std::vector<Tissue> tissue(tissues.labels.size());
  for (size_t v = 0; v < tissue.size(); ++v) tissue[v] = table[tissues.labels[v]];

  OsteotomyResult result;
  result.segments.geometry = g;
  auto& segment = result.segments.labels;
  segment.assign(tissue.size(), uint8_t(Segment::kNone));
  for (size_t v = 0; v < tissue.size(); ++v) {
    if (tissue[v] == Tissue::kOther) continue;
    ++result.input_bone_voxels;
    const bool lower = tissue[v] == Tissue::kLowerTooth || tissue[v] == Tissue::kMandible;
    segment[v] = uint8_t(lower ? Segment::kMandible : Segment::kCranium);
  }
  VoxelPositions position(g);
  if (cuts.le_fort_i) assign_maxilla(tissue, cuts, position, g.size, segment);
  if (cuts.bsso_right && cuts.bsso_left) {
    // The side axis is the line between the two cut points (robust to head orientation).
    const Eigen::Vector3d side_axis = (cuts.bsso_left->point - cuts.bsso_right->point).normalized();
    for (size_t v = 0; v < tissue.size(); ++v)
      if (segment[v] == uint8_t(Segment::kMandible))
        segment[v] = uint8_t(mandible_part(cuts, position.at(int64_t(v)), side_axis));
  }
  if (cuts.genioplasty) assign_chin(tissue, *cuts.genioplasty, position, g.size, segment);

  result.stats = segment_stats(result.segments);
  if (cuts.le_fort_i) require_segment(result.stats, Segment::kMaxilla, "Le Fort I");
  if (cuts.bsso_right) require_segment(result.stats, Segment::kRamusRight, "BSSO right");
  if (cuts.bsso_left) require_segment(result.stats, Segment::kRamusLeft, "BSSO left");
  if (cuts.genioplasty) require_segment(result.stats, Segment::kChin, "genioplasty");
  return result;
}

}  // namespace maxillo::planning
