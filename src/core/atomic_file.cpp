#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>  // renameat2, RENAME_NOREPLACE
#include <cstring>
#include <random>

#include "core/error.h"

namespace maxillo {
namespace {

ErrorCode code_for_errno(int error_number) {
  switch (error_number) {
    case ENOENT: return ErrorCode::kFileNotFound;
    case EACCES:
    case EPERM: return ErrorCode::kPermissionDenied;
    default: return ErrorCode::kWriteFailed;
  }
}

// Closes a descriptor on every path out of a function.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

void fsync_folder(const std::filesystem::path& folder) {
  FileDescriptor dir{::open(folder.c_str(), O_RDONLY | O_DIRECTORY)};
  if (dir.fd >= 0) ::fsync(dir.fd);
}

}  // namespace

std::vector<std::byte> read_file(const std::filesystem::path& path) {
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) {
    int e = errno;
    throw Error(e == EACCES || e == EPERM ? ErrorCode::kPermissionDenied : ErrorCode::kFileNotFound, path.string(),
                std::strerror(e));
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0 || S_ISDIR(info.st_mode))
    throw Error(ErrorCode::kBadValue, path.string(), "is a folder, not a file");
  std::vector<std::byte> bytes(static_cast<size_t>(info.st_size));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(ErrorCode::kPermissionDenied, path.string(), std::strerror(errno));
    if (n == 0) break;  // the file shrank while we read it
    done += static_cast<size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  thread_local std::mt19937_64 random{std::random_device{}()};
  auto name = "." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
              "-" + std::to_string(random() % 1000000);
  return path.parent_path() / name;
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes, Durability durability) {
  auto temporary = temporary_sibling(path);
  {
    FileDescriptor file{::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644)};
    if (file.fd < 0) throw Error(code_for_errno(errno), path.string(), std::strerror(errno));
    size_t done = 0;
    while (done < bytes.size()) {
      ssize_t n = ::write(file.fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        int e = errno;
        ::unlink(temporary.c_str());
        throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(e));
      }
      done += static_cast<size_t>(n);
    }
    if (durability == Durability::Flushed && ::fsync(file.fd) != 0) {
      int e = errno;
      ::unlink(temporary.c_str());
      throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(e));
    }
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    int e = errno;
    ::unlink(temporary.c_str());
    throw Error(ErrorCode::kWriteFailed, path.string(), std::strerror(e));
  }
  if (durability == Durability::Flushed)
    fsync_folder(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
}

void sync_folder(const std::filesystem::path& folder) { fsync_folder(folder); }

bool rename_without_replacing(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno == EEXIST) return false;
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
    throw Error(ErrorCode::kWriteFailed, from.string(), std::string("cannot rename: ") + std::strerror(errno));
  // A file system without RENAME_NOREPLACE (some network file systems): a hard link is
  // refused for an existing name too, and the second name is then removed.
  if (::link(from.c_str(), to.c_str()) != 0) {
    if (errno == EEXIST) return false;
    throw Error(ErrorCode::kWriteFailed, from.string(), std::string("cannot rename: ") + std::strerror(errno));
  }
  ::unlink(from.c_str());
  return true;
}

void create_folders_durably(const std::filesystem::path& folder) {
  if (folder.empty() || std::filesystem::is_directory(folder)) return;
  create_folders_durably(folder.parent_path());
  if (::mkdir(folder.c_str(), 0755) != 0 && errno != EEXIST)
    throw Error(ErrorCode::kWriteFailed, folder.string(), std::strerror(errno));
  fsync_folder(folder.parent_path().empty() ? std::filesystem::path(".") : folder.parent_path());
}

void write_file_atomically(const std::filesystem::path& path, std::string_view text, Durability durability) {
  write_file_atomically(path, std::as_bytes(std::span(text.data(), text.size())), durability);
}

}  // namespace maxillo
