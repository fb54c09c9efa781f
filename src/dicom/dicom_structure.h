#pragma once
// A bounded walk over the element headers of a DICOM Part 10 file, made before DCMTK parses it.
//
// DCMTK 3.6.7 trusts the file: it recurses once per nested sequence (10,000 levels overflow the
// stack: SIGSEGV), and a damaged file meta header sent it allocating gigabytes. This walk reads
// only tags, VRs and lengths, iteratively (an explicit stack, so depth costs no call stack), and
// refuses, with an Error naming the file and the byte offset:
// - a file meta group (0002,xxxx) that is not explicit VR little endian with known VRs, or a
//   Transfer Syntax UID that is not a UID (kNotDicom);
// - a transfer syntax DCMTK does not know (kUnsupportedSyntax): DCMTK would guess the data set's
//   encoding from its first bytes, and this walk could not know which encoding it guessed;
// - a length that runs past the end of the file or of the item enclosing it (kTruncated);
// - an unknown VR in an explicit-VR data set (kNotDicom);
// - sequences nested deeper than kMaxSequenceNesting (kBadValue);
// - a deflated data set that inflates beyond kMaxInflatedBytes (kBadValue).
// Each step consumes at least 8 bytes, so the walk ends in at most size/8 steps.
#include <cstddef>
#include <filesystem>
#include <span>

namespace maxillo {

// Structured reports nest 10-20 levels; no image a CT workflow meets nests more than a few.
inline constexpr int kMaxSequenceNesting = 64;
inline constexpr size_t kMaxInflatedBytes = size_t(1) << 30;

// Throws Error as above; returns normally for a file DCMTK can parse without those hazards.
void check_dicom_structure(std::span<const std::byte> bytes, const std::filesystem::path& path);

}  // namespace maxillo
