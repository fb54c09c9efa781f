#include "archive/import_scan.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <set>
#include <utility>

#include "archive/archive_sql.h"
#include "archive/archive_state.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/sha256.h"

namespace maxillo {
namespace {

ScannedFile failure(const std::filesystem::path& path, ErrorCode code, std::string reason) {
  ScannedFile item;
  item.path = path;
  item.stage = ScannedFile::Stage::Failed;
  item.code = code;
  item.reason = std::move(reason);
  return item;
}

// The folders already listed, by device and inode, so that a symbolic link back up the tree (or
// two links to one folder) is listed once and never loops.
using ListedFolders = std::set<std::pair<dev_t, ino_t>>;

bool first_visit(const std::filesystem::path& folder, ListedFolders& listed) {
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0) return true;  // the listing will say why it cannot be read
  return listed.emplace(info.st_dev, info.st_ino).second;
}

// Symbolic links to folders are followed (a series linked into an import folder is imported).
void list_folder(const std::filesystem::path& folder, FileList& list, ListedFolders& listed) {
  if (!first_visit(folder, listed)) {
    log::debug("import: ", folder.string(), " is a folder already listed (a symbolic link): skipped");
    return;
  }
  std::error_code error;
  std::filesystem::directory_iterator entries(folder, error);
  if (error) {
    list.unreachable.push_back(failure(folder, ErrorCode::kPermissionDenied, "cannot list folder: " + error.message()));
    return;
  }
  std::vector<std::filesystem::directory_entry> sorted;
  for (; entries != std::filesystem::directory_iterator(); entries.increment(error)) {
    if (error) break;
    sorted.push_back(*entries);
  }
  std::sort(sorted.begin(), sorted.end());
  for (const auto& entry : sorted) {
    std::error_code ignored;
    if (entry.is_directory(ignored))
      list_folder(entry.path(), list, listed);
    else
      list.files.push_back(entry.path());
  }
}

std::string gibibytes(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
  return text;
}

// A file is read whole to be hashed and parsed: refuse what no CT file can be before reading.
std::optional<ScannedFile> refuse_oversized(const std::filesystem::path& path, const struct stat& info) {
  const auto size = uint64_t(info.st_size);
  if (size <= kMaxImportFileBytes) return std::nullopt;
  std::string reason = "file is " + gibibytes(size) + ", more than the " + gibibytes(kMaxImportFileBytes) +
                       " a DICOM file may hold here";
  if (uint64_t(info.st_blocks) * 512 < size / 2) reason += " (a sparse file: most of it is not even on disk)";
  return failure(path, ErrorCode::kBadValue, reason);
}

}  // namespace

FileList list_input_files(const std::vector<std::filesystem::path>& paths) {
  FileList list;
  for (const auto& path : paths) {
    // Per path named: a folder named twice is listed twice, as asked (its files are then
    // already archived the second time); below each, every folder once.
    ListedFolders listed;
    std::error_code error;
    auto status = std::filesystem::status(path, error);
    if (std::filesystem::is_directory(status))
      list_folder(path, list, listed);
    else if (std::filesystem::exists(status) ||
             std::filesystem::is_symlink(std::filesystem::symlink_status(path, error)))
      list.files.push_back(path);
    else
      list.unreachable.push_back(failure(path, ErrorCode::kFileNotFound, "no such file or folder"));
  }
  return list;
}

struct FileScanner::Queries {
  explicit Queries(const ArchiveLocation& archive)
      : connection(connect_index(archive, sqlite::OpenKind::Existing)),
        db(*connection),
        known_object(db, sql::kInstanceWithObject),
        object_of_sop(db, sql::kObjectOfSopInstance) {
    db.make_read_only();
  }
  std::unique_ptr<db::Connection> connection;
  db::Connection& db;
  db::Statement known_object;
  db::Statement object_of_sop;
};

FileScanner::FileScanner(const ArchiveLocation& archive) : queries_(new Queries(archive)) {}
FileScanner::~FileScanner() { delete queries_; }

ScannedFile FileScanner::scan(const std::filesystem::path& path) {
  // stat first: a FIFO or device would block or never end if read.
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    int e = errno;
    return failure(path, e == EACCES ? ErrorCode::kPermissionDenied : ErrorCode::kFileNotFound,
                   std::string("unreadable: ") + std::strerror(e));
  }
  if (S_ISDIR(info.st_mode)) return failure(path, ErrorCode::kBadValue, "unreadable: is a folder");
  if (!S_ISREG(info.st_mode)) return failure(path, ErrorCode::kBadValue, "unreadable: not a regular file");
  if (auto refused = refuse_oversized(path, info)) return std::move(*refused);

  ScannedFile item;
  item.path = path;
  try {
    item.bytes = read_file(path);
  } catch (const Error& e) {
    return failure(path, e.code(), "unreadable: " + e.reason());
  }
  item.size = item.bytes.size();
  item.sha256 = sha256_hex(item.bytes);
  bool known = queries_->known_object.reset().bind(1, item.sha256).step();
  queries_->known_object.reset();  // ends the read snapshot
  if (known) {
    item.stage = ScannedFile::Stage::Known;
    return item;
  }
  try {
    item.header = parse_instance_header(item.bytes, path);
  } catch (const Error& e) {
    return failure(path, e.code(), e.reason());
  }
  std::string archived_object;
  if (queries_->object_of_sop.reset().bind(1, item.header.sop_instance_uid).step())
    archived_object = queries_->object_of_sop.text(0);
  queries_->object_of_sop.reset();
  if (archived_object == item.sha256) {  // archived by another process since the first lookup
    item.stage = ScannedFile::Stage::Known;
    return item;
  }
  if (!archived_object.empty()) {
    item.stage = ScannedFile::Stage::Conflict;
    item.code = ErrorCode::kConflict;
    item.reason = "SOP Instance UID " + item.header.sop_instance_uid + " is archived with other content (object " +
                  archived_object.substr(0, 12) + "...); the archived file is kept";
    item.bytes = {};
    return item;
  }
  item.stage = ScannedFile::Stage::Parsed;
  return item;
}

}  // namespace maxillo
