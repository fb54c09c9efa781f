#include "casework/softtissue/case_simulation.h"

#include <algorithm>
#include <cstdio>

#include "casework/landmarks/automatic_landmarks.h"
#include "ceph/landmark_frame.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "core/log.h"
#include "core/sha256.h"
#include "mesh/mesh_io.h"
#include "records/case_landmarks.h"
#include "casework/landmarks/case_orientation.h"
#include "casework/surfaces/case_surfaces.h"
#include "records/derivation.h"
#include "records/plan_archive.h"
#include "records/simulation_archive.h"
#include "casework/plan/planned_case.h"
#include "casework/softtissue/profile_response.h"
#include "planning/osteotomy.h"
#include "planning/plan_application.h"
#include "softtissue/vtu_writer.h"
#include "validation/distance_statistics.h"

namespace maxillo::casework {
namespace {

constexpr double kMovedSkinMm = 0.1;  // skin vertices that move less are left out of the band's statistics

LandmarkSet soft_landmarks_of(const LandmarkSet& landmarks) {
  LandmarkSet found;
  for (const auto& label : soft_tissue_landmark_labels())
    if (auto p = find_landmark(landmarks, label)) found.push_back({label, *p});
  return found;
}

// The moves of the case's soft tissue landmarks, in the anatomical frame.
std::vector<records::SimulationSummary::LandmarkMove> landmark_moves(const SoftTissuePrediction& prediction,
                                                                     const AnatomicalFrame& frame,
                                                                     const LandmarkSet& landmarks) {
  constexpr double kLandmarkBindingMm = 4.0;  // a landmark farther from the model is not moved
  VertexMatrix points(Eigen::Index(landmarks.size()), 3);
  for (size_t i = 0; i < landmarks.size(); ++i) points.row(Eigen::Index(i)) = landmarks[i].position.transpose();
  const auto u = displacement_at(prediction, points, kLandmarkBindingMm);
  std::vector<records::SimulationSummary::LandmarkMove> moves;
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const Eigen::Vector3d d = u.row(Eigen::Index(i)).transpose();
    moves.push_back({landmarks[i].label, d.dot(frame.anterior), d.dot(frame.superior), d.dot(frame.left), d.norm()});
  }
  return moves;
}

// The predicted profile's response to the maxilla's advancement, with the published bands it is
// judged against; none when the plan does not bring the maxilla forward.
std::optional<records::SimulationSummary::ProfileResponse> profile_response_record(const SimulationResult& result,
                                                                                   const SegmentMoves& moves,
                                                                                   const LandmarkSet& landmarks) {
  const auto advancement = maxillary_advancement(moves, landmarks, result.frame);
  if (!advancement) return std::nullopt;
  const auto& p = result.prediction;
  const ProfileResponse response = profile_response(result.skin_before, p.skin_displacement, result.frame, landmarks,
                                                    advancement->forward_mm, p.skin_on_bone, p.skin_lip_side);
  records::SimulationSummary::ProfileResponse record;
  record.advancement_mm = advancement->forward_mm;
  record.reference = advancement->reference;
  record.other_segments_moved = advancement->other_segments_moved;
  const auto& published = published_le_fort_advancement_response();
  for (size_t i = 0; i < response.points.size(); ++i) {
    const auto& point = response.points[i];
    record.points.push_back({point.label, point.present, point.forward_mm, point.ratio, published[i].published,
                             published[i].source, published[i].plausible_low, published[i].plausible_high});
  }
  record.gradient_p999 = response.gradient_p999;
  record.gradient_max = response.gradient_max;
  record.steepest_near = response.steepest_near;
  record.steepest_near_mm = response.steepest_near_mm;
  return record;
}

// What simulation.json holds, and the archive keeps, of a prediction.
records::SimulationSummary summarise(const SimulationResult& result, const SimulationRequest& request,
                                     const LandmarkSet& landmarks, const SegmentMoves& moves) {
  const auto& p = result.prediction;
  const SoftTissueOptions& options = request.options;
  records::SimulationSummary summary;
  summary.plan_text = request.plan_text.empty() ? request.plan.description : request.plan_text;
  summary.model = std::string(model_name(p.model));
  summary.model_fallback = result.fallback;
  summary.poisson_ratio = options.poisson_ratio;
  summary.plan_application_stored = result.reused_plan_application;
  summary.tetrahedra = p.mesh.tet_count();
  summary.nodes = p.mesh.node_count();
  summary.cell_size_mm = p.meshing.cell_size_mm;
  summary.meshing_attempts = p.meshing.attempts;
  summary.tet_budget = p.meshing.tet_budget;
  summary.over_tet_budget = p.meshing.over_budget(p.mesh);
  summary.min_dihedral_deg = p.quality.min_dihedral_deg;
  summary.mean_aspect_ratio = p.quality.mean_aspect_ratio;
  summary.max_aspect_ratio = p.quality.max_aspect_ratio;
  summary.prescribed_nodes = softtissue::count_nodes(p.bc, softtissue::NodeConstraint::kPrescribed);
  summary.fixed_nodes = softtissue::count_nodes(p.bc, softtissue::NodeConstraint::kFixed);
  summary.free_nodes = softtissue::count_nodes(p.bc, softtissue::NodeConstraint::kFree);
  summary.sliding_nodes = softtissue::count_nodes(p.bc, softtissue::NodeConstraint::kSliding);
  summary.bone_contact = softtissue::contact_name(options.attachment.moved_bone_contact);
  summary.iterations = p.iterations;
  summary.nose_tets = p.nose_tets;
  summary.nose_nodes_uncarried = p.nose_nodes_uncarried;
  summary.squeezed_nodes_freed = p.squeezed_nodes_freed;
  summary.enclosed_voxels_left_out = p.enclosed_voxels;
  summary.nose_stiffness = p.nose_stiffness;
  summary.max_skin_displacement_mm = p.skin_displacement.rows() ? p.skin_displacement.rowwise().norm().maxCoeff() : 0;
  summary.seconds = p.seconds;
  if (result.uncertainty)
    summary.uncertainty = {result.uncertainty->runs, result.uncertainty->p95_mm, result.uncertainty->max_mm};
  summary.soft_landmarks = landmark_moves(p, result.frame, soft_landmarks_of(landmarks));
  summary.profile_response = profile_response_record(result, moves, landmarks);
  const auto names = face_region_plane_names(p.region);
  for (size_t i = 0; i < p.boundary_move_mm.size() && i < names.size(); ++i)
    summary.boundary_moves.push_back({names[i], p.boundary_move_mm[i]});
  return summary;
}

// Writes the predicted skin, the model and simulation.json into `out`.
void write_outputs(SimulationResult& result, const std::filesystem::path& out) {
  const auto& p = result.prediction;
  Eigen::MatrixXd magnitude = p.skin_displacement.rowwise().norm();
  std::vector<PointArray> arrays{{"displacement", p.skin_displacement}, {"displacement_magnitude", magnitude}};
  if (result.uncertainty)
    arrays.push_back(
        {"uncertainty", Eigen::Map<const Eigen::VectorXd>(result.uncertainty->spread_mm.data(),
                                                          Eigen::Index(result.uncertainty->spread_mm.size()))});
  std::vector<std::filesystem::path>& files = result.files;
  files = {out / "predicted-skin.vtp", out / "predicted-skin.stl", out / "predicted-skin.ply",
           out / "soft-tissue-model.vtu", out / "simulation.json"};
  write_mesh(p.skin_after, files[0], arrays);
  write_mesh(p.skin_after, files[1]);
  write_mesh(p.skin_after, files[2]);
  softtissue::write_vtu(files[3], p.mesh, p.node_displacement, p.bc);
  write_file_atomically(files[4], to_json(result.summary).dump(2) + "\n");
}

// The prediction's summary and pictures into the archive, keyed by what it was made from: the
// case's CT, the plan and landmarks, the face model and the model's settings.
void store_outputs(Archive& archive, int64_t case_id, int64_t series, const SimulationResult& result,
                   const SimulationRequest& request, const LandmarkSet& landmarks) {
  const std::string plan_key =
      records::plan_application_key(sha256_hex(planning::serialise_plan(request.plan)), landmarks);
  const Json settings{{"face_model", result.prediction.face_model_key},
                      {"model", std::string(model_name(request.options.model))},  // asked for
                      {"poisson_ratio", request.options.poisson_ratio},
                      {"gradient_threshold_mm", request.options.gradient_threshold_mm},
                      {"skin_binding_mm", request.options.skin_binding_mm},
                      {"bone_contact", softtissue::contact_name(request.options.attachment.moved_bone_contact)},
                      {"uncertainty", request.uncertainty},
                      {"plan_text", result.summary.plan_text}};
  records::SimulationToStore stored{
      case_id,
      records::derivation_key({records::series_content_hash(archive, series), plan_key}, settings),
      result.summary,
      {}};
  for (const auto* pictures :
       {&result.views.before, &result.views.after, &result.views.displacement, &result.uncertainty_views})
    stored.pictures.insert(stored.pictures.end(), pictures->begin(), pictures->end());
  records::store_simulation(archive, stored);
}

}  // namespace

planning::Plan le_fort_advancement_plan(double advancement_mm) {
  planning::Plan plan;
  char text[64];
  std::snprintf(text, sizeof text, "Le Fort I, maxilla %.1f mm advancement", advancement_mm);
  plan.description = text;
  plan.osteotomies.le_fort_i = planning::CutSpec{planning::CutSpec::Kind::Default, planning::LeFortVariant::Low, {}};
  plan.osteotomies.pterygomaxillary = planning::CutSpec{};
  planning::SegmentMove move;
  move.segment = planning::Segment::kMaxilla;
  move.move.advancement_mm = advancement_mm;
  plan.moves.push_back(move);
  return plan;
}

Uncertainty prediction_uncertainty(const SoftTissuePrediction& base, const TriangleMesh& skin,
                                   const SoftTissueOptions& options) {
  Uncertainty band;
  std::vector<Eigen::MatrixX3d> answers{base.skin_displacement};
  char label[48];
  std::snprintf(label, sizeof label, "%s nu=%.2f", std::string(model_name(options.model)).c_str(),
                options.poisson_ratio);
  band.runs.push_back(label);
  auto add = [&](softtissue::SoftTissueModel model, double poisson) {
    SoftTissueOptions variant = options;
    variant.model = model;
    variant.poisson_ratio = poisson;
    answers.push_back(resolve_soft_tissue(base, skin, variant).skin_displacement);
    std::snprintf(label, sizeof label, "%s nu=%.2f", std::string(model_name(model)).c_str(), poisson);
    band.runs.push_back(label);
  };
  // The other models the table puts in the band (softtissue/soft_tissue_model.h says which, and why).
  for (const auto& other : softtissue::soft_tissue_models())
    if (other.in_uncertainty_band && other.model != options.model) add(other.model, options.poisson_ratio);
  // The Poisson ratios with linear FEM: near incompressibility (0.49) the point-wise iterations
  // of the mass tensor and mass-spring models converge so slowly that their stop criterion
  // would end them far from rest, and the band would show the solver, not the tissue.
  for (double poisson : {0.45, 0.49})
    if (poisson != options.poisson_ratio) add(softtissue::SoftTissueModel::kLinearFem, poisson);

  Eigen::MatrixX3d mean = Eigen::MatrixX3d::Zero(base.skin_displacement.rows(), 3);
  for (const auto& a : answers) mean += a;
  mean /= double(answers.size());
  band.spread_mm.assign(size_t(mean.rows()), 0.0);
  std::vector<double> moved;
  for (const auto& a : answers) {
    band.run_max_mm.push_back(a.rowwise().norm().maxCoeff());
    std::vector<double> off;
    for (Eigen::Index v = 0; v < a.rows(); ++v)
      if (answers[0].row(v).norm() > kMovedSkinMm) off.push_back((a.row(v) - answers[0].row(v)).norm());
    band.run_p95_from_first_mm.push_back(validation::percentile(off, 95));
  }
  for (Eigen::Index v = 0; v < mean.rows(); ++v) {
    for (const auto& a : answers)
      band.spread_mm[size_t(v)] = std::max(band.spread_mm[size_t(v)], (a.row(v) - mean.row(v)).norm());
    if (mean.row(v).norm() > kMovedSkinMm) moved.push_back(band.spread_mm[size_t(v)]);
  }
  band.p95_mm = validation::percentile(moved, 95);
  band.max_mm = moved.empty() ? 0 : *std::max_element(moved.begin(), moved.end());
  return band;
}

SoftTissuePrediction predict_face(const SoftTissueInput& input, const SoftTissueOptions& options,
                                  const FaceModel* model,
                                  std::optional<records::SimulationSummary::ModelFallback>& fallback) {
  // The face model is built once here when not given, so that a fallback solves the same mesh
  // without meshing the face again; the prediction still reports the building's seconds.
  std::optional<FaceModel> built;
  if (!model) model = &built.emplace(build_face_model(*input.tissues, input.landmarks, options));
  const auto with_building_time = [&](SoftTissuePrediction prediction) {
    if (built) {
      prediction.seconds.region = built->region_seconds;
      prediction.seconds.meshing = built->meshing_seconds;
    }
    return prediction;
  };
  try {
    return with_building_time(predict_soft_tissue(input, options, model));
  } catch (const Error& e) {
    const bool nonlinear_failed = options.model == softtissue::SoftTissueModel::kNonlinearFem &&
                                  e.code() == ErrorCode::kProcessing && e.subject() == "non-linear FEM";
    if (!nonlinear_failed) throw;
    log::warning("the non-linear FEM did not converge (", e.reason(), "): the linear FEM predicts the face instead");
    fallback = records::SimulationSummary::ModelFallback{std::string(model_name(options.model)), e.reason()};
    SoftTissueOptions linear = options;
    linear.model = softtissue::SoftTissueModel::kLinearFem;
    return with_building_time(predict_soft_tissue(input, linear, model));
  }
}

SimulationResult simulate_case(Archive& archive, int64_t case_id, const SimulationRequest& request,
                               const CaseTissues* given) {
  auto contents = archive.case_contents(case_id);
  const int64_t series = records::primary_series(contents);
  require_trusted_orientation(archive, case_id, "the face prediction");
  const std::string subject = "case:" + std::to_string(case_id);
  const auto stored = case_landmarks(archive, case_id);
  if (!stored || stored->landmarks.empty())
    throw Error(ErrorCode::kBadValue, subject, "the case has no landmarks and no CT to find them on");
  require_confirmed_landmarks(*stored, subject, request.accept_flagged);
  const LandmarkSet& landmarks = stored->landmarks;
  planning::validate_plan(request.plan, "plan");

  const CaseTissues loaded = given ? CaseTissues{} : load_case_tissues(archive, case_id, landmarks);
  const CaseTissues& case_tissues = given ? *given : loaded;
  SimulationResult result;
  const auto moves =
      plan_moves(archive, case_id, request.plan, landmarks, case_tissues.segmentation, &result.reused_plan_application);
  const LabelVolume& tissues = case_tissues.jaws;
  const auto cut = planning::cut_skeleton(tissues, planning::resolve_osteotomies(request.plan.osteotomies, landmarks));
  for (const auto& s : cut.stats)
    log::info("bone segment ", planning::segment_name(s.segment), ": ", s.volume_ml, " ml");

  const SurfaceRecipe recipe;
  result.skin_before =
      case_surfaces(archive, case_id, series, recipe, case_tissues.ct_labels_for(recipe.segmentation)).skin;
  const SegmentMoves segment_moves = moves_by_segment(moves);
  SoftTissueInput input{&tissues, &cut.segments, &result.skin_before, landmarks, segment_moves};
  result.prediction = predict_face(input, request.options, request.face_model.get(), result.fallback);
  SoftTissueOptions ran = request.options;
  ran.model = result.prediction.model;
  if (request.uncertainty) result.uncertainty = prediction_uncertainty(result.prediction, result.skin_before, ran);

  std::filesystem::create_directories(request.out);
  result.frame = anatomical_frame(landmarks);
  result.views = render_soft_tissue_views(result.skin_before, result.prediction, result.frame, request.out);
  if (result.uncertainty)
    result.uncertainty_views = render_uncertainty_views(result.prediction.skin_after, result.uncertainty->spread_mm,
                                                        result.frame, request.out);
  result.summary = summarise(result, request, landmarks, segment_moves);
  write_outputs(result, request.out);
  store_outputs(archive, case_id, series, result, request, landmarks);
  return result;
}

}  // namespace maxillo::casework
