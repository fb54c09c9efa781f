#pragma once
// A fresh folder under the system temporary directory, removed with its contents when the
// object goes out of scope (RAII): scratch space for converters and for tests.
#include <filesystem>
#include <string>

namespace maxillo {

class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& tag = "maxillo");
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace maxillo
