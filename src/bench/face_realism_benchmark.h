#pragma once
// `maxillo bench face --real`: does the predicted face move as published studies measure faces
// move (issue 34)? On the real cadaver head (../shared/data/cthead-stanford) with its landmarks
// found automatically: a Le Fort I advancement of each size asked for, solved with every soft
// tissue model on one face model; per model and advancement the forward move of the profile
// points (Prn, the dorsum 8 mm above it, Sn, Ls, Li, PogS) as a fraction of the advancement,
// the largest displacement gradient on the skin, and the time; the published figures beside them
// (casework/softtissue/profile_response.h).
#include <vector>

#include "casework/softtissue/nasal_cartilage.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "core/json.h"
#include "softtissue/bone_attachment.h"

namespace maxillo::bench {

struct FaceRealismOptions {
  std::vector<double> advancements_mm{3, 6, 9};
  bool free_cavities = false;  // moved bone carries only the tissue on its outer surface (AttachmentOptions)
  bool nose_root = false;      // the region's second piece above the orbits (SoftTissueOptions::nose_root)
  bool top_at_brows = true;    // the region's top at the brows, else the orbitales (SoftTissueOptions::top_at_brows)
  bool part_lips = false;      // the model parted between the lips (SoftTissueOptions::part_lips)
  double nose_stiffness = casework::kNasalCartilageStiffness;  // SoftTissueOptions::nose_stiffness
  // How tissue on the moved bone follows it (AttachmentOptions::moved_bone_contact).
  softtissue::MovedBoneContact bone_contact = softtissue::AttachmentOptions{}.moved_bone_contact;
  // The face model's meshing (SoftTissueOptions::meshing): a finer cell shows how much the
  // profile readings owe to the mesh.
  tetmesh::TetMeshingOptions meshing = casework::SoftTissueOptions{}.meshing;
  double poisson_ratio = casework::SoftTissueOptions{}.poisson_ratio;
};

// Error(kFileNotFound) when the cadaver head is absent. Figures: preparation_seconds,
// landmarks_by_hand, free_cavities, bone_contact (softtissue::contact_name), nose_root, top_at_brows, enclosed_voxels_left_out, part_lips, lips_parted_faces, nose_stiffness, poisson_ratio, nose_tets, face_model (tets, nodes, cell_mm, seconds), published (label,
// published, source, plausible_low/high), advancements_mm, runs (advancement_mm, model, title,
// seconds; error when it failed, else iterations, points: label, present, forward_mm, ratio,
// plausible; gradient_p999, gradient_max, moved_edges; boundary_move_mm, the largest move within
// 5 mm inside each region plane where it cuts tissue: below the orbits, under the chin, in front
// of the ears, and with nose_root above the orbits, under the forehead's cut, in front of the eyes;
// fixed_nodes, prescribed_nodes, sliding_nodes, nose_nodes_uncarried), peak_memory_mb.
Json run_face_realism_benchmark(const FaceRealismOptions& options);

std::string face_realism_text(const Json& figures);

}  // namespace maxillo::bench
