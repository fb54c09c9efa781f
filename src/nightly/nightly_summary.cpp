#include "nightly/nightly_summary.h"
#include "validation/face_regions.h"

#include <map>

#include "core/error.h"
#include "core/temporary_folder.h"
#include "core/version.h"
#include "sections/validation_section.h"
#include "render/chart.h"
#include "report/report_template.h"
#include "report/write_report.h"

namespace maxillo::nightly {
namespace {

std::string case_name(const records::StoredValidation& v) { return "case " + std::to_string(v.case_id); }

report::Table cohort_table(const std::vector<records::StoredValidation>& validations) {
  report::Table table;
  table.columns = sections::statistics_columns("Case");
  for (const auto& v : validations)
    table.rows.push_back(sections::statistics_row(case_name(v), v.record.regions.front().closest));
  return table;
}

render::BoxPlot per_case_boxes(const std::vector<records::StoredValidation>& validations) {
  render::BoxPlot plot;
  plot.title = "Signed distance per case";
  plot.y_title = "prediction - outcome (mm)";
  plot.reference_y = 0.0;
  for (const auto& v : validations) plot.groups.push_back({case_name(v), v.face_closest_mm});
  return plot;
}

// Every case's face vertices pooled by region.
render::BoxPlot per_region_boxes(const std::vector<records::StoredValidation>& validations) {
  std::map<std::string, std::vector<double>> pooled;
  for (const auto& v : validations)
    for (size_t i = 0; i < v.face_closest_mm.size(); ++i) pooled[v.face_regions[i]].push_back(v.face_closest_mm[i]);
  render::BoxPlot plot;
  plot.title = "Signed distance per region, all cases";
  plot.y_title = "prediction - outcome (mm)";
  plot.reference_y = 0.0;
  for (auto region : validation::kFaceSubregions) {
    auto found = pooled.find(std::string(validation::region_name(region)));
    if (found != pooled.end() && !found->second.empty()) plot.groups.push_back({found->first, found->second});
  }
  return plot;
}

}  // namespace

int write_validation_summary(const std::vector<records::StoredValidation>& validations,
                             const std::vector<std::string>& run_facts, const std::filesystem::path& pdf) {
  if (validations.empty()) throw Error(ErrorCode::kEmptyResult, pdf.string(), "no validated case to summarise");
  TemporaryFolder scratch("maxillo-nightly");  // the box plots live until the PDF is written
  const auto cases_png = scratch / "cases.png", regions_png = scratch / "regions.png";
  render::write_box_plot_png(per_case_boxes(validations), cases_png);
  const auto by_region = per_region_boxes(validations);
  if (!by_region.groups.empty()) render::write_box_plot_png(by_region, regions_png);

  report::ReportModel model;
  model.case_label = "validation summary";
  model.program_version = kVersion;
  report::Section cohort{"summary", {cohort_table(validations)}};
  report::ImageGrid charts{{{cases_png, "Per case: box P25-P75 with the median, whiskers P5-P95"}}, 1};
  if (!by_region.groups.empty()) charts.figures.push_back({regions_png, "Per face region, every case pooled"});
  cohort.blocks.push_back(charts);
  model.sections.push_back(cohort);

  report::Section cases{"validation", {}};
  for (const auto& v : validations) {
    cases.blocks.emplace_back(std::in_place_type<report::PageBreak>);
    cases.blocks.push_back(report::Subheading{case_name(v)});
    for (auto& block : sections::validation_blocks(v)) cases.blocks.push_back(std::move(block));
  }
  model.sections.push_back(cases);
  report::Section notes{"notes", {}};
  for (const auto& fact : run_facts) notes.blocks.push_back(report::Note{fact});
  model.sections.push_back(notes);

  // write_report writes through a temporary file and a rename: a reader never sees half a PDF,
  // and the log names the file a reader will open.
  return report::write_report(model, report::load_report_template("templates/validation-summary.json"), pdf);
}

}  // namespace maxillo::nightly
