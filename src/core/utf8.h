#pragma once
// UTF-8 checks and the one repair maxillo applies to text that is not valid UTF-8.
#include <string>
#include <string_view>

namespace maxillo {

// True when `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past
// U+10FFFF).
bool is_valid_utf8(std::string_view text);

// Each byte read as ISO 8859-1 (Latin-1), written as UTF-8.
std::string latin1_to_utf8(std::string_view text);

// `text` unchanged when it is valid UTF-8, else read as Latin-1: the usual encoding of DICOM
// files that use accented letters without declaring a Specific Character Set, and of file
// names made on such systems. Latin-1 maps every byte, so the result is always valid.
std::string repaired_utf8(std::string_view text);

}  // namespace maxillo
