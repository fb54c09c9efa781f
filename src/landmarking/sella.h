#pragma once
// Sella (S): the centre of the sella turcica, the pituitary fossa of the sphenoid bone. In the
// midsagittal section the fossa is a pocket of soft tissue walled in front (tuberculum sellae),
// behind (dorsum sellae) and below (its floor, or the sphenoid sinus's air behind a floor too
// thin to show as bone), open upwards to the brain. The pocket's pixels are those with such a
// wall within reach in those three directions; of the pockets that open into the cranial cavity
// the lowest is the fossa, and S is its centroid (the geometric centre the field defines). A
// circle fitted to its wall measures how much the pocket looks like a fossa.
#include <optional>

#include <Eigen/Core>

#include "landmarking/head_volume.h"

namespace maxillo::landmarking {

struct SellaFinding {
  Eigen::Vector3d centre{0, 0, 0};  // S, frame mm
  double radius_mm = 0;             // of the circle fitted to its wall (0: no fit)
  double pocket_mm2 = 0;            // area of the pocket in the section
  double fit_rms_mm = 0;            // of the wall points about the circle (1.5: no fit)
};

// The lowest pocket of a fossa's size in the section x = 0 within the window (frame mm) that
// opens into the cranial cavity; nullopt when there is none. Then `cut_by_the_field`, if given,
// says whether a pocket of a fossa's size ran into the scanned field's top edge (a fossa the
// field cuts, whose centre the pocket would misplace).
std::optional<SellaFinding> find_sella(const HeadVolume& v, const FrameBox& window, bool* cut_by_the_field = nullptr);

}  // namespace maxillo::landmarking
