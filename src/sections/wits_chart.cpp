#include "sections/wits_chart.h"

#include <chrono>

#include "archive/artefact_kind.h"
#include "ceph/follow_up_months.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/temporary_folder.h"
#include "records/derivation.h"

namespace maxillo::sections {
namespace {

const std::string kArtefactKind = kind_name(ArtefactKind::kChartWits);
const render::ChartSettings kChartSettings{{1200, 700}, {1.0, 1.0, 1.0}, 22};

std::string x_axis_title(const std::vector<ceph::MeasurementOverMonths>& charted) {
  bool any_end = false, any_first = false;
  for (const auto& c : charted) (c.origin == ceph::MonthsOrigin::kEndOfDistraction ? any_end : any_first) = true;
  if (any_end && !any_first) return "months since the end of distraction";
  if (!any_end) return "months since the first time point";
  return "months since the end of distraction (else the first time point)";
}

// The Wits values, labels and dates the chart shows, as the derivation's parameters.
Json chart_parameters(const ceph::CaseFollowUp& follow_up) {
  Json points = Json::array();
  for (const auto& tp : follow_up.time_points) {
    auto wits = tp.analysis.value("Wits");
    points.push_back({{"label", tp.label}, {"date", tp.date}, {"wits", wits ? Json(*wits) : Json(nullptr)}});
  }
  return {{"points", points}, {"width", kChartSettings.size.width}, {"height", kChartSettings.size.height}};
}

}  // namespace

bool has_wits_chart(const ceph::CaseFollowUp& follow_up) {
  return ceph::measurement_over_months(follow_up, "Wits").months.size() >= 2;
}

render::LineChart wits_line_chart(const std::vector<ceph::CaseFollowUp>& cohort) {
  std::vector<ceph::MeasurementOverMonths> charted;
  for (auto& c : ceph::measurement_over_months(cohort, "Wits"))
    if (c.months.size() >= 2) charted.push_back(std::move(c));
  if (charted.empty())
    throw Error(ErrorCode::kEmptyResult, "Wits chart", "no case has two dated time points with a Wits appraisal");

  render::LineChart chart;
  chart.x_title = x_axis_title(charted);
  chart.y_title = "Wits appraisal (mm)";
  chart.reference_y = 0.0;
  for (auto& c : charted) chart.series.push_back({c.name, std::move(c.months), std::move(c.values), std::nullopt});
  return chart;
}

void write_wits_chart(const std::vector<ceph::CaseFollowUp>& cohort, const std::filesystem::path& png) {
  const auto start = std::chrono::steady_clock::now();
  const auto chart = wits_line_chart(cohort);
  render::write_line_chart_png(chart, png, kChartSettings);
  log::debug("Wits chart (", chart.series.size(), " lines) rendered in ",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), " s");
}

std::optional<std::filesystem::path> case_wits_chart(Archive& archive, int64_t case_id,
                                                     const ceph::CaseFollowUp& follow_up) {
  if (!has_wits_chart(follow_up)) return std::nullopt;
  const Json parameters = chart_parameters(follow_up);
  const std::string key = records::derivation_key({}, parameters);
  if (auto stored = archive.find_artefact(case_id, kArtefactKind, key))
    return archive.object_path(stored->object_sha256);

  TemporaryFolder scratch("maxillo-chart");
  const auto png = scratch / "wits.png";
  write_wits_chart({follow_up}, png);
  const auto sha = archive.store_object(read_file(png));
  archive.add_artefact(NewArtefact{case_id, kArtefactKind, sha, "image/png", key, parameters.dump()});
  return archive.object_path(sha);
}

}  // namespace maxillo::sections
