#include "core/json_input.h"

#include <vector>

#include "core/error.h"

namespace maxillo {
namespace {

// A SAX pass that only follows where it is (object keys, array indices), so that when the
// parser gives up the key path of the value it stopped at is known.
class KeyPathTracker : public nlohmann::json_sax<Json> {
 public:
  std::string path() const {
    std::string text;
    for (const auto& level : levels_) {
      if (level.in_array)
        text += "[" + std::to_string(level.index) + "]";
      else if (!level.key.empty())
        text += (text.empty() ? "" : ".") + level.key;
    }
    return text;
  }
  const std::string& failure() const { return failure_; }

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& key) override {
    if (!levels_.empty()) levels_.back().key = key;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    failure_ = e.what();
    return false;
  }

 private:
  struct Level {
    bool in_array = false;
    long index = -1;
    std::string key;
  };
  // A value (or a container starting) takes the next index of an enclosing array.
  bool value() {
    if (!levels_.empty() && levels_.back().in_array) ++levels_.back().index;
    return true;
  }
  bool open(bool array) {
    value();
    levels_.push_back({array, -1, {}});
    return true;
  }
  bool close() {
    if (!levels_.empty()) levels_.pop_back();
    return true;
  }
  std::vector<Level> levels_;
  std::string failure_;
};

}  // namespace

Json parse_json_input(std::string_view text, const std::string& source) {
  Json json = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!json.is_discarded()) return json;
  KeyPathTracker tracker;
  Json::sax_parse(text, &tracker, nlohmann::detail::input_format_t::json, /*strict=*/true);
  const std::string where = tracker.path();
  std::string detail = tracker.failure();  // "[json.exception.parse_error.101] parse error at line 3, ..."
  if (auto bracket = detail.find("] "); detail.starts_with("[json.exception") && bracket != std::string::npos)
    detail.erase(0, bracket + 2);
  throw Error(ErrorCode::kBadValue, source, (where.empty() ? std::string() : where + ": ") + "invalid JSON: " + detail);
}

}  // namespace maxillo
