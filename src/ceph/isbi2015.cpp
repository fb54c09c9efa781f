#include "ceph/isbi2015.h"

#include <charconv>
#include <map>

#include "ceph/cephalometric_analysis.h"
#include "ceph/landmark_format_support.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace maxillo::ceph {
namespace {

std::string our_label(const std::string& challenge_label) {
  static const std::map<std::string, std::string> renamed = {{"LIT", "L1"}, {"UIT", "U1"}, {"SoftPog", "PogS"}};
  auto it = renamed.find(challenge_label);
  return it == renamed.end() ? challenge_label : it->second;
}

int parse_int(std::string_view field, const std::filesystem::path& path, size_t line) {
  int value = 0;
  auto result = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size())
    throw Error(ErrorCode::kBadValue, path.string(),
                "line " + std::to_string(line) + ": not an integer: '" + std::string(field) + "'");
  return value;
}

}  // namespace

std::vector<IsbiImage> read_isbi_landmark_table(const std::filesystem::path& path) {
  auto bytes = read_file(path);
  std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::vector<std::string_view> lines;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(landmark_format::trim(std::string_view(text).substr(start, end - start)));
    start = end + 1;
  }
  if (lines.empty()) throw Error(ErrorCode::kBadValue, path.string(), "empty file");
  auto header = landmark_format::split(lines[0], ',');
  std::map<std::string, size_t> column;
  for (size_t i = 0; i < header.size(); ++i) column[std::string(header[i])] = i;
  for (const char* required : {"image_id", "ANB_cls", "SNB_cls", "SNA_cls", "S_x", "N_x", "A_x", "B_x"})
    if (!column.count(required))
      throw Error(ErrorCode::kBadValue, path.string(), std::string("line 1: header lacks column '") + required + "'");
  std::vector<IsbiImage> images;
  for (size_t n = 1; n < lines.size(); ++n) {
    if (lines[n].empty()) continue;
    auto fields = landmark_format::split(lines[n], ',');
    if (fields.size() != header.size())
      throw Error(ErrorCode::kBadValue, path.string(),
                  "line " + std::to_string(n + 1) + ": " + std::to_string(fields.size()) + " fields, header has " +
                      std::to_string(header.size()));
    IsbiImage image;
    image.image_id = std::string(fields[column["image_id"]]);
    for (size_t i = 0; i < header.size(); ++i) {
      std::string_view name = header[i];
      if (name.size() < 3 || !name.ends_with("_x")) continue;
      std::string base(name.substr(0, name.size() - 2));
      auto y = column.find(base + "_y");
      if (y == column.end()) continue;
      double px = parse_int(fields[i], path, n + 1), py = parse_int(fields[y->second], path, n + 1);
      image.landmarks.push_back({our_label(base), Eigen::Vector3d(px, py, 0)});
    }
    image.anb_class = parse_int(fields[column["ANB_cls"]], path, n + 1);
    image.snb_class = parse_int(fields[column["SNB_cls"]], path, n + 1);
    image.sna_class = parse_int(fields[column["SNA_cls"]], path, n + 1);
    images.push_back(std::move(image));
  }
  return images;
}

int isbi_anb_class(double anb) { return anb > 5.7 ? 2 : anb < 3.2 ? 3 : 1; }
int isbi_snb_class(double snb) { return snb < 74.6 ? 2 : snb > 78.7 ? 3 : 1; }
int isbi_sna_class(double sna) { return sna > 83.2 ? 2 : sna < 79.4 ? 3 : 1; }

IsbiAgreement isbi_class_agreement(const std::vector<IsbiImage>& images) {
  IsbiAgreement agreement;
  auto compare = [&agreement](const IsbiImage& image, const char* id, std::optional<double> value,
                              int (*classify)(double), int expected, int& equal) {
    int ours = value ? classify(*value) : 0;
    if (ours == expected) {
      ++equal;
      return;
    }
    agreement.disagreements.push_back(image.image_id + " " + id + ": ours " + std::to_string(ours) + " (" +
                                      (value ? landmark_format::number(*value) : std::string("n/a")) +
                                      " deg), organisers " + std::to_string(expected));
  };
  for (const auto& image : images) {
    auto analysis = analyse(cephalogram_to_sagittal(image.landmarks, isbi_axes()));
    ++agreement.images;
    compare(image, "ANB", analysis.value("ANB"), isbi_anb_class, image.anb_class, agreement.anb_equal);
    compare(image, "SNB", analysis.value("SNB"), isbi_snb_class, image.snb_class, agreement.snb_equal);
    compare(image, "SNA", analysis.value("SNA"), isbi_sna_class, image.sna_class, agreement.sna_equal);
  }
  return agreement;
}

}  // namespace maxillo::ceph
