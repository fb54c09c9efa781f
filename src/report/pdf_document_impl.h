#pragma once
// Private to src/report: the libharu state behind a PdfDocument and the drawing primitives
// shared by pdf_document.cpp, pdf_tables.cpp and pdf_figures.cpp. Carries hpdf types:
// never include this from another module.
#include <hpdf.h>

#include <string>
#include <string_view>
#include <vector>

#include "report/pdf_document.h"

namespace maxillo::report {

struct Rgb {
  double r, g, b;
};

// The palette and type scale of every report (points unless stated).
namespace look {
inline constexpr Rgb kText{0.13, 0.14, 0.16};
inline constexpr Rgb kMuted{0.42, 0.44, 0.47};
inline constexpr Rgb kAccent{0.11, 0.29, 0.45};
inline constexpr Rgb kRule{0.75, 0.78, 0.82};
inline constexpr Rgb kWarning{0.80, 0.05, 0.05};
inline constexpr Rgb kHeaderFill{0.86, 0.90, 0.94};
inline constexpr Rgb kZebraFill{0.955, 0.962, 0.972};
inline constexpr double kLeading = 1.38;     // line height / font size
inline constexpr double kSmallScale = 0.85;  // notes, captions, table text
inline constexpr double kParagraphGap = 6;   // after paragraphs and blocks
inline constexpr double kCellPadX = 4.5;
inline constexpr double kCellPadY = 3.0;
}  // namespace look

inline double mm_to_pt(double mm) { return mm * 72.0 / 25.4; }

struct PdfDocument::Impl {
  PageStyle style;
  HPDF_Doc pdf = nullptr;
  HPDF_Font regular = nullptr;
  HPDF_Font bold = nullptr;
  std::vector<HPDF_Page> pages;
  // Layout box in points, PDF coordinates (origin bottom-left). cursor_y is the top of the
  // next block and moves down as content is added.
  double page_width = 0, page_height = 0, left = 0, right = 0, top = 0, bottom = 0;
  double cursor_y = 0;
  bool saved = false;  // headers and footers are drawn once, by save()
  // The last libharu error, recorded by the error handler (see pdf_document.cpp).
  HPDF_STATUS error_no = HPDF_OK;
  HPDF_STATUS detail_no = HPDF_OK;

  double text_width() const { return right - left; }
  double body() const { return style.body_size_pt; }
  double small() const { return style.body_size_pt * look::kSmallScale; }
  HPDF_Page page() const { return pages.back(); }

  // Throws Error(subject, "<what>: libharu error 0x....") if libharu reported an error.
  void check(std::string_view what, std::string_view subject = "PDF");
  void add_page();
  bool fits(double height) const { return cursor_y - height >= bottom - 0.01; }
  void ensure_space(double height) {
    if (!fits(height)) add_page();
  }

  double width_of(std::string_view text, HPDF_Font font, double size);
  // Greedy word wrap; words wider than `width` are split between characters; '\n' breaks.
  std::vector<std::string> wrap(std::string_view text, HPDF_Font font, double size, double width);
  void draw_text(std::string_view text, double x, double baseline, HPDF_Font font, double size, Rgb colour);
  void draw_aligned(std::string_view text, double x, double width, double baseline, Align align, HPDF_Font font,
                    double size, Rgb colour);
  // Wrapped lines from the cursor down (no page breaks inside); returns the height used.
  double draw_lines(const std::vector<std::string>& lines, double x, double width, double top_y, Align align,
                    HPDF_Font font, double size, Rgb colour);
  void fill_rect(double x, double y, double width, double height, Rgb colour);
  void stroke_line(double x1, double y1, double x2, double y2, double line_width, Rgb colour);
};

}  // namespace maxillo::report
