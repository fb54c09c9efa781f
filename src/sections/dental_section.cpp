#include "sections/dental_section.h"

#include <string>

#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using report::fixed;

std::string percent(double share) { return fixed(100 * share, 0) + " %"; }

// The search's start, short enough for a table cell.
std::string start_cell(const std::string& start) {
  return start.find("landmarks") != std::string::npos ? "landmarks" : "global search";
}

report::Table fit_table(const std::vector<records::CaseDentalArch>& arches) {
  report::Table table;
  table.columns = {{"arch", 0.08},
                   {"scan", 0.22},
                   {"on teeth", 0.1, report::Align::Right},
                   {"RMS mm", 0.1, report::Align::Right},
                   {"P95 mm", 0.1, report::Align::Right},
                   {"≤ 0.3 mm", 0.11, report::Align::Right},
                   {"confidence", 0.13, report::Align::Right},
                   {"start", 0.16}};
  for (const auto& arch : arches) {
    if (!arch.registration) continue;
    const records::DentalRegistrationRecord& r = arch.registration->record;
    table.rows.push_back({std::string(name_of(r.arch)),
                          arch.scan.source + " (v" + std::to_string(arch.scan.version) + ")", percent(r.on_teeth_share),
                          fixed(r.rms_mm, 3), fixed(r.p95_mm, 3), percent(r.within_0_3_share), fixed(r.confidence, 2),
                          start_cell(r.start)});
  }
  return table;
}

}  // namespace

std::optional<report::Section> dental_section(const records::CaseDentalScans& dental) {
  const std::vector<records::CaseDentalArch>& arches = dental.arches;
  if (arches.empty()) return std::nullopt;
  report::Section section{"dental", {}};
  if (!dental.augmented_pictures.empty()) {
    report::ImageGrid model;
    model.per_row = 2;
    for (size_t i = 0; i < dental.augmented_pictures.size(); ++i)
      model.figures.push_back({dental.augmented_pictures[i], i == 0 ? "The augmented model from the front: scanned "
                                                                      "crowns (blue) on the CT's teeth (ivory)"
                                                                    : "The augmented model from the right"});
    section.blocks.push_back(model);
  }
  report::ImageGrid pictures;
  pictures.per_row = 2;
  for (const auto& arch : arches)
    if (arch.fit_picture)
      pictures.figures.push_back({*arch.fit_picture, "The " + std::string(name_of(arch.scan.arch)) +
                                                         " arch's scan on the CT's teeth, from the occlusal side"});
  if (!pictures.figures.empty()) section.blocks.push_back(pictures);
  report::Table table = fit_table(arches);
  if (!table.rows.empty()) {
    section.blocks.push_back(std::move(table));
    section.blocks.push_back(report::Note{
        "On the teeth: the share of the scan within 0.5 mm of the CT's teeth (the crowns; the gingiva or a cast's "
        "base lie off them). RMS, P95 and ≤ 0.3 mm: the distances of that share. Confidence: 1 - the best other "
        "pose's share / this one's (0: two poses fit alike). Start: the search began from the dental landmarks' "
        "arch and from the principal axes (landmarks), or from the principal axes alone (global search)."});
  }
  for (const auto& arch : arches) {
    const std::string name(name_of(arch.scan.arch));
    if (!arch.registration)
      section.blocks.push_back(report::Note{"The " + name + " arch's newest scan (" + arch.scan.source +
                                            ") is not placed into the CT yet: `maxillo dental register`."});
    for (const auto& warning : arch.scan.warnings)
      section.blocks.push_back(report::Note{"The " + name + " arch's scan " + arch.scan.source + ": " + warning + "."});
  }
  return section;
}

}  // namespace maxillo::sections
