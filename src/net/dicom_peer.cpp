#include "net/dicom_peer.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/error.h"

namespace maxillo::net {
namespace {

[[noreturn]] void refuse(std::string_view text, std::string reason) {
  throw Error(ErrorCode::kUsage, std::string(text), std::move(reason));
}

void check_host(std::string_view host, std::string_view text) {
  if (host.empty()) refuse(text, "no host after '@'");
  const bool plain = std::all_of(host.begin(), host.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
  });
  if (!plain) refuse(text, "the host must be a name or an IPv4 address");
}

}  // namespace

void check_ae_title(std::string_view ae_title, std::string_view what) {
  if (ae_title.empty() || ae_title.size() > 16) refuse(what, "an AE title has 1 to 16 characters");
  for (char c : ae_title)
    if (c == '\\' || static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
      refuse(what, "an AE title has no backslash and no control or non-ASCII characters");
  if (ae_title.find_first_not_of(' ') == std::string_view::npos) refuse(what, "an AE title is not only spaces");
}

DicomPeer parse_peer(std::string_view text) {
  const auto at = text.rfind('@');
  const auto colon = text.rfind(':');
  if (at == std::string_view::npos || colon == std::string_view::npos || colon < at)
    refuse(text, "expected AE@host:port, e.g. PACS@127.0.0.1:4242");
  DicomPeer peer;
  peer.ae_title = std::string(text.substr(0, at));
  peer.host = std::string(text.substr(at + 1, colon - at - 1));
  check_ae_title(peer.ae_title, text);
  check_host(peer.host, text);
  const std::string_view port = text.substr(colon + 1);
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (error != std::errc() || end != port.data() + port.size() || value == 0 || value > 65535)
    refuse(text, "the port must be a number from 1 to 65535");
  peer.port = uint16_t(value);
  return peer;
}

std::string to_string(const DicomPeer& peer) {
  return peer.ae_title + "@" + peer.host + ":" + std::to_string(peer.port);
}

AllowedPeer parse_allowed_peer(std::string_view text) {
  AllowedPeer peer;
  const auto at = text.find('@');
  peer.ae_title = std::string(text.substr(0, at));
  check_ae_title(peer.ae_title, text);
  if (at != std::string_view::npos) {
    peer.host = std::string(text.substr(at + 1));
    check_host(peer.host, text);
  }
  return peer;
}

bool is_allowed(std::span<const AllowedPeer> allowed, std::string_view calling_ae, std::string_view peer_address) {
  return std::any_of(allowed.begin(), allowed.end(), [&](const AllowedPeer& peer) {
    return peer.ae_title == calling_ae && (peer.host.empty() || peer.host == peer_address);
  });
}

}  // namespace maxillo::net
