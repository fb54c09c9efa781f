#pragma once
// DICOM network peers as people write them: "AE@host:port" for a peer we call, "AE" or
// "AE@host" for a peer allowed to call us. AE titles follow PS3.5's AE value representation:
// 1 to 16 characters, no backslash or control characters, not only spaces.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace maxillo::net {

struct DicomPeer {
  std::string ae_title;
  std::string host;
  uint16_t port = 0;
};

// "AE@host:port" (host: a name or IPv4 address). Error(kUsage) naming the text and the reason.
DicomPeer parse_peer(std::string_view text);
std::string to_string(const DicomPeer& peer);

// Error(kUsage) naming `what` when `ae_title` is not a valid AE title.
void check_ae_title(std::string_view ae_title, std::string_view what);

// A calling peer that may store to us: its AE title, and the address it must call from (empty:
// any address).
struct AllowedPeer {
  std::string ae_title;
  std::string host;
};
// "AE" or "AE@host". Error(kUsage) as parse_peer.
AllowedPeer parse_allowed_peer(std::string_view text);

// True when some entry names this calling AE title and, if it names a host, this address.
bool is_allowed(std::span<const AllowedPeer> allowed, std::string_view calling_ae, std::string_view peer_address);

}  // namespace maxillo::net
