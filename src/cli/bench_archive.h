#pragma once
// A scratch archive for one benchmark run: a folder, or (with --postgres) a new database on
// that server with a fresh object folder; both removed when the run ends. And the median that
// every benchmark reports.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/server_admin.h"

namespace maxillo::cli {

class BenchArchive {
 public:
  // `server`: postgresql://USER@HOST:PORT/ or empty for an embedded archive in `folder`.
  BenchArchive(const std::string& server, const std::filesystem::path& folder, int run)
      : server_(server), folder_(folder) {
    if (server_.empty()) {
      address_ = folder_;
      return;
    }
    std::filesystem::create_directories(folder_);
    database_ = "maxillo_bench_" + std::to_string(::getpid()) + "_" + std::to_string(run);
    run_on_server(server_, "CREATE DATABASE " + database_);
    address_ = server_ + database_ + "?objects=" + folder_.string();
  }
  ~BenchArchive() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
    if (database_.empty()) return;
    try {
      run_on_server(server_, "DROP DATABASE " + database_ + " WITH (FORCE)");
    } catch (...) {  // a benchmark's leftover database is not worth failing its report for
    }
  }
  BenchArchive(const BenchArchive&) = delete;
  BenchArchive& operator=(const BenchArchive&) = delete;
  const std::filesystem::path& address() const { return address_; }
  const char* engine() const { return server_.empty() ? "SQLite" : "PostgreSQL"; }

 private:
  std::string server_;
  std::filesystem::path folder_;
  std::string database_;
  std::filesystem::path address_;
};

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace maxillo::cli
