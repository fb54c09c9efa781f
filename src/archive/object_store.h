#pragma once
// Content-addressed files: objects/<sha[0:2]>/<sha[2:64]>. A file appears under its final
// name only complete (temp file + rename). put() does not fsync each file: callers batch
// many puts and call make_durable() once before committing the rows naming them.
//
// Two folders of the store are not objects:
//   objects/journal/      the index journal (index_journal.h)
//   objects/quarantine/   files set aside instead of deleted: orphans and temporaries moved
//                         by `verify --repair`, damaged objects replaced by good bytes; kept
//                         until `verify --purge`, restored when an index row names them again.
//   objects/settings/     a server archive's shared settings (its de-identification secret).
// Both sit inside the store so that they live on the same file system (rename, never copy) and
// travel with the objects to shared storage.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace maxillo {

class ObjectStore {
 public:
  explicit ObjectStore(std::filesystem::path folder);  // creates the folder if missing

  std::filesystem::path path_of(std::string_view sha256) const;

  enum class PutOutcome { Written, AlreadyIntact, Replaced };
  // Writes bytes under their hash. A file already there is trusted only if it hashes to its
  // name: a damaged one is set aside in quarantine and replaced (Replaced).
  // Throws Error(WriteFailed) naming the object path.
  PutOutcome put(std::string_view sha256, std::span<const std::byte> bytes);
  // Flushes every object put since the last call (and their folder entries) to stable
  // storage: a few (a received instance) with fdatasync of each file and fsync of its folders,
  // many (an import batch) or files moved in or out of quarantine with one syncfs.
  void make_durable();

  enum class ObjectState { Absent, Intact, Damaged };
  // Hashes the file (Intact only when its bytes hash to its name).
  ObjectState state_of(std::string_view sha256) const;

  enum class EntryKind { Object, Temporary };
  // Calls visit(kind, sha256 (empty for temporaries), path) for every file in the store
  // except the journal and the quarantine.
  void for_each_file(
      const std::function<void(EntryKind, const std::string&, const std::filesystem::path&)>& visit) const;

  // --- quarantine ---
  std::filesystem::path quarantine_folder() const { return folder_ / "quarantine"; }
  // Moves a file of the store into quarantine/<UTC time>/, under a name that keeps its object
  // name (or its own name for a temporary), prefixed by `label` when given. Returns the new path.
  std::filesystem::path set_aside(const std::filesystem::path& file, std::string_view label = {});
  // Every quarantined file.
  std::vector<std::filesystem::path> quarantined_files() const;
  // A quarantined copy of this object whose bytes hash to it, moved back into place.
  bool restore_from_quarantine(std::string_view sha256);
  // Deletes the quarantine; returns the number of files deleted.
  size_t purge_quarantine();

  const std::filesystem::path& folder() const { return folder_; }

 private:
  void ensure_shard(std::string_view shard);
  void write_new(const std::filesystem::path& path, std::span<const std::byte> bytes);
  void sync_file_system() const;
  void sync_each_unsynced() const;
  static void sync_path(const std::filesystem::path& path, bool folder);

  // Up to this many files are synced one by one; beyond, one syncfs is cheaper than a journal
  // commit of the file system per file.
  static constexpr size_t kSyncedOneByOne = 32;

  std::filesystem::path folder_;
  std::set<std::string, std::less<>> shards_made_;
  std::optional<std::filesystem::path> quarantine_now_;  // this process's quarantine subfolder
  std::vector<std::filesystem::path> unsynced_;          // put since the last make_durable()
  bool moved_files_ = false;                             // to or from quarantine since then
};

// True for 64 lower-case hex digits.
bool is_sha256_hex(std::string_view text);

// The sha256 an object file's path names (shard + file name), if it is one.
std::optional<std::string> sha256_named_by(const std::filesystem::path& object_file);

}  // namespace maxillo
