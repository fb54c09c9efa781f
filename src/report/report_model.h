#pragma once
// What a consultation report says, as plain data: no layout, no libharu. The template
// (report_template.h) decides the order, headings and look; write_report() lays it out.
//
// Later analyses (planning, soft tissue, occlusion, cephalometry, validation) add a Section
// with their id and blocks; the template lists which ids appear and in which order.
#include <array>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "report/pdf_document.h"  // Table, Figure, KeyValues: plain structs

namespace maxillo::report {

struct Patient {
  std::string name;        // DICOM PN: "Family^Given^Middle^Prefix^Suffix" (UTF-8)
  std::string id;          // Patient ID
  std::string birth_date;  // DICOM DA "YYYYMMDD", may be empty
  std::string sex;         // DICOM CS "M", "F", "O" or empty
};

struct SeriesRow {
  std::string date;      // DICOM DA "YYYYMMDD"
  std::string modality;  // "CT", "MR", ...
  std::string description;
  int slices = 0;
  std::array<double, 3> spacing_mm{0, 0, 0};  // column, row, slice spacing
};

struct Paragraph {
  std::string text;
};
struct Note {  // small grey text: provenance, frames of reference, caveats
  std::string text;
};
struct Subheading {  // a heading inside a section (e.g. one case of a summary)
  std::string text;
};
struct PageBreak {};  // the next block starts a new page (e.g. a page per case)
struct KeyValueBlock {
  KeyValues pairs;
};
struct ImageGrid {
  std::vector<Figure> figures;
  int per_row = 3;  // 1 (full width, e.g. a chart), 2 or 3
};

using Block = std::variant<Paragraph, Note, KeyValueBlock, Table, ImageGrid, Subheading, PageBreak>;

struct Section {
  std::string id;  // one of known_section_ids() (report_template.h)
  std::vector<Block> blocks;
};

struct ReportModel {
  Patient patient;
  std::string case_label;
  std::string images_received;    // how the series came, e.g. "over DICOM from CT_ROOM2 (1 series)"; empty: not shown
  std::vector<SeriesRow> series;  // shown in the "patient" section
  std::string generated_at;       // ISO 8601, e.g. "2024-05-02T14:03:11Z"
  std::string program_version;    // maxillo::kVersion
  std::string warning_banner;     // red on every page when not empty (PageStyle::warning_banner)
  std::vector<Section> sections;  // any order; the template orders them
};

// "Müller-Łukasz^Zoë^Anna^Dr^PhD" -> "Müller-Łukasz, Dr Zoë Anna, PhD". Only the first
// (alphabetic) component group before '=' is used; empty parts are skipped.
std::string format_person_name(std::string_view dicom_pn);
// "20240131" -> "2024-01-31"; anything else is returned unchanged; "" -> "".
std::string format_dicom_date(std::string_view dicom_da);
// "M" -> "male", "F" -> "female", "O" -> "other", anything else unchanged.
std::string format_sex(std::string_view dicom_cs);

}  // namespace maxillo::report
