#pragma once
// How an instance reached the archive, as its index row records it (source_path): the path of
// the file it was imported from, or, for what came over the DICOM network (a spool file is no
// source), "dicom://AE@ADDRESS" naming the sender. One spelling for writers and readers.
#include <optional>
#include <string>
#include <string_view>

namespace maxillo {

inline constexpr std::string_view kNetworkSourcePrefix = "dicom://";

inline std::string network_source(std::string_view ae_title, std::string_view address) {
  return std::string(kNetworkSourcePrefix) + std::string(ae_title) + "@" + std::string(address);
}

// The sender's AE title when `source` is a network source; nothing for a file's path.
inline std::optional<std::string> network_sender(std::string_view source) {
  if (source.substr(0, kNetworkSourcePrefix.size()) != kNetworkSourcePrefix) return std::nullopt;
  source.remove_prefix(kNetworkSourcePrefix.size());
  return std::string(source.substr(0, source.find('@')));
}

}  // namespace maxillo
