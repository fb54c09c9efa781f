#include "sections/validation_section.h"

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using report::fixed;

std::string date_text(const std::string& date) { return date.empty() ? "(undated)" : report::format_dicom_date(date); }

report::Table segments_table(const std::vector<records::ValidationRecord::Segment>& segments) {
  report::Table table;
  table.columns = {{"Segment", 2},
                   {"Planned vs actual, mean (mm)", 2, report::Align::Right},
                   {"max (mm)", 1.2, report::Align::Right},
                   {"rotation (°)", 1.3, report::Align::Right},
                   {"ICP rms (mm)", 1.3, report::Align::Right}};
  for (const auto& s : segments)
    table.rows.push_back({s.segment, fixed(s.mean_difference_mm, 2), fixed(s.max_difference_mm, 2),
                          fixed(s.rotation_difference_deg, 2), fixed(s.icp_rms_mm, 2)});
  return table;
}

report::Table regions_table(const std::vector<records::ValidationRecord::Region>& regions, bool corresponding) {
  report::Table table;
  table.columns = statistics_columns("Region");
  for (const auto& r : regions)
    table.rows.push_back(statistics_row(
        r.region, corresponding ? r.corresponding.value_or(validation::DistanceStatistics{}) : r.closest));
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

std::vector<report::Block> validation_blocks(const records::StoredValidation& stored) {
  const records::ValidationRecord& record = stored.record;
  const records::ValidationRecord::Registration& registration = record.registration;
  std::vector<report::Block> blocks;
  blocks.push_back(
      report::Paragraph{"The post-operative CT (" + date_text(record.postop_date) +
                        ") was registered onto the pre-operative CT (" + date_text(record.preop_date) +
                        ") by mutual information on the cranium above the infraorbital rim. Each bone "
                        "segment the plan moves was then fitted to the post-operative bone (ICP from its "
                        "planned move), and the face was predicted again for the moves actually made. "
                        "Distances run from the predicted to the post-operative skin, on the outer face "
                        "without eyes and neck; negative means the prediction lies behind the real face."});
  blocks.push_back(report::KeyValueBlock{{
      {"Registration", "mutual information " + fixed(registration.metric, 3) + ", " +
                           std::to_string(registration.iterations) + " iterations, " + fixed(registration.seconds, 1) +
                           " s"},
      {"Cranium after registration",
       "ICP residual " + fixed(registration.cranium_icp_rms_mm, 2) + " mm rms against the post-operative bone"},
  }});
  if (!record.segments.empty()) blocks.push_back(segments_table(record.segments));
  const auto& regions = record.regions;
  blocks.push_back(report::Paragraph{"Closest-point distance (mm), predicted to post-operative skin:"});
  blocks.push_back(regions_table(regions, false));
  if (!regions.empty() && regions.front().corresponding && regions.front().corresponding->count > 0) {
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
      "agree; the scale runs from -3 to +3 mm (beyond it the end colours). Skin outside the compared region is "
      "plain."});
  blocks.push_back(report::ImageGrid{{{stored.profile,
                                       "Mid-sagittal profiles: pre-operative (grey), predicted (blue) "
                                       "and post-operative (red), millimetres from subnasale"}},
                                     1});
  return blocks;
}

report::Section validation_section(const records::StoredValidation& stored) {
  return report::Section{"validation", validation_blocks(stored)};
}

}  // namespace maxillo::sections
