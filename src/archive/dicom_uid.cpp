#include "archive/dicom_uid.h"

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

}  // namespace maxillo
