// Archive::export_series: a series' files out of the archive, as archived (byte-identical) or
// de-identified (dicom_deidentify.h) with the archive's own secret.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cerrno>
#include <random>

#include "archive/archive_state.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/sha256.h"
#include "dicom/dicom_deidentify.h"

namespace maxillo {
namespace {

constexpr const char* kSecretFile = "deidentify.key";

// The archived bytes of an instance, checked against their name: an export never hands out a
// silently corrupted file.
std::vector<std::byte> checked_object(const std::filesystem::path& source, const std::string& sha256) {
  std::vector<std::byte> bytes;
  try {
    bytes = read_file(source);
  } catch (const Error& e) {
    throw Error(ErrorCode::kArchiveCorrupt, source.string(), "archived object unreadable: " + e.reason());
  }
  if (sha256_hex(bytes) != sha256)
    throw Error(ErrorCode::kArchiveCorrupt, source.string(), "archived object no longer matches its hash");
  return bytes;
}

std::string file_name(const InstanceRecord& instance, const std::string& sop_instance_uid) {
  char number[16];
  std::snprintf(number, sizeof number, "%05d", instance.instance_number.value_or(0));
  return std::string(number) + "_" + sop_instance_uid + ".dcm";
}

std::string random_secret() {
  std::random_device device;
  std::string bytes(32, '\0');
  for (auto& b : bytes) b = char(device() & 0xFF);
  return sha256_hex(bytes);  // 64 hex characters holding the 256 random bits
}

}  // namespace

std::string Archive::deidentification_secret() const {
  // Beside the index of an embedded archive; in the shared object folder of a server archive,
  // where every node finds it and where it outlives the index, like the objects it keys.
  auto path = state_->location.embedded() ? state_->location.folder / kSecretFile
                                          : state_->objects.folder() / "settings" / kSecretFile;
  std::error_code ignored;
  std::filesystem::create_directories(path.parent_path(), ignored);
  if (!std::filesystem::exists(path)) {
    // O_EXCL: two processes creating it at once agree on the first one written.
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0 && (errno == EROFS || errno == EACCES || errno == EPERM)) {
      // A read-only archive without a secret yet: exporting must work, with pseudonyms of
      // this run alone (said once; a later export from a writable archive keys another secret).
      if (state_->unsaved_secret.empty()) {
        state_->unsaved_secret = random_secret();
        log::warning(path.string(),
                     ": the archive is read-only and has no de-identification secret yet: the "
                     "pseudonyms of this export are its own, and will differ from later exports'");
      }
      return state_->unsaved_secret;
    }
    if (fd >= 0) {
      std::string secret = random_secret();
      bool written = ::write(fd, secret.data(), secret.size()) == ssize_t(secret.size()) && ::fsync(fd) == 0;
      ::close(fd);
      if (!written) throw Error(ErrorCode::kWriteFailed, path.string(), "cannot write the de-identification secret");
    }
  }
  auto bytes = read_file(path);
  if (bytes.size() != 64) throw Error(ErrorCode::kArchiveCorrupt, path.string(), "de-identification secret damaged");
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// The export is written into a hidden sibling folder and moved into place only when every file
// is there: a failed export (a corrupt object, a full disk) leaves nothing in `out_dir`.
class StagingFolder {
 public:
  explicit StagingFolder(const std::filesystem::path& out_dir)
      : path_(out_dir.parent_path() / ("." + out_dir.filename().string() + ".partial-" + std::to_string(::getpid()))) {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
    std::filesystem::create_directories(path_, error);
    if (error) throw Error(ErrorCode::kWriteFailed, path_.string(), error.message());
  }
  ~StagingFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

  // Moves the files into out_dir (renamed whole when it does not exist yet).
  std::vector<std::filesystem::path> publish(const std::vector<std::string>& names,
                                             const std::filesystem::path& out_dir) {
    std::error_code error;
    if (!std::filesystem::exists(out_dir, error)) {
      std::filesystem::rename(path_, out_dir, error);
    } else {
      for (const auto& name : names) {
        std::filesystem::rename(path_ / name, out_dir / name, error);
        if (error) break;
      }
    }
    if (error) throw Error(ErrorCode::kWriteFailed, out_dir.string(), error.message());
    std::vector<std::filesystem::path> published;
    for (const auto& name : names) published.push_back(out_dir / name);
    return published;
  }

 private:
  std::filesystem::path path_;
};

std::vector<std::filesystem::path> Archive::export_series(int64_t series, const std::filesystem::path& out_dir,
                                                          ExportProfile profile) const {
  auto members = instances(series);
  if (members.empty()) throw Error(ErrorCode::kNotFound, std::to_string(series), "no such series or no instances");
  const auto target_dir = std::filesystem::absolute(out_dir);
  std::error_code error;
  std::filesystem::create_directories(target_dir.parent_path(), error);
  if (error) throw Error(ErrorCode::kWriteFailed, target_dir.string(), error.message());
  if (std::filesystem::exists(target_dir, error) && !std::filesystem::is_directory(target_dir, error))
    throw Error(ErrorCode::kWriteFailed, target_dir.string(), "exists and is not a folder");
  std::string secret = profile == ExportProfile::Deidentified ? deidentification_secret() : "";

  StagingFolder staging(target_dir);
  std::vector<std::string> names;
  for (const auto& instance : members) {
    auto source = state_->objects.path_of(instance.object_sha256);
    auto bytes = checked_object(source, instance.object_sha256);
    if (profile == ExportProfile::Original) {
      names.push_back(file_name(instance, instance.sop_instance_uid));
      write_file_atomically(staging.path() / names.back(), bytes, Durability::Unflushed);
    } else {
      names.push_back(file_name(instance, pseudonymous_uid(secret, instance.sop_instance_uid)));
      try {
        write_deidentified_copy(source, staging.path() / names.back(), secret);
      } catch (const Error& e) {  // named as the user knows it, not by its object file
        if (e.code() != ErrorCode::kCannotDeidentify) throw;
        throw Error(e.code(), "series:" + std::to_string(series), e.reason());
      }
    }
  }
  return staging.publish(names, target_dir);
}

}  // namespace maxillo
