#pragma once
// JSON for plans, landmarks, --json output and stored parameters: nlohmann::json.
#include <string>

#include <nlohmann/json.hpp>

namespace maxillo {
using Json = nlohmann::json;

// Text of `json` for output (--json, stored records): indented by `indent` spaces. A string
// that is not valid UTF-8 (a file name in Latin-1, say) gets U+FFFD in place of the bad bytes
// instead of failing: output never fails on encoding.
inline std::string json_text(const Json& json, int indent = 2) {
  return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}
}  // namespace maxillo
