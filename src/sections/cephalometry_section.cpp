#include "sections/cephalometry_section.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "ceph/follow_up_months.h"
#include "records/case_landmarks.h"
#include "records/cohort_archive.h"
#include "sections/wits_chart.h"

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using report::Align;

using report::fixed;

std::string with_unit(double value, const std::string& unit) {
  return fixed(value, 1) + (unit == "deg" ? "\u00b0" : " " + unit);
}

report::Table measurement_table(const ceph::CephalometricAnalysis& analysis) {
  report::Table table;
  table.columns = {{"Measurement", 3.2},
                   {"Value", 1.1, Align::Right},
                   {"Norm (mean \u00b1 SD)", 1.6, Align::Right},
                   {"Deviation", 1.4}};
  for (const auto& m : analysis.measurements) {
    std::string norm = m.norm ? fixed(m.norm->mean, 1) + " \u00b1 " + fixed(m.norm->sd, 1) : "";
    if (m.value)
      table.rows.push_back({m.name, with_unit(*m.value, m.unit), norm, std::string(ceph::deviation_name(m.deviation))});
    else
      table.rows.push_back({m.name, "n/a", norm, m.not_available_reason});
  }
  return table;
}

report::Table follow_up_table(const ceph::CaseFollowUp& follow_up) {
  report::Table table;
  table.columns.push_back({"Measurement", 1.4});
  for (const auto& tp : follow_up.time_points)
    table.columns.push_back({tp.label + (tp.date.empty() ? "" : " " + tp.date), 1, Align::Right});
  for (const auto& id : ceph::measurement_ids()) {
    std::vector<std::string> row = {id};
    bool any = false;
    for (const auto& tp : follow_up.time_points) {
      auto v = tp.analysis.value(id);
      any = any || v.has_value();
      row.push_back(v ? fixed(*v, 1) : "n/a");
    }
    if (any) table.rows.push_back(std::move(row));
  }
  return table;
}

const std::vector<std::string> kChangeIds = {"PNS_X", "Si_X", "ANS_X", "PNS_Y", "Si_Y", "ANS_Y",
                                             "alpha", "SNA",  "SNB",   "ANB",   "Wits"};

report::Table change_table(const std::vector<ceph::CaseFollowUp>& cohort, const std::string& from,
                           const std::string& to) {
  report::Table table;
  table.columns = {{"Measurement", 1.5},
                   {"Unit", 0.6},
                   {"Change " + from + " to " + to + " (mean \u00b1 SD)", 2.2, Align::Right},
                   {"n", 0.5, Align::Right}};
  for (const auto& row : ceph::cohort_changes(cohort, from, to, kChangeIds))
    if (row.n > 0) table.rows.push_back({row.id, row.unit, ceph::format_mean_sd(row), std::to_string(row.n)});
  return table;
}

std::vector<std::string> time_point_labels(const std::vector<ceph::CaseFollowUp>& cohort) {
  std::vector<std::string> labels;
  for (const auto& c : cohort)
    for (const auto& tp : c.time_points)
      if (std::find(labels.begin(), labels.end(), tp.label) == labels.end()) labels.push_back(tp.label);
  return labels;
}

report::Table wits_table(const std::vector<ceph::CaseFollowUp>& cohort) {
  report::Table table;
  auto labels = time_point_labels(cohort);
  table.columns.push_back({"Patient", 1.2});
  for (const auto& label : labels) table.columns.push_back({label, 1, Align::Right});
  for (const auto& c : cohort) {
    std::vector<std::string> row = {c.name};
    for (const auto& label : labels) {
      std::string cell = "-";
      for (const auto& tp : c.time_points)
        if (auto v = tp.label == label ? tp.analysis.value("Wits") : std::nullopt) cell = fixed(*v, 1);
      row.push_back(cell);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

report::ImageGrid chart_block(const std::filesystem::path& png, const std::string& caption) {
  return {{{png, caption}}, 1};
}

bool is_six_months_label(const std::string& label) {
  std::string l;
  for (char c : label)
    if (c != ' ' && c != '-') l += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return l == "6m" || l == "6months" || l == "6mo";
}

// The end of distraction and the 6-month time point of the cohort, when it has both.
std::optional<std::pair<std::string, std::string>> end_to_six_months(const std::vector<ceph::CaseFollowUp>& cohort) {
  std::string end, six;
  for (const auto& label : time_point_labels(cohort)) {
    if (end.empty() && ceph::is_end_of_distraction_label(label)) end = label;
    if (six.empty() && is_six_months_label(label)) six = label;
  }
  if (end.empty() || six.empty()) return std::nullopt;
  return std::pair{end, six};
}

constexpr double kStableMm = 1.0;
constexpr double kStableDeg = 1.0;

}  // namespace

std::string stability_summary(const std::vector<ceph::CaseFollowUp>& cohort, const std::string& from,
                              const std::string& to) {
  const ceph::ChangeRow* largest_mm = nullptr;
  const ceph::ChangeRow* alpha = nullptr;
  const auto rows =
      ceph::cohort_changes(cohort, from, to, {"PNS_X", "Si_X", "ANS_X", "PNS_Y", "Si_Y", "ANS_Y", "alpha"});
  for (const auto& row : rows) {
    if (!row.mean) continue;
    if (row.id == "alpha")
      alpha = &row;
    else if (!largest_mm || std::abs(*row.mean) > std::abs(*largest_mm->mean))
      largest_mm = &row;
  }
  if (!largest_mm) return "No case has both " + from + " and " + to + ": stability not assessed.";
  const bool stable = std::abs(*largest_mm->mean) <= kStableMm && (!alpha || std::abs(*alpha->mean) <= kStableDeg);
  std::string text = "Stability from " + from + " to " + to + ": the largest mean change of a maxillary point is " +
                     largest_mm->id + " " + ceph::format_mean_sd(*largest_mm) +
                     " mm (n = " + std::to_string(largest_mm->n) + ")";
  if (alpha) text += ", alpha " + ceph::format_mean_sd(*alpha) + "\u00b0";
  return text + (stable ? ": stable (every mean change within 1 mm and 1\u00b0)."
                        : ": not stable (a mean change exceeds 1 mm or 1\u00b0).");
}

report::Section cohort_follow_up_section(const std::vector<ceph::CaseFollowUp>& cohort,
                                         const std::vector<std::pair<std::string, std::string>>& changes,
                                         const std::optional<std::filesystem::path>& wits_chart) {
  std::vector<report::Block> blocks;
  blocks.emplace_back(report::Paragraph{"Cohort follow-up: " + std::to_string(cohort.size()) +
                                        " patients. Changes between time points in the nasion frame (mm) and of the "
                                        "palatal plane angle alpha (degrees)."});
  for (const auto& [from, to] : changes) blocks.emplace_back(change_table(cohort, from, to));
  blocks.emplace_back(
      report::Note{"Anterior and inferior displacements positive; alpha: upward rotation positive "
                   "(as the source's Tables II and III). SD: sample SD (n - 1)."});
  if (auto stability = end_to_six_months(cohort))
    blocks.emplace_back(report::Paragraph{stability_summary(cohort, stability->first, stability->second)});
  blocks.emplace_back(report::Paragraph{"Wits appraisal (mm) per patient and time point."});
  blocks.emplace_back(wits_table(cohort));
  if (wits_chart)
    blocks.emplace_back(chart_block(*wits_chart,
                                    "Wits appraisal over months, one line per patient (0 mm: normal; "
                                    "negative: Class III)"));
  return {"cephalometry", std::move(blocks)};
}

report::Section cephalometry_section(const std::optional<ceph::CephalometricAnalysis>& current,
                                     const std::string& current_label, const ceph::CaseFollowUp& follow_up,
                                     const std::optional<std::filesystem::path>& wits_chart) {
  if (!current)
    return {"cephalometry", {report::Note{"No landmarks are attached to this case: no cephalometric analysis."}}};
  std::string wits_note;
  if (const auto* wits = current->find("Wits"); wits && !wits->note.empty()) wits_note = " Wits: " + wits->note + ".";
  report::Note conventions{
      "Measured in the " + current->frame +
      ". ANB = SNA - SNB. Wits appraisal: A and B projected on the occlusal plane, positive in Class II." + wits_note +
      " Nasion frame: X through N, SN rotated 6\u00b0 (close to Frankfort), Y perpendicular through N; anterior and "
      "inferior positions positive. Alpha: palatal plane ANS-PNS against Y, upward rotation positive. Deviation "
      "flags: more than 1 or 2 SD from the norm."};
  report::Paragraph heading{"Cephalometric measurements of " + current_label + "."};
  if (follow_up.time_points.size() < 2) return {"cephalometry", {heading, measurement_table(*current), conventions}};
  report::Paragraph follow_up_heading{"Follow-up over " + std::to_string(follow_up.time_points.size()) +
                                      " time points (mm and degrees)."};
  report::Section section{
      "cephalometry",
      {heading, measurement_table(*current), conventions, follow_up_heading, follow_up_table(follow_up)}};
  if (wits_chart)
    section.blocks.emplace_back(
        chart_block(*wits_chart, "Wits appraisal over months (0 mm: normal; negative: Class III)"));
  return section;
}

report::Section case_cephalometry_section(Archive& archive, int64_t case_id, ceph::Sex sex) {
  auto follow_up = records::archived_case_follow_up(archive, case_id, "case " + std::to_string(case_id), sex);
  if (!follow_up.time_points.empty()) {
    const auto& last = follow_up.time_points.back();
    std::string label = "time point " + last.label + (last.date.empty() ? "" : " (" + last.date + ")");
    return cephalometry_section(last.analysis, label, follow_up, case_wits_chart(archive, case_id, follow_up));
  }
  auto landmarks = records::latest_landmarks(archive, case_id);
  if (landmarks.empty()) return cephalometry_section(std::nullopt, "", follow_up);
  auto sagittal = to_sagittal(landmarks, LandmarkGeometry::kAuto, {}, "case landmarks");
  return cephalometry_section(ceph::analyse(sagittal, sex), "the newest landmark set", follow_up);
}

}  // namespace maxillo::sections
