#include "bench/shared_data.h"

#include <cstdlib>

namespace maxillo::bench {

std::filesystem::path shared_data_folder() {
  const char* shared = std::getenv("MAXILLO_SHARED_DATA");
  return std::filesystem::path(shared ? shared : "../shared/data");
}

}  // namespace maxillo::bench
