// Key-value blocks and tables of a PdfDocument.
#include <algorithm>
#include <cassert>
#include <numeric>

#include "report/pdf_document.h"
#include "report/pdf_document_impl.h"

namespace maxillo::report {
namespace {

struct CellLayout {
  double x = 0, width = 0;
  Align align = Align::Left;
};

std::vector<CellLayout> column_layout(const Table& table, double left, double text_width) {
  double total = 0;
  for (const auto& column : table.columns) {
    assert(column.width_fraction > 0 && "table: column width fractions must be positive");
    total += column.width_fraction;
  }
  std::vector<CellLayout> cells;
  double x = left;
  for (const auto& column : table.columns) {
    const double width = text_width * column.width_fraction / total;
    cells.push_back({x, width, column.align});
    x += width;
  }
  return cells;
}

using WrappedRow = std::vector<std::vector<std::string>>;  // lines per cell

WrappedRow wrap_row(PdfDocument::Impl& impl, const std::vector<std::string>& cells,
                    const std::vector<CellLayout>& layout, HPDF_Font font) {
  WrappedRow row;
  for (std::size_t c = 0; c < cells.size(); ++c)
    row.push_back(impl.wrap(cells[c], font, impl.small(), layout[c].width - 2 * look::kCellPadX));
  return row;
}

double row_height(const PdfDocument::Impl& impl, const WrappedRow& row) {
  std::size_t lines = 1;
  for (const auto& cell : row) lines = std::max(lines, cell.size());
  return lines * impl.small() * look::kLeading + 2 * look::kCellPadY;
}

void draw_row(PdfDocument::Impl& impl, const WrappedRow& row, const std::vector<CellLayout>& layout, HPDF_Font font,
              const Rgb* fill) {
  const double height = row_height(impl, row);
  if (fill) impl.fill_rect(impl.left, impl.cursor_y - height, impl.text_width(), height, *fill);
  for (std::size_t c = 0; c < row.size(); ++c)
    impl.draw_lines(row[c], layout[c].x + look::kCellPadX, layout[c].width - 2 * look::kCellPadX,
                    impl.cursor_y - look::kCellPadY, layout[c].align, font, impl.small(), look::kText);
  impl.cursor_y -= height;
}

}  // namespace

void PdfDocument::table(const Table& table) {
  auto& impl = *impl_;
  assert(!table.columns.empty() && "table: no columns");
  const auto layout = column_layout(table, impl.left, impl.text_width());
  std::vector<std::string> titles;
  for (const auto& column : table.columns) titles.push_back(column.title);
  const WrappedRow header = wrap_row(impl, titles, layout, impl.bold);

  auto start_on_this_page = [&] {
    draw_row(impl, header, layout, impl.bold, &look::kHeaderFill);
    impl.stroke_line(impl.left, impl.cursor_y, impl.right, impl.cursor_y, 0.6, look::kAccent);
  };
  // The header never stands alone at the bottom of a page: it needs one row below it.
  const double first_row =
      table.rows.empty() ? 0 : row_height(impl, wrap_row(impl, table.rows[0], layout, impl.regular));
  impl.ensure_space(row_height(impl, header) + first_row);
  start_on_this_page();
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    assert(table.rows[r].size() == table.columns.size() && "table: a row has the wrong number of cells");
    const WrappedRow row = wrap_row(impl, table.rows[r], layout, impl.regular);
    if (!impl.fits(row_height(impl, row))) {
      impl.add_page();
      start_on_this_page();  // repeat the header row
    }
    draw_row(impl, row, layout, impl.regular, r % 2 == 1 ? &look::kZebraFill : nullptr);
  }
  impl.stroke_line(impl.left, impl.cursor_y, impl.right, impl.cursor_y, 0.5, look::kRule);
  impl.cursor_y -= look::kParagraphGap + 4;
}

void PdfDocument::key_values(const KeyValues& pairs) {
  auto& impl = *impl_;
  double key_width = 0;
  for (const auto& [key, value] : pairs) key_width = std::max(key_width, impl.width_of(key, impl.bold, impl.body()));
  key_width = std::min(key_width + 14, 0.4 * impl.text_width());
  const double value_width = impl.text_width() - key_width;
  const double line_height = impl.body() * look::kLeading;
  for (const auto& [key, value] : pairs) {
    const auto key_lines = impl.wrap(key, impl.bold, impl.body(), key_width - 10);
    const auto value_lines = impl.wrap(value.empty() ? "–" : value, impl.regular, impl.body(), value_width);
    const double height = std::max(key_lines.size(), value_lines.size()) * line_height + 2;
    impl.ensure_space(height);
    impl.draw_lines(key_lines, impl.left, key_width, impl.cursor_y, Align::Left, impl.bold, impl.body(), look::kMuted);
    impl.draw_lines(value_lines, impl.left + key_width, value_width, impl.cursor_y, Align::Left, impl.regular,
                    impl.body(), look::kText);
    impl.cursor_y -= height;
  }
  impl.cursor_y -= look::kParagraphGap;
}

}  // namespace maxillo::report
