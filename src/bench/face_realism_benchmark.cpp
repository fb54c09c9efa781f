#include "bench/face_realism_benchmark.h"

#include <string>

#include "bench/cadaver_head_landmarks.h"
#include "bench/formatted.h"
#include "bench/peak_memory.h"
#include "bench/registration_benchmark.h"
#include "bench/shared_data.h"
#include "bench/timing.h"
#include "casework/softtissue/case_simulation.h"
#include "casework/surfaces/case_surfaces.h"
#include "casework/surfaces/case_tissues.h"
#include "casework/plan/planned_case.h"
#include "casework/softtissue/profile_response.h"
#include "casework/softtissue/soft_tissue_prediction.h"
#include "ceph/landmark_frame.h"
#include "core/error.h"
#include "landmarking/landmark_detection.h"
#include "planning/distractor_checks.h"
#include "planning/osteotomy.h"
#include "planning/plan_application.h"

namespace maxillo::bench {
namespace {

using casework::SoftTissueOptions;
using softtissue::SoftTissueModel;

// The cadaver head prepared as `simulate` prepares a case: landmarks, tissues, skin, bone cut.
struct PreparedHead {
  LandmarkSet landmarks;
  casework::CaseTissues tissues;
  TriangleMesh skin;
  planning::OsteotomyResult cut;
  AnatomicalFrame frame;
  std::vector<std::string> by_hand;  // landmarks the detector did not find, placed by hand
};

PreparedHead prepare_cadaver_head() {
  const Volume ct = read_cadaver_head(shared_data_folder() / "cthead-stanford" / "slices");
  PreparedHead head;
  head.landmarks = completed_by_hand(landmarking::detect_landmarks(ct, "cadaver head").present(), head.by_hand);
  head.frame = anatomical_frame(head.landmarks);
  head.tissues = casework::segment_case_tissues(ct, head.landmarks);
  head.skin = casework::extract_case_surfaces(ct, {}, nullptr, &head.tissues.ct_labels).skin;
  const auto plan = casework::le_fort_advancement_plan(1);
  head.cut = planning::cut_skeleton(head.tissues.jaws, planning::resolve_osteotomies(plan.osteotomies, head.landmarks));
  return head;
}

Json response_json(const casework::ProfileResponse& response) {
  Json points = Json::array();
  const auto& published = casework::published_le_fort_advancement_response();
  for (size_t i = 0; i < response.points.size(); ++i) {
    const auto& p = response.points[i];
    points.push_back({{"label", p.label},
                      {"present", p.present},
                      {"forward_mm", p.forward_mm},
                      {"ratio", p.ratio},
                      {"plausible", p.present && casework::plausible(published[i], p.ratio)}});
  }
  return {{"points", points},
          {"gradient_p999", response.gradient_p999},
          {"gradient_max", response.gradient_max},
          {"steepest_near", response.steepest_near},
          {"steepest_near_mm", response.steepest_near_mm},
          {"moved_edges", response.moved_edges}};
}

// One model on one advancement: the prediction's profile response, or the error it stopped with.
// The segment moves of a Le Fort I advancement on the head, as `plan apply` finds them.
casework::SegmentMoves advancement_moves(const PreparedHead& head, double advancement_mm) {
  const auto applied =
      planning::apply_plan(casework::le_fort_advancement_plan(advancement_mm), head.tissues.segmentation,
                           head.landmarks, planning::segmentation_anatomy_labels());
  return casework::moves_by_segment(applied.moves);
}

// The soft tissue options the benchmark's variants ask for, with `model`.
SoftTissueOptions model_options(const FaceRealismOptions& variant, SoftTissueModel model) {
  SoftTissueOptions options;
  options.model = model;
  options.attachment.outer_surface_only = variant.free_cavities;
  options.attachment.moved_bone_contact = variant.bone_contact;
  options.nose_root = variant.nose_root;
  options.top_at_brows = variant.top_at_brows;
  options.part_lips = variant.part_lips;
  options.nose_stiffness = variant.nose_stiffness;
  options.meshing = variant.meshing;
  options.poisson_ratio = variant.poisson_ratio;
  return options;
}

Json run_model(const PreparedHead& head, const casework::FaceModel& face, double advancement_mm,
               const casework::SegmentMoves& moves, SoftTissueModel model, const FaceRealismOptions& variant) {
  casework::SoftTissueInput input{&head.tissues.jaws, &head.cut.segments, &head.skin, head.landmarks, moves};
  const SoftTissueOptions options = model_options(variant, model);
  Json run = {{"advancement_mm", advancement_mm},
              {"model", softtissue::model_name(model)},
              {"title", softtissue::model_title(model)}};
  const auto start = Clock::now();
  try {
    const auto prediction = casework::predict_soft_tissue(input, options, &face);
    run["seconds"] = seconds_since(start);
    run["iterations"] = prediction.iterations;
    run.update(
        response_json(casework::profile_response(head.skin, prediction.skin_displacement, head.frame, head.landmarks,
                                                 advancement_mm, prediction.skin_on_bone, prediction.skin_lip_side)));
    // The default planes: below the orbits, under the chin, in front of the ears; then above the
    // orbits, the forehead's cut and in front of the eyes (0 where a plane cuts no tissue).
    run["boundary_move_mm"] = prediction.boundary_move_mm;
    run["fixed_nodes"] = softtissue::count_nodes(prediction.bc, softtissue::NodeConstraint::kFixed);
    run["prescribed_nodes"] = softtissue::count_nodes(prediction.bc, softtissue::NodeConstraint::kPrescribed);
    run["sliding_nodes"] = softtissue::count_nodes(prediction.bc, softtissue::NodeConstraint::kSliding);
    run["nose_nodes_uncarried"] = prediction.nose_nodes_uncarried;
  } catch (const Error& error) {
    run["seconds"] = seconds_since(start);
    run["error"] = error.what();
  }
  return run;
}

Json published_json() {
  Json published = Json::array();
  for (const auto& p : casework::published_le_fort_advancement_response()) {
    Json entry = {{"label", p.label}, {"published", p.published}, {"source", p.source}};
    if (p.plausible_low) entry["plausible_low"] = *p.plausible_low;
    if (p.plausible_high) entry["plausible_high"] = *p.plausible_high;
    published.push_back(entry);
  }
  return published;
}

}  // namespace

Json run_face_realism_benchmark(const FaceRealismOptions& options) {
  auto start = Clock::now();
  const PreparedHead head = prepare_cadaver_head();
  const double preparation_seconds = seconds_since(start);
  start = Clock::now();
  const auto face = casework::build_face_model(head.tissues.jaws, head.landmarks,
                                               model_options(options, SoftTissueModel::kMassTensor));
  Json figures = {{"preparation_seconds", preparation_seconds},
                  {"landmarks_by_hand", head.by_hand},
                  {"free_cavities", options.free_cavities},
                  {"bone_contact", softtissue::contact_name(options.bone_contact)},
                  {"nose_root", options.nose_root},
                  {"top_at_brows", options.top_at_brows},
                  {"enclosed_voxels_left_out", face.enclosed_voxels},
                  {"part_lips", options.part_lips},
                  {"lips_parted_faces", face.lips_parted.faces},
                  {"nose_stiffness", options.nose_stiffness},
                  {"poisson_ratio", options.poisson_ratio},
                  {"nose_tets", face.nose_tets},
                  {"face_model",
                   {{"tets", face.mesh.tet_count()},
                    {"nodes", face.mesh.node_count()},
                    {"cell_mm", face.meshing.cell_size_mm},
                    {"seconds", seconds_since(start)}}},
                  {"published", published_json()},
                  {"advancements_mm", options.advancements_mm}};
  Json runs = Json::array();
  for (double advancement : options.advancements_mm) {
    const auto moves = advancement_moves(head, advancement);    // once for every model
    for (const auto& model : softtissue::soft_tissue_models())  // every model of the table, in its order
      runs.push_back(run_model(head, face, advancement, moves, model.model, options));
  }
  figures["runs"] = runs;
  figures["peak_memory_mb"] = double(peak_memory_kb()) / 1024.0;
  return figures;
}

std::string face_realism_text(const Json& figures) {
  const Json& face = figures["face_model"];
  std::string by_hand;
  for (const auto& label : figures["landmarks_by_hand"]) by_hand += " " + label.get<std::string>();
  std::string text = formatted(
      "cadaver head, landmarks found automatically, by hand where not found (%s); %.1f s "
      "with tissues and skin\nface model %d tets, %d nodes (cell %.2f mm) in %.1f s\n",
      by_hand.empty() ? " none" : by_hand.c_str(), figures["preparation_seconds"].get<double>(),
      face["tets"].get<int>(), face["nodes"].get<int>(), face["cell_mm"].get<double>(), face["seconds"].get<double>());
  if (figures["free_cavities"].get<bool>()) text += "moved bone carries only the tissue on its outer surface\n";
  text += "tissue on the moved bone: " + figures["bone_contact"].get<std::string>() + "\n";
  if (figures["nose_root"].get<bool>()) text += "the region goes on above the orbits in front of the eyes\n";
  text += figures["top_at_brows"].get<bool>()
              ? formatted("the region's top at the brows; %lld voxels of tissue shut in by bone left out\n",
                          figures["enclosed_voxels_left_out"].get<long long>())
              : std::string("the region's top at the orbitales\n");
  if (figures["part_lips"].get<bool>())
    text += formatted("the model parted between the lips: %d faces\n", figures["lips_parted_faces"].get<int>());
  text += formatted("the cartilaginous nose: %d tets, %.0f times the soft tissue's stiffness; Poisson ratio %.3g\n",
                    figures["nose_tets"].get<int>(), figures["nose_stiffness"].get<double>(),
                    figures["poisson_ratio"].get<double>());
  for (const auto& run : figures["runs"])  // the same face model and moved segments in every run
    if (run.contains("nose_nodes_uncarried")) {
      text += formatted("the nose's nodes on the moved bone, left free: %d\n", run["nose_nodes_uncarried"].get<int>());
      break;
    }
  text += "forward move / advancement at the profile points; * outside the plausible band\n";
  text += formatted("%-6s %-5s", "adv mm", "model");
  for (const auto& p : figures["published"]) text += formatted(" %7s", p["label"].get<std::string>().c_str());
  text +=
      "  gradient P99.9 / max (mm/mm), max near  seconds  boundary move (orbits, chin, ears; nose piece: orbits, "
      "forehead, eyes) "
      "mm\n";
  for (const auto& run : figures["runs"]) {
    text += formatted("%6.1f %-5s", run["advancement_mm"].get<double>(), run["model"].get<std::string>().c_str());
    if (run.contains("error")) {
      text += "  failed: " + run["error"].get<std::string>() + "\n";
      continue;
    }
    for (const auto& p : run["points"])
      text += p["present"].get<bool>()
                  ? formatted(" %6.2f%s", p["ratio"].get<double>(), p["plausible"].get<bool>() ? " " : "*")
                  : formatted(" %7s", "-");
    text += formatted("  %6.2f / %6.2f, %4s %3.0f mm  %7.1f ", run["gradient_p999"].get<double>(),
                      run["gradient_max"].get<double>(), run["steepest_near"].get<std::string>().c_str(),
                      run["steepest_near_mm"].get<double>(), run["seconds"].get<double>());
    for (const auto& move : run["boundary_move_mm"]) text += formatted(" %5.2f", move.get<double>());
    text += "\n";
  }
  text += "published (fraction of the advancement):\n";
  for (const auto& p : figures["published"])
    text +=
        formatted("  %-6s %s%s%s\n", p["label"].get<std::string>().c_str(), p["published"].get<std::string>().c_str(),
                  p["source"].get<std::string>().empty() ? "" : "; ", p["source"].get<std::string>().c_str());
  return text + formatted("peak memory: %.0f MB\n", figures["peak_memory_mb"].get<double>());
}

}  // namespace maxillo::bench
