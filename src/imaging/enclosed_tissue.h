#pragma once
// Soft tissue shut in by bone, told apart from the face's. A face model that reaches above the
// orbits (issue 34: its edge where the move has died out) would take in the brain lying on the
// orbits' roofs and in the middle cranial fossae: tissue that no bone move of the face deforms,
// and that would spend the model's tetrahedra. The skull is not closed: nerves and vessels
// pass through foramina, so on a CT the brain's soft tissue touches the face's through necks a
// few millimetres wide (the optic canal about 5 mm, the foramen ovale 4-8 mm, the superior
// orbital fissure). An erosion by a ball of the neck's radius parts them. Each piece it leaves
// (a core) is open when it comes within the ball's radius (and a voxel) of the outside air, as
// every piece of the face does through its skin, and enclosed when bone, or other tissue's
// necks, lie all around it. The outside air is the air that reaches the box's border through
// openings wider than 5 mm (the nostrils, the mouth, the airway): a sinus drains through a
// narrower ostium, and its air lies against the brain wherever the wall between them is too
// thin for the CT (the cadaver head's sphenoid sinus). The enclosed cores, dilated back by the
// ball within the tissue, are left out, and then whatever no open core holds (the brain's rim,
// cut off from the face).
#include <cstdint>

#include "core/volume.h"

namespace maxillo {

struct EnclosedTissue {
  LabelVolume kept;             // 1: tissue held by an open core; same geometry as the input
  int64_t enclosed_voxels = 0;  // left out: within the ball of an enclosed core
  int64_t loose_voxels = 0;     // left out: not held by any open core (thin pieces, the brain's rim)
};

// `tissue`: 1 where the tissue is (e.g. a face region's soft tissue). `labels`: the CT's
// tissue labels on the same grid, `outside_air` the label of the air around the head and in the
// airways open to it. Works on the tissue's box (the ball's radius and two voxels around it).
EnclosedTissue without_enclosed_tissue(const LabelVolume& tissue, const LabelVolume& labels, uint8_t outside_air,
                                       double neck_radius_mm);

}  // namespace maxillo
