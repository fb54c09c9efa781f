#pragma once
// Reading one JSON object field by field, for files a person gave us (plans) and for records
// we stored ourselves (plan results, validations). Every failure is an Error with the given
// code naming the source and the key path of the field ("moves[0].transform_lps: must be ..."),
// never a nlohmann exception. Optional fields leave their default when absent; required ones
// fail when absent or of the wrong type, so a damaged record is never read as a default.
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/json.h"

namespace maxillo {

class JsonReader {
 public:
  // `json` must be an object; `path` is its key path in the document ("" at the top, where
  // failures name `root`).
  JsonReader(const Json& json, std::string path, std::string source, ErrorCode code = ErrorCode::kBadValue,
             std::string root = "document");
  // The reader keeps a reference to the object: a temporary would be gone before the first read.
  JsonReader(Json&& json, std::string path, std::string source, ErrorCode code = ErrorCode::kBadValue,
             std::string root = "document") = delete;

  [[noreturn]] void fail(const std::string& field, const std::string& reason) const;
  // The key path of `key` in this object: "moves[0].segment".
  std::string field(const std::string& key) const;
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  ErrorCode code() const { return code_; }

  // Whether the key is present (and marks it as known for refuse_unknown_keys).
  bool has(const std::string& key);
  // The value of a key that must be present.
  const Json& at(const std::string& key);

  // Optional fields: `value` keeps its default when the key is absent.
  void number(const std::string& key, double& value, double min, double max);
  void integer(const std::string& key, int& value, int min, int max);
  void text(const std::string& key, std::string& value);
  std::optional<Eigen::Vector3d> point(const std::string& key);

  // Required fields: absent or mistyped is a failure naming the key.
  double required_number(const std::string& key, double min = -std::numeric_limits<double>::max(),
                         double max = std::numeric_limits<double>::max());
  int64_t required_integer(const std::string& key, int64_t min = std::numeric_limits<int64_t>::min(),
                           int64_t max = std::numeric_limits<int64_t>::max());
  bool required_bool(const std::string& key);
  std::string required_text(const std::string& key);
  Eigen::Vector3d required_point(const std::string& key);
  const Json& required_array(const std::string& key);
  // An array of strings; an element that is not a string fails naming it ("notes[2]").
  std::vector<std::string> required_texts(const std::string& key);
  // A rigid transform stored as 4 rows of 4 numbers: the last row (0, 0, 0, 1), the 3 x 3 part a
  // rotation (orthonormal to 1e-6, determinant +1).
  Eigen::Isometry3d required_rigid_transform(const std::string& key);
  // A reader of the object under `key` (required), or of element `index` of an array field.
  JsonReader object(const std::string& key);
  JsonReader element(const Json& array, const std::string& key, size_t index) const;

  // The record's "format_version": 1 when absent (records stored before the key existed have
  // version 1's layout); a version above `newest` fails, since a newer program wrote it.
  int format_version(int newest);

  // Three finite numbers at `name`.
  Eigen::Vector3d point_of(const Json& value, const std::string& name) const;

  // Call last: every key of the object must have been asked for.
  void refuse_unknown_keys() const;

  static std::string format(double x);  // %g

 private:
  const Json& json_;
  std::string path_;
  std::string source_;
  ErrorCode code_;
  std::string root_;
  std::set<std::string> known_;
};

}  // namespace maxillo
