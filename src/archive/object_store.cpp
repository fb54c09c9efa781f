#include "archive/object_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cassert>
#include <cerrno>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"

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

}  // namespace

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

void ObjectStore::put(std::string_view sha256, std::span<const std::byte> bytes) {
  auto path = path_of(sha256);
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && size_t(existing.st_size) == bytes.size()) return;
  ensure_shard(sha256.substr(0, 2));
  auto temporary = temporary_sibling(path);
  {
    Descriptor file{::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0444)};
    if (file.fd < 0) fail(temporary, errno);
    write_all(file.fd, bytes, temporary);
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    int error_number = errno;
    ::unlink(temporary.c_str());
    fail(path, error_number);
  }
}

void ObjectStore::make_durable() const {
  // One syncfs covers every file and folder entry written since the last one: much cheaper
  // than an fsync per object when a batch holds hundreds of files.
  Descriptor folder{::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (folder.fd < 0 || ::syncfs(folder.fd) != 0) fail(folder_, errno);
}

void ObjectStore::for_each_file(
    const std::function<void(EntryKind, const std::string&, const std::filesystem::path&)>& visit) const {
  std::error_code error;
  for (const auto& shard : std::filesystem::directory_iterator(folder_, error)) {
    std::string shard_name = shard.path().filename().string();
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

}  // namespace maxillo
