#pragma once
// Does the CT's header agree with the anatomy? A volume whose direction cosines or slice order
// are wrong (a flipped axis in a converted file, a scanner set up for another position) puts the
// face behind the head or the vertex below the chin in the patient frame, and then left and
// right cannot be trusted either: planning on it would move the wrong side.
//
// The check reads the anatomy alone, from two facts true of every head: the teeth lie at the
// front of the skull, and below most of its bone (the cranial vault). With the teeth located
// (enamel and restorations: the densest tissue of a head), the bone on either side of the plane
// through them across each patient axis is weighed:
//   imbalance(axis) = (bone beyond the plane towards +axis - bone towards -axis) / all bone,
// which is strongly positive along +y (posterior: cranium and spine lie behind the teeth) and
// positive along +z (superior: the vault lies above them) in a head whose header is right.
// The sign of each tells which way the face and the vertex point; a small imbalance (a field
// of view cut above the orbits, a scan of the jaws only) leaves the direction undetermined
// rather than guessed. The check cannot see a left-right mirror: a head is nearly symmetric.
#include <string>

#include <Eigen/Core>

#include "core/volume.h"
#include "imaging/grey_calibration.h"

namespace maxillo {

enum class AxisVerdict { kAsTheHeaderSays, kReversed, kUndetermined };

struct HeadOrientation {
  AxisVerdict face = AxisVerdict::kUndetermined;    // the face towards -y (anterior)?
  AxisVerdict vertex = AxisVerdict::kUndetermined;  // the vertex towards +z (superior)?
  bool sideways = false;               // the teeth's front-back imbalance is along x, not y: face points left or right
  Eigen::Vector3d imbalance{0, 0, 0};  // per patient axis x, y, z, in [-1, 1] (see above)
  Eigen::Vector3d teeth_centre{0, 0, 0};  // LPS mm
  double teeth_cm3 = 0;                   // the dense tissue the check stood on
  double bone_cm3 = 0;
  GreyCalibration grey;  // how the scan's values were read as HU

  // The header contradicts the anatomy: face posterior, vertex inferior or face sideways.
  bool contradicts_header() const {
    return face == AxisVerdict::kReversed || vertex == AxisVerdict::kReversed || sideways;
  }
  // One sentence a person reads: what was found, and why it matters.
  std::string finding() const;
};

struct HeadOrientationOptions {
  double dense_hu = 2000;         // enamel and restorations; cortical bone stays below
  double min_teeth_cm3 = 0.3;     // less is no dentition to stand on (edentulous, cropped): undetermined
  double bone_hu = 300;           // the bone weighed on either side
  double face_imbalance = 0.35;   // |imbalance| along the front-back axis needed to decide the face
  double vertex_imbalance = 0.2;  // along the vertical axis, to decide the vertex
};

// `ct` on its own grid, in HU or not (its values are read through estimate_grey_calibration, so
// a cone-beam scan or raw CT numbers are checked alike); its geometry is what is checked.
HeadOrientation check_head_orientation(const Volume& ct, const HeadOrientationOptions& options = {});

}  // namespace maxillo
