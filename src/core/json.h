#pragma once
// JSON for plans, landmarks, --json output and stored parameters: nlohmann::json.
#include <nlohmann/json.hpp>

namespace maxillo {
using Json = nlohmann::json;
}
