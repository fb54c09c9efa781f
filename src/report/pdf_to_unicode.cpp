#include "report/pdf_to_unicode.h"

#include <cstdio>
#include <string>

namespace maxillo::report {
namespace {

// The identity from 2-byte codes to UTF-16, as bfrange lines: a range may only vary in its last
// byte, and at most 100 entries go in one block (PDF 32000-1, 9.10.3). The surrogate block
// D800-DFFF is left out: those codes are not characters on their own.
std::string identity_cmap() {
  std::string ranges;
  int count = 0;
  std::string cmap =
      "/CIDInit /ProcSet findresource begin\n12 dict begin\nbegincmap\n"
      "/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) /Supplement 0 >> def\n"
      "/CMapName /Adobe-Identity-UCS def\n/CMapType 2 def\n"
      "1 begincodespacerange\n<0000> <FFFF>\nendcodespacerange\n";
  auto flush = [&] {
    if (count == 0) return;
    cmap += std::to_string(count) + " beginbfrange\n" + ranges + "endbfrange\n";
    ranges.clear();
    count = 0;
  };
  for (int high = 0; high < 256; ++high) {
    if (high >= 0xD8 && high <= 0xDF) continue;
    char line[32];
    std::snprintf(line, sizeof line, "<%02X00> <%02XFF> <%02X00>\n", high, high, high);
    ranges += line;
    if (++count == 100) flush();
  }
  flush();
  return cmap + "endcmap\nCMapName currentdict /CMap defineresource pop\nend\nend\n";
}

}  // namespace

bool use_identity_to_unicode(HPDF_Doc pdf, HPDF_Font font) {
  if (font == nullptr || HPDF_Dict_GetItem(font, "ToUnicode", HPDF_OCLASS_DICT) == nullptr) return false;
  HPDF_Dict cmap = HPDF_DictStream_New(pdf->mmgr, pdf->xref);
  if (cmap == nullptr) return false;
  if (pdf->compression_mode & HPDF_COMP_TEXT) cmap->filter = HPDF_STREAM_FILTER_FLATE_DECODE;
  if (HPDF_Stream_WriteStr(cmap->stream, identity_cmap().c_str()) != HPDF_OK) return false;
  // Replaces libharu's entry; its own stream stays in the file, referenced by nothing.
  return HPDF_Dict_Add(font, "ToUnicode", cmap) == HPDF_OK;
}

}  // namespace maxillo::report
