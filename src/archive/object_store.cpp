#include "archive/object_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/sha256.h"
#include "core/utc_time.h"

namespace maxillo {
namespace {

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail(const std::filesystem::path& path, int error_number) {
  throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(error_number));
}

void write_all(int fd, std::span<const std::byte> bytes, const std::filesystem::path& path) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, errno);
    done += size_t(n);
  }
}

// Folders of the store that hold no objects (see object_store.h).
bool is_reserved_folder(const std::string& name) {
  return name == "journal" || name == "quarantine" || name == "settings";
}

bool file_hashes_to(const std::filesystem::path& path, std::string_view sha256) {
  try {
    return sha256_hex(read_file(path)) == sha256;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

std::optional<std::string> sha256_named_by(const std::filesystem::path& object_file) {
  std::string sha = object_file.parent_path().filename().string() + object_file.filename().string();
  if (!is_sha256_hex(sha)) return std::nullopt;
  return sha;
}

bool is_sha256_hex(std::string_view text) {
  if (text.size() != 64) return false;
  for (char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

ObjectStore::ObjectStore(std::filesystem::path folder) : folder_(std::move(folder)) {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) throw Error(ErrorCode::kWriteFailed, folder_.string(), error.message());
}

std::filesystem::path ObjectStore::path_of(std::string_view sha256) const {
  assert(is_sha256_hex(sha256) && "object names are lower-case sha256 hex digests");
  return folder_ / std::string(sha256.substr(0, 2)) / std::string(sha256.substr(2));
}

void ObjectStore::ensure_shard(std::string_view shard) {
  if (shards_made_.contains(shard)) return;
  auto path = folder_ / std::string(shard);
  if (::mkdir(path.c_str(), 0755) != 0 && errno != EEXIST) fail(path, errno);
  shards_made_.emplace(shard);
}

ObjectStore::ObjectState ObjectStore::state_of(std::string_view sha256) const {
  auto path = path_of(sha256);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return ObjectState::Absent;
  return file_hashes_to(path, sha256) ? ObjectState::Intact : ObjectState::Damaged;
}

ObjectStore::PutOutcome ObjectStore::put(std::string_view sha256, std::span<const std::byte> bytes) {
  auto path = path_of(sha256);
  PutOutcome outcome = PutOutcome::Written;
  // Also an intact file: another writer may have put it and not yet synced it.
  unsynced_.push_back(path);
  switch (state_of(sha256)) {
    case ObjectState::Intact: return PutOutcome::AlreadyIntact;
    case ObjectState::Damaged:
      set_aside(path, "damaged-");  // kept for inspection, replaced by the good bytes
      outcome = PutOutcome::Replaced;
      break;
    case ObjectState::Absent: break;
  }
  ensure_shard(sha256.substr(0, 2));
  write_new(path, bytes);
  return outcome;
}

void ObjectStore::write_new(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  auto temporary = temporary_sibling(path);
  {
    Descriptor file{::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0444)};
    if (file.fd < 0) fail(temporary, errno);
    try {
      write_all(file.fd, bytes, path);  // the error names the object, not its temporary name
    } catch (const Error&) {
      ::unlink(temporary.c_str());  // a disk that filled up leaves no partial file behind (issue 29)
      throw;
    }
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    int error_number = errno;
    ::unlink(temporary.c_str());
    fail(path, error_number);
  }
}

void ObjectStore::make_durable() {
  const bool few = !moved_files_ && unsynced_.size() <= kSyncedOneByOne;
  few ? sync_each_unsynced() : sync_file_system();
  unsynced_.clear();
  moved_files_ = false;
}

void ObjectStore::sync_file_system() const {
  // One syncfs covers every file and folder entry written since the last one: much cheaper
  // than an fsync per object when a batch holds hundreds of files.
  Descriptor folder{::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (folder.fd < 0 || ::syncfs(folder.fd) != 0) fail(folder_, errno);
}

void ObjectStore::sync_each_unsynced() const {
  // A received instance is one file: its data, its shard's entry and the shard's own entry in
  // the store are all it needs, and syncfs would also wait for every other writer's dirty
  // files on the file system (a concurrent import's, anyone's).
  std::set<std::filesystem::path> folders;
  for (const auto& path : unsynced_) {
    sync_path(path, false);
    folders.insert(path.parent_path());
  }
  for (const auto& folder : folders) sync_path(folder, true);
  if (!unsynced_.empty()) sync_path(folder_, true);  // a shard made by us or another writer
}

void ObjectStore::sync_path(const std::filesystem::path& path, bool folder) {
  Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0))};
  if (file.fd < 0) fail(path, errno);
  if ((folder ? ::fsync(file.fd) : ::fdatasync(file.fd)) != 0) fail(path, errno);
}

void ObjectStore::for_each_file(
    const std::function<void(EntryKind, const std::string&, const std::filesystem::path&)>& visit) const {
  std::error_code error;
  for (const auto& shard : std::filesystem::directory_iterator(folder_, error)) {
    std::string shard_name = shard.path().filename().string();
    if (shard.is_directory() && is_reserved_folder(shard_name)) continue;
    if (!shard.is_directory()) {
      visit(EntryKind::Temporary, {}, shard.path());
      continue;
    }
    for (const auto& entry : std::filesystem::directory_iterator(shard.path(), error)) {
      std::string sha = shard_name + entry.path().filename().string();
      visit(is_sha256_hex(sha) ? EntryKind::Object : EntryKind::Temporary, is_sha256_hex(sha) ? sha : std::string(),
            entry.path());
    }
  }
  if (error) throw Error(ErrorCode::kArchiveCorrupt, folder_.string(), "cannot list objects: " + error.message());
}

std::filesystem::path ObjectStore::set_aside(const std::filesystem::path& file, std::string_view label) {
  if (!quarantine_now_) quarantine_now_ = quarantine_folder() / utc_stamp();
  create_folders_durably(*quarantine_now_);
  auto name = std::string(label) + sha256_named_by(file).value_or(file.filename().string());
  auto target = *quarantine_now_ / name;
  for (int n = 1; std::filesystem::exists(target); ++n) target = *quarantine_now_ / (name + "." + std::to_string(n));
  if (::rename(file.c_str(), target.c_str()) != 0) fail(file, errno);
  moved_files_ = true;
  return target;
}

std::vector<std::filesystem::path> ObjectStore::quarantined_files() const {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(quarantine_folder(), error), end; !error && it != end;
       it.increment(error))
    if (it->is_regular_file()) files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

bool ObjectStore::restore_from_quarantine(std::string_view sha256) {
  for (const auto& file : quarantined_files()) {
    if (file.filename() != sha256 || !file_hashes_to(file, sha256)) continue;
    auto path = path_of(sha256);
    ensure_shard(sha256.substr(0, 2));
    if (::rename(file.c_str(), path.c_str()) != 0) fail(path, errno);
    moved_files_ = true;
    return true;
  }
  return false;
}

size_t ObjectStore::purge_quarantine() {
  size_t files = quarantined_files().size();
  std::error_code error;
  std::filesystem::remove_all(quarantine_folder(), error);
  if (error) throw Error(ErrorCode::kWriteFailed, quarantine_folder().string(), error.message());
  quarantine_now_.reset();
  return files;
}

}  // namespace maxillo
