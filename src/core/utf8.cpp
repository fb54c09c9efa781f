#include "core/utf8.h"

#include <cstdint>

namespace maxillo {
namespace {

// Length of the sequence a lead byte starts (0: not a lead byte), and the smallest code point
// that length may encode (anything smaller is an overlong form).
struct Lead {
  int length;
  uint32_t minimum;
  uint32_t bits;
};

Lead lead_of(unsigned char byte) {
  if (byte < 0x80) return {1, 0, byte};
  if ((byte & 0xE0) == 0xC0) return {2, 0x80, byte & 0x1Fu};
  if ((byte & 0xF0) == 0xE0) return {3, 0x800, byte & 0x0Fu};
  if ((byte & 0xF8) == 0xF0) return {4, 0x10000, byte & 0x07u};
  return {0, 0, 0};
}

}  // namespace

bool is_valid_utf8(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    Lead lead = lead_of(static_cast<unsigned char>(text[i]));
    if (lead.length == 0 || i + size_t(lead.length) > text.size()) return false;
    uint32_t code = lead.bits;
    for (int k = 1; k < lead.length; ++k) {
      auto byte = static_cast<unsigned char>(text[i + size_t(k)]);
      if ((byte & 0xC0) != 0x80) return false;
      code = (code << 6) | (byte & 0x3Fu);
    }
    if (code < lead.minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += size_t(lead.length);
  }
  return true;
}

std::string latin1_to_utf8(std::string_view text) {
  std::string out;
  out.reserve(text.size() * 2);
  for (char c : text) {
    auto byte = static_cast<unsigned char>(c);
    if (byte < 0x80) {
      out.push_back(c);
    } else {
      out.push_back(static_cast<char>(0xC0 | (byte >> 6)));
      out.push_back(static_cast<char>(0x80 | (byte & 0x3F)));
    }
  }
  return out;
}

std::string repaired_utf8(std::string_view text) {
  return is_valid_utf8(text) ? std::string(text) : latin1_to_utf8(text);
}

std::string bytes_as_utf8(std::string_view bytes) {
  if (is_valid_utf8(bytes) && bytes.find('\0') == std::string_view::npos && !bytes.starts_with(kBytesMarker))
    return std::string(bytes);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text(kBytesMarker);
  for (unsigned char byte : bytes) text.append({kHex[byte >> 4], kHex[byte & 15]});
  return text;
}

std::string bytes_from_utf8(std::string_view text) {
  if (!text.starts_with(kBytesMarker)) return std::string(text);
  auto nibble = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
  std::string bytes;
  for (size_t n = kBytesMarker.size(); n + 1 < text.size(); n += 2)
    bytes += char(nibble(text[n]) << 4 | nibble(text[n + 1]));
  return bytes;
}

}  // namespace maxillo
