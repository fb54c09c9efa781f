#pragma once
// Virtual osteotomies on a labelled skeleton: the bone and teeth voxels of a tissue label volume
// are split into bone segments (cranium, Le Fort I maxilla, distal mandible, rami, chin) by cut
// planes. Every bone or tooth voxel gets exactly one segment label, so no bone is lost or
// duplicated: the segments' voxel counts add up to the input's bone and teeth voxels.
//
// Cuts are half-spaces, as a surgeon's saw cuts are nearly planar over the width of a segment:
//   Le Fort I  : the maxilla below the plane (normal pointing down, to the part that moves),
//                anterior to the pterygomaxillary junction (a coronal plane behind PNS).
//                The segment is the connected part of that region holding the upper teeth.
//   BSSO       : bilateral sagittal split; the distal mandible (tooth-bearing body) is the part
//                of the mandible anterior to a cut plane on each side (behind the last molar);
//                the two proximal segments (rami with condyles) keep their place.
//   Genioplasty: the chin below a plane through the symphysis (normal pointing down/forward).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <string_view>
#include <vector>

#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo::planning {

// Segment labels of an OsteotomyResult::segments volume (values stable: files rely on them).
enum class Segment : uint8_t {
  kNone = 0,        // not bone
  kCranium = 1,     // everything that does not move (skull, zygomas, upper midface)
  kMaxilla = 2,     // Le Fort I segment with the upper teeth
  kMandible = 3,    // distal mandible with the lower teeth (whole mandible without BSSO)
  kRamusRight = 4,  // proximal segments of a BSSO
  kRamusLeft = 5,
  kChin = 6,  // genioplasty segment
};
inline constexpr int kSegmentCount = 7;
std::string_view segment_name(Segment segment);  // "cranium", "maxilla", ...
std::optional<Segment> parse_segment(std::string_view name);

// A cut plane: `point` on the plane, `normal` (unit) pointing into the part that is cut off.
struct CutPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = -Eigen::Vector3d::UnitZ();
  // Signed distance of p from the plane, positive on the cut-off side.
  double side(const Eigen::Vector3d& p) const { return normal.dot(p - point); }
};

// Which input labels are which tissue. The defaults are the phantom's Tissue values
// (sample/phantom.h). A CT segmented by imaging/segmentation.h has no separate mandible label:
// mandible_labels empty means "the mandible is whatever bone lies below the Le Fort I plane and
// is not connected to the upper teeth there".
struct SkeletonLabels {
  std::vector<uint8_t> bone{2};
  std::vector<uint8_t> upper_teeth{3};
  std::vector<uint8_t> lower_teeth{6};
  std::vector<uint8_t> mandible{7};
};

struct Osteotomies {
  std::optional<CutPlane> le_fort_i;
  // Coronal plane behind the maxillary tuberosity (normal anterior): the Le Fort I segment lies
  // on its positive side. Defaults to 6 mm behind PNS when the plan gives landmarks.
  std::optional<CutPlane> pterygomaxillary;
  // BSSO: one plane per side, normal pointing anterior (to the distal segment).
  std::optional<CutPlane> bsso_right, bsso_left;
  std::optional<CutPlane> genioplasty;
};

enum class LeFortVariant { Low, High };
// Default cut planes from landmarks (LPS mm). Le Fort I: parallel to the palatal plane
// (ANS-PNS, tilted about the transverse axis only), 5 mm (low) or 10 mm (high) above ANS, and
// at least 10 mm below the orbitale; the junction cut 3 mm behind PNS. The BSSO needs L6R and
// L6L; the genioplasty B, Pog and Me. Missing landmarks -> Error naming them.
CutPlane default_le_fort_i(const LandmarkSet& landmarks, LeFortVariant variant);
CutPlane default_pterygomaxillary(const LandmarkSet& landmarks);
CutPlane default_genioplasty(const LandmarkSet& landmarks);
// Right and left sagittal split cuts: coronal planes behind the lower first molars (L6R, L6L).
std::pair<CutPlane, CutPlane> default_bsso(const LandmarkSet& landmarks);

struct OsteotomyChoice {
  bool le_fort_i = true;
  LeFortVariant le_fort_variant = LeFortVariant::Low;
  bool bsso = false;
  bool genioplasty = false;
};
// The chosen osteotomies with their default cut planes (the Le Fort I with its junction cut).
Osteotomies default_osteotomies(const LandmarkSet& landmarks, const OsteotomyChoice& choice);

struct SegmentStats {
  Segment segment = Segment::kNone;
  int64_t voxels = 0;
  double volume_ml = 0;
};

struct OsteotomyResult {
  LabelVolume segments;             // Segment values, same geometry as the input
  std::vector<SegmentStats> stats;  // one per segment present, in Segment order
  int64_t input_bone_voxels = 0;    // bone + teeth voxels of the input (== sum of stats)
};

// Splits the bone and teeth of `tissues` by the osteotomies. Throws Error when a cut yields an
// empty segment (e.g. a Le Fort I plane above the skull) naming the cut.
OsteotomyResult cut_skeleton(const LabelVolume& tissues, const Osteotomies& cuts, const SkeletonLabels& labels = {});

}  // namespace maxillo::planning
