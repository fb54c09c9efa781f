// maxillo plan create|show|apply CASE: the surgical plan of a case (issue #4).
//   create  stores a new plan version: from a plan JSON file (--from) or from options
//           (--advance 10 --widen 6 ...: a maxillary distraction with default high Le Fort I).
//   show    the newest plan (or --version N) and the list of stored versions.
//   apply   the newest plan on the case's CT and landmarks: distraction vectors, checks,
//           activation schedule, forward simulation; writes DIR/plan-result.json and stores the
//           result for the report. Exit code 63 (UnsafePlan) when a check fails, with the reasons.
#include <cstdio>
#include <iostream>

#include "archive/archive.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "casework/softtissue/case_simulation.h"
#include "records/plan_archive.h"
#include "casework/plan/plan_case.h"

namespace maxillo::cli {
namespace {

using planning::Plan;

struct CreateOptions {
  std::string case_text;
  std::filesystem::path from;
  std::string description;
  planning::MaxillaryTarget target;
  double expected_clockwise_deg = 0;
  double screw_length_mm = planning::DistractorDevice{}.screw_length_mm;
  int latency_days = planning::ScheduleSettings{}.latency_days;
  double rate_mm_per_day = planning::ScheduleSettings{}.rate_mm_per_day;
  int consolidation_days = planning::ScheduleSettings{}.consolidation_days;
  std::string le_fort = "high";
};

Plan plan_from_options(const CreateOptions& o) {
  if (!o.from.empty()) {
    const auto bytes = read_file(o.from);
    return planning::parse_plan(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                                o.from.string());
  }
  Plan plan = planning::distraction_plan(o.target, o.description);
  plan.osteotomies.le_fort_i->variant =
      o.le_fort == "low" ? planning::LeFortVariant::Low : planning::LeFortVariant::High;
  plan.distraction->expected_clockwise_rotation_deg = o.expected_clockwise_deg;
  plan.distraction->device.screw_length_mm = o.screw_length_mm;
  plan.distraction->schedule.latency_days = o.latency_days;
  plan.distraction->schedule.rate_mm_per_day = o.rate_mm_per_day;
  plan.distraction->schedule.consolidation_days = o.consolidation_days;
  planning::validate_plan(plan, "plan create");
  return plan;
}

int run_create(const CreateOptions& options, const GlobalOptions& global) {
  const Plan plan = plan_from_options(options);
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(options.case_text);
  const records::StoredPlan stored = records::store_plan(archive, case_id, plan);
  if (global.json)
    std::cout << Json{{"case", case_id},
                      {"version", stored.version},
                      {"artefact", stored.artefact_id},
                      {"plan", planning::plan_to_json(plan)}}
                     .dump(2)
              << "\n";
  else
    std::printf("case %lld: plan version %d stored (artefact %lld)\n", static_cast<long long>(case_id), stored.version,
                static_cast<long long>(stored.artefact_id));
  return 0;
}

int run_show(const std::string& case_text, int version, const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(case_text);
  const auto history = records::plan_history(archive, case_id);
  if (history.empty())
    throw Error(ErrorCode::kNotFound, case_text, "the case has no plan: make one with `maxillo plan create`");
  if (version > static_cast<int>(history.size()))
    throw Error(ErrorCode::kNotFound, case_text, "the case has " + std::to_string(history.size()) + " plan versions");
  const records::StoredPlan& shown = version > 0 ? history[version - 1] : history.back();
  if (global.json) {
    Json versions = Json::array();
    for (const auto& s : history)
      versions.push_back({{"version", s.version},
                          {"artefact", s.artefact_id},
                          {"created_at", s.created_at},
                          {"description", s.plan.description}});
    std::cout << Json{{"case", case_id},
                      {"version", shown.version},
                      {"plan", planning::plan_to_json(shown.plan)},
                      {"history", versions}}
                     .dump(2)
              << "\n";
    return 0;
  }
  std::printf("case %lld, plan version %d of %zu (%s)\n", static_cast<long long>(case_id), shown.version,
              history.size(), shown.created_at.c_str());
  std::cout << planning::serialise_plan(shown.plan);
  std::printf("history:\n");
  for (const auto& s : history)
    std::printf("  version %d  %s  artefact %lld  %s\n", s.version, s.created_at.c_str(),
                static_cast<long long>(s.artefact_id), s.plan.description.c_str());
  return 0;
}

void print_result(const planning::PlanResult& r) {
  std::printf("frame: %s\n", r.frame.source.c_str());
  if (!r.distraction) {
    std::printf("no distraction in the plan\n");
    return;
  }
  const auto& d = *r.distraction;
  for (const auto* v : {&d.vectors.right, &d.vectors.left})
    std::printf(
        "%-5s entry (%.1f, %.1f, %.1f) axis (%.3f, %.3f, %.3f) outward %.2f deg elevation %.2f deg "
        "activation %.2f mm\n",
        std::string(planning::side_name(v->side)).c_str(), v->entry.x(), v->entry.y(), v->entry.z(), v->axis.x(),
        v->axis.y(), v->axis.z(), v->outward_deg, v->elevation_deg, v->activation_mm);
  std::printf("divergence %.2f deg (3D angle %.2f deg)\n", d.vectors.divergence_deg, d.vectors.angle_deg);
  for (const auto& note : d.sinus_notes) std::printf("sinus: %s\n", note.c_str());
  for (const auto& c : d.checks)
    std::printf("check %-5s %-18s %-11s value %.1f mm limit %.1f mm %s\n",
                std::string(planning::side_name(c.side)).c_str(), c.name.c_str(),
                std::string(planning::status_name(c.status)).c_str(), c.value, c.limit, c.reason.c_str());
  const auto& s = d.schedule;
  std::printf("schedule: latency %d days, %.2f mm/day in %d activations of %.2f turn (%.2f mm/turn)\n",
              s.settings.latency_days, s.settings.rate_mm_per_day, s.settings.activations_per_day,
              s.turns_per_activation, s.settings.mm_per_turn);
  for (const auto* side : {&s.right, &s.left})
    std::printf("  %-5s %.2f turns = %.2f mm, days %d-%d (%d days)\n",
                std::string(planning::side_name(side->side)).c_str(), side->turns, side->delivered_mm, side->first_day,
                side->last_day, side->distraction_days);
  std::printf("  last activation day %d, consolidation until day %d\n", s.distraction_end_day, s.consolidation_end_day);
  for (const auto& p : d.simulation.points)
    std::printf("forward simulation %-4s error %.3f mm\n", p.label.c_str(), p.error_mm);
}

int run_apply(const std::string& case_text, const std::filesystem::path& out, bool predict_face, bool accept_flagged,
              const GlobalOptions& global) {
  auto archive = Archive::open(resolve_archive_dir(global));
  const int64_t case_id = archive.resolve_case(case_text);
  const casework::CasePlanResult applied = casework::apply_case_plan(archive, case_id, out, nullptr, accept_flagged);
  if (predict_face && !applied.result.moves.empty()) {
    // The face for the planned moves (soft tissue engine, pipeline/case_simulation.h).
    casework::SimulationRequest simulation;
    simulation.plan = applied.plan.plan;
    simulation.out = out / "soft-tissue";
    simulation.accept_flagged = accept_flagged;
    const auto predicted = casework::simulate_case(archive, case_id, simulation, &applied.tissues);
    if (!global.json)
      std::printf("predicted face: largest skin displacement %.1f mm (%s)\n", predicted.views.max_displacement_mm,
                  simulation.out.string().c_str());
  }
  if (global.json)
    std::cout << planning::plan_result_json(applied.result).dump(2) << "\n";
  else {
    std::printf("case %lld, plan version %d\n", static_cast<long long>(case_id), applied.plan.version);
    print_result(applied.result);
    std::printf("wrote %s\n", applied.result_json.string().c_str());
  }
  if (applied.result.feasible) return 0;
  for (const auto& refusal : applied.result.refusals) std::cerr << "maxillo: plan refused: " << refusal << "\n";
  return exit_code_for(ErrorCode::kUnsafePlan);
}

}  // namespace

void attach_plan(CLI::App& app, CommandContext& ctx) {
  app.require_subcommand(1);

  CLI::App* create = app.add_subcommand("create", "store a new plan version (from --from FILE or from the options)");
  create->fallthrough();
  auto o = std::make_shared<CreateOptions>();
  create->add_option("CASE", o->case_text, "case id, or a Patient ID (its default case)")->required();
  create->add_option("--from", o->from, "a plan JSON file (format_version 1); the other options are ignored")
      ->check(CLI::ExistingFile);
  create->add_option("--description", o->description, "free text");
  create->add_option("--advance", o->target.advancement_mm, "maxillary advancement, mm (+ forward)")
      ->check(CLI::Range(-60.0, 60.0));
  create->add_option("--vertical", o->target.vertical_mm, "vertical change, mm (+ down, - impaction)")
      ->check(CLI::Range(-60.0, 60.0));
  create->add_option("--widen", o->target.widening_mm, "transverse widening between the two halves, mm")
      ->check(CLI::Range(0.0, 30.0));
  create->add_option("--midline", o->target.midline_shift_mm, "incisor midline shift, mm (+ to the patient's left)")
      ->check(CLI::Range(-15.0, 15.0));
  create->add_option("--rotate", o->target.rotation_deg, "pitch, deg (+ anterior end up)")
      ->check(CLI::Range(-45.0, 45.0));
  create
      ->add_option("--counter-rotate", o->target.counter_rotation_deg,
                   "tilt the vectors anterior-end-up by this much, deg (against the clockwise drift)")
      ->check(CLI::Range(-45.0, 45.0));
  create
      ->add_option("--expected-clockwise", o->expected_clockwise_deg,
                   "clockwise drift expected during distraction, deg (forward simulation)")
      ->check(CLI::Range(-45.0, 45.0));
  create->add_option("--screw-length", o->screw_length_mm, "distraction screw length, mm")
      ->check(CLI::Range(5.0, 80.0))
      ->capture_default_str();
  create->add_option("--latency", o->latency_days, "latency, days")->check(CLI::Range(0, 60))->capture_default_str();
  create->add_option("--rate", o->rate_mm_per_day, "distraction rate, mm/day")
      ->check(CLI::Range(0.05, 5.0))
      ->capture_default_str();
  create->add_option("--consolidation", o->consolidation_days, "consolidation, days")
      ->check(CLI::Range(0, 365))
      ->capture_default_str();
  create->add_option("--le-fort", o->le_fort, "Le Fort I level: high (the source's) or low")
      ->check(CLI::IsMember({"high", "low"}))
      ->capture_default_str();
  create->callback([o, &ctx] { ctx.exit_code = run_create(*o, ctx.global); });

  CLI::App* show = app.add_subcommand("show", "the newest plan of a case (or --version N) and its history");
  show->fallthrough();
  auto show_case = std::make_shared<std::string>();
  auto version = std::make_shared<int>(0);
  show->add_option("CASE", *show_case, "case id, or a Patient ID")->required();
  show->add_option("--version", *version, "show this version (1 = the first)")->check(CLI::PositiveNumber);
  show->callback([show_case, version, &ctx] { ctx.exit_code = run_show(*show_case, *version, ctx.global); });

  CLI::App* apply = app.add_subcommand("apply", "vectors, checks, schedule and forward simulation of the newest plan");
  apply->fallthrough();
  auto apply_case = std::make_shared<std::string>();
  auto out = std::make_shared<std::filesystem::path>();
  auto no_face = std::make_shared<bool>(false);
  apply->add_option("CASE", *apply_case, "case id, or a Patient ID")->required();
  apply
      ->add_option("--out", *out,
                   "output folder (created): plan-result.json, transfer-model.stl, planned segments, renders, "
                   "soft-tissue/ (the predicted face)")
      ->required();
  apply->add_flag("--no-face", *no_face, "skip the soft-tissue prediction of the planned face");
  auto accept_flagged = std::make_shared<bool>(false);
  apply->add_flag(
      "--accept-flagged", *accept_flagged,
      "plan on automatic landmarks that failed a check (see `maxillo landmarks detect`) without confirming them");
  apply->callback([apply_case, out, no_face, accept_flagged, &ctx] {
    ctx.exit_code = run_apply(*apply_case, *out, !*no_face, *accept_flagged, ctx.global);
  });
}

}  // namespace maxillo::cli
