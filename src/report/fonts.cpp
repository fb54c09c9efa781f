#include "report/fonts.h"

#include <cstdlib>
#include <string>

#include "core/error.h"

namespace maxillo::report {
namespace fs = std::filesystem;

std::vector<fs::path> font_search_path() {
  std::vector<fs::path> folders;
  if (const char* custom = std::getenv("MAXILLO_FONT_DIR"); custom && *custom) folders.emplace_back(custom);
  for (const char* folder : {"/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/truetype", "/usr/share/fonts"})
    folders.emplace_back(folder);
  return folders;
}

fs::path resolve_font(std::string_view name_or_path) {
  const fs::path requested(name_or_path);
  if (requested.is_absolute()) {
    if (!fs::is_regular_file(requested))
      throw Error(ErrorCode::kFileNotFound, requested.string(), "font file not found");
    return requested;
  }
  std::string searched;
  for (const auto& folder : font_search_path()) {
    if (fs::is_regular_file(folder / requested)) return folder / requested;
    searched += (searched.empty() ? "" : ", ") + folder.string();
  }
  throw Error(ErrorCode::kFileNotFound, requested.string(),
              "font not found in " + searched + " (install fonts-dejavu-core or set MAXILLO_FONT_DIR)");
}

}  // namespace maxillo::report
