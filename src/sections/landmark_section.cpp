#include "sections/landmark_section.h"

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

report::Table landmark_table(const records::StoredLandmarks& stored) {
  report::Table table;
  table.columns = {{"Landmark", 0.11},
                   {"x", 0.09, report::Align::Right},
                   {"y", 0.09, report::Align::Right},
                   {"z", 0.09, report::Align::Right},
                   {"Confidence", 0.12, report::Align::Right},
                   {"Status", 0.5}};
  const auto* facts = stored.automatic ? &*stored.automatic : nullptr;
  for (const auto& l : stored.landmarks) {
    std::string confidence = "by hand", status = "placed by hand";
    if (facts) {
      const auto c = facts->confidence.find(l.label);
      confidence = c != facts->confidence.end() ? report::fixed(c->second, 2) : "-";
      const auto f = facts->flagged.find(l.label);
      status = f != facts->flagged.end() ? "FLAGGED: " + f->second : "automatic, checks passed";
    }
    table.rows.push_back({l.label, report::fixed(l.position.x(), 1), report::fixed(l.position.y(), 1),
                          report::fixed(l.position.z(), 1), confidence, status});
  }
  if (facts)
    for (const auto& [label, why] : facts->absent) table.rows.push_back({label, "", "", "", "", "absent: " + why});
  return table;
}

}  // namespace

std::optional<report::Section> landmark_section(const std::optional<records::StoredLandmarks>& stored) {
  if (!stored || stored->landmarks.empty()) return std::nullopt;
  report::Section section{"landmarks", {}};
  if (stored->automatic) {
    section.blocks.push_back(report::Paragraph{
        "Found automatically on the CT (" + stored->automatic->method +
        "): no landmark file was attached. Flagged landmarks failed a check (a bilateral pair that does not mirror, "
        "an order the anatomy forbids, a size outside adult ranges) or had weak evidence: they are not used for "
        "planning until a person confirms them."});
  } else {
    section.blocks.push_back(report::Paragraph{"Placed by hand: " + stored->source + "."});
  }
  section.blocks.push_back(landmark_table(*stored));
  section.blocks.push_back(report::Note{"Positions in the patient frame (LPS), millimetres."});
  return section;
}

}  // namespace maxillo::sections
