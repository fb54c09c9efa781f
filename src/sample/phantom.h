#pragma once
// maxillo's synthetic craniofacial phantom: an adult head built from analytic shapes, with a
// CT volume in HU, a tissue label per voxel, and landmarks placed by construction. It is the
// demo's default case and the tests' known answer.
//
// Frame: DICOM patient LPS, millimetres. x towards the patient's left, y posterior, z superior;
// the face looks towards -y. The mid-sagittal plane is x = 0, Frankfort horizontal (Po-Or) is
// the plane z = 0 and sella S sits at (0, 0, 20). The default phantom is exactly mirror
// symmetric about x = 0 (noise aside): every part is defined on |x|.
//
// Default cephalometry (mid-sagittal): S-N 70 mm, SN 7 deg to Frankfort, SNA 82, SNB 80,
// ANB 2 deg, Class I molars and incisors (overjet and overbite 2.5 mm).
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string_view>

#include "ceph/landmark.h"
#include "core/volume.h"

namespace maxillo {

// Tissue labels of Phantom::labels (values are stable: files and tests rely on them).
enum class Tissue : uint8_t {
  kAir = 0,         // outside air and airways open to it (nasal cavity, nostrils, ear canals)
  kSoftTissue = 1,  // skin, fat, muscle, tongue, brain, eyes, pituitary
  kBone = 2,        // cranium and facial skeleton (maxilla with palate, zygomas, nasal bones)
  kUpperTooth = 3,  // maxillary teeth (enamel crowns, dentine roots)
  kSinusAir = 4,    // air of the two maxillary sinuses (closed cavities, no ostium)
  kHeadRest = 5,    // curved plastic head rest under the occiput
  kLowerTooth = 6,  // mandibular teeth
  kMandible = 7,    // mandibular bone
  kTable = 8,       // flat CT table plate below the head rest
};
inline constexpr int kTissueCount = 9;
std::string_view tissue_name(Tissue tissue);

enum class SkeletalClass { I, II, III };
// Partial volume: Blurred applies a [1 2 1]/4 kernel along each axis to the HU (labels stay sharp).
enum class PartialVolume { Blurred, Sharp };

// Where the head lies in the scanner and how big it is: a similarity from the anatomy frame
// described above to the scanner's LPS frame. The identity is the head as designed, straight
// and centred; another placement is another patient's size in another pose (the CT is
// voxelised in the placed frame, not re-headered, so the voxels are not aligned with the anatomy).
struct PhantomPlacement {
  double scale = 1;  // about the anatomy frame's origin (mid-porion at Frankfort level)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // mm

  Eigen::Vector3d to_scanner(const Eigen::Vector3d& anatomy) const { return rotation * (scale * anatomy) + shift; }
  Eigen::Vector3d to_anatomy(const Eigen::Vector3d& scanner) const {
    return rotation.transpose() * (scanner - shift) / scale;
  }
  bool is_identity() const { return scale == 1 && rotation.isIdentity(0) && shift.isZero(0); }
};

// A cone-beam scanner's flavour (absent: a calibrated CT). Its grey values are not Hounsfield
// units: a linear map of the attenuation chosen by the maker, darkened towards the axis
// (cupping: scatter and beam hardening), crossed by streaks from metal fillings, and only a
// cylinder of the head is reconstructed (outside it: the padding value).
struct ConeBeamFlavour {
  double grey_per_hu = 1;       // slope of the grey value against HU
  double grey_of_air = 0;       // grey value of air (-1000 HU)
  double cupping = 0.12;        // attenuation lost on the axis relative to the field's rim (fraction)
  bool metal_fillings = true;   // amalgam in the four first molars, with streaks
  double streak_hu = 350;       // amplitude of the streaks next to the metal (HU)
  double field_radius_mm = 85;  // the reconstructed cylinder about the scanner's z axis
  double field_top_mm = 45, field_bottom_mm = -95;  // its ends (scanner z, mm)
  Eigen::Vector2d field_centre_mm{0, -30};          // its axis (scanner x, y)
  double padding_grey = 0;                          // the value outside the cylinder (scanners pad with air's or lower)

  // Whether a point of the scanner frame lies in the reconstructed cylinder.
  bool reconstructs(const Eigen::Vector3d& scanner) const {
    return scanner.z() >= field_bottom_mm && scanner.z() <= field_top_mm &&
           (scanner.head<2>() - field_centre_mm).norm() <= field_radius_mm;
  }
};

struct PhantomSpec {
  double spacing_mm = 1.0;  // isotropic voxel spacing; the default (1 mm) takes ~1-2 s
  // Anterior displacement (mm, + = forward, - = retrusion) of the maxilla below the Le Fort I
  // level (upper teeth, palate, alveolar process, upper lip follow).
  double maxillary_advancement_mm = 0;
  // Anterior displacement (mm) of the mandibular body and chin (+ = protrusion, Class III);
  // the rami and condyles stay in place, the body between them is stretched.
  double mandibular_protrusion_mm = 0;
  // Lateral displacement (mm, + = the patient's left, LPS +x) of the mandibular body and chin,
  // the rami and condyles staying in place: a chin deviated to one side (asymmetry).
  double mandibular_deviation_mm = 0;
  double noise_sigma_hu = 15;  // Gaussian noise added to the HU; 0 = none
  uint32_t noise_seed = 20240521;
  PartialVolume partial_volume = PartialVolume::Blurred;
  PhantomPlacement placement{};                // identity: the designed head, straight and centred
  std::optional<ConeBeamFlavour> cone_beam{};  // absent: Hounsfield units
};

// Class I: no displacement. Class II: mandible 5 mm retruded (ANB ~ 5 deg).
// Class III: maxilla 2 mm retruded, mandible 5 mm protruded (ANB ~ -3 deg).
PhantomSpec phantom_spec_for_class(SkeletalClass skeletal_class);

struct Phantom {
  Volume ct;              // HU, int16
  LabelVolume labels;     // Tissue values, same geometry as ct
  LandmarkSet landmarks;  // LPS mm, see phantom_landmarks.h for the list and definitions
};

// Deterministic: the same spec gives the same bytes.
Phantom make_phantom(const PhantomSpec& spec);

// The landmarks make_phantom(spec) places, without voxelising the volume (milliseconds rather
// than a second: for cohorts of phantoms).
LandmarkSet make_phantom_landmarks(const PhantomSpec& spec);

}  // namespace maxillo
