#pragma once
// Where a test's archive lives. The archive suites run twice: on embedded archives (a folder),
// and against a real PostgreSQL server that a CTest fixture started (scripts/test-postgres),
// whose address file MAXILLO_TEST_POSTGRES names. On the server every archive_at() folder
// gets a database of its own, and the folder becomes the archive's shared object folder.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "archive/server_admin.h"

namespace maxillo::testing {

// The server's base address (postgresql://postgres@127.0.0.1:PORT/), or empty for embedded runs.
inline std::string test_postgres_server() {
  const char* file = std::getenv("MAXILLO_TEST_POSTGRES");
  if (!file || !*file) return {};
  std::ifstream in(file);
  std::string uri;
  if (!std::getline(in, uri) || uri.empty())
    throw std::runtime_error(std::string("MAXILLO_TEST_POSTGRES: no server address in ") + file);
  return uri;
}

inline bool on_server() { return !test_postgres_server().empty(); }

// A new, empty database on the test server; returns its address.
inline std::string new_test_database() {
  static std::mutex mutex;
  static int count = 0;
  std::lock_guard lock(mutex);
  const std::string server = test_postgres_server();
  const std::string name = "test_" + std::to_string(::getpid()) + "_" + std::to_string(++count);
  run_on_server(server, "CREATE DATABASE " + name);
  return server + name;
}

// What a test passes to Archive::open or --archive for the archive it keeps in `folder`: the
// folder itself, or (on the server) a database of its own with `folder` as its object folder.
// The same folder gives the same address for the whole test program.
inline std::filesystem::path archive_at(const std::filesystem::path& folder) {
  if (!on_server()) return folder;
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::string> addresses;
  const auto key = std::filesystem::absolute(folder);
  {
    std::lock_guard lock(mutex);
    if (auto found = addresses.find(key); found != addresses.end()) return found->second;
  }
  std::filesystem::create_directories(key);
  std::string address = new_test_database() + "?objects=" + key.string();
  std::lock_guard lock(mutex);
  return addresses.emplace(key, address).first->second;
}

// The object store of the archive kept in `folder` (see archive_at).
inline std::filesystem::path objects_of(const std::filesystem::path& folder) {
  return on_server() ? folder : folder / "objects";
}

}  // namespace maxillo::testing
