// maxillo followup CASE | --cohort FILE | --cohort-archive NAME | --import-cohort FILE:
// cephalometric follow-up over time points. For a case,
// the measurements per archived time point; for a cohort CSV (ceph/follow_up.h), the changes
// between time points as mean ± SD with n (the source's Tables II and III) and the Wits appraisal
// per patient and time point (the data of the source's Fig. 10).
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "ceph/follow_up.h"
#include "cli/ceph_options.h"
#include "cli/command.h"
#include "core/error.h"
#include "records/case_landmarks.h"
#include "records/cohort_archive.h"
#include "followup/cohort_report.h"

namespace maxillo::cli {
namespace {

struct FollowupOptions {
  std::string case_text;
  std::filesystem::path cohort;
  std::filesystem::path import_cohort;  // store this cohort CSV's landmark sets in the archive
  std::string cohort_archive;           // the archived cohort of this name
  std::string cohort_name;              // --import-cohort: default the CSV's file stem
  std::string from, to;                 // cohort change between these time points; empty = every consecutive pair
  bool csv = false;
  std::filesystem::path pdf;  // cohort: also write the follow-up tables as a PDF report
  GeometryOptions geometry;
};

// Measurements of the source's Tables II/III, then the skeletal relationship.
const std::vector<std::string> kChangeIds = {"PNS_X", "Si_X", "ANS_X", "PNS_Y", "Si_Y", "ANS_Y",
                                             "alpha", "SNA",  "SNB",   "ANB",   "Wits"};

void print_case_table(const ceph::CaseFollowUp& c) {
  std::printf("%s\n%-7s", c.name.c_str(), "");
  for (const auto& tp : c.time_points) std::printf(" %12s", tp.label.c_str());
  std::printf("\n%-7s", "date");
  for (const auto& tp : c.time_points) std::printf(" %12s", tp.date.empty() ? "-" : tp.date.c_str());
  std::printf("\n");
  for (const auto& id : ceph::measurement_ids()) {
    std::printf("%-7s", id.c_str());
    for (const auto& tp : c.time_points) {
      auto v = tp.analysis.value(id);
      std::printf(" %12s", v ? fixed(*v, 2).c_str() : "n/a");
    }
    std::printf("\n");
  }
}

void print_case_csv(const ceph::CaseFollowUp& c, bool header) {
  if (header) std::printf("case,time_point,date,measurement,unit,value\n");
  for (const auto& tp : c.time_points)
    for (const auto& m : tp.analysis.measurements)
      std::printf("%s,%s,%s,%s,%s,%s\n", c.name.c_str(), tp.label.c_str(), tp.date.c_str(), m.id.c_str(),
                  m.unit.c_str(), m.value ? fixed(*m.value, 3).c_str() : "");
}

std::vector<ceph::CaseFollowUp> cohort_from_csv(const FollowupOptions& options) {
  return followup::analyse_cohort(ceph::read_cohort_csv(options.cohort),
                                  {options.geometry.geometry, options.geometry.axes()}, options.geometry.sex,
                                  options.cohort.string());
}

int run_cohort(const std::vector<ceph::CaseFollowUp>& cohort, const std::string& cohort_label,
               const FollowupOptions& options, const GlobalOptions& global) {
  auto labels = followup::cohort_time_point_labels(cohort);
  std::vector<std::pair<std::string, std::string>> pairs;
  if (!options.from.empty())
    pairs.push_back({options.from, options.to});
  else
    pairs = followup::consecutive_pairs(labels);

  Json json_changes = Json::array();
  if (options.csv) std::printf("from,to,measurement,unit,n,mean,sd\n");
  for (const auto& [from, to] : pairs) {
    auto rows = ceph::cohort_changes(cohort, from, to, kChangeIds);
    if (!options.csv && !global.json) std::printf("change %s -> %s (mean ± SD, n)\n", from.c_str(), to.c_str());
    for (const auto& row : rows) {
      if (options.csv)
        std::printf("%s,%s,%s,%s,%d,%s,%s\n", from.c_str(), to.c_str(), row.id.c_str(), row.unit.c_str(), row.n,
                    row.mean ? fixed(*row.mean, 3).c_str() : "", row.sd ? fixed(*row.sd, 3).c_str() : "");
      else if (!global.json)
        std::printf("  %-7s %-18s %-3s n=%d\n", row.id.c_str(), ceph::format_mean_sd(row).c_str(), row.unit.c_str(),
                    row.n);
      Json j{{"from", from}, {"to", to}, {"measurement", row.id}, {"unit", row.unit}, {"n", row.n}};
      j["mean"] = row.mean ? Json(*row.mean) : Json(nullptr);
      j["sd"] = row.sd ? Json(*row.sd) : Json(nullptr);
      json_changes.push_back(j);
    }
  }
  if (!options.pdf.empty()) {
    int pages = followup::write_cohort_report(cohort, pairs, cohort_label, options.pdf);
    if (!global.json && !options.csv) std::printf("report: %s (%d pages)\n", options.pdf.string().c_str(), pages);
  }
  Json wits = Json::array();
  if (!options.csv && !global.json) {
    std::printf("Wits appraisal (mm) per patient\n%-10s", "case");
    for (const auto& label : labels) std::printf(" %9s", label.c_str());
    std::printf("\n");
  }
  for (const auto& c : cohort) {
    Json row{{"case", c.name}, {"wits", Json::object()}};
    if (!options.csv && !global.json) std::printf("%-10s", c.name.c_str());
    for (const auto& label : labels) {
      std::optional<double> v;
      for (const auto& tp : c.time_points)
        if (tp.label == label) v = tp.analysis.value("Wits");
      if (!options.csv && !global.json) std::printf(" %9s", v ? fixed(*v, 1).c_str() : "-");
      if (v) row["wits"][label] = *v;
    }
    if (!options.csv && !global.json) std::printf("\n");
    wits.push_back(row);
  }
  if (global.json && !options.csv)
    std::cout
        << Json{{"cases", cohort.size()}, {"time_points", labels}, {"changes", json_changes}, {"wits", wits}}.dump(2)
        << "\n";
  return 0;
}

int run_import_cohort(const FollowupOptions& options, const GlobalOptions& global) {
  const std::string name = options.cohort_name.empty() ? options.import_cohort.stem().string() : options.cohort_name;
  auto archive = Archive::open(resolve_archive_dir(global), OpenMode::CreateIfMissing);
  const auto cohort = ceph::read_cohort_csv(options.import_cohort);
  records::LandmarkFrame frame{options.geometry.geometry, options.geometry.axes()};
  const auto imported = records::import_cohort(archive, cohort, name, frame, options.import_cohort.filename().string());
  if (global.json)
    std::cout << Json{{"cohort", name},
                      {"cases", imported.cases},
                      {"sets_stored", imported.sets_stored},
                      {"sets_unchanged", imported.sets_unchanged}}
                     .dump(2)
              << "\n";
  else
    std::printf("cohort %s: %d cases, %d landmark sets stored, %d already archived\n", name.c_str(), imported.cases,
                imported.sets_stored, imported.sets_unchanged);
  return 0;
}

int run_followup(const FollowupOptions& options, const GlobalOptions& global) {
  if (!options.import_cohort.empty()) return run_import_cohort(options, global);
  if (!options.cohort.empty())
    return run_cohort(cohort_from_csv(options), "cohort " + options.cohort.filename().string(), options, global);
  if (!options.cohort_archive.empty()) {
    auto archive = Archive::open(resolve_archive_dir(global));
    return run_cohort(records::archived_cohort_follow_up(archive, options.cohort_archive, options.geometry.sex),
                      "cohort " + options.cohort_archive, options, global);
  }
  if (options.case_text.empty())
    throw Error(ErrorCode::kUsage, "followup",
                "give a CASE, --cohort FILE, --cohort-archive NAME or --import-cohort FILE");
  auto archive = Archive::open(resolve_archive_dir(global));
  auto case_id = archive.resolve_case(options.case_text);
  auto follow_up =
      records::archived_case_follow_up(archive, case_id, "case " + std::to_string(case_id), options.geometry.sex);
  if (follow_up.time_points.empty())
    throw Error(ErrorCode::kNotFound, "case " + std::to_string(case_id),
                "no landmark set with a time point (maxillo ceph add CASE --time-point LABEL ...)");
  if (options.csv) {
    print_case_csv(follow_up, true);
  } else if (global.json) {
    Json points = Json::array();
    for (const auto& tp : follow_up.time_points) {
      Json j = analysis_json(tp.analysis);
      j["time_point"] = tp.label;
      j["date"] = tp.date;
      points.push_back(j);
    }
    std::cout << Json{{"case", case_id}, {"time_points", points}}.dump(2) << "\n";
  } else {
    print_case_table(follow_up);
  }
  return 0;
}

}  // namespace

void attach_followup(CLI::App& app, CommandContext& ctx) {
  auto options = std::make_shared<FollowupOptions>();
  app.add_option("CASE", options->case_text, "case id, or a Patient ID (its default case)");
  auto* cohort = app.add_option("--cohort", options->cohort, "cohort CSV: case,time_point,date,label,x,y,z")
                     ->check(CLI::ExistingFile);
  auto* cohort_archive = app.add_option("--cohort-archive", options->cohort_archive,
                                        "the cohort of this name stored with --import-cohort");
  auto* import = app.add_option("--import-cohort", options->import_cohort,
                                "store a cohort CSV's landmark sets in the archive (idempotent)")
                     ->check(CLI::ExistingFile);
  app.add_option("--cohort-name", options->cohort_name, "--import-cohort: the cohort's name (default: the file stem)")
      ->needs(import);
  cohort->excludes(cohort_archive)->excludes(import);
  cohort_archive->excludes(import);
  auto* from =
      app.add_option("--from", options->from, "cohort change from this time point (default: consecutive pairs)");
  auto* to = app.add_option("--to", options->to, "cohort change to this time point");
  from->needs(to);
  to->needs(from);
  app.add_flag("--csv", options->csv, "CSV output");
  app.add_option("--pdf", options->pdf, "cohort: also write the change and Wits tables and the Wits chart as a PDF");
  add_geometry_options(app, options->geometry);
  app.callback([options, &ctx] { ctx.exit_code = run_followup(*options, ctx.global); });
}

}  // namespace maxillo::cli
