#include "ceph/landmark_io.h"

#include "ceph/landmark_format_support.h"
#include "core/atomic_file.h"

namespace maxillo {

using namespace landmark_format;

LandmarkFormat landmark_format_for(const std::filesystem::path& path) {
  std::string name = lower(path.filename().string());
  auto ends_with = [&](std::string_view suffix) {
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends_with(".json")) return LandmarkFormat::kSlicerMarkupsJson;
  if (ends_with(".fcsv")) return LandmarkFormat::kSlicerFcsv;
  if (ends_with(".csv")) return LandmarkFormat::kCsv;
  throw Error(ErrorCode::kBadValue, path.string(),
              "unknown landmark file extension (expected .mrk.json, .json, .fcsv or .csv)");
}

LandmarkSet parse_landmarks(std::string_view text, LandmarkFormat format, const std::string& source_name) {
  switch (format) {
    case LandmarkFormat::kSlicerMarkupsJson: return parse_markups_json(text, source_name);
    case LandmarkFormat::kSlicerFcsv: return parse_fcsv(text, source_name);
    case LandmarkFormat::kCsv: return parse_csv(text, source_name);
  }
  return {};
}

std::string format_landmarks(const LandmarkSet& landmarks, LandmarkFormat format) {
  switch (format) {
    case LandmarkFormat::kSlicerMarkupsJson: return format_markups_json(landmarks);
    case LandmarkFormat::kSlicerFcsv: return format_fcsv(landmarks);
    case LandmarkFormat::kCsv: return format_csv(landmarks);
  }
  return {};
}

LandmarkSet read_landmarks(const std::filesystem::path& path) {
  LandmarkFormat format = landmark_format_for(path);
  std::vector<std::byte> bytes = read_file(path);
  return parse_landmarks(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), format,
                         path.string());
}

void write_landmarks(const std::filesystem::path& path, const LandmarkSet& landmarks) {
  write_file_atomically(path, format_landmarks(landmarks, landmark_format_for(path)));
}

}  // namespace maxillo
