#include "bench/shared_data.h"

#include <cstdlib>

namespace maxillo::bench {

std::filesystem::path shared_data_folder() {
  const char* shared = std::getenv("MAXILLO_SHARED_DATA");
  return std::filesystem::path(shared ? shared : "../shared/data");
}

RealTeeth real_teeth(const std::filesystem::path& data) {
  RealTeeth teeth;
  teeth.folder = data.empty() ? shared_data_folder() / "openfulljaw-p26-teeth" : data;
  teeth.upper = teeth.folder / "upper_teeth_merged.stl";
  teeth.lower = teeth.folder / "lower_teeth_merged.stl";
  if (!std::filesystem::exists(teeth.upper) || !std::filesystem::exists(teeth.lower))
    teeth.absent = "the real teeth are not at " + teeth.folder.string() +
                   " (set MAXILLO_SHARED_DATA or --data to the folder holding openfulljaw-p26-teeth)";
  return teeth;
}

}  // namespace maxillo::bench
