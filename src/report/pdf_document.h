#pragma once
// A small flowing layout engine over libharu: A4 portrait pages with margins, a running
// header and a footer with "page N of M", headings, wrapped paragraphs, key-value blocks,
// tables (column widths, header row repeated after page breaks, zebra rows) and PNG images
// (alone or in grids of 2 or 3 per row) with captions. Content flows top to bottom and moves
// to a new page when it does not fit. All text is UTF-8; fonts are TrueType, embedded.
//
// Units: millimetres for lengths given here, points (1/72 inch) for font sizes.
// Failures (unreadable font or PNG, libharu errors, cannot write) throw maxillo::Error.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace maxillo::report {

struct PageStyle {
  double margin_top_mm = 24;     // the running header sits inside the top margin
  double margin_bottom_mm = 22;  // the footer sits inside the bottom margin
  double margin_left_mm = 20;
  double margin_right_mm = 20;
  std::filesystem::path regular_font;  // TrueType files (see fonts.h: resolve_font)
  std::filesystem::path bold_font;
  double body_size_pt = 10;
  std::string header_left;   // e.g. the report title
  std::string header_right;  // e.g. the patient's name and ID
  std::string footer_text;   // e.g. "Not a diagnosis: planning aid, verify clinically"
  // Drawn in red under the running header of every page when not empty: what makes the whole
  // document unsafe to act on (a CT whose header contradicts the anatomy).
  std::string warning_banner;
  std::string document_title;  // PDF metadata
};

enum class HeadingLevel { Title, Section, Subsection };
enum class Align { Left, Centre, Right };

struct TableColumn {
  std::string title;
  double width_fraction = 1;  // of the text width; the fractions of a table are normalised
  Align align = Align::Left;
};

struct Table {
  std::vector<TableColumn> columns;
  std::vector<std::vector<std::string>> rows;  // each row has columns.size() cells; cells wrap
};

struct Figure {
  std::filesystem::path png;  // RGB or RGBA PNG file
  std::string caption;
};

using KeyValues = std::vector<std::pair<std::string, std::string>>;

class PdfDocument {
 public:
  // Loads the fonts and opens the first page. Throws Error(FileNotFound) for a missing font.
  explicit PdfDocument(PageStyle style);
  ~PdfDocument();
  PdfDocument(const PdfDocument&) = delete;
  PdfDocument& operator=(const PdfDocument&) = delete;

  void heading(std::string_view text, HeadingLevel level);
  void paragraph(std::string_view text);                              // wrapped to the text width
  void note(std::string_view text);                                   // smaller grey text (provenance, remarks)
  void key_values(const KeyValues& pairs);                            // two columns: bold keys, values
  void table(const Table& table);                                     // asserts each row has one cell per column
  void figure(const Figure& figure, double max_height_mm);            // centred, scaled to fit
  void figure_grid(const std::vector<Figure>& figures, int per_row);  // per_row: 1 (full width, e.g. a chart), 2 or 3
  void vertical_space(double mm);
  void new_page();

  int page_count() const;
  double text_width_mm() const;

  // Draws headers and footers ("page N of M") and writes the PDF atomically
  // (temporary file + rename). Call once, after all content. Throws Error(WriteFailed).
  void save(const std::filesystem::path& path);

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace maxillo::report
