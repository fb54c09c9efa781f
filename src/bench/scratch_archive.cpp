#include "bench/scratch_archive.h"

#include <unistd.h>

#include "archive/server_admin.h"

namespace maxillo::bench {

ScratchArchive::ScratchArchive(const std::string& server, const std::filesystem::path& folder, int run)
    : server_(server), folder_(folder) {
  if (server_.empty()) {
    address_ = folder_;
    return;
  }
  database_ = "maxillo_bench_" + std::to_string(::getpid()) + "_" + std::to_string(run);
  run_on_server(server_, "CREATE DATABASE " + database_);  // first: a refused login leaves no folder
  std::filesystem::create_directories(folder_);
  address_ = server_ + database_ + "?objects=" + folder_.string();
}

ScratchArchive::~ScratchArchive() {
  std::error_code ignored;
  std::filesystem::remove_all(folder_, ignored);
  if (database_.empty()) return;
  try {
    run_on_server(server_, "DROP DATABASE " + database_ + " WITH (FORCE)");
  } catch (...) {  // a benchmark's leftover database is not worth failing its report for
  }
}

}  // namespace maxillo::bench
