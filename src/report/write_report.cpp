#include "report/write_report.h"

#include <algorithm>
#include <cassert>
#include <cstdio>

#include "core/error.h"
#include "core/log.h"
#include "report/fonts.h"
#include "report/pdf_document.h"

namespace maxillo::report {
namespace {

PageStyle page_style(const ReportModel& model, const ReportTemplate& t) {
  PageStyle style;
  style.margin_top_mm = t.margin_top_mm;
  style.margin_bottom_mm = t.margin_bottom_mm;
  style.margin_left_mm = t.margin_left_mm;
  style.margin_right_mm = t.margin_right_mm;
  style.regular_font = resolve_font(t.regular_font);
  style.bold_font = resolve_font(t.bold_font);
  style.body_size_pt = t.body_size_pt;
  style.header_left = t.title;
  style.header_right =
      format_person_name(model.patient.name) + (model.patient.id.empty() ? "" : "  ·  ID " + model.patient.id);
  style.footer_text = t.footer;
  style.warning_banner = model.warning_banner;
  style.document_title = t.title;
  return style;
}

std::string format_spacing(const std::array<double, 3>& spacing) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2f × %.2f × %.2f", spacing[0], spacing[1], spacing[2]);
  return text;
}

void patient_section(PdfDocument& pdf, const ReportModel& model) {
  const auto& p = model.patient;
  std::vector<std::pair<std::string, std::string>> facts = {{"Patient", format_person_name(p.name)},
                                                            {"Patient ID", p.id},
                                                            {"Birth date", format_dicom_date(p.birth_date)},
                                                            {"Sex", format_sex(p.sex)},
                                                            {"Case", model.case_label}};
  if (!model.images_received.empty()) facts.emplace_back("Images received", model.images_received);
  pdf.key_values(facts);
  if (model.series.empty()) return;
  Table table{{{"Date", 1.3, Align::Left},
               {"Modality", 1.1, Align::Left},
               {"Description", 3.4, Align::Left},
               {"Slices", 0.9, Align::Right},
               {"Spacing (mm)", 2.2, Align::Right}},
              {}};
  for (const auto& s : model.series)
    table.rows.push_back(
        {format_dicom_date(s.date), s.modality, s.description, std::to_string(s.slices), format_spacing(s.spacing_mm)});
  pdf.table(table);
}

void draw_block(PdfDocument& pdf, const Block& block) {
  std::visit(
      [&](const auto& b) {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, Paragraph>) pdf.paragraph(b.text);
        if constexpr (std::is_same_v<T, Note>) pdf.note(b.text);
        if constexpr (std::is_same_v<T, KeyValueBlock>) pdf.key_values(b.pairs);
        if constexpr (std::is_same_v<T, Table>) pdf.table(b);
        if constexpr (std::is_same_v<T, ImageGrid>) pdf.figure_grid(b.figures, b.per_row);
        if constexpr (std::is_same_v<T, Subheading>) pdf.heading(b.text, HeadingLevel::Subsection);
        if constexpr (std::is_same_v<T, PageBreak>) pdf.new_page();
      },
      block);
}

const Section* find_section(const ReportModel& model, const std::string& id) {
  auto found = std::find_if(model.sections.begin(), model.sections.end(), [&](const Section& s) { return s.id == id; });
  return found == model.sections.end() ? nullptr : &*found;
}

void check_sections_are_listed(const ReportModel& model, const ReportTemplate& t) {
  for (const auto& section : model.sections) {
    const bool listed =
        std::any_of(t.sections.begin(), t.sections.end(), [&](const TemplateSection& s) { return s.id == section.id; });
    if (!listed) throw Error(ErrorCode::kBadTemplate, t.source, "the template has no section '" + section.id + "'");
    assert(std::count_if(model.sections.begin(), model.sections.end(),
                         [&](const Section& s) { return s.id == section.id; }) == 1 &&
           "write_report: a section id appears twice in the model");
  }
}

void title_block(PdfDocument& pdf, const ReportModel& model, const ReportTemplate& t) {
  pdf.heading(t.title, HeadingLevel::Title);
  std::string provenance = t.subtitle;
  if (!model.generated_at.empty())
    provenance += (provenance.empty() ? "" : "  ·  ") + ("generated " + model.generated_at);
  if (!model.program_version.empty()) provenance += " by maxillo " + model.program_version;
  if (!provenance.empty()) pdf.note(provenance);
}

}  // namespace

int write_report(const ReportModel& model, const ReportTemplate& report_template,
                 const std::filesystem::path& out_pdf) {
  check_sections_are_listed(model, report_template);
  PdfDocument pdf(page_style(model, report_template));
  title_block(pdf, model, report_template);
  for (const auto& entry : report_template.sections) {
    const Section* section = find_section(model, entry.id);
    if (entry.id != "patient" && !section) continue;
    // A section whose content starts on a new page starts there with its heading, which would
    // otherwise be left alone at the foot of the page before.
    const bool starts_with_page_break =
        section && !section->blocks.empty() && std::holds_alternative<PageBreak>(section->blocks.front());
    if (starts_with_page_break) pdf.new_page();
    pdf.heading(entry.heading, HeadingLevel::Section);
    if (!entry.intro.empty()) pdf.paragraph(entry.intro);
    if (entry.id == "patient") patient_section(pdf, model);
    if (section)
      for (size_t b = starts_with_page_break ? 1 : 0; b < section->blocks.size(); ++b)
        draw_block(pdf, section->blocks[b]);
  }
  pdf.save(out_pdf);
  log::debug("report for ", model.patient.id, " written to ", out_pdf.string());
  log::info("report written: ", out_pdf.string(), " (", pdf.page_count(), " pages)");
  return pdf.page_count();
}

}  // namespace maxillo::report
