#include "planning/jaw_separation.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "planning/osteotomy.h"
#include "planning/voxel_components.h"
#include "ceph/landmark_frame.h"

namespace maxillo::planning {
namespace {

// Segmentation labels in (imaging/segmentation.h) and phantom labels out (sample/phantom.h).
enum InLabel : uint8_t { kInBackground = 0, kInSoft = 1, kInAir = 2, kInBone = 3, kInTeeth = 4 };
enum OutLabel : uint8_t {
  kAir = 0,
  kSoft = 1,
  kBone = 2,
  kUpperTooth = 3,
  kInnerAir = 4,
  kLowerTooth = 6,
  kMandible = 7
};

// Mean adult angles to S-N: the occlusal plane about 16 degrees, the palatal plane about 8
// (Riolo's Michigan norms, rounded): the occlusal plane runs 8 degrees steeper than the palate,
// its front end lower.
constexpr double kOcclusalBelowPalatalPlaneDeg = 8;

std::optional<Eigen::Vector3d> contact(const LandmarkSet& landmarks, const std::string& upper,
                                       const std::string& lower) {
  auto u = find_landmark(landmarks, upper), l = find_landmark(landmarks, lower);
  if (u && l) return 0.5 * (*u + *l);
  if (u) return *u;
  return l;
}

// The two planes the jaws are told apart by: the occlusal plane (normal pointing down) and the
// coronal plane behind the dental arches (normal pointing back): the rami lie behind it.
struct ArchPlanes {
  CutPlane occlusal, arch_end;
};

// Through the incisor contact and the two first molar contacts; the arches end
// `arch_behind_first_molar_mm` behind the molars.
ArchPlanes planes_from_molars(const Eigen::Vector3d& incisor, const Eigen::Vector3d& right, const Eigen::Vector3d& left,
                              const AnatomicalFrame& frame, const JawSeparationOptions& o) {
  Eigen::Vector3d normal = (right - incisor).cross(left - incisor).normalized();
  if (normal.dot(frame.superior) > 0) normal = -normal;
  const Eigen::Vector3d molars = 0.5 * (right + left);
  return {{(incisor + right + left) / 3.0, normal},
          {molars - o.arch_behind_first_molar_mm * frame.anterior, -frame.anterior}};
}

// Without first molars (crowns a CT's metal streaks hide, a posterior arch without teeth): the
// occlusal plane through the incisor contact at the adults' mean tilt to the palatal plane
// (ANS-PNS), and the arches ending at PNS, beside which the maxillary tuberosities lie.
std::optional<ArchPlanes> planes_from_palate(const LandmarkSet& landmarks, const Eigen::Vector3d& incisor,
                                             const AnatomicalFrame& frame) {
  auto ans = find_landmark(landmarks, "ANS"), pns = find_landmark(landmarks, "PNS");
  if (!ans || !pns) return std::nullopt;
  Eigen::Vector3d forward = *ans - *pns;
  forward -= forward.dot(frame.left) * frame.left;
  if (forward.norm() < 10) return std::nullopt;  // no palate to speak of: degenerate landmarks
  forward.normalize();
  const Eigen::Vector3d up = forward.cross(frame.left);  // superior, perpendicular to the palate
  const double tilt = kOcclusalBelowPalatalPlaneDeg * std::numbers::pi / 180;
  const Eigen::Vector3d occlusal_forward = std::cos(tilt) * forward - std::sin(tilt) * up;
  Eigen::Vector3d normal = occlusal_forward.cross(frame.left).normalized();
  if (normal.dot(frame.superior) > 0) normal = -normal;
  return ArchPlanes{{incisor, normal}, {*pns, -frame.anterior}};
}

ArchPlanes arch_planes(const LandmarkSet& landmarks, const JawSeparationOptions& o) {
  const auto incisor = contact(landmarks, "U1", "L1");
  if (!incisor) throw Error(ErrorCode::kBadValue, "jaw separation", "the occlusal plane needs U1 or L1");
  const auto frame = anatomical_frame(landmarks);
  const auto right = contact(landmarks, "U6R", "L6R"), left = contact(landmarks, "U6L", "L6L");
  if (right && left) return planes_from_molars(*incisor, *right, *left, frame, o);
  if (const auto from_palate = planes_from_palate(landmarks, *incisor, frame)) return *from_palate;
  throw Error(ErrorCode::kBadValue, "jaw separation",
              std::string("the occlusal plane needs ") + (right ? "U6L or L6L" : "U6R or L6R") +
                  ", or ANS and PNS to estimate it from the palate");
}

// Coronal plane a little in front of the porions (normal anterior), if they are known.
std::optional<CutPlane> in_front_of_ears(const LandmarkSet& landmarks, const JawSeparationOptions& o) {
  auto right = find_landmark(landmarks, "PoR"), left = find_landmark(landmarks, "PoL");
  if (!right || !left) return std::nullopt;
  const auto frame = anatomical_frame(landmarks);
  return CutPlane{0.5 * (*right + *left) + o.condyle_in_front_of_porion_mm * frame.anterior, frame.anterior};
}

}  // namespace

LabelVolume separate_jaws(const LabelVolume& ct_tissues, const LandmarkSet& landmarks, const JawSeparationOptions& o) {
  const ArchPlanes planes = arch_planes(landmarks, o);
  const CutPlane& occlusal = planes.occlusal;
  auto menton = find_landmark(landmarks, "Me");
  if (!menton) throw Error(ErrorCode::kBadValue, "jaw separation", "the mandible is found from the landmark Me");
  const auto& g = ct_tissues.geometry;
  const size_t n = ct_tissues.labels.size();

  // Bone that may belong to the mandible. Along the dental arches the occlusal plane itself
  // divides the jaws (the alveolar bone of both touches through the teeth); behind the arches
  // the rami rise above it, up to ramus_height_mm.
  const CutPlane& behind_arches = planes.arch_end;
  // The condyles sit in front of the ear canals: bone behind them (mastoid, occiput, spine)
  // never belongs to the mandible, and may touch it on a CT.
  const std::optional<CutPlane> ears = in_front_of_ears(landmarks, o);
  std::vector<uint8_t> candidate(n, 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        if (ct_tissues.labels[v] != kInBone) continue;
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        const double reach = behind_arches.side(p) > 0 ? o.ramus_height_mm : 0.0;
        candidate[v] = occlusal.side(p) > -reach && (!ears || ears->side(p) > 0);
      }
  const auto components = voxel_components(candidate, g.size);
  // Mandibular: the component holding the bone voxel nearest to menton, and every component
  // with bone below the occlusal plane in front of the arches' end. On a real CT the mandible
  // is often in pieces (thin cortex, metal streaks at the teeth); no maxillary bone lies there.
  std::vector<char> mandibular(size_t(components.count) + 1, 0);
  int32_t nearest = 0;
  double best = 1e300;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        if (!components.id[v]) continue;
        const Eigen::Vector3d p = g.world(Eigen::Vector3d(i, j, k));
        if (behind_arches.side(p) <= 0 && occlusal.side(p) > o.below_occlusal_mm)
          mandibular[size_t(components.id[v])] = 1;
        const double d = (p - *menton).squaredNorm();
        if (d < best) best = d, nearest = components.id[v];
      }
  if (!nearest) throw Error(ErrorCode::kEmptyResult, "jaw separation", "no bone near menton");
  mandibular[size_t(nearest)] = 1;

  LabelVolume out;
  out.geometry = g;
  out.labels.assign(n, kAir);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const auto v = size_t(g.index(i, j, k));
        switch (ct_tissues.labels[v]) {
          case kInSoft: out.labels[v] = kSoft; break;
          case kInAir: out.labels[v] = kInnerAir; break;
          case kInBone: out.labels[v] = mandibular[size_t(components.id[v])] ? kMandible : kBone; break;
          case kInTeeth:
            out.labels[v] = occlusal.side(g.world(Eigen::Vector3d(i, j, k))) > 0 ? kLowerTooth : kUpperTooth;
            break;
          default: break;
        }
      }
  return out;
}

}  // namespace maxillo::planning
