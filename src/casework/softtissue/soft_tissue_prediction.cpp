#include "casework/softtissue/soft_tissue_prediction.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "casework/softtissue/exposed_bone.h"
#include "imaging/enclosed_tissue.h"
#include "ceph/landmark_frame.h"
#include "softtissue/boundary_move.h"
#include "core/error.h"
#include "core/log.h"
#include "core/sha256.h"
#include "render/anatomical_views.h"
#include "softtissue/shape_function_mapping.h"
#include "softtissue/squeezed_nodes.h"

namespace maxillo::casework {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

constexpr double kBelowMentonMm = 15;
// The region's top with SoftTissueOptions::top_at_brows: a plane through the brows, where the forehead's tissue lies on the unmoved
// frontal bone and the move has died out (issue 34: at the orbitales, the cut ran through the
// nasal dorsum and the cheeks, and held them, 0.5 mm from a moving node on the cadaver at 6 mm).
// At 15 mm above the nasion the skin's gradient rose (P99.9 1.19 against 0.94 mm per mm) and the
// non-linear FEM stopped at 98 % of the cadaver's 6 mm advancement.
constexpr double kBrowsAboveNasionMm = 8;
// Above the orbitales the region holds the brain's base (the frontal lobes on the orbits' roofs,
// the temporal poles in the middle cranial fossae), joined to the orbits and the face through
// foramina; a ball of this radius parts them (imaging/enclosed_tissue.h). At 3 mm the orbits'
// contents and the brain stayed one piece on the cadaver head.
constexpr double kForamenRadiusMm = 4;
constexpr uint8_t kOutsideAir = 0;  // both label sets: the air around the head and in the airways
// The nose's root and the glabella up to here: where the forehead's tissue lies on unmoved bone, so
// that the move has died out (the cadaver head: under 0.01 mm at this cut for a 6 mm advancement).
constexpr double kAboveNasionMm = 15;
// Behind the nasion the frontal bone and the eyes begin; the brain lies more than this behind it.
constexpr double kBehindNasionMm = 10;

// The model's solver from the table (softtissue/soft_tissue_model.h), with the options' material
// and stop rule; `assembly_seconds` gets its set-up time.
softtissue::ModelSolution solve(const softtissue::TetMesh& mesh, const softtissue::BoundaryConditions& bc,
                                const SoftTissueOptions& o, double& assembly_seconds) {
  const softtissue::ModelSolveOptions solve_options{
      {o.young_modulus_mpa, o.poisson_ratio}, o.gradient_threshold_mm, o.max_sweeps};
  auto solution = softtissue::solve_model(o.model, mesh, bc, solve_options);
  assembly_seconds = solution.assembly_seconds;
  return solution;
}

// Per skin vertex, the lip whose tet it is bound to: +1 upper, -1 lower, 0 elsewhere.
std::vector<int8_t> lip_sides(const softtissue::TetMesh& mesh, const softtissue::ShapeFunctionMapping& mapping,
                              const LipParting& lips) {
  std::vector<int8_t> side(mapping.tet.size(), 0);
  for (size_t v = 0; v < mapping.tet.size(); ++v) {
    if (mapping.tet[v] < 0) continue;
    const Eigen::Vector3d centroid = softtissue::tet_corners(mesh, mapping.tet[v]).colwise().mean().transpose();
    side[v] = int8_t(lips.side(centroid));
  }
  return side;
}

// The model's move onto the skin; skin on exposed teeth or bone moves with its segment.
void map_to_skin(SoftTissuePrediction& prediction, const TriangleMesh& skin, double binding_mm) {
  auto start = Clock::now();
  const auto mapping = softtissue::init_shape_function_mapping(prediction.mesh, skin.vertices, binding_mm);
  if (prediction.lips) prediction.skin_lip_side = lip_sides(prediction.mesh, mapping, *prediction.lips);
  prediction.skin_displacement = softtissue::map_displacement(prediction.mesh, mapping, prediction.node_displacement);
  if (!prediction.skin_on_bone.empty())
    move_exposed_bone(skin, prediction.skin_on_bone, prediction.bone_moves, prediction.skin_displacement);
  prediction.skin_vertices_bound = mapping.bound_count();
  prediction.skin_after = skin;
  prediction.skin_after.vertices += prediction.skin_displacement;
  prediction.seconds.mapping = seconds_since(start);
}

}  // namespace

softtissue::RegionShape default_face_region(const LandmarkSet& landmarks, bool nose_root, bool top_at_brows) {
  const auto frame = anatomical_frame(landmarks);
  const auto orbitale = bilateral_mean(landmarks, "Or"), porion = bilateral_mean(landmarks, "Po");
  if (!orbitale || !porion)
    throw Error(ErrorCode::kBadValue, "face region", "needs the landmarks Or and Po (or their R/L)");
  const Eigen::Vector3d menton = require_landmark(landmarks, "Me", "face region");
  const auto nasion = find_landmark(landmarks, "N");
  const bool at_brows = top_at_brows && nasion;
  const Eigen::Vector3d top = at_brows ? Eigen::Vector3d(*nasion + kBrowsAboveNasionMm * frame.superior) : *orbitale;
  const softtissue::RegionPlane below_top{top, -frame.superior},
      above_chin{menton - kBelowMentonMm * frame.superior, frame.superior}, before_ears{*porion, frame.anterior};
  softtissue::RegionShape shape(std::vector{below_top, above_chin, before_ears});
  shape.plane_names = {at_brows ? "at the brows" : "below the orbits", "under the chin", "in front of the ears"};
  if (nose_root && nasion) {
    shape.pieces.push_back({{*orbitale, frame.superior},                                     // above the orbits
                            {*nasion + kAboveNasionMm * frame.superior, -frame.superior},    // below the forehead's cut
                            {*nasion - kBehindNasionMm * frame.anterior, frame.anterior}});  // in front of the eyes
    shape.plane_names.insert(shape.plane_names.end(),
                             {"above the orbits (nose root)", "the forehead's cut", "in front of the eyes"});
  }
  return shape;
}

std::vector<std::string> face_region_plane_names(const softtissue::RegionShape& region) {
  const size_t planes = region.planes().size();
  std::vector<std::string> named;
  for (size_t i = 0; i < planes; ++i)
    named.push_back(i < region.plane_names.size() ? region.plane_names[i] : "plane " + std::to_string(i + 1));
  return named;
}

std::string face_model_key(const LabelVolume& tissues, const LandmarkSet& landmarks, const SoftTissueOptions& options) {
  // Every field of the meshing options is in the key: a new field must be added here too.
  static_assert(sizeof(tetmesh::TetMeshingOptions) == 56, "update face_model_key for the new meshing option");
  Sha256 hash;
  hash.update(std::string_view(reinterpret_cast<const char*>(tissues.labels.data()), tissues.labels.size()));
  char text[512];
  const auto& g = tissues.geometry;
  std::snprintf(text, sizeof text, "grid %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g\n", g.size.x(), g.size.y(),
                g.size.z(), g.spacing.x(), g.spacing.y(), g.spacing.z(), g.origin.x(), g.origin.y(), g.origin.z());
  hash.update(text);
  for (const auto& piece : default_face_region(landmarks, options.nose_root, options.top_at_brows).pieces) {
    hash.update("piece\n");
    for (const auto& plane : piece) {
      std::snprintf(text, sizeof text, "plane %.17g %.17g %.17g %.17g %.17g %.17g\n", plane.point.x(), plane.point.y(),
                    plane.point.z(), plane.normal.x(), plane.normal.y(), plane.normal.z());
      hash.update(text);
    }
  }
  for (uint8_t label : options.soft_labels) hash.update("label " + std::to_string(label) + "\n");
  if (options.top_at_brows) hash.update("tissue shut in by bone left out\n");  // imaging/enclosed_tissue.h
  if (options.part_lips) hash.update("lips parted\n");  // where: from the labels and landmarks hashed above
  if (options.nose_stiffness != 1) {                    // where: from the landmarks hashed above
    std::snprintf(text, sizeof text, "nose stiffness %.17g\n", options.nose_stiffness);
    hash.update(text);
  }
  const auto& m = options.meshing;
  // No time limit on the optimisers (tetmesh/labelled_tet_mesher.h) since 2026-11-29: earlier
  // models were meshed with one, and their keys, which named it, no longer match.
  std::snprintf(text, sizeof text, "meshing %.17g %.17g %.17g %.17g %d %.17g %d\n", m.cell_size_mm, m.facet_distance_mm,
                m.facet_angle_deg, m.radius_edge_ratio, m.max_tets, m.sliver_bound_deg, m.random_seed);
  hash.update(text);
  return hash.hex_digest();
}

FaceModel build_face_model(const LabelVolume& tissues, const LandmarkSet& landmarks, const SoftTissueOptions& options) {
  FaceModel model;
  model.key = face_model_key(tissues, landmarks, options);
  auto start = Clock::now();
  model.region = default_face_region(landmarks, options.nose_root, options.top_at_brows);
  auto region = softtissue::face_region(tissues, options.soft_labels, model.region);
  if (options.top_at_brows) {
    auto enclosed = without_enclosed_tissue(region, tissues, kOutsideAir, kForamenRadiusMm);
    model.enclosed_voxels = enclosed.enclosed_voxels + enclosed.loose_voxels;
    log::debug("face region: ", model.enclosed_voxels, " voxels of tissue shut in by bone left out");
    region = std::move(enclosed.kept);
  }
  model.region_seconds = seconds_since(start);

  start = Clock::now();
  auto meshed = tetmesh::mesh_label(region, 1, options.meshing);
  model.mesh = std::move(meshed.mesh);
  if (options.part_lips)
    if ((model.lips = lip_parting(tissues, options.soft_labels, landmarks))) {
      model.lips_parted = softtissue::part_mesh(model.mesh, model.lips->side);
      log::debug("lips parted at the stomion (", model.lips->stomion.transpose(), "): ", model.lips_parted.faces,
                 " faces, ", model.lips_parted.added_nodes, " nodes added");
    }
  if (options.nose_stiffness != 1)
    if (const auto nose = nasal_cartilage_region(landmarks)) {
      model.nose_tets = stiffen_region(model.mesh, *nose, options.nose_stiffness);
      model.nose_nodes = region_tet_nodes(model.mesh, *nose);
    }
  model.meshing = {meshed.cell_size_mm, meshed.attempts, meshed.tet_budget};
  model.quality = softtissue::mesh_quality(model.mesh);
  model.meshing_seconds = seconds_since(start);
  return model;
}

SoftTissuePrediction predict_soft_tissue(const SoftTissueInput& input, const SoftTissueOptions& options,
                                         const FaceModel* given) {
  const FaceModel built = given ? FaceModel{} : build_face_model(*input.tissues, input.landmarks, options);
  if (given && given->key != face_model_key(*input.tissues, input.landmarks, options))
    throw Error(ErrorCode::kProcessing, "soft tissue model",
                "the face model given was built from other tissues, landmarks or meshing options");
  const FaceModel& model = given ? *given : built;
  SoftTissuePrediction prediction;
  prediction.model = options.model;
  prediction.mesh = model.mesh;
  prediction.lips = model.lips;
  prediction.lips_parted = model.lips_parted;
  prediction.nose_tets = model.nose_tets;
  prediction.enclosed_voxels = model.enclosed_voxels;
  prediction.nose_stiffness = model.nose_tets > 0 ? options.nose_stiffness : 1;
  prediction.meshing = model.meshing;
  prediction.face_model_key = model.key;
  prediction.quality = model.quality;
  prediction.seconds.region = given ? 0 : model.region_seconds;
  prediction.seconds.meshing = given ? 0 : model.meshing_seconds;

  auto start = Clock::now();
  auto attachment = softtissue::attach_to_bone(prediction.mesh, *input.segments, input.moves, model.region,
                                               options.attachment, model.nose_nodes);
  prediction.bc = std::move(attachment.bc);
  prediction.nose_nodes_uncarried = attachment.uncarried_nodes;
  prediction.squeezed_nodes_freed = softtissue::release_squeezed_sliding_nodes(prediction.mesh, prediction.bc);
  log::debug("sliding nodes pinched between moved and unmoved bone, left free: ", prediction.squeezed_nodes_freed);
  prediction.seconds.attachment = seconds_since(start);
  if (softtissue::count_nodes(prediction.bc, softtissue::NodeConstraint::kFixed) == 0)
    throw Error(ErrorCode::kProcessing, "soft tissue model",
                "no node touches unmoved bone or a cut: the model would float");

  start = Clock::now();
  auto solved = solve(prediction.mesh, prediction.bc, options, prediction.seconds.assembly);
  prediction.node_displacement = std::move(solved.displacement);
  prediction.iterations = solved.iterations;
  prediction.seconds.solve = seconds_since(start) - prediction.seconds.assembly;
  prediction.region = model.region;
  prediction.boundary_move_mm =
      softtissue::largest_move_near_planes(prediction.mesh, prediction.node_displacement, model.region);

  prediction.skin_on_bone = exposed_bone_segments(*input.skin, *input.segments);
  prediction.bone_moves = input.moves;
  map_to_skin(prediction, *input.skin, options.skin_binding_mm);
  return prediction;
}

SoftTissuePrediction resolve_soft_tissue(const SoftTissuePrediction& base, const TriangleMesh& skin,
                                         const SoftTissueOptions& options) {
  SoftTissuePrediction prediction;
  prediction.model = options.model;
  prediction.mesh = base.mesh;
  prediction.quality = base.quality;
  prediction.bc = base.bc;
  prediction.meshing = base.meshing;
  prediction.face_model_key = base.face_model_key;
  prediction.skin_on_bone = base.skin_on_bone;
  prediction.bone_moves = base.bone_moves;
  prediction.lips = base.lips;
  prediction.lips_parted = base.lips_parted;
  prediction.nose_tets = base.nose_tets;
  prediction.nose_nodes_uncarried = base.nose_nodes_uncarried;
  prediction.squeezed_nodes_freed = base.squeezed_nodes_freed;
  prediction.enclosed_voxels = base.enclosed_voxels;
  prediction.nose_stiffness = base.nose_stiffness;
  prediction.region = base.region;
  auto start = Clock::now();
  auto solved = solve(prediction.mesh, prediction.bc, options, prediction.seconds.assembly);
  prediction.node_displacement = std::move(solved.displacement);
  prediction.iterations = solved.iterations;
  prediction.seconds.solve = seconds_since(start) - prediction.seconds.assembly;
  prediction.boundary_move_mm =
      softtissue::largest_move_near_planes(prediction.mesh, prediction.node_displacement, prediction.region);
  map_to_skin(prediction, skin, options.skin_binding_mm);
  return prediction;
}

Eigen::MatrixX3d displacement_at(const SoftTissuePrediction& prediction, const VertexMatrix& points,
                                 double max_distance_mm) {
  const auto mapping = softtissue::init_shape_function_mapping(prediction.mesh, points, max_distance_mm);
  return softtissue::map_displacement(prediction.mesh, mapping, prediction.node_displacement);
}

}  // namespace maxillo::casework
