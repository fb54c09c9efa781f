#pragma once
// Soft tissue prediction for a planned bone move (thesis ch. 6), from labelled volumes to the
// predicted skin:
//   1. the face region: soft tissue below the orbits (optionally the brows, without the brain's
//      base that lies there, imaging/enclosed_tissue.h), above a plane under the chin, in front of
//      the ears, optionally with the nose's root and the glabella above the orbits
//      (softtissue/face_region.h, default_face_region below);
//   2. a tet mesh of it (CGAL, tetmesh/labelled_tet_mesher.h) within the tet budget, parted
//      between the lips (casework/softtissue/lip_parting.h), its cartilaginous nose stiffer than the rest
//      (casework/softtissue/nasal_cartilage.h);
//   3. join points from the bone segments and their planned moves, fixed nodes on the cuts
//      (softtissue/bone_attachment.h);
//   4. the static solve with the chosen model's solver from the table of models
//      (softtissue/soft_tissue_model.h: mass tensor, linear FEM, mass-spring or non-linear FEM);
//   5. the displacement mapped onto the dense skin by the shape functions (eq. 13).
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casework/softtissue/lip_parting.h"
#include "casework/softtissue/nasal_cartilage.h"
#include "ceph/landmark.h"
#include "core/triangle_mesh.h"
#include "core/volume.h"
#include "records/soft_tissue_timings.h"
#include "softtissue/bone_attachment.h"
#include "softtissue/soft_tissue_model.h"
#include "softtissue/element_quality.h"
#include "softtissue/face_region.h"
#include "softtissue/mesh_parting.h"
#include "tetmesh/labelled_tet_mesher.h"

namespace maxillo::casework {

struct SoftTissueOptions {
  softtissue::SoftTissueModel model = softtissue::SoftTissueModel::kMassTensor;
  double poisson_ratio = 0.46;
  double young_modulus_mpa = 0.003;     // scales forces only: the static answer does not depend on it
  double gradient_threshold_mm = 1e-3;  // local dynamic stop criterion (mass tensor, mass-spring)
  int max_sweeps = 100000;              // their sweep limit: a model still moving after it is an error, not an answer
  tetmesh::TetMeshingOptions meshing;
  softtissue::AttachmentOptions attachment;
  double skin_binding_mm = 4.0;         // skin farther from the model keeps its place
  std::vector<uint8_t> soft_labels{1};  // phantom and CT segmentation both use 1 for soft tissue
  // The region's second piece, the nose's root and the glabella (default_face_region). Off by
  // default: the non-linear FEM does not converge on the phantom with it (issue 34).
  bool nose_root = false;
  // The region's top at the brows, 8 mm above the nasion, with the brain's base it holds left out
  // (imaging/enclosed_tissue.h), so that the model's edge lies where the move has died out (issue
  // 34); false: at the orbitales, as until 2026-11-30, where the cut held the nasal dorsum and
  // the cheeks that still moved (0.5 mm on the cadaver at 6 mm).
  bool top_at_brows = true;
  // The model parted between the lips at their cleft (casework/softtissue/lip_parting.h), so that they slide
  // on each other instead of being tied node to node. Off by default: the parting follows the
  // tets' faces, up to half a cell from the cleft, and on the phantom meshed at 5 mm it gave the
  // lower lip more of the advancement, not less (issue 34, docs/ARCHITECTURE.md).
  bool part_lips = false;
  // Young's modulus of the cartilaginous nose over the soft tissue's (casework/softtissue/nasal_cartilage.h);
  // 1 makes the face one homogeneous tissue, as the thesis' models were.
  double nose_stiffness = kNasalCartilageStiffness;
};

struct SoftTissueInput {
  const LabelVolume* tissues = nullptr;        // tissue labels (soft tissue = options.soft_labels)
  const LabelVolume* segments = nullptr;       // bone segments (planning/osteotomy.h), same geometry
  const TriangleMesh* skin = nullptr;          // dense pre-operative skin surface
  LandmarkSet landmarks;                       // for the region's planes
  std::map<uint8_t, Eigen::Isometry3d> moves;  // segment label -> planned rigid move
};

// How the face's tet mesh met its budget (tetmesh::TetMeshingResult's numbers): a mesh over its
// budget is kept, and the report and simulation.json say so.
struct MeshingOutcome {
  double cell_size_mm = 0;  // of the meshing kept
  int attempts = 0;         // meshings run, each coarser than the last
  int tet_budget = 0;       // the most tetrahedra asked for
  bool over_budget(const softtissue::TetMesh& mesh) const { return mesh.tet_count() > tet_budget; }
};

struct SoftTissuePrediction {
  softtissue::SoftTissueModel model = softtissue::SoftTissueModel::kMassTensor;  // the model that solved it
  softtissue::TetMesh mesh;
  softtissue::MeshQuality quality;
  softtissue::BoundaryConditions bc;
  Eigen::MatrixX3d node_displacement;  // n x 3, mm
  int iterations = 0;                  // sweeps (MTM, MSM) or Krylov iterations (FEM)
  TriangleMesh skin_after;             // the skin's vertices moved, same faces
  Eigen::MatrixX3d skin_displacement;  // per skin vertex, mm
  int skin_vertices_bound = 0;
  std::vector<uint8_t> skin_on_bone;                // per skin vertex, the segment of the exposed bone under it, else 0
  std::map<uint8_t, Eigen::Isometry3d> bone_moves;  // the segments' moves it was solved for
  std::optional<LipParting> lips;                   // the face model's parting between the lips
  softtissue::Parting lips_parted;
  int nose_tets = 0;             // the face model's tets of the cartilaginous nose
  int nose_nodes_uncarried = 0;  // its nodes touching moved bone, left free (nasal_cartilage.h)
  int64_t enclosed_voxels = 0;   // FaceModel::enclosed_voxels of its model
  int squeezed_nodes_freed =
      0;  // sliding nodes pinched between moved and unmoved bone, left free (softtissue/squeezed_nodes.h)
  double nose_stiffness = 1;  // their Young's modulus over the soft tissue's
  // Per skin vertex: +1 upper lip, -1 lower lip (bound to a tet parted there), else 0.
  std::vector<int8_t> skin_lip_side;
  // Per plane of the face region (RegionShape::planes() order, named by face_region_plane_names),
  // the largest move within 5 mm inside it where it cuts tissue (softtissue/boundary_move.h).
  std::vector<double> boundary_move_mm;
  softtissue::RegionShape region;  // the face model's
  MeshingOutcome meshing;
  std::string face_model_key;  // FaceModel::key of the model it was solved on
  records::SoftTissueTimings seconds;
};

// The face region from landmarks: the face below the orbitales (with `top_at_brows` and N, below
// a plane 8 mm above the nasion, and build_face_model leaves the brain's base it holds out),
// above a plane 15 mm below menton, in front of the porions; with `nose_root` and N, a second piece for the nose's root and the
// glabella: above the orbitales, below a plane 15 mm above the nasion, in front of a plane 10 mm
// behind it (the eyelids and the front of the eyes; the brain behind the forehead stays out), so
// that no cut runs through the nose. Or, Po and Me are needed (missing ones -> Error naming them).
softtissue::RegionShape default_face_region(const LandmarkSet& landmarks, bool nose_root = false,
                                            bool top_at_brows = false);
// Where each of the region's planes lies, in its planes() order: "at the brows", ... (the names
// default_face_region gave them; "plane N" for a plane it did not name).
std::vector<std::string> face_region_plane_names(const softtissue::RegionShape& region);

// Steps 1-2, which look at no move: the face region and its tet mesh. Built once for a case, one
// model serves every move on the same tissues and landmarks (the planned move, the moves found after
// surgery); `key` names what it was built from, and predict_soft_tissue refuses a model whose key
// is not its input's.
struct FaceModel {
  softtissue::RegionShape region;
  softtissue::TetMesh mesh;
  std::optional<LipParting> lips;   // where the mesh was parted between the lips (none: not asked for, or no stomion)
  softtissue::Parting lips_parted;  // the faces parted there
  int nose_tets = 0;                // tets given the nose's stiffness (0: none asked for, or no nose region)
  std::vector<uint8_t> nose_nodes;  // per node, 1 for a corner of those tets: no moved bone carries them
  softtissue::MeshQuality quality;
  MeshingOutcome meshing;
  int64_t enclosed_voxels = 0;  // with top_at_brows: the region's tissue shut in by bone (the brain's base), left out
  double region_seconds = 0, meshing_seconds = 0;
  std::string key;
};
FaceModel build_face_model(const LabelVolume& tissues, const LandmarkSet& landmarks, const SoftTissueOptions& options);
// SHA-256 over the tissue labels, the region's pieces and planes, the soft labels and the meshing options.
std::string face_model_key(const LabelVolume& tissues, const LandmarkSet& landmarks, const SoftTissueOptions& options);

// `model`: the case's face model when the caller has it (build_face_model with the same tissues,
// landmarks and options; Error(kProcessing) otherwise), else it is built here. The same answer
// either way.
SoftTissuePrediction predict_soft_tissue(const SoftTissueInput& input, const SoftTissueOptions& options = {},
                                         const FaceModel* model = nullptr);

// Re-solves an existing model (same mesh and boundary nodes) with another model or material,
// for the uncertainty band; fills node_displacement, skin_after and skin_displacement.
SoftTissuePrediction resolve_soft_tissue(const SoftTissuePrediction& base, const TriangleMesh& skin,
                                         const SoftTissueOptions& options);

// The displacement at arbitrary points (e.g. soft tissue landmarks), by the shape functions.
Eigen::MatrixX3d displacement_at(const SoftTissuePrediction& prediction, const VertexMatrix& points,
                                 double max_distance_mm);

}  // namespace maxillo::casework
