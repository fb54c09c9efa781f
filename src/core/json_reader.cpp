#include "core/json_reader.h"

#include <cmath>
#include <cstdio>

namespace maxillo {

JsonReader::JsonReader(const Json& json, std::string path, std::string source, ErrorCode code, std::string root)
    : json_(json), path_(std::move(path)), source_(std::move(source)), code_(code), root_(std::move(root)) {
  if (!json_.is_object()) fail(path_.empty() ? root_ : path_, "must be an object");
}

void JsonReader::fail(const std::string& field, const std::string& reason) const {
  throw Error(code_, source_, field + ": " + reason);
}

std::string JsonReader::field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

bool JsonReader::has(const std::string& key) {
  known_.insert(key);
  return json_.contains(key);
}

const Json& JsonReader::at(const std::string& key) {
  if (!has(key)) fail(field(key), "missing");
  return json_.at(key);
}

void JsonReader::number(const std::string& key, double& value, double min, double max) {
  if (!has(key)) return;
  value = required_number(key, min, max);
}

void JsonReader::integer(const std::string& key, int& value, int min, int max) {
  if (!has(key)) return;
  value = static_cast<int>(required_integer(key, min, max));
}

void JsonReader::text(const std::string& key, std::string& value) {
  if (!has(key)) return;
  value = required_text(key);
}

std::optional<Eigen::Vector3d> JsonReader::point(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return point_of(json_.at(key), field(key));
}

double JsonReader::required_number(const std::string& key, double min, double max) {
  const Json& v = at(key);
  if (!v.is_number()) fail(field(key), "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < min || x > max)
    fail(field(key), "must lie in [" + format(min) + ", " + format(max) + "], got " + format(x));
  return x;
}

int64_t JsonReader::required_integer(const std::string& key, int64_t min, int64_t max) {
  const Json& v = at(key);
  if (!v.is_number_integer()) fail(field(key), "must be an integer");
  const int64_t x = v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max())
                        ? std::numeric_limits<int64_t>::max()
                        : v.get<int64_t>();
  if (x < min || x > max) fail(field(key), "must lie in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return x;
}

bool JsonReader::required_bool(const std::string& key) {
  const Json& v = at(key);
  if (!v.is_boolean()) fail(field(key), "must be true or false");
  return v.get<bool>();
}

std::string JsonReader::required_text(const std::string& key) {
  const Json& v = at(key);
  if (!v.is_string()) fail(field(key), "must be a string");
  return v.get<std::string>();
}

Eigen::Vector3d JsonReader::required_point(const std::string& key) { return point_of(at(key), field(key)); }

const Json& JsonReader::required_array(const std::string& key) {
  const Json& v = at(key);
  if (!v.is_array()) fail(field(key), "must be an array");
  return v;
}

std::vector<std::string> JsonReader::required_texts(const std::string& key) {
  const Json& array = required_array(key);
  std::vector<std::string> texts;
  for (size_t i = 0; i < array.size(); ++i) {
    if (!array[i].is_string()) fail(field(key) + "[" + std::to_string(i) + "]", "must be a string");
    texts.push_back(array[i].get<std::string>());
  }
  return texts;
}

Eigen::Isometry3d JsonReader::required_rigid_transform(const std::string& key) {
  const Json& rows = required_array(key);
  const std::string name = field(key);
  Eigen::Matrix4d m;
  if (rows.size() != 4) fail(name, "must be 4 rows of 4 numbers");
  for (size_t i = 0; i < 4; ++i) {
    if (!rows[i].is_array() || rows[i].size() != 4) fail(name, "must be 4 rows of 4 numbers");
    for (size_t j = 0; j < 4; ++j) {
      if (!rows[i][j].is_number() || !std::isfinite(rows[i][j].get<double>()))
        fail(name, "must be 4 rows of 4 numbers");
      m(Eigen::Index(i), Eigen::Index(j)) = rows[i][j].get<double>();
    }
  }
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-9) fail(name, "last row must be 0 0 0 1");
  const Eigen::Matrix3d rotation = m.topLeftCorner<3, 3>();
  if ((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() > 1e-6 || rotation.determinant() < 0)
    fail(name, "is not a rigid transform (its 3 x 3 part is not a rotation)");
  Eigen::Isometry3d transform;
  transform.matrix() = m;
  return transform;
}

int JsonReader::format_version(int newest) {
  int version = 1;
  integer("format_version", version, 1, 1000000);
  if (version > newest)
    fail("format_version", "is " + std::to_string(version) + ", newer than this program reads (" +
                               std::to_string(newest) + "): update maxillo");
  return version;
}

JsonReader JsonReader::object(const std::string& key) { return JsonReader(at(key), field(key), source_, code_, root_); }

JsonReader JsonReader::element(const Json& array, const std::string& key, size_t index) const {
  return JsonReader(array.at(index), field(key) + "[" + std::to_string(index) + "]", source_, code_, root_);
}

Eigen::Vector3d JsonReader::point_of(const Json& v, const std::string& name) const {
  if (!v.is_array() || v.size() != 3) fail(name, "must be an array of 3 numbers (LPS mm)");
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    if (!v[size_t(i)].is_number() || !std::isfinite(v[size_t(i)].get<double>()))
      fail(name, "must be an array of 3 numbers (LPS mm)");
    p[i] = v[size_t(i)].get<double>();
  }
  return p;
}

void JsonReader::refuse_unknown_keys() const {
  for (auto it = json_.begin(); it != json_.end(); ++it)
    if (!known_.count(it.key())) fail(field(it.key()), "unknown key");
}

std::string JsonReader::format(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace maxillo
