#pragma once
// Where the benchmarks on real data find it: the shared data folder (its README lists the data
// sets), which the benchmarks skip cleanly without.
#include <filesystem>
#include <string>

namespace maxillo::bench {

// $MAXILLO_SHARED_DATA, else ../shared/data (relative to the working folder).
std::filesystem::path shared_data_folder();

// The real teeth in occlusion (openfulljaw-p26-teeth: upper_teeth_merged.stl,
// lower_teeth_merged.stl, one STL per tooth in maxilla/ and mandible/), in `data` or else the
// shared data folder; `absent` says why a benchmark skips when the merged arches are not there.
struct RealTeeth {
  std::filesystem::path folder, upper, lower;  // the folder and its two merged arches
  std::string absent;                          // empty when both arches are there
};
RealTeeth real_teeth(const std::filesystem::path& data);

}  // namespace maxillo::bench
