#pragma once
// The augmented dentition of one jaw (issue 30): the CT's teeth with their crowns replaced by the
// scanned ones, as a solid on a fine grid (its surface is traced by the caller). A CT shows the
// roots and the teeth's bodies well and the crowns poorly (fillings throw streaks across them);
// a dental scan shows the crowns exactly and nothing below the gingiva. Planning systems join the
// two at the gingival level; so does this, on voxels:
// 1. Height: along the jaw's occlusal direction (from the roots towards the opposing teeth).
// 2. The gingival level over each point of the occlusal plane: the lowest scan point that lies
//    on the CT's teeth (within on_teeth_mm) within neck_search_mm around it — the crown's neck,
//    where the scan leaves the tooth for the gingiva. No such point nearby: no level, the CT's
//    tooth is kept whole (a tooth the scan does not hold).
// 3. The scan's crowns: its triangles above the level (the gingiva and a cast's base lie below
//    it), drawn into the grid as a shell from the surface to shell_inward_mm behind it.
// 4. The CT's teeth of this jaw kept below the level + seal_mm (the overlap closes the neck
//    against the crown's shell); above it they are cut away, streaks and all.
// 5. Everything the outside reaches through neither the shell nor the kept CT is outside (a flood
//    fill from the grid's border); the rest is the augmented dentition.
// 6. Within crown_band_mm of a crown, where the scan's side agrees with the solid, the scan's
//    signed distance: a field whose zero level is the scanned crowns to a fraction of a voxel.
// Plain Eigen and core types, no toolkit.
#include <Eigen/Core>
#include <cstdint>

#include "core/triangle_mesh.h"
#include "core/volume.h"

namespace maxillo::dental {

struct AugmentedDentitionOptions {
  double voxel_mm = 0.25;
  double on_teeth_mm = 0.5;      // a scan point this close to the CT's teeth lies on a tooth
  double neck_search_mm = 4.0;   // how far around a point its crown's neck is looked for
  double seal_mm = 0.3;          // the CT kept this far above the neck, under the crown's shell
  double shell_inward_mm = 0.6;  // the crowns' shell this deep behind the scan's surface (closes the neck)
  double teeth_hu = 1500;        // the CT's teeth: at least this (HU), where the jaw's labels say so
  double margin_mm = 2.0;        // around the jaw's teeth and the scan
  double crown_band_mm = 0.75;   // step 6's band around the crowns
};

inline constexpr int16_t kFieldSaturation = 1000;  // µm: the field's value away from the crowns

struct AugmentedDentition {
  LabelVolume solid;  // 1 inside the augmented teeth, on a grid aligned with the CT's axes
  // The same as a field whose zero level is the surface (µm, positive inside, saturated at
  // ±kFieldSaturation): near a crown, minus the signed distance to the scan (step 6); elsewhere
  // the solid's inside or outside. Its zero level puts the crowns where the scan is, between the
  // grid's voxels, which the solid alone cannot.
  Volume field;
  std::vector<uint8_t> crown_vertex;              // per vertex of the placed scan: 1 on a crown (above the level)
  int64_t crown_voxels = 0;                       // voxels of the scan's crowns' shell
  int64_t ct_voxels_kept = 0, ct_voxels_cut = 0;  // the CT's teeth below and above the level
};

// `ct`: HU (a cone-beam scan converted); `jaw_labels`: the CT's labels, `jaw_label` marking this
// jaw's teeth; `ct_teeth`: their surface (LPS mm); `placed_scan`: the arch's scan in the CT's
// frame; `towards_occlusal`: unit, from this jaw's roots towards the opposing teeth. Throws
// Error(kProcessing) when no scan point lies on the CT's teeth.
AugmentedDentition augmented_dentition(const Volume& ct, const LabelVolume& jaw_labels, uint8_t jaw_label,
                                       const TriangleMesh& ct_teeth, const TriangleMesh& placed_scan,
                                       const Eigen::Vector3d& towards_occlusal,
                                       const AugmentedDentitionOptions& options = {});

}  // namespace maxillo::dental
