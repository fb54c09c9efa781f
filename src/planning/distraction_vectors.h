#pragma once
// Distraction vectors of the two trans-sinusal maxillary distractors (TS-MD, thesis ch. 2, 4, 5).
//
// The TS-MD is unidirectional: its screw turns in a cylinder on the upper plate (fixed to the
// cranium above the Le Fort I cut) and pushes the lower plate, screwed to the maxilla below the
// cut, along the screw axis. The screw lies in the maxillary sinus and enters it through a hole
// in the anterior maxillary wall (the entry point). So each distractor moves its entry point
// along its axis by its activation length, and the plan is: for the target move of the maxilla,
// where must each entry point go?
//
// The target maxillary move (in the planning frame, anatomical_moves.h), about a pivot (PNS by
// default, the posterior end of the palatal plane the source measures):
//   advancement      + forward (mm)
//   vertical         + down (extrusion), - up (impaction) (mm)
//   widening         transverse expansion (mm): the increase of the distance between homologous
//                    points of the two maxillary halves (molars, entry points), each half moving
//                    widening/2 outwards. This is what the source reports as "6 mm widening"
//                    (ch. 4b, patients EE and GS): it needs the Le Fort I segment split in the
//                    midline, and divergent vectors in the horizontal plane produce it.
//   midline shift    lateral displacement of the upper incisor midline (mm, + to the patient's
//                    left), made as a yaw about the pivot: the side away from the shift advances
//                    more. This is the source's "distracting one side more than the other".
//   rotation         pitch about the pivot (deg, + anterior end up, as alpha in ch. 5).
// Every half moves by T_half = (lateral shift of +-widening/2) o T_common, and the vector of a
// side is the displacement of its entry point: d = T_half(entry) - entry, axis = d / |d|,
// activation = |d|.
//
// With advancement a and widening w only, both vectors lie in the horizontal plane, each turned
// outwards from the mid-sagittal direction by atan(w / (2a)), so the angle between them (the
// divergence) is 2 atan(w / (2a)) and each activation is sqrt(a^2 + (w/2)^2): for a = 10 mm and
// w = 6 mm, 16.70 deg per side, 33.40 deg between the vectors, 10.44 mm per side. The divergence
// does not depend on how far apart the distractors sit: both halves translate.
//
// Counter-rotation: the source saw the maxilla rotate clockwise (anterior end down) during
// distraction (ch. 4b, 2 of 3 patients) and proposed "slightly counter-clockwise distraction
// vectors". counter_rotation_deg turns both axes by that angle anterior-end-up about the
// transverse axis, keeping their activation lengths (a divergent axis's elevation then comes out
// slightly less than the angle); 0 (the default) leaves the vectors as computed. A tilt cannot
// undo a pitch about the devices (forward_simulation.h): it lifts the anterior maxilla only.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "planning/anatomical_moves.h"

namespace maxillo::planning {

struct MaxillaryTarget {
  double advancement_mm = 0;
  double vertical_mm = 0;
  double widening_mm = 0;
  double midline_shift_mm = 0;
  double rotation_deg = 0;
  double counter_rotation_deg = 0;
};

enum class Side { Right, Left };
std::string_view side_name(Side side);  // "right", "left"
// +1 for the patient's left half, -1 for the right (the frame's transverse axis points left).
inline double outward_sign(Side side) { return side == Side::Left ? 1.0 : -1.0; }

// Where the maxilla is: the pivot of the move and the incisor point that the midline shift is
// measured at (U1), both LPS mm.
struct MaxillaryReference {
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  Eigen::Vector3d incisor = Eigen::Vector3d::Zero();
};

struct DistractionVector {
  Side side = Side::Right;
  Eigen::Vector3d entry = Eigen::Vector3d::Zero();  // LPS mm, on the anterior maxillary wall
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();   // unit, LPS: the direction the maxilla moves
  double activation_mm = 0;
  // The axis in frame terms: angle out of the mid-sagittal direction in the horizontal plane
  // (+ outwards = towards this side), and elevation (+ anterior end up), degrees.
  double outward_deg = 0;
  double elevation_deg = 0;
};

struct DistractionVectors {
  DistractionVector right, left;
  // Sum of the two outward angles: the angle between the axes in the horizontal plane,
  // + divergent (widening), - convergent.
  double divergence_deg = 0;
  double angle_deg = 0;  // 3D angle between the axes
};

// The common rigid move of the maxilla (both halves before widening) as an LPS transform.
Eigen::Isometry3d common_move(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref);
// The move of one half: common move then widening/2 outwards along the frame's transverse axis.
Eigen::Isometry3d half_move(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref,
                            Side side);
// The yaw (deg) that shifts the incisor by midline_shift_mm about the pivot. Error(kBadValue)
// when the shift exceeds the incisor's distance in front of the pivot.
double midline_yaw_deg(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref);

DistractionVectors distraction_vectors(const PlanningFrame& frame, const MaxillaryTarget& target,
                                       const MaxillaryReference& ref, const Eigen::Vector3d& entry_right,
                                       const Eigen::Vector3d& entry_left);

// The analytic divergence (deg) for advancement a and widening w only: 2 atan(w / 2a).
double divergence_for_widening_deg(double advancement_mm, double widening_mm);

}  // namespace maxillo::planning
