// Archive::export_series: a series' files out of the archive, as archived (byte-identical) or
// de-identified (dicom_deidentify.h) with the archive's own secret.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <random>

#include "archive/archive_state.h"
#include "archive/dicom_deidentify.h"
#include "core/atomic_file.h"
#include "core/sha256.h"

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
  auto path = state_->folder / kSecretFile;
  if (!std::filesystem::exists(path)) {
    // O_EXCL: two processes creating it at once agree on the first one written.
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
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

std::vector<std::filesystem::path> Archive::export_series(int64_t series, const std::filesystem::path& out_dir,
                                                          ExportProfile profile) const {
  auto members = instances(series);
  if (members.empty()) throw Error(ErrorCode::kNotFound, std::to_string(series), "no such series or no instances");
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw Error(ErrorCode::kWriteFailed, out_dir.string(), error.message());
  std::string secret = profile == ExportProfile::Deidentified ? deidentification_secret() : "";

  std::vector<std::filesystem::path> written;
  for (const auto& instance : members) {
    auto source = state_->objects.path_of(instance.object_sha256);
    auto bytes = checked_object(source, instance.object_sha256);
    if (profile == ExportProfile::Original) {
      auto target = out_dir / file_name(instance, instance.sop_instance_uid);
      write_file_atomically(target, bytes, Durability::Unflushed);
      written.push_back(target);
    } else {
      auto target = out_dir / file_name(instance, pseudonymous_uid(secret, instance.sop_instance_uid));
      write_deidentified_copy(source, target, secret);
      written.push_back(target);
    }
  }
  return written;
}

}  // namespace maxillo
