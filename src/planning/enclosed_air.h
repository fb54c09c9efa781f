#pragma once
// Closed air cavities of a CT: air voxels (HU below a threshold) that no face-connected path of
// air links to the border of the volume. In a head these are the maxillary sinuses (and other
// closed air cells); the nasal airway, open to the outside through the nostrils, is not. The
// distractor checks need the sinus air. Read from the HU, not from a tissue segmentation: the
// segmentation's body mask is opened with a 3 mm ball, which can erase the thin medial sinus
// wall and join the sinus to the nasal airway.
#include <cstdint>

#include "core/volume.h"

namespace maxillo::planning {

// A copy of `tissues` (same grid as `ct`) with every enclosed air voxel relabelled `enclosed`.
LabelVolume with_enclosed_air(const LabelVolume& tissues, const Volume& ct, double air_below_hu, uint8_t enclosed);

}  // namespace maxillo::planning
