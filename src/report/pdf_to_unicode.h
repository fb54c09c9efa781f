#pragma once
// libharu 2.3 gives a TrueType font used with its UTF-8 encoder a ToUnicode entry that is its
// encoding CMap (a "cidrange" CMap) instead of a ToUnicode CMap ("bfrange"): text extraction
// works only because readers fall back on the font's own tables; poppler warns "Invalid
// 'begincidrange' operator in ToUnicode CMap" on every page, and a PDF/A validator would reject
// the file. The encoder's character codes are the characters' UTF-16 code units (the content
// streams show "<0043>" for "C"), so the right ToUnicode is the identity on the Basic
// Multilingual Plane; this replaces libharu's with it.
#include <hpdf.h>

namespace maxillo::report {

// Call right after HPDF_GetFont(pdf, name, "UTF-8"). Returns false when the font has no
// ToUnicode entry to replace or libharu failed (then the document's error is set).
bool use_identity_to_unicode(HPDF_Doc pdf, HPDF_Font font);

}  // namespace maxillo::report
