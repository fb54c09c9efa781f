#include "records/archived_series.h"

#include <map>

#include "archive/instance_source.h"
#include "imaging/volume_assembly.h"

namespace maxillo::records {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

}  // namespace

Volume load_archived_series(const Archive& archive, int64_t series) {
  std::vector<std::filesystem::path> files;
  std::map<std::string, std::string> source_of;  // object path -> the path it was imported from
  for (const auto& instance : archive.instances(series)) {
    files.push_back(archive.object_path(instance.object_sha256));
    // What arrived over the network has no file of its own to name (ImportOptions::source_label).
    if (!network_sender(instance.source_path)) source_of[files.back().string()] = instance.source_path;
  }
  try {
    return load_series_volume(files);
  } catch (const Error& e) {
    auto source = source_of.find(e.subject());
    if (source == source_of.end()) throw;
    // "a gap between A and B" names other slices too, by path or by file name.
    std::string reason = e.reason();
    for (const auto& [object, original] : source_of) {
      replace_all(reason, object, original);
      replace_all(reason, std::filesystem::path(object).filename().string(),
                  std::filesystem::path(original).filename().string());
    }
    throw Error(e.code(), source->second + " (archived as " + source->first + ")", reason);
  }
}

}  // namespace maxillo::records
