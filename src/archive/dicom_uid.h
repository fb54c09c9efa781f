#pragma once
// DICOM UIDs derived from text instead of drawn at random: the same seed always gives the same
// UID, so regenerated data (the phantom) keeps its identity and re-imports as already archived.
#include <string>
#include <string_view>

namespace maxillo {

// "2.25." + the first 128 bits of SHA-256(seed) in decimal (PS3.5 B.2, the UUID-derived form).
std::string derived_uid(std::string_view seed);

}  // namespace maxillo
