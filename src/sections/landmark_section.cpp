#include "sections/landmark_section.h"

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

report::Table landmark_table(const records::StoredLandmarks& stored) {
  report::Table table;
  table.columns = {{"Label", 0.1},
                   {"x", 0.1, report::Align::Right},
                   {"y", 0.1, report::Align::Right},
                   {"z", 0.1, report::Align::Right},
                   {"Confidence", 0.15, report::Align::Right},
                   {"Status", 0.45}};
  const auto* facts = stored.automatic ? &*stored.automatic : nullptr;
  for (const auto& l : stored.landmarks) {
    std::string confidence = "given", status = "attached";
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

// Per label of the automatic set found in the given one: the distance between the two, and the
// automatic landmark's status.
report::Table comparison_table(const records::StoredLandmarks& given, const records::StoredLandmarks& automatic,
                               double& mean_mm) {
  report::Table table;
  table.columns = {{"Landmark", 0.15}, {"Distance (mm)", 0.2, report::Align::Right}, {"Automatic landmark", 0.65}};
  double sum = 0;
  int count = 0;
  for (const auto& l : automatic.landmarks) {
    const auto at = find_landmark(given.landmarks, l.label);
    if (!at) continue;
    const double distance = (l.position - *at).norm();
    const auto f = automatic.automatic->flagged.find(l.label);
    table.rows.push_back({l.label, report::fixed(distance, 2),
                          f != automatic.automatic->flagged.end() ? "FLAGGED: " + f->second : "checks passed"});
    sum += distance;
    ++count;
  }
  for (const auto& [label, why] : automatic.automatic->absent)
    if (find_landmark(given.landmarks, label)) table.rows.push_back({label, "-", "absent: " + why});
  mean_mm = count ? sum / count : 0;
  return table;
}

// The automatic set measured against `against` (a given or a reference set): a heading, what
// the comparison is (`mean_said`, followed by the mean distance) and the table.
void add_comparison(report::Section& section, const records::StoredLandmarks& against,
                    const records::StoredLandmarks& automatic, const std::string& heading,
                    const std::string& mean_said) {
  double mean = 0;
  report::Table comparison = comparison_table(against, automatic, mean);
  section.blocks.push_back(report::Subheading{heading});
  section.blocks.push_back(report::Paragraph{mean_said + report::fixed(mean, 2) + " mm."});
  section.blocks.push_back(std::move(comparison));
}

// The pictures two to a row (large enough to read the labels), with what the colours mean.
void add_pictures(report::Section& section, const records::StoredLandmarks& stored,
                  const std::vector<casework::LandmarkView>& pictures) {
  if (pictures.empty()) return;
  report::ImageGrid grid;
  grid.per_row = 2;
  for (const auto& p : pictures) grid.figures.push_back({p.png, p.caption});
  section.blocks.push_back(std::move(grid));
  section.blocks.push_back(report::Note{
      stored.automatic ? "Blue: found automatically, every check passed. Orange: flagged (see the table), not used for "
                         "planning until confirmed. Points inside the skull (the sella) are drawn over the bone."
                       : "Green: given with the case. Points inside the skull (the sella) are drawn over the bone."});
}

}  // namespace

std::optional<report::Section> landmark_section(const std::optional<records::StoredLandmarks>& stored,
                                                const std::optional<records::StoredLandmarks>& automatic_beside,
                                                const std::vector<casework::LandmarkView>& pictures,
                                                const std::optional<records::StoredLandmarks>& reference) {
  if (!stored || stored->landmarks.empty()) return std::nullopt;
  report::Section section{"landmarks", {}};
  if (stored->automatic) {
    section.blocks.push_back(report::Paragraph{
        "Found automatically on the CT (" + stored->automatic->method +
        "): no landmark file was attached. Flagged landmarks failed a check (a bilateral pair that does not mirror, "
        "an order the anatomy forbids, a size outside adult ranges) or had weak evidence: they are not used for "
        "planning until a person confirms them."});
  } else {
    section.blocks.push_back(report::Paragraph{"Attached to the case (" + stored->source + ")."});
  }
  add_pictures(section, *stored, pictures);
  section.blocks.push_back(landmark_table(*stored));
  section.blocks.push_back(report::Note{"Positions in the patient frame (LPS), millimetres."});
  if (!stored->automatic && automatic_beside && automatic_beside->automatic)
    add_comparison(section, *stored, *automatic_beside, "Automatic detection against these landmarks",
                   "The landmarks were also found automatically on the CT (" + automatic_beside->automatic->method +
                       "); the given set keeps precedence. Mean distance of the automatic landmarks from the given "
                       "ones: ");
  if (stored->automatic && reference)
    add_comparison(section, *reference, *stored, "Automatic detection against the known landmarks",
                   "The true places of these landmarks are known (" + reference->source +
                       "); the case works with the automatic ones. Mean distance of the automatic landmarks from "
                       "the true places: ");
  return section;
}

}  // namespace maxillo::sections
