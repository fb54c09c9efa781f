#pragma once
// What a face prediction reports (simulate's simulation.json, `maxillo --json simulate`): one
// struct with one writer and one strict reader. The reader fails with Error(kArchiveCorrupt)
// naming the document and the key path on a missing or mistyped field; a document without
// "format_version" has version 1's layout, a newer one is refused.
#include <optional>
#include <string>
#include <vector>

#include "core/json.h"
#include "records/soft_tissue_timings.h"

namespace maxillo::records {

struct SimulationSummary {
  // 2: the report's facts (plan_text, mean_aspect_ratio, meshing_attempts, soft_landmarks) added,
  // required from this version on; a version 1 summary has none of them.
  // 3: profile_response (null when the plan does not advance the maxilla) and boundary_moves,
  // required from 3 on.
  // 4: nose_tets and nose_stiffness (the cartilaginous nose, casework/softtissue/nasal_cartilage.h) and
  // model_fallback (null when the model asked for ran), required from 4 on; before it every
  // model was one homogeneous tissue.
  // 5: sliding_nodes and bone_contact (how tissue on moved bone follows it,
  // softtissue/bone_attachment.h), required from 5 on; before it that tissue was tied to the bone.
  // 6: nose_nodes_uncarried (the cartilaginous nose's nodes on moved bone, left free), required
  // from 6 on; before it the moved bone carried them.
  // 7: squeezed_nodes_freed (sliding nodes pinched between moved and unmoved bone, left free,
  // softtissue/squeezed_nodes.h) and enclosed_voxels_left_out (the region's tissue shut in by
  // bone, imaging/enclosed_tissue.h), required from 7 on; before it neither was done.
  static constexpr int kFormatVersion = 7;

  struct UncertaintyBand {
    std::vector<std::string> runs;  // "mtm nu=0.46", ...
    double p95_mm = 0, max_mm = 0;  // spread of the runs about their mean, skin that moved
  };
  // A soft tissue landmark's predicted move in the anatomical frame (forward, up, to the left).
  struct LandmarkMove {
    std::string label;
    double forward_mm = 0, up_mm = 0, left_mm = 0, total_mm = 0;
  };

  // How the predicted profile follows a maxillary advancement, beside published series
  // (casework/softtissue/profile_response.h): stored with the published bands it was judged against.
  struct ProfilePoint {
    std::string label;      // Prn, dorsum, Sn, Ls, Li, PogS
    bool present = false;   // the landmark (the dorsum: the profile) was there
    double forward_mm = 0;  // the predicted skin's forward move there
    double ratio = 0;       // forward_mm / advancement_mm
    std::string published, source;
    std::optional<double> plausible_low, plausible_high;  // the band, as a fraction of the advancement
  };
  struct ProfileResponse {
    double advancement_mm = 0;          // the maxilla's forward move at `reference`
    std::string reference;              // the landmark it was read at ("A")
    bool other_segments_moved = false;  // the mandible or chin moved too: the series' bands are for the maxilla alone
    std::vector<ProfilePoint> points;
    double gradient_p999 = 0, gradient_max = 0;  // |du| / |dx| over the skin's edges that moved
    std::string steepest_near;                   // the landmark nearest to the steepest edge
    double steepest_near_mm = 0;                 // and its distance from it
  };

  // The model asked for when another one ran instead, and why (casework/softtissue/case_simulation.h).
  struct ModelFallback {
    std::string requested;  // model_name: "nfem"
    std::string reason;     // its error
  };

  // Where the model's region cuts tissue, and how far the tissue still moves just inside the cut.
  struct BoundaryMove {
    std::string where;           // "below the orbits", ...
    double largest_move_mm = 0;  // within 5 mm inside the cut (softtissue/boundary_move.h)
  };

  int format_version = kFormatVersion;
  std::string plan_text;  // the plan in one line, e.g. "maxilla 6.0 mm advancement"
  std::string model;      // model_name of the model that ran: "mtm", "fem", "msm", "nfem"
  double poisson_ratio = 0;
  bool plan_application_stored = false;  // the moves came from `plan apply`'s stored result
  int tetrahedra = 0, nodes = 0;
  double cell_size_mm = 0;
  int meshing_attempts = 0;  // meshings run, each coarser than the last
  int tet_budget = 0;
  bool over_tet_budget = false;
  double min_dihedral_deg = 0, mean_aspect_ratio = 0, max_aspect_ratio = 0;
  int prescribed_nodes = 0, fixed_nodes = 0, free_nodes = 0;
  int iterations = 0;
  double max_skin_displacement_mm = 0;
  SoftTissueTimings seconds;
  std::optional<UncertaintyBand> uncertainty;
  std::vector<LandmarkMove> soft_landmarks;         // those of the case's landmarks that are soft tissue ones
  std::optional<ProfileResponse> profile_response;  // version 3; none when the maxilla was not advanced
  std::vector<BoundaryMove> boundary_moves;         // version 3
  int nose_tets = 0;                                // version 4: tets of the cartilaginous nose (0: none)
  double nose_stiffness = 1;                        // version 4: their Young's modulus over the soft tissue's
  std::optional<ModelFallback> model_fallback;      // version 4: none when the model asked for ran
  int sliding_nodes = 0;                            // version 5: nodes sliding on moved bone
  std::string bone_contact = "tied";                // version 5: softtissue::contact_name of the attachment
  int nose_nodes_uncarried = 0;                     // version 6: the nose's nodes on moved bone, left free
  int squeezed_nodes_freed = 0;                     // version 7: sliding nodes pinched between bones, left free
  int64_t enclosed_voxels_left_out = 0;             // version 7: the region's tissue shut in by bone
};

Json to_json(const SimulationSummary& summary);
// `source` names the document in errors (its file, or "artefact N").
SimulationSummary read_simulation_summary(const Json& json, const std::string& source);

}  // namespace maxillo::records
