#include "dicom/dicom_uid.h"

#include "core/sha256.h"

namespace maxillo {

std::string derived_uid(std::string_view seed) {
  __extension__ typedef unsigned __int128 Uint128;  // GCC/Clang; a UUID is 128 bits
  std::string hex = sha256_hex(seed).substr(0, 32);
  Uint128 value = 0;
  for (char c : hex) value = (value << 4) | unsigned(c <= '9' ? c - '0' : c - 'a' + 10);
  std::string digits;
  do {
    digits.insert(digits.begin(), char('0' + int(value % 10)));
    value /= 10;
  } while (value > 0);
  return "2.25." + digits;
}

std::optional<std::string> uid_fault(std::string_view text, LeadingZeros leading_zeros) {
  if (text.empty()) return "it is empty";
  if (text.size() > 64) return "it has " + std::to_string(text.size()) + " characters, more than 64";
  size_t component_start = 0;
  for (size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] >= '0' && text[i] <= '9') continue;
    if (i < text.size() && text[i] != '.') {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      return "character " + std::to_string(i + 1) + " is " +
             (c >= 0x21 && c < 0x7f ? "'" + std::string(1, char(c)) + "'" : "byte " + std::to_string(int(c))) +
             ", not a digit or a dot";
    }
    const size_t length = i - component_start;
    if (length == 0) return "it has an empty component";
    if (length > 1 && text[component_start] == '0' && leading_zeros == LeadingZeros::Refused)
      return "a component starts with a zero";
    component_start = i + 1;
  }
  return std::nullopt;
}

}  // namespace maxillo
