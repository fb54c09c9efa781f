#include "followup/cohort_report.h"

#include <algorithm>
#include <optional>

#include "core/temporary_folder.h"
#include "core/version.h"
#include "sections/cephalometry_section.h"
#include "sections/wits_chart.h"
#include "report/report_template.h"
#include "report/write_report.h"

namespace maxillo::followup {

std::vector<ceph::CaseFollowUp> analyse_cohort(const std::vector<ceph::CohortCase>& cohort,
                                               const records::LandmarkFrame& frame, ceph::Sex sex,
                                               const std::string& source) {
  std::vector<ceph::CaseFollowUp> analysed;
  for (const auto& c : cohort) {
    std::vector<ceph::TimePointAnalysis> analyses;
    for (const auto& tp : c.time_points) {
      auto sagittal = to_sagittal(tp.landmarks, frame.geometry, frame.axes, source + " " + c.name + "/" + tp.label);
      analyses.push_back({tp.label, tp.date, ceph::analyse(sagittal, sex)});
    }
    analysed.push_back(ceph::make_follow_up(c.name, std::move(analyses)));
  }
  return analysed;
}

std::vector<std::string> cohort_time_point_labels(const std::vector<ceph::CaseFollowUp>& cohort) {
  std::vector<std::string> labels;
  for (const auto& c : cohort)
    for (const auto& tp : c.time_points)
      if (std::find(labels.begin(), labels.end(), tp.label) == labels.end()) labels.push_back(tp.label);
  return labels;
}

std::vector<std::pair<std::string, std::string>> consecutive_pairs(const std::vector<std::string>& labels) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (std::size_t i = 1; i < labels.size(); ++i) pairs.push_back({labels[i - 1], labels[i]});
  return pairs;
}

int write_cohort_report(const std::vector<ceph::CaseFollowUp>& cohort,
                        const std::vector<std::pair<std::string, std::string>>& changes, const std::string& title,
                        const std::filesystem::path& pdf) {
  report::ReportModel model;
  model.case_label = title;
  model.program_version = kVersion;
  TemporaryFolder scratch("maxillo-cohort-report");  // the chart PNG lives until the PDF is written
  std::optional<std::filesystem::path> chart;
  if (std::any_of(cohort.begin(), cohort.end(), sections::has_wits_chart)) {
    chart = scratch / "wits.png";
    sections::write_wits_chart(cohort, *chart);
  }
  model.sections.push_back(sections::cohort_follow_up_section(cohort, changes, chart));
  // Its own template: a cohort is not a patient, so no consultation title and no patient fields.
  return report::write_report(model, report::load_report_template("templates/cohort-followup.json"), pdf);
}

}  // namespace maxillo::followup
