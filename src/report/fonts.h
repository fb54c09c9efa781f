#pragma once
// Where report fonts come from. Reports use DejaVu Sans (Debian: fonts-dejavu-core), which
// covers Latin, Greek and Cyrillic, so names like "Müller-Łukasz" print as written.
#include <filesystem>
#include <string_view>
#include <vector>

namespace maxillo::report {

// Folders searched for a font given by file name, in order: $MAXILLO_FONT_DIR (if set),
// /usr/share/fonts/truetype/dejavu, /usr/share/fonts/truetype, /usr/share/fonts.
std::vector<std::filesystem::path> font_search_path();

// An absolute path is used as is; a bare file name ("DejaVuSans.ttf") is looked up in
// font_search_path(). Throws Error(FileNotFound) naming the font and the folders searched.
std::filesystem::path resolve_font(std::string_view name_or_path);

}  // namespace maxillo::report
