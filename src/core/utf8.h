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

// Bytes through a medium that holds only UTF-8 text without NUL (JSON, PostgreSQL's text), and
// back unchanged: a file path is bytes on Linux, and a Latin-1 "schädel.dcm" must come back as
// the same bytes, not a repaired look-alike. Text that is valid UTF-8 without NUL passes as it
// is; anything else becomes kBytesMarker followed by the hex of its bytes (as does text that
// happens to start with the marker). The same bytes always encode alike, so equality holds.
inline constexpr std::string_view kBytesMarker = "\x01maxillo-bytes:";
std::string bytes_as_utf8(std::string_view bytes);
std::string bytes_from_utf8(std::string_view text);  // the inverse; other text is returned as it is

}  // namespace maxillo
