#include "archive/object_adoption.h"

#include <algorithm>
#include <optional>

#include "archive/import_batch.h"
#include "core/atomic_file.h"
#include "core/sha256.h"
#include "dicom/dicom_header.h"

namespace maxillo {
namespace {

constexpr size_t kAdoptionBatch = 500;

// The object read, checked against its name and parsed as an import would; nothing when it is
// not an intact DICOM instance.
std::optional<ScannedFile> scanned_object(const std::filesystem::path& path) {
  ScannedFile file;
  file.path = path;
  try {
    file.bytes = read_file(path);
    file.sha256 = sha256_hex(file.bytes);
    if (file.sha256 != sha256_named_by(path)) return std::nullopt;
    file.size = file.bytes.size();
    file.header = parse_instance_header(file.bytes, path);
  } catch (const Error&) {
    return std::nullopt;
  }
  return file;
}

}  // namespace

AdoptionResult adopt_objects(db::Connection& db, ObjectStore& store, const IndexJournal& journal,
                             std::vector<std::filesystem::path> objects, const std::string& source_label) {
  std::sort(objects.begin(), objects.end());  // the same store gives the same ids
  AdoptionResult result;
  BatchWriter writer(db, store, journal, source_label);
  ImportReport imported;
  for (const auto& path : objects) {
    auto file = scanned_object(path);
    std::string reason;
    if (file && writer.add(std::move(*file), reason) == ImportOutcome::Imported)
      result.adopted.push_back(path);
    else
      result.not_adopted.push_back(path);
    if (writer.pending() >= kAdoptionBatch) writer.commit(imported, {});
  }
  writer.commit(imported, {});
  for (const auto& problem : imported.problems) {  // refused at commit: not adopted after all
    std::erase(result.adopted, problem.path);
    result.not_adopted.push_back(problem.path);
  }
  return result;
}

}  // namespace maxillo
