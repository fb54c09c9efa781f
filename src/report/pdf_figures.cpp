// PNG figures of a PdfDocument: one centred figure, or a grid of 2 or 3 per row.
#include <algorithm>
#include <cassert>

#include "core/error.h"
#include "report/pdf_document.h"
#include "report/pdf_document_impl.h"

namespace maxillo::report {
namespace {

constexpr double kGridGap = 10;    // points between figures of a row
constexpr double kCaptionGap = 4;  // points between a figure and its caption

HPDF_Image load_png(PdfDocument::Impl& impl, const std::filesystem::path& png) {
  if (!std::filesystem::is_regular_file(png))
    throw Error(ErrorCode::kFileNotFound, png.string(), "figure image not found");
  HPDF_Image image = HPDF_LoadPngImageFromFile(impl.pdf, png.c_str());
  impl.check("reading the PNG image", png.string());
  if (HPDF_Image_GetWidth(image) == 0 || HPDF_Image_GetHeight(image) == 0)
    throw Error(ErrorCode::kBadValue, png.string(), "PNG image has no pixels");
  return image;
}

struct Placed {
  HPDF_Image image;
  double width, height;  // points
  std::vector<std::string> caption;
};

Placed place(PdfDocument::Impl& impl, const Figure& figure, double box_width, double box_height) {
  HPDF_Image image = load_png(impl, figure.png);
  const double aspect = double(HPDF_Image_GetHeight(image)) / HPDF_Image_GetWidth(image);
  double width = box_width, height = box_width * aspect;
  if (height > box_height) height = box_height, width = box_height / aspect;
  return {image, width, height, impl.wrap(figure.caption, impl.regular, impl.small(), box_width)};
}

double caption_height(const PdfDocument::Impl& impl, const Placed& placed) {
  return placed.caption.empty() || placed.caption.front().empty()
             ? 0
             : kCaptionGap + placed.caption.size() * impl.small() * look::kLeading;
}

// Draws the figure with its top at cursor_y, centred in [x, x + cell_width].
void draw_placed(PdfDocument::Impl& impl, const Placed& placed, double x, double cell_width) {
  const double image_x = x + 0.5 * (cell_width - placed.width);
  const double image_y = impl.cursor_y - placed.height;
  HPDF_Page_DrawImage(impl.page(), placed.image, image_x, image_y, placed.width, placed.height);
  impl.check("placing an image");
  HPDF_Page_SetRGBStroke(impl.page(), look::kRule.r, look::kRule.g, look::kRule.b);
  HPDF_Page_SetLineWidth(impl.page(), 0.5);
  HPDF_Page_Rectangle(impl.page(), image_x, image_y, placed.width, placed.height);
  HPDF_Page_Stroke(impl.page());
  impl.draw_lines(placed.caption, x, cell_width, image_y - kCaptionGap, Align::Centre, impl.regular, impl.small(),
                  look::kMuted);
}

}  // namespace

void PdfDocument::figure(const Figure& figure, double max_height_mm) {
  auto& impl = *impl_;
  const double usable = impl.top - impl.bottom - 3 * impl.small() * look::kLeading;
  const Placed placed = place(impl, figure, impl.text_width(), std::min(mm_to_pt(max_height_mm), usable));
  impl.ensure_space(placed.height + caption_height(impl, placed));
  draw_placed(impl, placed, impl.left, impl.text_width());
  impl.cursor_y -= placed.height + caption_height(impl, placed) + look::kParagraphGap + 4;
}

void PdfDocument::figure_grid(const std::vector<Figure>& figures, int per_row) {
  assert(per_row >= 1 && per_row <= 3 && "figure_grid: 1, 2 or 3 figures per row");
  auto& impl = *impl_;
  const double cell_width = (impl.text_width() - (per_row - 1) * kGridGap) / per_row;
  const double max_height = 0.6 * (impl.top - impl.bottom);
  for (std::size_t first = 0; first < figures.size(); first += per_row) {
    std::vector<Placed> row;
    double row_height = 0;
    for (std::size_t i = first; i < std::min(figures.size(), first + per_row); ++i) {
      row.push_back(place(impl, figures[i], cell_width, max_height));
      row_height = std::max(row_height, row.back().height + caption_height(impl, row.back()));
    }
    impl.ensure_space(row_height);
    for (std::size_t k = 0; k < row.size(); ++k)
      draw_placed(impl, row[k], impl.left + k * (cell_width + kGridGap), cell_width);
    impl.cursor_y -= row_height + kGridGap;
  }
  impl.cursor_y -= look::kParagraphGap;
}

}  // namespace maxillo::report
