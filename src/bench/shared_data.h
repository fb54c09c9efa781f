#pragma once
// Where the benchmarks on real data find it: the shared data folder (its README lists the data
// sets), which the benchmarks skip cleanly without.
#include <filesystem>

namespace maxillo::bench {

// $MAXILLO_SHARED_DATA, else ../shared/data (relative to the working folder).
std::filesystem::path shared_data_folder();

}  // namespace maxillo::bench
