#pragma once
// A scratch archive for one run of an archive benchmark: a folder, or (with a PostgreSQL
// server) a new database on that server with a fresh object folder; both removed when the run
// ends, so that every run starts from nothing and leaves nothing behind.
#include <filesystem>
#include <string>

namespace maxillo::bench {

class ScratchArchive {
 public:
  // `server`: postgresql://USER@HOST:PORT/ or empty for an embedded archive in `folder`. `run`
  // numbers the database, so that the runs of one benchmark process never meet.
  ScratchArchive(const std::string& server, const std::filesystem::path& folder, int run);
  ~ScratchArchive();
  ScratchArchive(const ScratchArchive&) = delete;
  ScratchArchive& operator=(const ScratchArchive&) = delete;

  const std::filesystem::path& address() const { return address_; }
  const char* index_kind() const { return server_.empty() ? "SQLite" : "PostgreSQL"; }

 private:
  std::string server_;
  std::filesystem::path folder_;
  std::string database_;
  std::filesystem::path address_;
};

}  // namespace maxillo::bench
