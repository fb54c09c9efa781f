#pragma once
// The current time in UTC, as text: one clock for every timestamp maxillo writes.
#include <string>

namespace maxillo {

// strftime(3) of the current UTC time, e.g. utc_time_text("%Y-%m-%d").
std::string utc_time_text(const char* format);

// ISO 8601, e.g. 2024-05-01T12:00:00Z: archive rows, reports.
inline std::string utc_now() { return utc_time_text("%Y-%m-%dT%H:%M:%SZ"); }
// Compact, for file names: 20240501T120000Z.
inline std::string utc_stamp() { return utc_time_text("%Y%m%dT%H%M%SZ"); }

}  // namespace maxillo
