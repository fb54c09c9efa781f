// maxillo simulate CASE (--plan PLAN.json | --advance MM) --out DIR: the predicted face.
#include <iostream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json.h"
#include "casework/softtissue/case_simulation.h"

namespace maxillo::cli {
namespace {

std::string text_of(const std::filesystem::path& path) {
  const auto bytes = read_file(path);
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

struct SimulateOptions {
  std::string case_text;
  std::filesystem::path plan_file;
  double advance_mm = 0;
  std::string model = "mtm";
  double poisson = 0.46;
  std::string bone_contact = softtissue::contact_name(softtissue::AttachmentOptions{}.moved_bone_contact);
  int max_tets = 100000;
  double cell_mm = 4.0;
  bool uncertainty = false;
  bool accept_flagged = false;
  std::filesystem::path out = "simulation";
};

casework::SimulationRequest make_request(const SimulateOptions& o) {
  casework::SimulationRequest request;
  if (!o.plan_file.empty()) {
    request.plan = planning::parse_plan(text_of(o.plan_file), o.plan_file.string());
  } else if (o.advance_mm != 0) {
    request.plan = casework::le_fort_advancement_plan(o.advance_mm);
  } else {
    throw Error(ErrorCode::kUsage, "simulate",
                "give a plan (--plan PLAN.json) or a Le Fort I advancement (--advance MM)");
  }
  request.options.model = *softtissue::parse_model(o.model);
  request.options.poisson_ratio = o.poisson;
  request.options.attachment.moved_bone_contact = *softtissue::contact_named(o.bone_contact);
  request.options.meshing.max_tets = o.max_tets;
  request.options.meshing.cell_size_mm = o.cell_mm;
  request.uncertainty = o.uncertainty;
  request.accept_flagged = o.accept_flagged;
  request.out = o.out;
  return request;
}

int run_simulate(const SimulateOptions& options, const GlobalOptions& global) {
  const auto request = make_request(options);  // usage first: before the archive is looked at
  auto archive = Archive::open(resolve_archive_dir(global));
  const auto case_id = archive.resolve_case(options.case_text);
  const auto result = casework::simulate_case(archive, case_id, request);
  const auto& p = result.prediction;
  if (global.json) {
    std::cout << records::to_json(result.summary).dump(2) << "\n";
    return 0;
  }
  if (result.fallback)
    std::cout << "the " << softtissue::model_title(request.options.model) << " did not converge ("
              << result.fallback->reason << "): the face is the " << softtissue::model_title(p.model) << "'s\n";
  std::cout << "model: " << softtissue::model_title(p.model) << ", " << p.mesh.tet_count()
            << " tetrahedra (smallest dihedral angle " << p.quality.min_dihedral_deg << " deg)\n"
            << "solve: " << p.seconds.solve << " s, " << p.iterations << " iterations; mesh " << p.seconds.meshing
            << " s; mapping " << p.seconds.mapping << " s\n"
            << "largest skin displacement: " << result.views.max_displacement_mm << " mm\n";
  if (result.uncertainty) {
    std::cout << "uncertainty (" << result.uncertainty->runs.size() << " runs): P95 " << result.uncertainty->p95_mm
              << " mm, max " << result.uncertainty->max_mm << " mm\n";
    for (size_t r = 0; r < result.uncertainty->runs.size(); ++r)
      std::cout << "  " << result.uncertainty->runs[r] << ": largest skin displacement "
                << result.uncertainty->run_max_mm[r] << " mm, P95 " << result.uncertainty->run_p95_from_first_mm[r]
                << " mm from the first run\n";
  }
  if (const auto& profile = result.summary.profile_response) {
    std::cout << "profile for the maxilla's " << profile->advancement_mm << " mm advancement (at " << profile->reference
              << "), forward move as a fraction of it:\n";
    for (const auto& point : profile->points) {
      std::cout << "  " << point.label << ": ";
      if (!point.present) {
        std::cout << "not on the skin\n";
        continue;
      }
      std::cout << point.ratio;
      if (point.plausible_low || point.plausible_high)
        std::cout << " (published " << point.published << ", plausible " << point.plausible_low.value_or(0) << "-"
                  << point.plausible_high.value_or(1) << ")";
      std::cout << "\n";
    }
  }
  for (const auto& file : result.files) std::cout << "wrote " << file.string() << "\n";
  return 0;
}

}  // namespace

void attach_simulate(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<SimulateOptions>();
  app.add_option("CASE", options->case_text, "case id, or a Patient ID (its default case)")->required();
  app.add_option("--plan", options->plan_file, "plan JSON (maxillo plan); its osteotomies and segment moves are used");
  app.add_option("--advance", options->advance_mm, "instead of a plan: Le Fort I advancement of the maxilla, mm")
      ->check(kAdvancementMm);
  app.add_option("--model", options->model, softtissue::model_choices())
      ->check(CLI::IsMember(softtissue::model_names()))
      ->capture_default_str();
  app.add_option("--poisson", options->poisson, "Poisson ratio of the soft tissue")
      ->check(CLI::Range(0.3, 0.499))
      ->capture_default_str();
  app.add_option("--bone-contact", options->bone_contact,
                 "tissue on moved bone: tied to it, sliding on it (the subperiosteal dissection), or sliding only "
                 "inside its cavities")
      ->check(CLI::IsMember(softtissue::contact_names()))
      ->capture_default_str();
  app.add_option("--max-tets", options->max_tets, "tetrahedra budget of the face model")
      ->check(kTetrahedra)
      ->capture_default_str();
  app.add_option("--cell-mm", options->cell_mm, "target tetrahedron size, mm (grows to meet --max-tets)")
      ->check(kCellMm)
      ->capture_default_str();
  app.add_flag("--accept-flagged", options->accept_flagged,
               "predict on automatic landmarks that failed a check (see `maxillo landmarks detect`)");
  app.add_flag("--uncertainty", options->uncertainty,
               "also solve with the other models and Poisson ratios 0.45 and 0.49: per-vertex spread");
  app.add_option("--out", options->out, "output folder: predicted skin (vtp, stl, ply), model (vtu), renders, json")
      ->capture_default_str();
  app.callback([options, &ctx] { ctx.exit_code = run_simulate(*options, ctx.global); });
}

}  // namespace maxillo::cli
