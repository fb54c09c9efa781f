#pragma once
// The files of a DICOM folder as the commands that take one read it: every regular file below
// it, sorted, DICOMDIR and hidden files skipped.
#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/error.h"

namespace maxillo::cli {

// Error(kFileNotFound, folder) when there are none.
inline std::vector<std::filesystem::path> files_below(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name != "DICOMDIR" && !name.starts_with(".")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw Error(ErrorCode::kFileNotFound, folder.string(), "no files in the folder");
  return files;
}

}  // namespace maxillo::cli
