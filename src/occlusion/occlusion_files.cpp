#include "occlusion/occlusion_files.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_input.h"

namespace maxillo::occlusion {
namespace {

std::string file_text(const std::filesystem::path& path) {
  const std::vector<std::byte> bytes = read_file(path);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// Parses comma-separated numbers; false if any field is not a number. "nan" and "inf" parse
// as numbers but mean nothing here: they are refused by the caller (non_finite).
bool parse_numbers(const std::string& line, std::vector<double>& values) {
  values.clear();
  std::stringstream fields(line);
  std::string field;
  while (std::getline(fields, field, ',')) {
    const auto first = field.find_first_not_of(" \t\r"), last = field.find_last_not_of(" \t\r");
    if (first == std::string::npos) return false;
    double value = 0;
    const char* begin = field.data() + first;
    const char* end = field.data() + last + 1;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end) return false;
    values.push_back(value);
  }
  return true;
}

}  // namespace

std::vector<SpringPair> read_spring_pairs(const std::filesystem::path& path) {
  std::stringstream lines(file_text(path));
  std::vector<SpringPair> pairs;
  std::string line;
  std::vector<double> values;
  for (int row = 1; std::getline(lines, line); ++row) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!parse_numbers(line, values)) {
      if (row == 1) continue;  // header
      throw Error(ErrorCode::kBadValue, path.string(), "row " + std::to_string(row) + " is not six numbers");
    }
    if (values.size() != 6)
      throw Error(ErrorCode::kBadValue, path.string(),
                  "row " + std::to_string(row) + " has " + std::to_string(values.size()) +
                      " values, expected ux,uy,uz,lx,ly,lz");
    for (double value : values)
      if (!std::isfinite(value))
        throw Error(ErrorCode::kBadValue, path.string(),
                    "row " + std::to_string(row) + " holds a value that is not a finite number");
    pairs.push_back({{values[0], values[1], values[2]}, {values[3], values[4], values[5]}});
  }
  if (pairs.size() < 3)
    throw Error(ErrorCode::kBadValue, path.string(),
                "guided alignment needs at least 3 point pairs, found " + std::to_string(pairs.size()));
  return pairs;
}

Json transform_to_json(const Eigen::Isometry3d& transform) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 4; ++c) row.push_back(transform.matrix()(r, c));
    rows.push_back(row);
  }
  return rows;
}

Eigen::Isometry3d transform_from_json(const Json& value, const std::string& subject) {
  Eigen::Matrix4d m;
  if (!value.is_array() || value.size() != 4)
    throw Error(ErrorCode::kBadValue, subject, "upper_transform must be a 4x4 array of numbers");
  for (int r = 0; r < 4; ++r) {
    if (!value[size_t(r)].is_array() || value[size_t(r)].size() != 4)
      throw Error(ErrorCode::kBadValue, subject, "upper_transform must be a 4x4 array of numbers");
    for (int c = 0; c < 4; ++c) {
      if (!value[size_t(r)][size_t(c)].is_number())
        throw Error(ErrorCode::kBadValue, subject, "upper_transform must be a 4x4 array of numbers");
      m(r, c) = value[size_t(r)][size_t(c)].get<double>();
    }
  }
  const Eigen::Matrix3d rotation = m.topLeftCorner<3, 3>();
  const bool rigid = (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
                     std::abs(rotation.determinant() - 1) < 1e-6 &&
                     (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() < 1e-12;
  if (!rigid)
    throw Error(ErrorCode::kBadValue, subject, "upper_transform is not a rigid transform (rotation + translation)");
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotation;
  transform.translation() = m.topRightCorner<3, 1>();
  return transform;
}

Eigen::Isometry3d read_upper_transform(const std::filesystem::path& path) {
  const Json document = parse_json_input(file_text(path), path.string());
  if (!document.is_object() || !document.contains("upper_transform"))
    throw Error(ErrorCode::kBadValue, path.string(), "no key upper_transform");
  return transform_from_json(document["upper_transform"], path.string());
}

}  // namespace maxillo::occlusion
