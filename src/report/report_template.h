#pragma once
// A report template: the title, which sections appear in which order with their headings and
// introductions, the page margins, fonts and the footer. Templates are JSON files under
// templates/ (embedded in the program; MAXILLO_RESOURCE_DIR overrides, see core/resources.h).
//
// Format (every key below is allowed, no other; all are required unless marked optional):
//   {
//     "title": "Consultation report",
//     "subtitle": "...",                                          (optional)
//     "page": {"size": "A4", "orientation": "portrait",
//              "margins_mm": {"top": 24, "bottom": 22, "left": 20, "right": 20}},
//     "fonts": {"regular": "DejaVuSans.ttf", "bold": "DejaVuSans-Bold.ttf", "body_size_pt": 10},
//     "footer": "Not a diagnosis: planning aid, verify clinically",
//     "sections": [{"id": "patient", "heading": "Patient and imaging", "intro": "..."(optional)}, ...]
//   }
// Section ids must be known_section_ids(), each at most once. Only A4 portrait is supported.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace maxillo::report {

struct TemplateSection {
  std::string id;
  std::string heading;
  std::string intro;  // may be empty
};

struct ReportTemplate {
  std::string source;  // where it was loaded from, for error messages
  std::string title;
  std::string subtitle;
  double margin_top_mm = 24, margin_bottom_mm = 22, margin_left_mm = 20, margin_right_mm = 20;
  std::string regular_font;  // file name or absolute path (report/fonts.h: resolve_font)
  std::string bold_font;
  double body_size_pt = 10;
  std::string footer;
  std::vector<TemplateSection> sections;
};

// The section ids a template may name. "patient" is filled by write_report() from the model's
// patient and series; the others come from ReportModel::sections.
std::span<const std::string_view> known_section_ids();

// Parses and validates a template. Throws Error(BadTemplate, source, reason) for invalid JSON,
// an unknown key (named, with its path, e.g. "unknown key 'colour' in page"), a missing or
// mistyped value, an unknown or repeated section id, or an unsupported page size.
ReportTemplate parse_report_template(std::string_view json_text, std::string_view source);

// load_resource(path) then parse_report_template.
ReportTemplate load_report_template(std::string_view resource_path = "templates/consultation.json");

}  // namespace maxillo::report
