#include "report/pdf_document.h"
#include "report/pdf_to_unicode.h"

#include <cassert>
#include <cstdio>
#include <string>

#include "core/atomic_file.h"
#include "core/error.h"
#include "report/pdf_document_impl.h"

namespace maxillo::report {
namespace {

// libharu calls this on every error. It must not throw: the exception would unwind through
// libharu's C frames. It records the error; Impl::check() turns it into a maxillo::Error
// right after the call that failed.
void record_error(HPDF_STATUS error_no, HPDF_STATUS detail_no, void* user_data) {
  auto* impl = static_cast<PdfDocument::Impl*>(user_data);
  if (impl->error_no == HPDF_OK) impl->error_no = error_no, impl->detail_no = detail_no;
}

std::string hex(HPDF_STATUS code) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04lX", static_cast<unsigned long>(code));
  return text;
}

// Width of the A4 page in points (210 x 297 mm).
constexpr double kA4WidthPt = 595.276, kA4HeightPt = 841.89;
// Baseline below the top of a line, as a fraction of the font size (DejaVu's ascent ~0.76 em).
constexpr double kAscent = 0.78;

double baseline_below(double top_y, double size) { return top_y - size * (0.5 * (look::kLeading - 1) + kAscent); }

HPDF_Font load_font(PdfDocument::Impl& impl, const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file))
    throw Error(ErrorCode::kFileNotFound, file.string(), "font file not found");
  const char* name = HPDF_LoadTTFontFromFile(impl.pdf, file.c_str(), HPDF_TRUE);  // embedded
  impl.check("loading the TrueType font", file.string());
  HPDF_Font font = HPDF_GetFont(impl.pdf, name, "UTF-8");
  impl.check("selecting the font with UTF-8 encoding", file.string());
  use_identity_to_unicode(impl.pdf, font);  // libharu's own is malformed (pdf_to_unicode.h)
  impl.check("writing the font's ToUnicode map", file.string());
  return font;
}

}  // namespace

void PdfDocument::Impl::check(std::string_view what, std::string_view subject) {
  if (error_no == HPDF_OK) return;
  const std::string reason =
      std::string(what) + ": libharu error " + hex(error_no) + " (detail " + std::to_string(detail_no) + ")";
  error_no = detail_no = HPDF_OK;
  HPDF_ResetError(pdf);
  throw Error(ErrorCode::kWriteFailed, std::string(subject), reason);
}

void PdfDocument::Impl::add_page() {
  HPDF_Page page = HPDF_AddPage(pdf);
  HPDF_Page_SetWidth(page, kA4WidthPt);
  HPDF_Page_SetHeight(page, kA4HeightPt);
  check("adding a page");
  pages.push_back(page);
  cursor_y = top;
}

double PdfDocument::Impl::width_of(std::string_view text, HPDF_Font font, double size) {
  if (text.empty()) return 0;
  HPDF_TextWidth measured =
      HPDF_Font_TextWidth(font, reinterpret_cast<const HPDF_BYTE*>(text.data()), static_cast<HPDF_UINT>(text.size()));
  return measured.width * size / 1000.0;
}

std::vector<std::string> PdfDocument::Impl::wrap(std::string_view text, HPDF_Font font, double size, double width) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {  // one pass per '\n'-separated paragraph
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view paragraph = text.substr(start, end - start);
    std::string line;
    std::size_t pos = 0;
    while (pos < paragraph.size()) {
      const std::size_t space = std::min(paragraph.find(' ', pos), paragraph.size());
      std::string word(paragraph.substr(pos, space - pos));
      pos = space + 1;
      if (word.empty()) continue;
      std::string candidate = line.empty() ? word : line + " " + word;
      if (width_of(candidate, font, size) <= width) {
        line = std::move(candidate);
        continue;
      }
      if (!line.empty()) lines.push_back(std::move(line)), line.clear();
      // A word wider than the line: split it between UTF-8 characters.
      while (width_of(word, font, size) > width) {
        std::size_t cut = 0, next = 0;
        while (next < word.size()) {
          std::size_t after = next + 1;
          while (after < word.size() && (static_cast<unsigned char>(word[after]) & 0xC0) == 0x80) ++after;
          if (cut > 0 && width_of(word.substr(0, after), font, size) > width) break;
          cut = next = after;
        }
        lines.push_back(word.substr(0, cut));
        word.erase(0, cut);
      }
      line = std::move(word);
    }
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

void PdfDocument::Impl::draw_text(std::string_view text, double x, double baseline, HPDF_Font font, double size,
                                  Rgb colour) {
  if (text.empty()) return;
  const std::string zero_terminated(text);
  HPDF_Page_SetRGBFill(page(), colour.r, colour.g, colour.b);
  HPDF_Page_BeginText(page());
  HPDF_Page_SetFontAndSize(page(), font, size);
  HPDF_Page_TextOut(page(), x, baseline, zero_terminated.c_str());
  HPDF_Page_EndText(page());
  check("drawing text");
}

void PdfDocument::Impl::draw_aligned(std::string_view text, double x, double width, double baseline, Align align,
                                     HPDF_Font font, double size, Rgb colour) {
  const double w = width_of(text, font, size);
  const double offset = align == Align::Left ? 0 : align == Align::Right ? width - w : 0.5 * (width - w);
  draw_text(text, x + offset, baseline, font, size, colour);
}

double PdfDocument::Impl::draw_lines(const std::vector<std::string>& lines, double x, double width, double top_y,
                                     Align align, HPDF_Font font, double size, Rgb colour) {
  const double line_height = size * look::kLeading;
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_aligned(lines[i], x, width, baseline_below(top_y - i * line_height, size), align, font, size, colour);
  return lines.size() * line_height;
}

void PdfDocument::Impl::fill_rect(double x, double y, double width, double height, Rgb colour) {
  HPDF_Page_SetRGBFill(page(), colour.r, colour.g, colour.b);
  HPDF_Page_Rectangle(page(), x, y, width, height);
  HPDF_Page_Fill(page());
  check("filling a rectangle");
}

void PdfDocument::Impl::stroke_line(double x1, double y1, double x2, double y2, double line_width, Rgb colour) {
  HPDF_Page_SetRGBStroke(page(), colour.r, colour.g, colour.b);
  HPDF_Page_SetLineWidth(page(), line_width);
  HPDF_Page_MoveTo(page(), x1, y1);
  HPDF_Page_LineTo(page(), x2, y2);
  HPDF_Page_Stroke(page());
  check("drawing a line");
}

PdfDocument::PdfDocument(PageStyle style) : impl_(std::make_unique<Impl>()) {
  auto& impl = *impl_;
  impl.style = std::move(style);
  impl.pdf = HPDF_New(record_error, &impl);
  if (!impl.pdf) throw Error(ErrorCode::kWriteFailed, "PDF", "libharu cannot create a document");
  HPDF_SetCompressionMode(impl.pdf, HPDF_COMP_ALL);
  HPDF_UseUTFEncodings(impl.pdf);
  impl.check("enabling UTF-8");
  impl.regular = load_font(impl, impl.style.regular_font);
  impl.bold = load_font(impl, impl.style.bold_font);
  HPDF_SetInfoAttr(impl.pdf, HPDF_INFO_CREATOR, "maxillo");
  if (!impl.style.document_title.empty())
    HPDF_SetInfoAttr(impl.pdf, HPDF_INFO_TITLE, impl.style.document_title.c_str());
  impl.check("setting document information");

  impl.page_width = kA4WidthPt;
  impl.page_height = kA4HeightPt;
  impl.left = mm_to_pt(impl.style.margin_left_mm);
  impl.right = kA4WidthPt - mm_to_pt(impl.style.margin_right_mm);
  impl.top = kA4HeightPt - mm_to_pt(impl.style.margin_top_mm);
  impl.bottom = mm_to_pt(impl.style.margin_bottom_mm);
  assert(impl.right - impl.left > 72 && impl.top - impl.bottom > 144 && "PdfDocument: margins leave no room");
  impl.add_page();
}

PdfDocument::~PdfDocument() {
  if (impl_->pdf) HPDF_Free(impl_->pdf);
}

int PdfDocument::page_count() const { return static_cast<int>(impl_->pages.size()); }
double PdfDocument::text_width_mm() const { return impl_->text_width() * 25.4 / 72.0; }

void PdfDocument::heading(std::string_view text, HeadingLevel level) {
  auto& impl = *impl_;
  const double size = level == HeadingLevel::Title     ? impl.body() * 1.9
                      : level == HeadingLevel::Section ? impl.body() * 1.3
                                                       : impl.body() * 1.1;
  const double space_before = level == HeadingLevel::Title ? 0 : level == HeadingLevel::Section ? 12 : 7;
  const auto lines = impl.wrap(text, impl.bold, size, impl.text_width());
  const double height = lines.size() * size * look::kLeading + (level == HeadingLevel::Section ? 5 : 2);
  // Keep a heading with at least three lines of what follows it.
  const bool at_top = impl.cursor_y >= impl.top - 0.01;
  impl.ensure_space((at_top ? 0 : space_before) + height + 3 * impl.body() * look::kLeading);
  if (impl.cursor_y < impl.top - 0.01) impl.cursor_y -= space_before;
  impl.cursor_y -= impl.draw_lines(lines, impl.left, impl.text_width(), impl.cursor_y, Align::Left, impl.bold, size,
                                   level == HeadingLevel::Subsection ? look::kText : look::kAccent);
  if (level == HeadingLevel::Section) {
    impl.stroke_line(impl.left, impl.cursor_y - 1.5, impl.right, impl.cursor_y - 1.5, 0.6, look::kAccent);
    impl.cursor_y -= 5;
  }
  impl.cursor_y -= level == HeadingLevel::Title ? 6 : 2;
}

void PdfDocument::paragraph(std::string_view text) {
  auto& impl = *impl_;
  const double line_height = impl.body() * look::kLeading;
  for (const auto& line : impl.wrap(text, impl.regular, impl.body(), impl.text_width())) {
    impl.ensure_space(line_height);
    impl.draw_text(line, impl.left, baseline_below(impl.cursor_y, impl.body()), impl.regular, impl.body(), look::kText);
    impl.cursor_y -= line_height;
  }
  impl.cursor_y -= look::kParagraphGap;
}

void PdfDocument::note(std::string_view text) {
  auto& impl = *impl_;
  const double line_height = impl.small() * look::kLeading;
  for (const auto& line : impl.wrap(text, impl.regular, impl.small(), impl.text_width())) {
    impl.ensure_space(line_height);
    impl.draw_text(line, impl.left, baseline_below(impl.cursor_y, impl.small()), impl.regular, impl.small(),
                   look::kMuted);
    impl.cursor_y -= line_height;
  }
  impl.cursor_y -= look::kParagraphGap;
}

void PdfDocument::vertical_space(double mm) {
  impl_->cursor_y -= mm_to_pt(mm);
  if (impl_->cursor_y < impl_->bottom) impl_->add_page();
}

void PdfDocument::new_page() { impl_->add_page(); }

void PdfDocument::save(const std::filesystem::path& path) {
  auto& impl = *impl_;
  assert(!impl.saved && "PdfDocument::save: a document is saved once");
  impl.saved = true;
  const int total = page_count();
  const double size = impl.style.body_size_pt * 0.8;
  const double header_baseline = impl.page_height - mm_to_pt(impl.style.margin_top_mm) + 16;
  const double footer_baseline = impl.bottom - 26;
  for (int i = 0; i < total; ++i) {
    impl.pages.push_back(impl.pages[i]);  // draw on page i through page()
    impl.draw_text(impl.style.header_left, impl.left, header_baseline, impl.bold, size, look::kAccent);
    impl.draw_aligned(impl.style.header_right, impl.left, impl.text_width(), header_baseline, Align::Right,
                      impl.regular, size, look::kMuted);
    impl.stroke_line(impl.left, header_baseline - 5, impl.right, header_baseline - 5, 0.5, look::kRule);
    if (!impl.style.warning_banner.empty())
      impl.draw_aligned(impl.style.warning_banner, impl.left, impl.text_width(), header_baseline - 16, Align::Centre,
                        impl.bold, size, look::kWarning);
    impl.stroke_line(impl.left, footer_baseline + 11, impl.right, footer_baseline + 11, 0.5, look::kRule);
    impl.draw_text(impl.style.footer_text, impl.left, footer_baseline, impl.regular, size, look::kMuted);
    impl.draw_aligned("page " + std::to_string(i + 1) + " of " + std::to_string(total), impl.left, impl.text_width(),
                      footer_baseline, Align::Right, impl.regular, size, look::kMuted);
    impl.pages.pop_back();
  }
  HPDF_SaveToStream(impl.pdf);
  impl.check("encoding the PDF", path.string());
  std::vector<std::byte> bytes(HPDF_GetStreamSize(impl.pdf));
  HPDF_UINT32 size_read = static_cast<HPDF_UINT32>(bytes.size());
  HPDF_ResetStream(impl.pdf);
  HPDF_ReadFromStream(impl.pdf, reinterpret_cast<HPDF_BYTE*>(bytes.data()), &size_read);
  impl.check("reading the encoded PDF", path.string());
  bytes.resize(size_read);
  write_file_atomically(path, bytes);
}

}  // namespace maxillo::report
