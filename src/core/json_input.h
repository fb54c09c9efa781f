#pragma once
// JSON read from a file a person gave us (plans, landmarks, poses, templates). Every failure is
// an input error naming the file and, where the text is valid JSON but a value is not usable
// (a number too large for a double, 1e400), the key path of the value: "moves[0].advancement_mm".
#include <string>
#include <string_view>

#include "core/json.h"

namespace maxillo {

// Throws Error(kBadValue, source, reason). Never lets a nlohmann exception escape.
Json parse_json_input(std::string_view text, const std::string& source);

}  // namespace maxillo
