#include "pipeline/validation_section.h"

#include "pipeline/validation_json.h"
#include "report/number_text.h"

namespace maxillo::pipeline {
namespace {

using report::fixed;

std::string date_text(const Json& summary, const char* key) {
  const auto date = summary.value(key, "");
  return date.empty() ? "(undated)" : report::format_dicom_date(date);
}

report::Table segments_table(const Json& summary) {
  report::Table table;
  table.columns = {{"Segment", 2},
                   {"Planned vs actual, mean (mm)", 2, report::Align::Right},
                   {"max (mm)", 1.2, report::Align::Right},
                   {"rotation (°)", 1.3, report::Align::Right},
                   {"ICP rms (mm)", 1.3, report::Align::Right}};
  for (const auto& s : summary.at("segments"))
    table.rows.push_back({s.at("segment").get<std::string>(), fixed(s.at("mean_difference_mm").get<double>(), 2),
                          fixed(s.at("max_difference_mm").get<double>(), 2),
                          fixed(s.at("rotation_difference_deg").get<double>(), 2),
                          fixed(s.at("icp_rms_mm").get<double>(), 2)});
  return table;
}

report::Table regions_table(const std::vector<StoredRegion>& regions, bool corresponding) {
  report::Table table;
  table.columns = statistics_columns("Region");
  for (const auto& r : regions)
    table.rows.push_back(statistics_row(r.region, corresponding ? r.corresponding : r.closest));
  return table;
}

}  // namespace

std::vector<report::TableColumn> statistics_columns(const std::string& first_column) {
  const auto right = report::Align::Right;
  return {{first_column, 2.0},     {"n", 1.0, right},    {"mean |d|", 1.2, right}, {"mean", 1.0, right},
          {"SD", 0.9, right},      {"P5", 0.9, right},   {"P50", 0.9, right},      {"P95", 0.9, right},
          {"max |d|", 1.1, right}, {"±2 mm", 1.1, right}};
}

std::vector<std::string> statistics_row(const std::string& name, const validation::DistanceStatistics& s) {
  if (s.count == 0) return {name, "0", "-", "-", "-", "-", "-", "-", "-", "-"};
  return {name,
          std::to_string(s.count),
          fixed(s.mean_absolute, 2),
          fixed(s.mean_signed, 2),
          fixed(s.standard_deviation, 2),
          fixed(s.p5, 2),
          fixed(s.p50, 2),
          fixed(s.p95, 2),
          fixed(s.max_absolute, 2),
          fixed(s.within_tolerance_percent, 1) + " %"};
}

std::vector<report::Block> validation_blocks(const StoredValidation& stored) {
  const Json& summary = stored.summary;
  const auto& registration = summary.at("registration");
  std::vector<report::Block> blocks;
  blocks.push_back(report::Paragraph{"The post-operative CT (" + date_text(summary, "postop_date") +
                                     ") was registered onto the pre-operative CT (" + date_text(summary, "preop_date") +
                                     ") by mutual information on the cranium above the infraorbital rim. Each bone "
                                     "segment the plan moves was then fitted to the post-operative bone (ICP from its "
                                     "planned move), and the face was predicted again for the moves actually made. "
                                     "Distances run from the predicted to the post-operative skin, on the outer face "
                                     "without eyes and neck; negative means the prediction lies behind the real face."});
  blocks.push_back(report::KeyValueBlock{{
      {"Registration", "mutual information " + fixed(registration.at("metric").get<double>(), 3) + ", " +
                           std::to_string(registration.at("iterations").get<int>()) + " iterations, " +
                           fixed(registration.at("seconds").get<double>(), 1) + " s"},
      {"Cranium after registration", "ICP residual " + fixed(registration.at("cranium_icp_rms_mm").get<double>(), 2) +
                                         " mm rms against the post-operative bone"},
  }});
  if (!summary.at("segments").empty()) blocks.push_back(segments_table(summary));
  const auto regions = stored_regions(summary);
  blocks.push_back(report::Paragraph{"Closest-point distance (mm), predicted to post-operative skin:"});
  blocks.push_back(regions_table(regions, false));
  if (!regions.empty() && regions.front().corresponding.count > 0) {
    blocks.push_back(report::Paragraph{
        "Corresponding-point distance (mm), after a smooth non-rigid registration of the prediction onto the outcome "
        "(coherent point drift): a point may not slide along the surface to its nearest neighbour."});
    blocks.push_back(regions_table(regions, true));
  }
  report::ImageGrid maps;
  const std::array<std::string, 3> views{"frontal", "right lateral", "oblique"};
  for (size_t i = 0; i < stored.error_maps.size() && i < views.size(); ++i)
    maps.figures.push_back({stored.error_maps[i], "Error map, " + views[i]});
  blocks.push_back(maps);
  blocks.push_back(report::Note{
      "Error map: blue where the prediction lies behind the real face, red where it lies in front, white where they "
      "agree; the scale runs from -3 to +3 mm (beyond it the end colours). Skin outside the compared region is plain."});
  blocks.push_back(report::ImageGrid{{{stored.profile,
                                       "Mid-sagittal profiles: pre-operative (grey), predicted (blue) "
                                       "and post-operative (red), millimetres from subnasale"}},
                                     1});
  return blocks;
}

report::Section validation_section(const StoredValidation& stored) {
  return report::Section{"validation", validation_blocks(stored)};
}

}  // namespace maxillo::pipeline
