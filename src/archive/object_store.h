#pragma once
// Content-addressed files: objects/<sha[0:2]>/<sha[2:64]>. A file appears under its final
// name only complete (temp file + rename). put() does not fsync each file: callers batch
// many puts and call make_durable() once (syncfs) before committing the rows naming them.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <set>
#include <span>
#include <string>
#include <string_view>

namespace maxillo {

class ObjectStore {
 public:
  explicit ObjectStore(std::filesystem::path folder);  // creates the folder if missing

  std::filesystem::path path_of(std::string_view sha256) const;
  // Writes bytes under their hash unless a file of that size is already there.
  // Throws Error(WriteFailed) naming the object path.
  void put(std::string_view sha256, std::span<const std::byte> bytes);
  // Flushes every object written so far (and their folder entries) to stable storage.
  void make_durable() const;

  enum class EntryKind { Object, Temporary };
  // Calls visit(kind, sha256 (empty for temporaries), path) for every file in the store.
  void for_each_file(const std::function<void(EntryKind, const std::string&, const std::filesystem::path&)>& visit) const;

  const std::filesystem::path& folder() const { return folder_; }

 private:
  void ensure_shard(std::string_view shard);

  std::filesystem::path folder_;
  std::set<std::string, std::less<>> shards_made_;
};

// True for 64 lower-case hex digits.
bool is_sha256_hex(std::string_view text);

}  // namespace maxillo
