#pragma once
// DICOM UIDs derived from text instead of drawn at random: the same seed always gives the same
// UID, so regenerated data (the phantom) keeps its identity and re-imports as already archived.
#include <optional>
#include <string>
#include <string_view>

namespace maxillo {

// "2.25." + the first 128 bits of SHA-256(seed) in decimal (PS3.5 B.2, the UUID-derived form).
std::string derived_uid(std::string_view seed);

// What makes `text` not a DICOM UID by PS3.5 9.1 (at most 64 characters, components of digits
// separated by single dots, none empty, none with a leading zero), or nothing when it is one.
// LeadingZeros::Tolerated lets components such as "0123" through: some scanners write them,
// every toolkit reads them, and refusing them would refuse real studies; everything else
// (slashes, letters, NUL bytes, empty components, 65 characters or more) breaks export, file
// names and look-ups, so it is refused.
enum class LeadingZeros { Refused, Tolerated };
std::optional<std::string> uid_fault(std::string_view text, LeadingZeros leading_zeros = LeadingZeros::Refused);

}  // namespace maxillo
