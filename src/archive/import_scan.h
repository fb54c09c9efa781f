#pragma once
// The first stage of an import: find the files, read each once, hash it, and parse its header
// unless the archive already holds those exact bytes. Runs on its own thread with its own
// read-only view of the index, so the main thread only writes objects and commits rows.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "archive/archive_location.h"
#include "core/error.h"
#include "dicom/dicom_header.h"

namespace maxillo {

struct ScannedFile {
  enum class Stage {
    Known,     // these bytes are archived already: nothing to do unless the object file was lost
    Conflict,  // its SOP Instance UID is archived with other bytes
    Parsed,    // new: header parsed, bytes to store
    Failed,    // bad input: code and reason say why
  };
  std::filesystem::path path;
  Stage stage = Stage::Failed;
  std::vector<std::byte> bytes;  // kept for Parsed and Known files (a lost object is restored)
  std::string sha256;
  size_t size = 0;  // bytes in the file
  InstanceHeader header;
  ErrorCode code = ErrorCode::kProcessing;
  std::string reason;
};

// Files are read whole: larger ones are refused unread (a multi-frame cone-beam CT of 700^3
// 16-bit voxels is 0.7 GiB; DICOM lengths are 32-bit).
inline constexpr uint64_t kMaxImportFileBytes = uint64_t(4) << 30;

// Input paths expanded to files: folders recursively (symlinked folders are not followed),
// sorted within each folder. A path that does not exist or a folder that cannot be listed
// becomes a Failed entry, so it is reported like any bad file.
struct FileList {
  std::vector<std::filesystem::path> files;
  std::vector<ScannedFile> unreachable;
};
FileList list_input_files(const std::vector<std::filesystem::path>& paths);

// Reads, hashes and (for unknown content) parses one file. Never throws for bad input.
class FileScanner {
 public:
  // Opens its own connection to the archive's index, read-only.
  explicit FileScanner(const ArchiveLocation& archive);
  ~FileScanner();
  FileScanner(const FileScanner&) = delete;
  FileScanner& operator=(const FileScanner&) = delete;
  ScannedFile scan(const std::filesystem::path& path);

 private:
  struct Queries;
  Queries* queries_;
};

}  // namespace maxillo
